// `bespoke measure SCAN -o MEAS.json [--csv MEAS.csv] [--vit MEAS.vit]
//  [--freesewing FS.json] [--landmarks OVERRIDE.json] [--render OUT.png]
//  [--units mm|cm|dm|m] [--geometry] [--threads N]`
// Reads a scan (any supported format, unit given or guessed; a mesh is
// sampled over its faces, scanners/clean/mesh_sampling.h), cleans it into
// the body frame (scanners/clean), finds the datum points (measure/landmarks;
// the override file's points replace or add to them), takes every catalogue
// measurement (measure/measurements) and writes the measurement document
// (docs/contracts.md: values in mm, datum points, quality flags, the
// settings used and per-stage times) plus the requested exports and the
// render. Prints a table of stage times (wall and CPU) unless --quiet.
// Outputs are checked before any work and written atomically; a bad file
// or option is an InputError (exit 1) naming it, with nothing written.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <nlohmann/json.hpp>

#include "measure/measurements/measure_scan.h"
#include "measure/measurements/measurement_document.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "scanners/clean/clean.h"
#include "scanners/clean/clean_json.h"
#include "scanners/clean/mesh_sampling.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/core/units.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

struct MeasureCommandOptions {
  std::filesystem::path scan;
  MeasureOutputs outputs;
  std::filesystem::path landmarks;  // --landmarks: override file (optional)
  std::string units;                // "" (guess) or mm / cm / dm / m
  int threads = 0;                  // cleaning threads; 0 = all cores
  CleanOptions clean;
  LandmarkOptions landmark_options;
  MeasureOptions measure;

  void Check() const {
    if (!units.empty() && !ParseLengthUnit(units))
      throw InputError("--units must be mm, cm, dm or m, not '" + units + "'");
    CheckMeasureOutputs(outputs);
    if (!landmarks.empty() && !std::filesystem::is_regular_file(landmarks))
      throw InputError(landmarks, "the landmark override file does not exist");
    clean.Check();
    landmark_options.Check();
    measure.Check();
  }
};

class Clock {
 public:
  MeasureStage Stop(const std::string& name) const {
    return {name, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count(),
            static_cast<double>(std::clock() - cpu_) / CLOCKS_PER_SEC};
  }

 private:
  std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
  std::clock_t cpu_ = std::clock();
};

nlohmann::json StagesJson(const std::vector<MeasureStage>& stages) {
  nlohmann::json out = nlohmann::json::array();
  for (const MeasureStage& s : stages)
    out.push_back({{"name", s.name}, {"time_s", s.time_s}, {"cpu_s", s.cpu_s}});
  return out;
}

void PrintTable(const std::vector<MeasureStage>& stages, std::size_t points_read,
                std::size_t points_clean, const MeasureResult& result) {
  std::printf("%-18s %9s %9s\n", "stage", "wall s", "cpu s");
  double wall = 0, cpu = 0;
  for (const MeasureStage& s : stages) {
    std::printf("%-18s %9.3f %9.3f\n", s.name.c_str(), s.time_s, s.cpu_s);
    wall += s.time_s, cpu += s.cpu_s;
  }
  std::printf("%-18s %9.3f %9.3f\n", "total", wall, cpu);
  std::size_t flagged = 0;
  for (const Measurement& m : result.measurements) flagged += !m.flags.empty();
  std::printf("%zu points read, %zu cleaned; %zu measurements (%zu flagged), %zu skipped\n",
              points_read, points_clean, result.measurements.size(), flagged,
              result.skipped.size());
  std::fflush(stdout);
}

