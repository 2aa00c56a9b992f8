// The single-scan job behind `bespoke run` (and each worker of `bespoke
// batch`): scan file in, one folder of results out.
//
// Steps, in order (scan_steps.h): read -> clean (body frame) -> measure ->
// resize (only with a design). Each step calls the library and writes its
// outputs into `out_dir` atomically; a step whose library is not part of
// this build yet is recorded as skipped with the reason, as are the steps
// that need its results. The folder then gets done.json LAST (done_record.h):
// status, per-step times, versions, settings, and every output file with size
// and SHA-256 - a folder without it is partial.
//
// Failure: the error propagates (InputError for a bad scan or option ->
// exit 1, InternalError -> exit 2) after done.json is written with status
// "failed", the error kind and message. An old done.json in `out_dir` is
// removed before anything else, so a half-redone folder never looks done.
//
// Units: the scan's points are read in millimetres (units given or guessed);
// every output is in millimetres, in the body frame once cleaned.
#ifndef BESPOKE_PIPELINE_BATCH_SCAN_JOB_H_
#define BESPOKE_PIPELINE_BATCH_SCAN_JOB_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "pipeline/batch/done_record.h"
#include "scanners/core/progress.h"

namespace bespoke {

struct ScanJobOptions {
  std::string scan_id;              // "" (default) = the scan file's stem
  std::string units;                // "" (default) = guess from the extent; mm, cm, dm, m
  std::string design;               // "" (default) = no pattern; "shirt" or "trousers"
  std::filesystem::path landmarks;  // "" (default) = automatic landmarks; else an override JSON
  bool write_cleaned_cloud = true;  // write cleaned.ply (default yes)
  int threads = 0;                  // threads of the parallel stages; 0 (default) = all CPUs
  // Throws InputError for an unknown design or unit, a missing landmark file,
  // or threads < 0.
  void Check() const;
  nlohmann::json ToJson() const;
};

// Runs the job; returns the record written to out_dir/done.json (status "ok").
DoneRecord RunScanJob(const ScanJobOptions& options, const std::filesystem::path& scan,
                      const std::filesystem::path& out_dir, Progress* progress);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_SCAN_JOB_H_
