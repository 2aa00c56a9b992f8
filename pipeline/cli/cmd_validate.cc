// `bespoke validate SCAN [--pairs PAIRS.json] [-o REPORT.json] [--mesh-out MESH.ply]`
// Checks the point-cloud geodesics of a scan against an exact reference: the
// scan is reconstructed into a mesh (Poisson), CGAL's exact geodesics are
// computed on it between the same end points, and per pair the cloud length,
// the mesh length and their absolute and relative difference are printed as
// a table and written as JSON (eval/validate/validate.h).
//
// PAIRS.json: {"pairs": [{"name": "back_length", "from": [x, y, z],
// "to": [x, y, z]}, ...]} in the scan's frame and file units. Without it,
// --count pairs of scan points are drawn (seeded). Slow and memory-hungry
// (an exact propagation per distinct start point; CGAL needs several GB on a
// 100k-vertex mesh): a check, not a production step.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "eval/validate/validate.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

struct ValidateCommandOptions {
  std::filesystem::path scan;      // the scan
  std::filesystem::path pairs;     // optional PAIRS.json
  std::filesystem::path report;    // optional REPORT.json
  std::filesystem::path mesh_out;  // optional reference mesh (.ply .obj .off .stl)
  std::string units;               // the scan's unit; "" = guessed
  int count = 10;                  // pairs drawn without --pairs
  unsigned seed = 1;               // their seed
  int depth = 9;                   // Poisson octree depth
  int max_vertices = 60000;        // decimate the reference above this
  double cell_size_mm = 0;         // cloud grid cell; 0 = auto

  void Check() const {
    if (!units.empty() && !ParseLengthUnit(units))
      throw InputError("--units must be mm, cm, dm or m, not '" + units + "'");
    if (count < 1 || count > 1000) throw InputError("--count must be in [1, 1000]");
    if (!(cell_size_mm >= 0)) throw InputError("--cell-size must be >= 0 mm");
  }
};

std::vector<GeodesicPair> ReadPairs(const std::filesystem::path& file, double mm) {
  const nlohmann::json doc = ReadJsonFile(file);
  if (!doc.is_object() || !doc.contains("pairs") || !doc["pairs"].is_array())
    throw InputError(file, "expected {\"pairs\": [{\"name\", \"from\", \"to\"}, ...]}");
  std::vector<GeodesicPair> pairs;
  for (const auto& p : doc["pairs"]) {
    const std::string where = "pair " + std::to_string(pairs.size() + 1);
    if (!p.is_object() || !p.contains("from") || !p.contains("to"))
      throw InputError(file, where + " needs \"from\" and \"to\"");
    GeodesicPair pair;
    pair.name = p.value("name", "pair_" + std::to_string(pairs.size() + 1));
    pair.from = Vector3FromJson(p["from"], where + " from") * mm;
    pair.to = Vector3FromJson(p["to"], where + " to") * mm;
    pairs.push_back(pair);
  }
  if (pairs.empty()) throw InputError(file, "no pairs");
  return pairs;
}

void PrintTable(const ValidationReport& r) {
  std::printf("%-24s %11s %11s %9s %8s\n", "pair", "cloud_mm", "mesh_mm", "diff_mm", "diff_%");
  for (const PairComparison& c : r.pairs) {
    if (!c.error.empty()) {
      std::printf("%-24s  failed: %s\n", c.pair.name.c_str(), c.error.c_str());
      continue;
    }
    std::printf("%-24s %11.2f %11.2f %9.2f %8.3f\n", c.pair.name.c_str(), c.cloud_mm, c.mesh_mm,
                c.cloud_mm - c.mesh_mm, 100 * c.rel_diff);
  }
  std::printf("%d of %zu pairs compared: mean |diff| %.2f mm (%.3f %%), max %.2f mm (%.3f %%)\n",
              r.compared, r.pairs.size(), r.mean_abs_mm, 100 * r.mean_rel, r.max_abs_mm,
              100 * r.max_rel);
  std::printf(
      "reference mesh: %lld vertices, %lld faces; time: cloud %.1f s, "
      "reconstruction %.1f s, exact %.1f s\n",
      static_cast<long long>(r.mesh_vertices), static_cast<long long>(r.mesh_faces), r.cloud_time_s,
      r.reconstruction_time_s, r.exact_time_s);
}