int Run(MeasureCommandOptions& o, const GlobalOptions& global) {
  o.clean.threads = o.threads;
  o.Check();
  std::vector<MeasureStage> stages;
  Clock read_clock;
  ReadOptions read;
  if (!o.units.empty()) read.units = ParseLengthUnit(o.units);
  Scan scan = ReadScanSamplingMeshes(read, MeshSamplingOptions(), o.scan);
  stages.push_back(read_clock.Stop("read"));
  for (const std::string& w : scan.report.warnings) spdlog::warn("{}: {}", o.scan.string(), w);
  const std::size_t points_read = static_cast<std::size_t>(scan.cloud.size());

  ProgressBar bar(global.quiet);
  Clock clean_clock;
  const CleanResult clean = CleanScan(o.clean, std::move(scan.cloud), &bar);
  stages.push_back(clean_clock.Stop("clean"));
  for (const std::string& flag : clean.flags) spdlog::warn("clean: {}", flag);

  FoundLandmarks found =
      FindLandmarks(o.landmark_options, clean.cloud, clean.body_from_scanner, o.landmarks, &bar);
  stages.push_back(found.stage);
  for (const std::string& w : found.warnings) spdlog::warn("{}", w);
  for (const auto& [name, why] : found.set.missing)
    spdlog::debug("landmark {} not placed: {}", name, why);

  const MeasureResult result =
      Measure(o.measure, Catalogue::Builtin(), clean.cloud, found.set, &bar);
  stages.insert(stages.end(), result.stages.begin(), result.stages.end());
  for (const auto& [name, reason] : result.skipped)
    spdlog::warn("{} not measured: {}", name, reason);

  Clock write_clock;
  const ReadReport& r = scan.report;
  nlohmann::json extra = {
      {"input",
       {{"file", o.scan.string()},
        {"format", ToString(r.format)},
        {"file_unit", ToString(r.unit)},
        {"unit_guessed", r.unit_guessed},
        {"points_in_file", r.points_in_file},
        {"points_cleaned", clean.cloud.size()}}},
      {"body_from_scanner", ToJson(Eigen::Affine3d(clean.body_from_scanner.matrix()))},
      {"clean_flags", clean.flags},
      {"landmark_overrides", o.landmarks.string()},
      {"settings",
       {{"clean", ToJson(o.clean)},
        {"landmarks", ToJson(o.landmark_options)},
        {"measure", ToJson(o.measure)}}},
      {"timings", StagesJson({stages.begin(), stages.begin() + 3})}};
  WriteMeasureOutputs(o.outputs, clean.cloud, found.set, result, extra);
  stages.push_back(write_clock.Stop("write"));
  if (!global.quiet)
    PrintTable(stages, points_read, static_cast<std::size_t>(clean.cloud.size()), result);
  return 0;
}

}  // namespace

CommandRunner SetupMeasureCommand(CLI::App& app) {
  auto o = std::make_shared<MeasureCommandOptions>();
  app.add_option("SCAN", o->scan, "Scan file (.ply .pcd .obj .xyz .csv .txt .off .stl)")
      ->required();
  app.add_option("-o,--output", o->outputs.json, "Measurement document (.json, mm, body frame)")
      ->required();
  app.add_option("--csv", o->outputs.csv, "Also a CSV table of the measurements (.csv)");
  app.add_option("--vit", o->outputs.vit,
                 "Also Valentina/Seamly2D individual measurements (.vit, cm)");
  app.add_option("--freesewing", o->outputs.freesewing, "Also FreeSewing measurements (.json, mm)");
  app.add_option("--render", o->outputs.render,
                 "Also a picture: front and side views with datum points, girths, paths (.png)");
  app.add_option(
      "--landmarks", o->landmarks,
      "Landmark override file (JSON name -> [x, y, z]; a measurement or truth document works too)");
  app.add_option("--units", o->units,
                 "The scan's length unit: mm, cm, dm or m (default: guessed from its size)");
  app.add_flag("--geometry", o->outputs.geometry,
               "Write girth loops and geodesic paths into the JSON document");
  app.add_option("--threads", o->threads, "Cleaning threads (0: all cores)")->capture_default_str();
  app.add_option("--slab-mm", o->measure.section.half_thickness_mm,
                 "Girths: half thickness of the section slab, mm")
      ->capture_default_str();
  app.add_option("--smooth-mm", o->measure.section.smooth_arc_mm,
                 "Girths: arc of the denoising bins, mm (0: raw hull)")
      ->capture_default_str();
  return [o](const GlobalOptions& global) { return Run(*o, global); };
}

}  // namespace bespoke
