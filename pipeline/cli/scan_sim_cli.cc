#include "pipeline/cli/scan_sim_cli.h"

#include <CLI/CLI.hpp>
#include <cstdio>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// "AxB" -> (A, B); "A" -> (A, 1) when `single_ok`. InputError otherwise.
std::pair<int, int> ParsePair(const std::string& text, const std::string& option, bool single_ok) {
  int a = 0, b = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%dx%d%c", &a, &b, &tail) == 2 && a > 0 && b > 0) return {a, b};
  if (single_ok && std::sscanf(text.c_str(), "%d%c", &a, &tail) == 1 && a > 0) return {a, 1};
  throw InputError(option + " must look like " + (single_ok ? "6x7 or 16" : "240x180") + ", not '" +
                   text + "'");
}

}  // namespace

void ScanSimCli::Check() const {
  ToOptions().Check();
  const auto unit = ParseLengthUnit(units);
  if (!unit || (*unit != LengthUnit::kMetre && *unit != LengthUnit::kMillimetre)) {
    throw InputError("--units must be m or mm, not '" + units + "'");
  }
}

ScanSimOptions ScanSimCli::ToOptions() const {
  ScanSimOptions o;
  o.seed = seed;
  o.noise_sigma_mm = noise_mm;
  o.booth = BoothPreset(booth);
  if (!sensors.empty()) {
    const auto [directions, heights] = ParsePair(sensors, "--sensors", true);
    o.booth.directions = directions;
    o.booth.heights = heights;
  }
  if (!resolution.empty()) {
    const auto [width, height] = ParsePair(resolution, "--resolution", false);
    o.booth.width_px = width;
    o.booth.height_px = height;
  }
  o.outlier_fraction = outliers;
  o.floor = floor;
  o.stray_objects = stray_objects;
  o.transform = ParseScanTransform(transform);
  o.misalign_mm = misalign_mm;
  o.misalign_deg = misalign_deg;
  return o;
}

void ScanSimCli::Apply(ScanSimFiles* files) const {
  files->units = *ParseLengthUnit(units);
  files->pcd = pcd;
  files->labels = labels;
}

void AddScanSimOptions(CLI::App& app, ScanSimCli* cli, bool seed_option) {
  if (seed_option)
    app.add_option("--seed", cli->seed, "Seed of everything random in the scan (default 1)");
  app.add_option("--noise-mm", cli->noise_mm, "Range noise SD along each ray, mm (default 1)");
  app.add_option("--booth", cli->booth,
                 "Named booth: default, sparse, sparse-3, 60k, 120k, 250k, 500k (default default)");
  app.add_option("--sensors", cli->sensors,
                 "DIRECTIONSxHEIGHTS sensors, or N columns of 1 (default: the booth's, 6x7)");
  app.add_option("--resolution", cli->resolution,
                 "Depth image per sensor, WIDTHxHEIGHT px (default: the booth's, 240x180)");
  app.add_option("--outliers", cli->outliers,
                 "Fraction of outlier points in the output (default 0.02)");
  app.add_flag("--floor,!--no-floor", cli->floor,
               "Scan a floor patch around the feet (default on)");
  app.add_option("--stray-objects", cli->stray_objects,
                 "Poles and boxes standing in the booth (default 0)");
  app.add_option("--transform", cli->transform,
                 "Scanner frame: none, random (rigid) or y-up (default none)");
  app.add_option("--units", cli->units, "Unit of the written scan: m or mm (default m)");
  app.add_option("--misalign-mm", cli->misalign_mm,
                 "Per-sensor calibration error SD, mm (default 0)");
  app.add_option("--misalign-deg", cli->misalign_deg,
                 "Per-sensor calibration error SD, degrees (default 0)");
  app.add_flag("--pcd", cli->pcd, "Also write the scan as PCD beside the PLY");
  app.add_flag("--labels", cli->labels,
               "Write per-point source (body/floor/stray/outlier) and sensor fields");
}

}  // namespace bespoke
