// `bespoke geodesic SCAN --from X,Y,Z [--to X,Y,Z] [--path-out PATH.ply]
//                   [--field-out FIELD.ply] [--report REPORT.json] ...`
// Geodesic (shortest over-the-surface) distances computed directly on a
// scan's points (measure/cloud_geodesic/cloud_geodesics.h, thesis Algorithms 4-5).
//   --to: point to point; prints the length in mm, --path-out writes the
//         polyline (PLY vertices in order, with `arc_length_mm`).
//   --field-out: the scan with a per-point scalar `distance_mm` (NaN where
//         no surface path reaches), single source to all points.
// Coordinates are in the scan's frame and file units (as `bespoke info`
// shows them); every output is in mm. A coordinate that is not three finite
// numbers, or that lies far from the scan, is an InputError (exit 1); one in
// an unscanned region the scan surrounds (the crotch) is used with a warning.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <tuple>

#include "measure/cloud_geodesic/cloud_geodesics.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

struct GeodesicCommandOptions {
  std::filesystem::path scan;       // the scan (any format ReadScan reads)
  std::string from, to;             // "X,Y,Z" in the scan's frame and file units
  std::filesystem::path path_out;   // optional PLY of the path
  std::filesystem::path field_out;  // optional PLY of the scan with distance_mm
  std::filesystem::path report;     // optional JSON with results and settings
  std::string units;                // the file's unit; "" = guessed
  double cell_size_mm = 0;          // 0 = auto (3 point spacings)
  double sheet_gap_mm = 0;          // 0 = auto (2 x the 90th-percentile point spacing)
  int window = 30;                  // flow window, samples
  bool whole_path = false;          // flow whole paths (Algorithm 2 on the grid)
  bool use_normals = false;         // use the scan's normals (must face outwards consistently)
  bool cells_only = false;          // field: each point its grid node's distance (the thesis)

  void Check() const {
    if (from.empty()) throw InputError("--from is required");
    if (to.empty() && field_out.empty())
      throw InputError("give --to (point to point) and/or --field-out (distance to every point)");
    if (!path_out.empty() && to.empty()) throw InputError("--path-out needs --to");
    if (!units.empty() && !ParseLengthUnit(units))
      throw InputError("--units must be mm, cm, dm or m, not '" + units + "'");
    if (!(cell_size_mm >= 0)) throw InputError("--cell-size must be >= 0 mm");
    if (!(sheet_gap_mm >= 0)) throw InputError("--sheet-gap must be >= 0 mm");
    if (window < 3) throw InputError("--window must be at least 3 samples");
  }
};

Eigen::Vector3d ParsePoint(const std::string& text, const std::string& option) {
  std::string spaced = text;
  for (char& c : spaced)
    if (c == ',') c = ' ';
  std::istringstream in(spaced);
  Eigen::Vector3d p;
  std::string rest;
  if (!(in >> p.x() >> p.y() >> p.z()) || (in >> rest))
    throw InputError(option +
                     " must be X,Y,Z (three numbers in the scan's frame and units), got '" + text +
                     "'");
  if (!p.allFinite())
    throw InputError(option + " has a coordinate that is not finite: '" + text + "'");
  return p;
}

void WritePath(const CloudGeodesicPath& path, const std::filesystem::path& file) {
  PointCloud cloud;
  cloud.points = path.points;
  Eigen::VectorXd arc(path.points.rows());
  arc[0] = 0;
  for (Eigen::Index i = 1; i < path.points.rows(); ++i)
    arc[i] = arc[i - 1] + (path.points.row(i) - path.points.row(i - 1)).norm();
  cloud.scalars["arc_length_mm"] = arc;
  WriteOptions write;
  write.comment = "bespoke geodesic path; units mm; scan frame";
  WriteScan(write, cloud, file);
}

nlohmann::json Settings(const GeodesicCommandOptions& o, const CloudGrid& grid) {
  return {{"cell_size_mm", grid.cell_size_mm()},
          {"sheet_gap_mm", grid.sheet_gap_mm()},
          {"oriented_normals", grid.oriented()},
          {"point_spacing_mm", grid.spacing_mm()},
          {"window", o.window},
          {"whole_path", o.whole_path},
          {"cells", grid.num_cells()},
          {"nodes", grid.num_nodes()},
          {"links", grid.num_links()},
          {"point_field", !o.cells_only}};
}

