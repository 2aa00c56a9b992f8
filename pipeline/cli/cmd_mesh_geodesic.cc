// `bespoke mesh-geodesic MESH --source V [--target V]
//                        [--algorithm approx|accurate|exact] [--window 30]
//                        [--field-out FIELD.ply] [--path-out PATH.ply]
//                        [--report REPORT.json] [--units mm|cm|dm|m]`
// Geodesics on a triangle mesh (OFF, OBJ, PLY, STL) from vertex V:
//   approx   thesis Algorithm 3 (window of --window samples), default;
//   accurate thesis Algorithm 2 (whole-path flow; slower);
//   exact    CGAL's exact polyhedral geodesics (memory grows fast: ~5.6 GB
//            at 116k vertices).
// For approx/accurate both the "offset" length (the flowed curve floating on
// tangent planes) and the "projected" length (Algorithm 1, the curve cut onto
// the faces) are reported, with the Eq 3.24 error estimate for approx.
//   --target: prints the lengths to vertex T; --path-out writes the path on
//             the faces (PLY vertices in order, with `arc_length_mm`).
//   --field-out: the mesh's vertices (PLY points, mm) with `distance_mm`
//             (offset, or exact), `projected_distance_mm`, `error_bound_mm`;
//             NaN where no path reaches (other components, unused vertices).
// The mesh is checked first (measure/mesh_geodesic/mesh_surface.h): a mesh
// with non-manifold edges or no faces is an InputError (exit 1) naming the
// file; degenerate faces are dropped, other components are unreachable.
// Lengths are in mm: the file's unit is --units or guessed from its extent.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>

#include "measure/mesh_geodesic/mesh_geodesics.h"
#include "measure/mesh_geodesic/path_projection.h"
#include "oracle/truth/exact_geodesics.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

struct MeshGeodesicCommandOptions {
  std::filesystem::path mesh;        // any format ReadMesh reads
  int source = -1;                   // vertex index
  int target = -1;                   // vertex index, -1 = none
  std::string algorithm = "approx";  // approx | accurate | exact
  int window = 30;                   // Algorithm 3 window, samples
  std::filesystem::path field_out, path_out, report;
  std::string units;  // the file's unit; "" = guessed

  void Check() const {
    if (source < 0) throw InputError("--source must be a vertex index >= 0");
    if (algorithm != "approx" && algorithm != "accurate" && algorithm != "exact")
      throw InputError("--algorithm must be approx, accurate or exact, not '" + algorithm + "'");
    if (window < 3) throw InputError("--window must be at least 3 samples");
    if (target < 0 && field_out.empty())
      throw InputError("give --target V (one path) and/or --field-out FIELD.ply (every vertex)");
    if (!path_out.empty() && target < 0) throw InputError("--path-out needs --target");
    if (!units.empty() && !ParseLengthUnit(units))
      throw InputError("--units must be mm, cm, dm or m, not '" + units + "'");
  }
};

void WritePath(const Eigen::MatrixX3d& points, const std::filesystem::path& file) {
  PointCloud cloud;
  cloud.points = points;
  Eigen::VectorXd arc(points.rows());
  arc[0] = 0;
  for (Eigen::Index i = 1; i < points.rows(); ++i)
    arc[i] = arc[i - 1] + (points.row(i) - points.row(i - 1)).norm();
  cloud.scalars["arc_length_mm"] = arc;
  WriteOptions write;
  write.comment = "bespoke mesh-geodesic path on the faces; units mm; mesh frame";
  WriteScan(write, cloud, file);
}

void CheckVertex(const MeshSurface& surface, int v, const char* option) {
  if (v >= surface.num_vertices())
    throw InputError(surface.name(), std::string(option) + " " + std::to_string(v) +
                                         " is out of range (the mesh has " +
                                         std::to_string(surface.num_vertices()) + " vertices)");
  if (!surface.used(v))
    throw InputError(surface.name(),
                     std::string(option) + " vertex " + std::to_string(v) + " is used by no face");
}

