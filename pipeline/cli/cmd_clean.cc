// `bespoke clean SCAN -o OUT.ply [--report REPORT.json] [--units mm|cm|dm|m]
//  [stage options] [--no-<stage>]`: reads a scan (ReadScan: any supported
// format, unit given or guessed, NaN/Inf dropped; a mesh sampled over its
// faces, scanners/clean/mesh_sampling.h), runs the cleaning chain
// (scanners/clean/clean.h), prints a table of per-stage point counts and wall
// times, and writes the cleaned cloud in the body frame (mm; PLY with
// normals by default, or .pcd / .xyz) and, with --report, a JSON report: the
// settings used, the file's unit and whether it was guessed, counts, times,
// body_from_scanner (4x4 row-major, scanner mm -> body mm), the frame's cues
// and flags. Both outputs are written atomically; a bad file or option is an
// InputError (exit 1) and leaves no output behind.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "scanners/clean/clean.h"
#include "scanners/clean/clean_json.h"
#include "scanners/clean/mesh_sampling.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

struct CleanCommandOptions {
  std::filesystem::path scan;    // input scan
  std::filesystem::path output;  // -o: cleaned cloud, .ply (default binary) / .pcd / .xyz
  std::filesystem::path report;  // --report: JSON report (optional)
  std::string units;             // "" (guess, default) or mm / cm / dm / m
  bool ascii = false;            // --ascii: ASCII PLY/PCD instead of binary
  bool no_voxel = false, no_sor = false, no_ror = false, no_floor = false, no_cluster = false,
       no_normals = false;
  CleanOptions clean;

  void Check() const {
    if (!units.empty() && !ParseLengthUnit(units)) {
      throw InputError("--units must be mm, cm, dm or m, not '" + units + "'");
    }
    const std::string ext = output.extension().string();
    if (ext != ".ply" && ext != ".pcd" && ext != ".xyz") {
      throw InputError(output, "the output must end in .ply, .pcd or .xyz");
    }
    if (!report.empty() && report.extension() != ".json") {
      throw InputError(report, "the report must end in .json");
    }
    if (std::filesystem::exists(scan) && std::filesystem::exists(output) &&
        std::filesystem::equivalent(scan, output)) {
      throw InputError(output, "the output would overwrite the input scan");
    }
    clean.Check();
  }

  // The --no-<stage> flags into the chain's options.
  void ApplyStageSwitches() {
    clean.use_voxel_grid = !no_voxel;
    clean.use_statistical_outliers = !no_sor;
    clean.use_radius_outliers = !no_ror;
    clean.use_floor = !no_floor;
    clean.use_largest_cluster = !no_cluster;
    clean.use_normals = !no_normals;
  }
};

double Seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

void AddStageOptions(CLI::App& app, CleanCommandOptions& o) {
  CleanOptions& c = o.clean;
  app.add_option("--voxel-mm", c.voxel_grid.leaf_mm, "Voxel grid leaf, mm")->capture_default_str();
  app.add_option("--sor-k", c.statistical_outliers.mean_k,
                 "Statistical outliers: neighbours averaged")
      ->capture_default_str();
  app.add_option("--sor-mul", c.statistical_outliers.stddev_mul,
                 "Statistical outliers: reject above median + mul * robust sigma")
      ->capture_default_str();
  app.add_option("--ror-radius-mm", c.radius_outliers.radius_mm, "Radius outliers: radius, mm")
      ->capture_default_str();
  app.add_option("--ror-min", c.radius_outliers.min_neighbors,
                 "Radius outliers: other points required within the radius")
      ->capture_default_str();
  app.add_option("--floor-mm", c.floor.distance_mm, "Floor: RANSAC inlier and removal band, mm")
      ->capture_default_str();
  app.add_option("--cluster-mm", c.cluster.tolerance_mm, "Largest cluster: widest gap bridged, mm")
      ->capture_default_str();
  app.add_option("--normal-k", c.normals.k, "Normals: neighbours in the plane fit")
      ->capture_default_str();
  app.add_option("--threads", c.threads, "Threads (0: all cores)")->capture_default_str();
  app.add_flag("--no-voxel", o.no_voxel, "Skip the voxel grid (keep the scan's own density)");
  app.add_flag("--no-sor", o.no_sor, "Skip the statistical outlier test");
  app.add_flag("--no-ror", o.no_ror, "Skip the radius outlier test");
  app.add_flag("--no-floor", o.no_floor, "Do not look for a floor (up from the body's long axis)");
  app.add_flag("--no-cluster", o.no_cluster, "Keep every cluster, not only the largest");
  app.add_flag("--no-normals", o.no_normals, "Do not estimate normals");
}