int Run(const GeodesicCommandOptions& o, const GlobalOptions& global) {
  o.Check();
  ReadOptions read;
  if (!o.units.empty()) read.units = ParseLengthUnit(o.units);
  Scan scan = ReadScan(read, o.scan);
  const double mm = MillimetresPer(scan.report.unit);
  const Eigen::Vector3d from = ParsePoint(o.from, "--from") * mm;
  CloudGeodesicsOptions options;
  options.grid.cell_size_mm = o.cell_size_mm;
  options.grid.sheet_gap_mm = o.sheet_gap_mm;
  options.propagation.window = o.window;
  options.propagation.whole_path = o.whole_path;
  options.grid.use_normals = o.use_normals;
  options.point_field.enabled = !o.cells_only;
  ProgressBar progress(global.quiet);
  const auto start = std::chrono::steady_clock::now();
  if (o.use_normals && !scan.cloud.has_normals())
    throw InputError(o.scan.string() + ": --use-normals given but the file has no normals");
  CloudGeodesics geodesics(options, scan.cloud.points,
                           o.use_normals ? scan.cloud.normals : Eigen::MatrixX3d(0, 3), &progress);
  nlohmann::json report = {{"scan", o.scan.string()},
                           {"file_unit", ToString(scan.report.unit)},
                           {"points", scan.cloud.size()},
                           {"from", ToJson(from)},
                           {"settings", Settings(o, geodesics.grid())}};
  if (!o.to.empty()) {
    const Eigen::Vector3d to = ParsePoint(o.to, "--to") * mm;
    const CloudGeodesicPath path = geodesics.Between(from, to);
    std::cout << "geodesic length: " << path.length_mm << " mm\n";
    if (!global.quiet)
      std::cout << "  " << path.points.rows() << " path samples, " << path.nodes_settled << " of "
                << geodesics.grid().num_nodes() << " grid nodes visited\n";
    report["to"] = ToJson(to);
    report["length_mm"] = path.length_mm;
    report["path_samples"] = path.points.rows();
    report["from_on_surface"] = ToJson(Eigen::Vector3d(path.points.row(0).transpose()));
    report["to_on_surface"] =
        ToJson(Eigen::Vector3d(path.points.row(path.points.rows() - 1).transpose()));
    report["final_flow_converged"] = path.polish_converged;
    report["from_snap_mm"] = path.from_snap_mm;
    report["to_snap_mm"] = path.to_snap_mm;
    report["from_unscanned"] = path.from_unscanned;
    report["to_unscanned"] = path.to_unscanned;
    for (const auto& [end, snap, unscanned] :
         {std::tuple<const char*, double, bool>{"--from", path.from_snap_mm, path.from_unscanned},
          {"--to", path.to_snap_mm, path.to_unscanned}})
      if (unscanned)
        std::cerr << "warning: " << end << " lies in an unscanned region of the scan, " << snap
                  << " mm from the nearest scanned skin; the length spans that hole with a "
                     "straight line\n";
    if (!o.path_out.empty()) WritePath(path, o.path_out);
  }
  if (!o.field_out.empty()) {
    const CloudDistanceField field = geodesics.DistancesFrom(from, &progress);
    PointCloud out = scan.cloud;
    Eigen::VectorXd distance = field.point_distance_mm;
    Eigen::Index reached = 0;
    double farthest = 0;
    for (Eigen::Index i = 0; i < distance.size(); ++i) {
      if (std::isfinite(distance[i])) {
        ++reached;
        farthest = std::max(farthest, distance[i]);
      } else {
        distance[i] = std::numeric_limits<double>::quiet_NaN();
      }
    }
    out.scalars["distance_mm"] = distance;
    WriteOptions write;
    write.comment = "bespoke geodesic distance field; units mm; distance_mm NaN = unreachable";
    WriteScan(write, out, o.field_out);
    std::cout << "distance field: " << reached << " of " << distance.size()
              << " points reached, farthest " << farthest << " mm\n";
    report["field_points_reached"] = reached;
    report["field_farthest_mm"] = farthest;
  }
  report["time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.report.empty()) WriteJsonFile(o.report, report);
  return 0;
}

}  // namespace

CommandRunner SetupGeodesicCommand(CLI::App& app) {
  auto o = std::make_shared<GeodesicCommandOptions>();
  app.add_option("SCAN", o->scan, "Scan file (.ply .pcd .obj .xyz .off .stl)")->required();
  app.add_option("--from", o->from, "Start point X,Y,Z in the scan's frame and units")->required();
  app.add_option("--to", o->to, "End point X,Y,Z: print the geodesic length (mm)");
  app.add_option("--path-out", o->path_out, "Write the geodesic polyline (PLY, mm)");
  app.add_option("--field-out", o->field_out,
                 "Write the scan with per-point geodesic distance from --from (PLY, distance_mm)");
  app.add_option("--report", o->report, "Write results and settings as JSON");
  app.add_option("--units", o->units, "The scan's length unit: mm, cm, dm or m (default: guessed)");
  app.add_option("--cell-size", o->cell_size_mm,
                 "Grid cell size in mm (default: 3 point spacings)");
  app.add_option("--sheet-gap", o->sheet_gap_mm,
                 "Surfaces farther apart than this (mm) are never joined (default: 2 x the "
                 "90th-percentile point spacing)");
  app.add_option("--window", o->window, "Samples flowed per propagation step (default 30)");
  app.add_flag("--whole-path", o->whole_path, "Flow whole paths while propagating (slower)");
  app.add_flag("--use-normals", o->use_normals,
               "Use the scan's normals: surfaces facing opposite ways are never joined (the "
               "normals must face outwards consistently; wrongly turned patches cut the surface)");
  app.add_flag("--cells-only", o->cells_only,
               "Field: give each point its grid cell's distance (the thesis's cells alone) "
               "instead of the per-point sweep");
  return [o](const GlobalOptions& global) { return Run(*o, global); };
}

}  // namespace bespoke
