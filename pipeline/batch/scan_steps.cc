// The single-scan job's steps: read, clean, measure, resize (with a design).
#include "pipeline/batch/scan_steps.h"

#include <spdlog/spdlog.h>

#include "measure/measurements/measure_scan.h"
#include "measure/measurements/measurement_document.h"
#include "pipeline/batch/scan_step_resize.h"
#include "scanners/clean/clean.h"
#include "scanners/clean/clean_json.h"
#include "scanners/clean/mesh_sampling.h"
#include "scanners/core/json_io.h"
#include "scanners/core/units.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

void Read(JobState& s) {
  ReadOptions options;
  if (!s.options->units.empty()) options.units = ParseLengthUnit(s.options->units);
  Scan scan = ReadScanSamplingMeshes(options, MeshSamplingOptions(), s.scan_file);
  const ReadReport& r = scan.report;
  s.SetResult("file_format", ToString(r.format));
  s.SetResult("file_unit", ToString(r.unit));
  s.SetResult("points_in_file", r.points_in_file);
  s.SetResult("non_finite_dropped", r.non_finite_dropped);
  s.SetResult("points_read", static_cast<std::int64_t>(scan.cloud.size()));
  nlohmann::json bounds = nullptr;
  if (!r.bounds_file_units.isEmpty()) {
    bounds = {{"min", ToJson(Eigen::Vector3d(r.bounds_file_units.min()))},
              {"max", ToJson(Eigen::Vector3d(r.bounds_file_units.max()))}};
  }
  WriteJsonFile(s.out_dir / "input.json", {{"file", r.file.string()},
                                           {"format", ToString(r.format)},
                                           {"encoding", r.encoding},
                                           {"fields", r.fields},
                                           {"points_in_file", r.points_in_file},
                                           {"non_finite_dropped", r.non_finite_dropped},
                                           {"faces_in_file", r.faces_in_file},
                                           {"file_unit", ToString(r.unit)},
                                           {"unit_guessed", r.unit_guessed},
                                           {"bounds_file_units", bounds}});
  s.AddOutput("input.json");
  spdlog::info("read {}: {} points ({}, unit {}{})", s.scan_file.string(), scan.cloud.size(),
               ToString(r.format), ToString(r.unit), r.unit_guessed ? ", guessed" : "");
  s.scan_mm = std::move(scan.cloud);
}

// scanners/clean: the cleaning chain with its documented defaults; the cloud
// in the body frame (mm) and the report (settings, per-stage counts, transform).
void Clean(JobState& s) {
  CleanOptions options;
  options.threads = s.options->threads;
  CleanResult r = CleanScan(options, *s.scan_mm, s.progress);
  if (s.options->write_cleaned_cloud) {
    WriteOptions w;
    w.comment = "bespoke cleaned scan; units mm; frame body (z up, feet at z = 0, facing +y)";
    WriteScan(w, r.cloud, s.out_dir / "cleaned.ply");
    s.AddOutput("cleaned.ply");
  }
  WriteJsonFile(s.out_dir / "clean_report.json", {{"format", "bespoke-clean-report"},
                                                  {"version", 1},
                                                  {"input", s.scan_file.string()},
                                                  {"units", "mm"},
                                                  {"settings", ToJson(options)},
                                                  {"result", ToJson(r)}});
  s.AddOutput("clean_report.json");
  std::string flags;
  for (const std::string& f : r.flags) flags += (flags.empty() ? "" : ";") + f;
  s.SetResult("points_cleaned", static_cast<std::int64_t>(r.cloud.size()));
  s.SetResult("clean_flags", flags);
  spdlog::info("clean: {} -> {} points in the body frame{}", s.scan_mm->size(), r.cloud.size(),
               flags.empty() ? "" : " (flags: " + flags + ")");
  s.body_from_scanner = Eigen::Affine3d(r.body_from_scanner.matrix());
  s.body_cloud = std::move(r.cloud);
  s.scan_mm.reset();  // the raw cloud is no longer needed: free its memory
}

// measure/measurements: datum points (automatic, then the job's override
// file), every catalogue measurement, and the files of `bespoke measure`
// (measurements.json/.csv/.vit, freesewing.json, render.png). The summary
// takes its columns from measurements.json; results get the counts.
void MeasureStep(JobState& s) {
  const Eigen::Isometry3d body_from_scanner(s.body_from_scanner->matrix());
  const LandmarkOptions landmark_options;
  const MeasureOptions options;
  FoundLandmarks found = FindLandmarks(landmark_options, *s.body_cloud, body_from_scanner,
                                       s.options->landmarks, s.progress);
  for (const std::string& w : found.warnings) spdlog::warn("{}", w);
  const MeasureResult result =
      Measure(options, Catalogue::Builtin(), *s.body_cloud, found.set, s.progress);
  const MeasureOutputs outputs{s.out_dir / "measurements.json", s.out_dir / "measurements.csv",
                               s.out_dir / "measurements.vit",  s.out_dir / "freesewing.json",
                               s.out_dir / "render.png",        false};
  const nlohmann::json extra = {
      {"input", {{"file", s.scan_file.string()}, {"points_cleaned", s.body_cloud->size()}}},
      {"landmark_overrides", s.options->landmarks.string()},
      {"settings", {{"landmarks", ToJson(landmark_options)}, {"measure", ToJson(options)}}},
      {"timings", nlohmann::json::array({{{"name", "landmarks"},
                                          {"time_s", found.stage.time_s},
                                          {"cpu_s", found.stage.cpu_s}}})}};
  for (const std::filesystem::path& file :
       WriteMeasureOutputs(outputs, *s.body_cloud, found.set, result, extra))
    s.AddOutput(file.filename().string());
  std::size_t flagged = 0;
  for (const Measurement& m : result.measurements) flagged += !m.flags.empty();
  s.SetResult("landmarks_found", static_cast<std::int64_t>(found.set.points.size()));
  s.SetResult("measurements", static_cast<std::int64_t>(result.measurements.size()));
  s.SetResult("measurements_skipped", static_cast<std::int64_t>(result.skipped.size()));
  spdlog::info("measure: {} landmarks, {} measurements ({} flagged, {} skipped)",
               found.set.points.size(), result.measurements.size(), flagged, result.skipped.size());
  s.measurements = MeasurementDocument(result, found.set, extra);
}

const char* NeedsScan(const JobState& s) {
  return s.scan_mm ? nullptr : "needs the scan (read step skipped)";
}
const char* NeedsBodyCloud(const JobState& s) {
  return s.body_cloud ? nullptr : "needs the cleaned body-frame cloud (clean step skipped)";
}
const char* NeedsDesignAndMeasurements(const JobState& s) {
  if (s.options->design.empty()) return "no --design given";
  return s.measurements ? nullptr : "needs measurements (measure step skipped)";
}

}  // namespace

void JobState::AddOutput(const std::string& relative) {
  record->outputs.push_back(DescribeOutput(out_dir, relative));
}

const std::vector<ScanStep>& ScanSteps() {
  static const std::vector<ScanStep> steps = {
      {"read", &Read, nullptr, nullptr},
      {"clean", &Clean, nullptr, &NeedsScan},
      {"measure", &MeasureStep, nullptr, &NeedsBodyCloud},
      {"resize", &ResizeStep, nullptr, &NeedsDesignAndMeasurements},
  };
  return steps;
}

}  // namespace bespoke