nlohmann::json ReportJson(const ValidateCommandOptions& o, const ValidationReport& r) {
  auto number = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); };
  nlohmann::json pairs = nlohmann::json::array();
  for (const PairComparison& c : r.pairs)
    pairs.push_back({{"name", c.pair.name},
                     {"from", ToJson(c.pair.from)},
                     {"to", ToJson(c.pair.to)},
                     {"cloud_mm", number(c.cloud_mm)},
                     {"mesh_mm", number(c.mesh_mm)},
                     {"abs_diff_mm", c.error.empty() ? number(c.abs_diff_mm) : nlohmann::json()},
                     {"rel_diff", c.error.empty() ? number(c.rel_diff) : nlohmann::json()},
                     {"error", c.error}});
  return {{"format", "bespoke-geodesic-validation"},
          {"version", 1},
          {"units", "mm"},
          {"scan", o.scan.string()},
          {"pairs", pairs},
          {"compared", r.compared},
          {"mean_abs_diff_mm", r.mean_abs_mm},
          {"max_abs_diff_mm", r.max_abs_mm},
          {"mean_rel_diff", r.mean_rel},
          {"max_rel_diff", r.max_rel},
          {"mesh_vertices", r.mesh_vertices},
          {"mesh_faces", r.mesh_faces},
          {"time_s",
           {{"cloud", r.cloud_time_s},
            {"reconstruction", r.reconstruction_time_s},
            {"exact", r.exact_time_s}}},
          {"settings",
           {{"poisson_depth", o.depth},
            {"max_mesh_vertices", o.max_vertices},
            {"cell_size_mm", o.cell_size_mm},
            {"count", o.count},
            {"seed", o.seed},
            {"pairs_file", o.pairs.string()}}}};
}

int Run(const ValidateCommandOptions& o, const GlobalOptions& global) {
  o.Check();
  ReadOptions read;
  if (!o.units.empty()) read.units = ParseLengthUnit(o.units);
  const Scan scan = ReadScan(read, o.scan);
  const std::vector<GeodesicPair> pairs =
      o.pairs.empty() ? SpreadPairs(scan.cloud, o.count, o.seed)
                      : ReadPairs(o.pairs, MillimetresPer(scan.report.unit));
  ValidateOptions options;
  options.geodesics.grid.cell_size_mm = o.cell_size_mm;
  options.poisson.depth = o.depth;
  options.poisson.max_vertices = o.max_vertices;
  ProgressBar progress(global.quiet);
  const ValidationReport report = ValidateGeodesics(options, scan.cloud, pairs, &progress);
  PrintTable(report);
  if (!o.mesh_out.empty()) WriteMesh({}, report.mesh, o.mesh_out);
  if (!o.report.empty()) WriteJsonFile(o.report, ReportJson(o, report));
  return 0;
}

}  // namespace

CommandRunner SetupValidateCommand(CLI::App& app) {
  auto o = std::make_shared<ValidateCommandOptions>();
  app.add_option("SCAN", o->scan, "Scan file (.ply .pcd .obj .xyz .off .stl)")->required();
  app.add_option(
      "--pairs", o->pairs,
      "JSON {\"pairs\": [{\"name\", \"from\": [x,y,z], \"to\": [x,y,z]}]} in scan units");
  app.add_option("-o,--output", o->report, "Write the comparison as JSON");
  app.add_option("--mesh-out", o->mesh_out, "Write the reference mesh (mm)");
  app.add_option("--units", o->units, "The scan's length unit: mm, cm, dm or m (default: guessed)");
  app.add_option("--count", o->count, "Pairs of scan points drawn without --pairs (default 10)");
  app.add_option("--seed", o->seed, "Seed of those pairs (default 1)");
  app.add_option("--depth", o->depth, "Poisson octree depth (default 9)");
  app.add_option("--max-mesh-vertices", o->max_vertices,
                 "Decimate the reference mesh above this many vertices (default 60000)");
  app.add_option("--cell-size", o->cell_size_mm, "Cloud grid cell size in mm (default: auto)");
  return [o](const GlobalOptions& global) { return Run(*o, global); };
}

}  // namespace bespoke
