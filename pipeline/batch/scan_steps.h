// The steps of the single-scan job (scan_job.h) and the state they pass on.
//
// This is the seam where the per-scan stages plug in: each step is a plain
// function of JobState calling one library (scanners/io, scanners/clean,
// measure, resize) and registering the files it wrote. A stage that is not
// part of this build yet is a step with `run == nullptr` and the reason.
#ifndef BESPOKE_PIPELINE_BATCH_SCAN_STEPS_H_
#define BESPOKE_PIPELINE_BATCH_SCAN_STEPS_H_

#include <Eigen/Geometry>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/batch/done_record.h"
#include "pipeline/batch/scan_job.h"
#include "scanners/core/progress.h"
#include "scanners/core/types.h"

namespace bespoke {

struct JobState {
  const ScanJobOptions* options = nullptr;
  std::filesystem::path scan_file;
  std::filesystem::path out_dir;
  Progress* progress = nullptr;

  // Filled by the steps, in order.
  std::optional<PointCloud> scan_mm;     // read: scanner axes, mm
  std::optional<PointCloud> body_cloud;  // clean: body frame, mm
  std::optional<Eigen::Affine3d> body_from_scanner;
  std::optional<nlohmann::json> measurements;  // measure: docs/contracts.md document

  DoneRecord* record = nullptr;  // results (flat, deterministic), outputs

  // Registers `relative` (already written, atomically) as an output.
  void AddOutput(const std::string& relative);
  // Sets a deterministic result value (goes to summary.csv).
  template <typename T>
  void SetResult(const std::string& name, const T& value) {
    record->results[name] = value;
  }
};

struct ScanStep {
  const char* name;         // "read", "clean", "measure", "resize"
  void (*run)(JobState&);   // nullptr: not in this build
  const char* unavailable;  // why not, when run == nullptr
  // Why the step does not apply to this job (e.g. resize without a design,
  // measure without a cleaned cloud), or nullptr when it does. May be null.
  const char* (*skip_reason)(const JobState&) = nullptr;
};

// The job's steps in order.
const std::vector<ScanStep>& ScanSteps();

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_SCAN_STEPS_H_