void PrintTable(const CleanResult& result, double read_s, double write_s) {
  std::printf("%-22s %10s %10s %9s %9s\n", "stage", "points in", "points out", "wall s", "cpu s");
  std::printf("%-22s %10s %10lld %9.3f\n", "read", "",
              static_cast<long long>(result.stages.front().points_in), read_s);
  double cpu = 0;
  for (const CleanStage& s : result.stages) {
    if (!s.enabled) {
      std::printf("%-22s %10s\n", s.name.c_str(), "off");
      continue;
    }
    std::printf("%-22s %10lld %10lld %9.3f %9.3f\n", s.name.c_str(),
                static_cast<long long>(s.points_in), static_cast<long long>(s.points_out), s.time_s,
                s.cpu_s);
    cpu += s.cpu_s;
  }
  std::printf("%-22s %10s %10s %9.3f\n", "write", "", "", write_s);
  std::printf("%-22s %10s %10lld %9.3f %9.3f\n", "cleaning", "",
              static_cast<long long>(result.cloud.size()), result.total_time_s, cpu);
  std::printf("%-22s %10s %10s %9.3f\n", "total", "", "", read_s + result.total_time_s + write_s);
  const BodyFrame& f = result.frame;
  std::printf(
      "body frame: up from %s, front from %s (feet %.0f mm, nose %.0f mm), height %.0f mm\n",
      f.up_source.c_str(), f.front_source.c_str(), f.foot_offset_mm, f.nose_cue_mm, f.height_mm);
  std::fflush(stdout);
}

nlohmann::json FileJson(const ReadReport& r) {
  return {{"path", r.file.string()},
          {"format", ToString(r.format)},
          {"encoding", r.encoding},
          {"fields", r.fields},
          {"points_in_file", r.points_in_file},
          {"non_finite_dropped", r.non_finite_dropped},
          {"file_unit", ToString(r.unit)},
          {"unit_guessed", r.unit_guessed},
          {"mm_per_file_unit", MillimetresPer(r.unit)},
          {"warnings", r.warnings}};
}

int Run(CleanCommandOptions& o, const GlobalOptions& global) {
  o.ApplyStageSwitches();
  o.Check();
  auto start = std::chrono::steady_clock::now();
  ReadOptions read;
  if (!o.units.empty()) read.units = ParseLengthUnit(o.units);
  Scan scan = ReadScanSamplingMeshes(read, MeshSamplingOptions(), o.scan);
  const double read_s = Seconds(start);
  for (const std::string& w : scan.report.warnings) spdlog::warn("{}: {}", o.scan.string(), w);

  CleanResult result;
  {
    ProgressBar bar(global.quiet);
    result = CleanScan(o.clean, std::move(scan.cloud), &bar);
  }

  start = std::chrono::steady_clock::now();
  WriteOptions write;
  write.ply_encoding = o.ascii ? PlyEncoding::kAscii : PlyEncoding::kBinaryLittleEndian;
  write.pcd_encoding = o.ascii ? PcdEncoding::kAscii : PcdEncoding::kBinary;
  write.comment = "bespoke cleaned scan; units mm; frame body (z up, feet at z = 0, facing +y)";
  WriteScan(write, result.cloud, o.output);
  const double write_s = Seconds(start);

  if (!o.report.empty()) {
    WriteJsonFile(o.report, {{"format", "bespoke-clean-report"},
                             {"version", 1},
                             {"input", o.scan.string()},
                             {"output", o.output.string()},
                             {"units", "mm"},
                             {"file", FileJson(scan.report)},
                             {"non_finite_dropped",
                              scan.report.non_finite_dropped + result.non_finite_dropped},
                             {"settings", ToJson(o.clean)},
                             {"result", ToJson(result)},
                             {"read_time_s", read_s},
                             {"write_time_s", write_s}});
  }
  if (!global.quiet) PrintTable(result, read_s, write_s);
  for (const std::string& flag : result.flags) spdlog::warn("clean: {}", flag);
  return 0;
}

}  // namespace

CommandRunner SetupCleanCommand(CLI::App& app) {
  auto options = std::make_shared<CleanCommandOptions>();
  app.add_option("SCAN", options->scan, "Scan file (.ply .pcd .obj .xyz .csv .txt .off .stl)")
      ->required();
  app.add_option("-o,--output", options->output, "Cleaned cloud in the body frame (.ply .pcd .xyz)")
      ->required();
  app.add_option("--report", options->report,
                 "JSON report: settings, counts, times, body_from_scanner");
  app.add_option("--units", options->units,
                 "The scan's length unit: mm, cm, dm or m (default: guessed from its size)");
  app.add_flag("--ascii", options->ascii, "Write ASCII PLY/PCD instead of binary");
  AddStageOptions(app, *options);
  return [options](const GlobalOptions& global) { return Run(*options, global); };
}

}  // namespace bespoke