int Run(const MeshGeodesicCommandOptions& o, const GlobalOptions& global) {
  o.Check();
  ReadOptions read;
  if (!o.units.empty()) read.units = ParseLengthUnit(o.units);
  Mesh input = ReadMesh(read, o.mesh);
  input.mesh.vertices *= MillimetresPer(input.report.unit);
  const auto start = std::chrono::steady_clock::now();
  const MeshSurface surface(MeshPrepOptions{}, input.mesh, o.mesh.string());
  CheckVertex(surface, o.source, "--source");
  if (o.target >= 0) CheckVertex(surface, o.target, "--target");
  for (const auto& w : surface.report().warnings)
    if (!global.quiet) std::cerr << "warning: " << o.mesh.string() << ": " << w << "\n";
  const int n = surface.num_vertices();
  Eigen::VectorXd offset = Eigen::VectorXd::Constant(n, kNaN);
  Eigen::VectorXd projected = offset, bound = offset;
  Eigen::MatrixX3d path;
  nlohmann::json report = {{"mesh", o.mesh.string()},
                           {"file_unit", ToString(input.report.unit)},
                           {"vertices", n},
                           {"faces_used", surface.mesh().num_faces()},
                           {"algorithm", o.algorithm},
                           {"source", o.source},
                           {"mesh_warnings", surface.report().warnings}};
  ProgressBar progress(global.quiet);
  if (o.algorithm == "exact") {
    if (surface.report().non_manifold_vertices > 0 || surface.report().misoriented_edges > 0)
      throw InputError(o.mesh,
                       "the exact algorithm (CGAL) needs an oriented 2-manifold; use "
                       "--algorithm approx, which handles bow-tie vertices and flipped faces");
    ExactGeodesics exact(surface.mesh());
    const SurfacePoint from = exact.AtVertex(o.source);
    if (!o.field_out.empty()) offset = exact.DistancesToVertices(from);
    if (o.target >= 0) {
      const GeodesicPath p = exact.Path(from, exact.AtVertex(o.target));
      offset[o.target] = p.length;
      path = p.points;
    }
  } else {
    MeshGeodesicsOptions options;
    options.wavefront.window = o.window;
    options.wavefront.whole_path = o.algorithm == "accurate";
    options.keep_paths = !o.path_out.empty();
    MeshGeodesics geodesics(options, surface, o.source);
    geodesics.Run(o.field_out.empty() ? o.target : -1, &progress);
    for (int v = 0; v < n; ++v) {
      if (!geodesics.settled(v)) continue;
      offset[v] = geodesics.offset_distance(v);
      projected[v] = geodesics.projected_distance(v);
      bound[v] = geodesics.error_bound(v);
    }
    if (!o.path_out.empty()) {
      std::vector<int> hints;
      const Eigen::MatrixX3d floating = geodesics.Path(o.target, &hints);
      path = ProjectPolyline(surface, floating, &hints, nullptr, true).points;
    }
    const auto& s = geodesics.stats();
    report["stats"] = {{"settled", s.settled},
                       {"flows", s.flows},
                       {"unconverged", s.unconverged},
                       {"held", s.undone},
                       {"projection_fallbacks", s.projection_fallbacks}};
    report["window"] = o.window;
  }
  if (o.target >= 0) {
    if (!std::isfinite(offset[o.target]))
      throw InputError(o.mesh, "vertex " + std::to_string(o.target) +
                                   " cannot be reached from vertex " + std::to_string(o.source) +
                                   " (another component of the mesh)");
    if (o.algorithm == "exact") {
      std::cout << "geodesic length (exact): " << offset[o.target] << " mm\n";
    } else {
      std::cout << "geodesic length: " << projected[o.target] << " mm projected on the faces, "
                << offset[o.target] << " mm offset (floating)";
      if (o.algorithm == "approx")
        std::cout << ", Eq 3.24 error estimate " << bound[o.target] << " mm";
      std::cout << "\n";
    }
    report["target"] = o.target;
    report["offset_mm"] = offset[o.target];
    report["projected_mm"] =
        std::isfinite(projected[o.target]) ? nlohmann::json(projected[o.target]) : nlohmann::json();
    report["error_bound_mm"] =
        std::isfinite(bound[o.target]) ? nlohmann::json(bound[o.target]) : nlohmann::json();
    if (!o.path_out.empty()) WritePath(path, o.path_out);
  }
  if (!o.field_out.empty()) {
    PointCloud field;
    field.points = surface.mesh().vertices;
    Eigen::Index reached = 0;
    for (Eigen::Index v = 0; v < n; ++v) {
      if (!std::isfinite(offset[v])) offset[v] = kNaN;
      reached += std::isfinite(offset[v]);
    }
    field.scalars["distance_mm"] = offset;
    if (o.algorithm != "exact") {
      field.scalars["projected_distance_mm"] = projected;
      field.scalars["error_bound_mm"] = bound;
    }
    WriteOptions write;
    write.comment = "bespoke mesh-geodesic field; units mm; NaN = unreachable";
    WriteScan(write, field, o.field_out);
    std::cout << "distance field: " << reached << " of " << n << " vertices reached\n";
    report["field_vertices_reached"] = reached;
  }
  report["time_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!o.report.empty()) WriteJsonFile(o.report, report);
  return 0;
}

}  // namespace

CommandRunner SetupMeshGeodesicCommand(CLI::App& app) {
  auto o = std::make_shared<MeshGeodesicCommandOptions>();
  app.add_option("MESH", o->mesh, "Triangle mesh (.off .obj .ply .stl)")->required();
  app.add_option("--source", o->source, "Source vertex index")->required();
  app.add_option("--target", o->target, "Target vertex index: print the geodesic length (mm)");
  app.add_option("--algorithm", o->algorithm,
                 "approx (thesis Algorithm 3, default), accurate (Algorithm 2) or exact (CGAL)");
  app.add_option("--window", o->window, "Algorithm 3 window in samples (default 30)");
  app.add_option("--field-out", o->field_out,
                 "Write every vertex's distance from --source (PLY points, distance_mm)");
  app.add_option("--path-out", o->path_out, "Write the path to --target on the faces (PLY, mm)");
  app.add_option("--report", o->report, "Write results and settings as JSON");
  app.add_option("--units", o->units, "The mesh's length unit: mm, cm, dm or m (default: guessed)");
  return [o](const GlobalOptions& global) { return Run(*o, global); };
}

}  // namespace bespoke
