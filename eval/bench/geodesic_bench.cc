// geodesic_bench: speed, memory and accuracy of the point-cloud geodesics
// (thesis Algorithms 4-5) against CGAL's exact geodesics, in one run.
//
//   build/eval/bench/geodesic_bench [--shared DIR] [--no-cgal] [--quick] [--body-only] [--dump DIR]
//                                [--fit-wedge-deg D] [--surface-offset-fraction F] [--fit-points N]
//   (--body-only: the 116k body and generated-scan field rows alone; --dump DIR:
//   per-vertex cloud and exact distances of those rows as DIR/<name>.txt, to
//   see where the errors are; the last three set the point field's options,
//   point_field.h, for every row)
//
// Rows (each algorithm runs in a forked child so its peak memory is its own):
//   - single source to all destinations on clouds made of the vertices of the
//     meshes in ../shared/data/meshes (116k-vertex MakeHuman body, the 35k and
//     109k bunnies; MakeHuman is in dm, the bunny in m: both converted to mm),
//     source vertex 0, errors per vertex against CGAL from the same vertex;
//   - the body's faces within 100 mm of the mouth, from the chin (the lips,
//     closer together than the vertex spacing, seen from a near source);
//   - the same on a generated scan (parametric body through the virtual
//     scanner, 0.5 mm noise), source the back neck point, errors at the body
//     mesh's vertices that the scan saw (within 3 mm of a scan point);
//   - point to point between ten pairs of datum points on that scan;
//   - the 116k body at four cell sizes, to show how the cost grows.
// Relative errors are over vertices at least 10 mm from the source. CGAL
// needs several GB (about 5.6 GB on the 116k body): run the bench alone.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "eval/bench/bench_main.h"
#include "eval/bench/child_run.h"
#include "measure/catalogue/catalogue.h"
#include "measure/cloud_geodesic/cloud_geodesics.h"
#include "measure/cloud_geodesic/local_surface.h"
#include "measure/cloud_geodesic/point_index.h"
#include "oracle/body/parametric_body.h"
#include "oracle/scan_sim/scan_sim.h"
#include "oracle/truth/exact_geodesics.h"
#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"

namespace bespoke {
namespace {

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU seconds (user + system) of the last child run: the load of other jobs
// on the machine inflates wall times, much less CPU times.
double g_child_cpu_s = 0;
std::string g_dump;  // --dump DIR: per-vertex distances of the mesh rows
// Every cloud row's options: the defaults, with the point-field settings
// given on the command line (--fit-wedge-deg, --surface-offset-fraction,
// --fit-points), to rerun the sensitivity figures in docs/geodesics.md.
CloudGeodesicsOptions g_options;

// Runs `work` in a child process; returns its numbers, and its peak resident
// memory in MB through `peak_mb` (its CPU time in g_child_cpu_s).
std::vector<double> InChild(const std::function<std::vector<double>()>& work, double* peak_mb) {
  ChildUsage usage;
  std::vector<double> out = RunInChild(work, &usage);
  *peak_mb = usage.peak_mb;
  g_child_cpu_s = usage.cpu_s;
  if (!usage.ok) throw InternalError("child run failed");
  return out;
}

struct Errors {
  double mean_rel = 0, max_rel = 0, p999_rel = 0, mean_abs_mm = 0, max_abs_mm = 0;
  int counted = 0, missing = 0;
};

Errors Compare(const Eigen::VectorXd& cloud, const Eigen::VectorXd& exact,
               const std::vector<bool>* use = nullptr) {
  Errors e;
  std::vector<double> rel;
  double sum_abs = 0;
  int abs_count = 0;
  for (Eigen::Index i = 0; i < exact.size(); ++i) {
    if (!std::isfinite(exact[i]) || (use && !(*use)[static_cast<size_t>(i)])) continue;
    if (!std::isfinite(cloud[i])) {
      ++e.missing;
      continue;
    }
    const double d = std::abs(cloud[i] - exact[i]);
    sum_abs += d;
    ++abs_count;
    e.max_abs_mm = std::max(e.max_abs_mm, d);
    if (exact[i] >= 10) rel.push_back(d / exact[i]);
  }
  e.counted = static_cast<int>(rel.size());
  if (rel.empty()) return e;
  double sum = 0;
  for (const double r : rel) sum += r;
  e.mean_rel = sum / static_cast<double>(rel.size());
  std::sort(rel.begin(), rel.end());
  e.max_rel = rel.back();
  e.p999_rel = rel[static_cast<size_t>(0.999 * static_cast<double>(rel.size() - 1))];
  e.mean_abs_mm = sum_abs / std::max(1, abs_count);
  return e;
}

void PrintHeader() {
  std::printf("\n%-26s %7s %6s %7s %7s %7s %7s %8s %8s %7s %7s %6s %7s %7s %7s\n", "run", "points",
              "nodes", "grid_s", "prop_s", "cpu_s", "peak_MB", "cgal_s", "cgal_cpu", "cgal_MB",
              "ratio", "mean_%", "p99.9_%", "max_%", "mean_mm");
}

// `cpu`, `cgal_cpu`: CPU seconds of the two child runs (cloud: grid, propagation
// and evaluation at the reference vertices); the ratio is of CPU times.
void PrintRow(const std::string& name, Eigen::Index points, double nodes, double grid_s,
              double prop_s, double cpu, double peak, double cgal_s, double cgal_cpu,
              double cgal_peak, const Errors& e) {
  std::printf(
      "%-26s %7lld %6.0f %7.3f %7.3f %7.2f %7.0f %8.2f %8.2f %7.0f %7.1f %6.3f %7.3f %7.3f "
      "%7.3f\n",
      name.c_str(), static_cast<long long>(points), nodes, grid_s, prop_s, cpu, peak, cgal_s,
      cgal_cpu, cgal_peak, cgal_cpu > 0 ? cgal_cpu / cpu : 0.0, 100 * e.mean_rel, 100 * e.p999_rel,
      100 * e.max_rel, e.mean_abs_mm);
  if (e.missing > 0)
    std::printf("%-26s %d reference points not reached by the cloud (left out above)\n", "",
                e.missing);
  std::fflush(stdout);
}

// The same errors over the vertices a scanner sees (`seen`), under a row.
void PrintSeen(const Eigen::VectorXd& cloud, const Eigen::VectorXd& exact,
               const std::vector<bool>* seen) {
  if (!seen) return;
  const Errors e = Compare(cloud, exact, seen);
  std::printf(
      "%-26s over the %d vertices a scanner sees: mean %.3f %%  p99.9 %.3f %%  "
      "max %.3f %%\n",
      "", e.counted, 100 * e.mean_rel, 100 * e.p999_rel, 100 * e.max_rel);
}

// Cloud single source in a child: {grid_s, prop_s, nodes, d_0 .. d_{Q-1}} at `query`.
// `normals`: the cloud's outward normals, or 0 x 3 for none.
std::vector<double> CloudField(const CloudGeodesicsOptions& options, const Eigen::MatrixX3d& cloud,
                               const Eigen::MatrixX3d& normals, const Eigen::Vector3d& source,
                               const Eigen::MatrixX3d& query) {
  double t = Now();
  CloudGeodesics geodesics(options, cloud, normals);
  const double grid_s = Now() - t;
  t = Now();
  geodesics.DistancesFrom(source);
  const double prop_s = Now() - t;
  const Eigen::VectorXd d = geodesics.DistancesAt(query);
  std::vector<double> out = {grid_s, prop_s, static_cast<double>(geodesics.grid().num_nodes())};
  out.insert(out.end(), d.data(), d.data() + d.size());
  return out;
}

// CloudField on a mesh's vertices as the cloud, from vertex 0, evaluated at
// the vertices, in a child (InChild: peak memory, g_child_cpu_s).
std::vector<double> VertexField(const CloudGeodesicsOptions& options,
                                const Eigen::MatrixX3d& vertices, const Eigen::MatrixX3d& normals,
                                double* peak_mb) {
  return InChild(
      [&] { return CloudField(options, vertices, normals, vertices.row(0).transpose(), vertices); },
      peak_mb);
}

// CGAL single source in a child: {seconds, d_0 .. d_{V-1}}.
std::vector<double> ExactField(const TriangleMesh& mesh, const SurfacePoint& source) {
  const double t = Now();
  ExactGeodesics exact(mesh);
  const Eigen::VectorXd d = exact.DistancesToVertices(source);
  std::vector<double> out = {Now() - t};
  out.insert(out.end(), d.data(), d.data() + d.size());
  return out;
}

Eigen::VectorXd Tail(const std::vector<double>& v, size_t skip) {
  return Eigen::Map<const Eigen::VectorXd>(v.data() + skip,
                                           static_cast<Eigen::Index>(v.size() - skip));
}

// Area-weighted vertex normals of a consistently oriented mesh (#V x 3, unit;
// the normals a scanner's software or `bespoke clean` would give the cloud).
Eigen::MatrixX3d VertexNormals(const TriangleMesh& mesh) {
  Eigen::MatrixX3d normals = Eigen::MatrixX3d::Zero(mesh.num_vertices(), 3);
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::RowVector3d a = mesh.vertices.row(mesh.faces(f, 0));
    const Eigen::RowVector3d n =
        (mesh.vertices.row(mesh.faces(f, 1)) - a).cross(mesh.vertices.row(mesh.faces(f, 2)) - a);
    for (int k = 0; k < 3; ++k) normals.row(mesh.faces(f, k)) += n;
  }
  for (Eigen::Index v = 0; v < normals.rows(); ++v)
    if (normals.row(v).norm() > 0) normals.row(v).normalize();
  return normals;
}

void Dump(const std::string& name, const Eigen::MatrixX3d& vertices, const Eigen::VectorXd& cloud,
          const Eigen::VectorXd& exact) {
  if (g_dump.empty()) return;  // per vertex: x y z cloud_mm exact_mm, to find where errors are
  if (FILE* f = std::fopen((g_dump + "/" + name + ".txt").c_str(), "w")) {
    for (Eigen::Index v = 0; v < vertices.rows(); ++v)
      std::fprintf(f, "%.3f %.3f %.3f %.4f %.4f\n", vertices(v, 0), vertices(v, 1), vertices(v, 2),
                   cloud[v], exact[v]);
    std::fclose(f);
  }
}

// One mesh row, one with the mesh's vertex normals given to the cloud, and
// one with the grid's cells alone (no per-point field); returns the exact
// distances (for the growth rows).
Eigen::VectorXd MeshRow(const std::string& name, const TriangleMesh& mesh, bool cgal,
                        const CloudGeodesicsOptions& options,
                        const std::vector<bool>* seen = nullptr) {
  double peak = 0, cgal_peak = 0;
  const auto cloud = VertexField(options, mesh.vertices, Eigen::MatrixX3d(0, 3), &peak);
  const double cpu = g_child_cpu_s;
  double peak_n = 0;
  const Eigen::MatrixX3d normals = VertexNormals(mesh);  // the cloud's input, not timed
  const auto with_normals = VertexField(options, mesh.vertices, normals, &peak_n);
  const double cpu_n = g_child_cpu_s;
  // The thesis's cells alone: each point takes its node's distance.
  CloudGeodesicsOptions cells_only = options;
  cells_only.point_field.enabled = false;
  double peak_c = 0;
  const auto cells = VertexField(cells_only, mesh.vertices, Eigen::MatrixX3d(0, 3), &peak_c);
  const double cpu_c = g_child_cpu_s;
  Eigen::VectorXd exact = Eigen::VectorXd::Constant(mesh.num_vertices(), NAN);
  double cgal_s = 0, cgal_cpu = 0;
  if (cgal) {
    const auto e = InChild(
        [&] {
          SurfacePoint source;
          for (Eigen::Index f = 0; f < mesh.num_faces() && source.face < 0; ++f)
            for (int k = 0; k < 3; ++k)
              if (mesh.faces(f, k) == 0) {
                source.face = static_cast<int>(f);
                source.barycentric = Eigen::Vector3d::Unit(k);
              }
          return ExactField(mesh, source);
        },
        &cgal_peak);
    cgal_cpu = g_child_cpu_s;
    cgal_s = e[0];
    exact = Tail(e, 1);
  }
  PrintRow(name, mesh.num_vertices(), cloud[2], cloud[0], cloud[1], cpu, peak, cgal_s, cgal_cpu,
           cgal_peak, Compare(Tail(cloud, 3), exact));
  PrintSeen(Tail(cloud, 3), exact, seen);
  PrintRow("  + normals", mesh.num_vertices(), with_normals[2], with_normals[0], with_normals[1],
           cpu_n, peak_n, cgal_s, cgal_cpu, cgal_peak, Compare(Tail(with_normals, 3), exact));
  PrintSeen(Tail(with_normals, 3), exact, seen);
  PrintRow("  cells only (Alg 5)", mesh.num_vertices(), cells[2], cells[0], cells[1], cpu_c, peak_c,
           cgal_s, cgal_cpu, cgal_peak, Compare(Tail(cells, 3), exact));
  PrintSeen(Tail(cells, 3), exact, seen);
  const std::string file = name.substr(0, name.find(' '));
  Dump(file, mesh.vertices, Tail(cloud, 3), exact);
  Dump(file + "-normals", mesh.vertices, Tail(with_normals, 3), exact);
  return exact;
}

// Which vertices of the MakeHuman body (y up, facing +z, mm) a body scanner
// sees: the mesh stood in the body frame (z up, feet at 0, facing +y), a
// noise-free 640x480 px scan of it in the default 42-sensor booth, and a
// vertex seen when a scan point lies within 1.75 mm (half the vertex spacing).
std::vector<bool> SeenByScanner(const TriangleMesh& mesh) {
  TriangleMesh standing = mesh;
  const double feet = mesh.vertices.col(1).minCoeff();
  standing.vertices.col(0) = -mesh.vertices.col(0);
  standing.vertices.col(1) = mesh.vertices.col(2);
  standing.vertices.col(2) = mesh.vertices.col(1).array() - feet;
  ScanSimOptions booth;
  booth.floor = false;
  booth.outlier_fraction = 0;
  booth.noise_sigma_mm = 0;
  booth.booth.width_px = 640;
  booth.booth.height_px = 480;
  const ScanSimResult scan = SimulateScan(booth, standing);
  const PointIndex index(scan.cloud.points);
  std::vector<bool> seen(static_cast<size_t>(mesh.num_vertices()));
  for (Eigen::Index v = 0; v < mesh.num_vertices(); ++v) {
    double d2 = 0;
    index.Nearest(standing.vertices.row(v).transpose(), &d2);
    seen[static_cast<size_t>(v)] = d2 <= 1.75 * 1.75;
  }
  return seen;
}

TriangleMesh LoadMesh(const std::filesystem::path& file, LengthUnit unit) {
  ReadOptions read;
  read.units = unit;
  read.min_finite_points = 0;
  Mesh mesh = ReadMesh(read, file);
  mesh.mesh.vertices *= MillimetresPer(unit);
  return mesh.mesh;
}

// The faces of `mesh` with every vertex within `radius_mm` of `centre`, the
// vertex nearest `source` renumbered 0 (MeshRow's source).
TriangleMesh Patch(const TriangleMesh& mesh, const Eigen::Vector3d& centre, double radius_mm,
                   const Eigen::Vector3d& source) {
  Eigen::Index first = 0;
  for (Eigen::Index v = 1; v < mesh.num_vertices(); ++v)
    if ((mesh.vertices.row(v).transpose() - source).norm() <
        (mesh.vertices.row(first).transpose() - source).norm())
      first = v;
  std::vector<int> renumber(static_cast<size_t>(mesh.num_vertices()), -1);
  std::vector<Eigen::Index> kept = {first};
  renumber[static_cast<size_t>(first)] = 0;
  std::vector<Eigen::Vector3i> faces;
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    bool inside = true;
    for (int k = 0; k < 3; ++k)
      inside =
          inside && (mesh.vertices.row(mesh.faces(f, k)).transpose() - centre).norm() < radius_mm;
    if (!inside) continue;
    Eigen::Vector3i face;
    for (int k = 0; k < 3; ++k) {
      int& to = renumber[static_cast<size_t>(mesh.faces(f, k))];
      if (to < 0) to = static_cast<int>(kept.size()), kept.push_back(mesh.faces(f, k));
      face[k] = to;
    }
    faces.push_back(face);
  }
  TriangleMesh patch;
  patch.vertices = mesh.vertices(kept, Eigen::all);
  patch.faces.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (size_t f = 0; f < faces.size(); ++f)
    patch.faces.row(static_cast<Eigen::Index>(f)) = faces[f];
  return patch;
}

// Normals as a scanner's software estimates them: a plane through each point's
// 16 nearest neighbours, turned to face the sensor that saw the point (the
// side of the simulator's `sensor_facing` normal). #P x 3, unit.
Eigen::MatrixX3d SensorFacingNormals(const Eigen::MatrixX3d& cloud,
                                     const Eigen::MatrixX3d& sensor_facing) {
  const PointIndex index(cloud);
  Eigen::MatrixX3d normals(cloud.rows(), 3);
  std::vector<int> near;
  std::vector<double> d2;
  for (Eigen::Index i = 0; i < cloud.rows(); ++i) {
    index.Knn(cloud.row(i).transpose(), 16, &near, &d2);
    Eigen::MatrixX3d around(static_cast<Eigen::Index>(near.size()), 3);
    for (size_t k = 0; k < near.size(); ++k)
      around.row(static_cast<Eigen::Index>(k)) = cloud.row(near[k]);
    Eigen::Vector3d n = PcaPlane(around).normal();
    if (n.dot(sensor_facing.row(i).transpose()) < 0) n = -n;
    normals.row(i) = n.transpose();
  }
  return normals;
}

void GeneratedScanRows(bool cgal, bool quick, bool field_only) {
  ParametricBodyOptions shape;  // the average woman, girth rings coarser than default
  shape.girth_ring_segments = 64;
  shape.max_girth_deficit_mm = 1.0;
  const Body body = GenerateParametricBody(shape);
  ScanSimOptions booth;
  booth.floor = false;
  booth.outlier_fraction = 0;
  booth.noise_sigma_mm = 0.5;
  if (quick) booth.booth.width_px = 160, booth.booth.height_px = 120;
  const ScanSimResult scan = SimulateScan(booth, body.mesh);
  const Eigen::MatrixX3d& cloud = scan.cloud.points;
  const SurfacePoint source = body.landmarks.at("back_neck");
  // Mesh vertices the scan saw.
  std::vector<bool> seen(static_cast<size_t>(body.mesh.num_vertices()));
  {
    const PointIndex index(cloud);
    for (Eigen::Index v = 0; v < body.mesh.num_vertices(); ++v) {
      double d2 = 0;
      index.Nearest(body.mesh.vertices.row(v).transpose(), &d2);
      seen[static_cast<size_t>(v)] = d2 <= 9.0;
    }
  }
  double peak = 0, cgal_peak = 0, peak_n = 0;
  const auto field = InChild(
      [&] {
        return CloudField(g_options, cloud, Eigen::MatrixX3d(0, 3), PositionOf(body.mesh, source),
                          body.mesh.vertices);
      },
      &peak);
  double cpu = g_child_cpu_s;
  const Eigen::MatrixX3d normals = SensorFacingNormals(cloud, scan.cloud.normals);  // not timed
  const auto field_n = InChild(
      [&] {
        return CloudField(g_options, cloud, normals, PositionOf(body.mesh, source),
                          body.mesh.vertices);
      },
      &peak_n);
  const double cpu_n = g_child_cpu_s;
  Eigen::VectorXd exact = Eigen::VectorXd::Constant(body.mesh.num_vertices(), NAN);
  double cgal_s = 0, cgal_cpu = 0;
  if (cgal) {
    const auto e = InChild([&] { return ExactField(body.mesh, source); }, &cgal_peak);
    cgal_cpu = g_child_cpu_s;
    cgal_s = e[0];
    exact = Tail(e, 1);
  }
  std::printf("%-26s body mesh %lld vertices, %lld seen by the scan\n", "",
              static_cast<long long>(body.mesh.num_vertices()),
              static_cast<long long>(std::count(seen.begin(), seen.end(), true)));
  PrintRow("generated scan, field", cloud.rows(), field[2], field[0], field[1], cpu, peak, cgal_s,
           cgal_cpu, cgal_peak, Compare(Tail(field, 3), exact, &seen));
  PrintRow("  + normals", cloud.rows(), field_n[2], field_n[0], field_n[1], cpu_n, peak_n, cgal_s,
           cgal_cpu, cgal_peak, Compare(Tail(field_n, 3), exact, &seen));
  if (!g_dump.empty()) {  // per body-mesh vertex: x y z cloud_mm exact_mm seen cloud_normals_mm
    if (FILE* f = std::fopen((g_dump + "/generated.txt").c_str(), "w")) {
      const Eigen::VectorXd c = Tail(field, 3), cn = Tail(field_n, 3);
      for (Eigen::Index v = 0; v < body.mesh.num_vertices(); ++v)
        std::fprintf(f, "%.3f %.3f %.3f %.4f %.4f %d %.4f\n", body.mesh.vertices(v, 0),
                     body.mesh.vertices(v, 1), body.mesh.vertices(v, 2), c[v], exact[v],
                     static_cast<int>(seen[static_cast<size_t>(v)]), cn[v]);
      std::fclose(f);
    }
  }
  if (field_only) return;

  // Ten datum-point segments, point to point.
  std::vector<std::pair<std::string, std::string>> pairs;
  std::set<std::pair<std::string, std::string>> unique;
  for (const MeasurementDef& m : Catalogue::Builtin().measurements()) {
    if (m.method != MeasurementMethod::kGeodesic) continue;
    for (size_t i = 0; i + 1 < m.datum.size() && pairs.size() < 10; ++i) {
      const std::string& a = m.datum[i];
      const std::string& b = m.datum[i + 1];
      if (a == "crotch" || b == "crotch" || !body.landmarks.count(a) || !body.landmarks.count(b))
        continue;
      if (unique.emplace(a, b).second) pairs.emplace_back(a, b);
    }
  }
  const auto cloud_p2p = InChild(
      [&] {
        std::vector<double> out;
        double t = Now();
        CloudGeodesics geodesics(g_options, cloud);
        out.push_back(Now() - t);
        t = Now();
        for (const auto& [a, b] : pairs)
          out.push_back(geodesics
                            .Between(PositionOf(body.mesh, body.landmarks.at(a)),
                                     PositionOf(body.mesh, body.landmarks.at(b)))
                            .length_mm);
        out.insert(out.begin() + 1, Now() - t);
        out.insert(out.begin() + 2, geodesics.grid().num_nodes());
        return out;
      },
      &peak);
  cpu = g_child_cpu_s;
  std::vector<double> exact_p2p(pairs.size(), NAN);
  cgal_s = 0, cgal_cpu = 0;
  if (cgal) {
    const auto e = InChild(
        [&] {
          const double t = Now();
          ExactGeodesics exact_mesh(body.mesh);
          std::vector<double> out;
          for (const auto& [a, b] : pairs)
            out.push_back(exact_mesh.Distance(body.landmarks.at(a), body.landmarks.at(b)));
          out.insert(out.begin(), Now() - t);
          return out;
        },
        &cgal_peak);
    cgal_cpu = g_child_cpu_s;
    cgal_s = e[0];
    std::copy(e.begin() + 1, e.end(), exact_p2p.begin());
  }
  Eigen::VectorXd c(static_cast<Eigen::Index>(pairs.size())), x(c.size());
  for (size_t i = 0; i < pairs.size(); ++i) c[i] = cloud_p2p[3 + i], x[i] = exact_p2p[i];
  PrintRow("generated scan, 10 pairs", cloud.rows(), cloud_p2p[2], cloud_p2p[0], cloud_p2p[1], cpu,
           peak, cgal_s, cgal_cpu, cgal_peak, Compare(c, x));
  for (size_t i = 0; i < pairs.size(); ++i)
    std::printf("    %-20s -> %-20s cloud %8.2f  exact %8.2f  diff %+6.2f mm\n",
                pairs[i].first.c_str(), pairs[i].second.c_str(), c[i], x[i], c[i] - x[i]);
}

int Main(int argc, char** argv) {
  std::filesystem::path shared = BESPOKE_DEFAULT_SHARED_DIR;
  bool cgal = true, quick = false, body_only = false;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--no-cgal"))
      cgal = false;
    else if (!std::strcmp(argv[i], "--quick"))
      quick = true;
    else if (!std::strcmp(argv[i], "--shared") && i + 1 < argc)
      shared = argv[++i];
    else if (!std::strcmp(argv[i], "--dump") && i + 1 < argc)
      g_dump = argv[++i];
    else if (!std::strcmp(argv[i], "--body-only"))
      body_only = true;
    else if (!std::strcmp(argv[i], "--fit-wedge-deg") && i + 1 < argc)
      g_options.point_field.fit_wedge_deg = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--surface-offset-fraction") && i + 1 < argc)
      g_options.point_field.surface_offset_fraction = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--fit-points") && i + 1 < argc)
      g_options.point_field.fit_points = std::atoi(argv[++i]);
    else {
      std::fprintf(stderr,
                   "usage: geodesic_bench [--shared DIR] [--no-cgal] [--quick] [--body-only] "
                   "[--dump DIR] [--fit-wedge-deg D] [--surface-offset-fraction F] "
                   "[--fit-points N]\n");
      return 1;
    }
  }
  g_options.point_field.Check();  // InputError (exit 2 below) on a value out of range
  std::printf("point field: fit_points %d, fit_wedge_deg %g, surface_offset_fraction %g\n",
              g_options.point_field.fit_points, g_options.point_field.fit_wedge_deg,
              g_options.point_field.surface_offset_fraction);
  PrintLoadAverage("at start");
  PrintHeader();
  const std::filesystem::path meshes = shared / "data" / "meshes";
  const bool have_meshes = std::filesystem::exists(meshes / "makehuman-body-remesh-116k.off");
  if (!have_meshes) std::printf("(no %s: mesh rows skipped)\n", meshes.string().c_str());
  Eigen::VectorXd body_exact;
  TriangleMesh body;
  if (have_meshes) {
    body = LoadMesh(meshes / "makehuman-body-remesh-116k.off", LengthUnit::kDecimetre);
    if (!quick && !body_only) {
      MeshRow("bunny 35k (vertices)", LoadMesh(meshes / "bunny-35k.off", LengthUnit::kMetre), cgal,
              g_options);
      MeshRow("bunny 109k (vertices)",
              LoadMesh(meshes / "bunny-remesh-109k.off", LengthUnit::kMetre), cgal, g_options);
    }
    // In a child, so the scan's memory does not count in the rows' peaks.
    double scan_peak = 0;
    const std::vector<double> seen_flags = InChild(
        [&] {
          const std::vector<bool> flags = SeenByScanner(body);
          return std::vector<double>(flags.begin(), flags.end());
        },
        &scan_peak);
    std::vector<bool> seen(seen_flags.size());
    for (size_t v = 0; v < seen.size(); ++v) seen[v] = seen_flags[v] > 0.5;
    std::printf("%-26s body mesh %lld vertices, %lld seen by a 640x480 px scan\n", "",
                static_cast<long long>(body.num_vertices()),
                static_cast<long long>(std::count(seen.begin(), seen.end(), true)));
    body_exact = MeshRow("body 116k (vertices)", body, cgal && !quick, g_options, &seen);
    // The same body near a source close to the mouth: the lips' faces meet
    // closer than the vertex spacing, and relative errors near the source are
    // large where the cloud crosses them (the body row's source is 860 mm away).
    std::printf("%-26s the body's faces within 100 mm of the mouth, from the chin:\n", "");
    MeshRow("mouth patch (vertices)",
            Patch(body, Eigen::Vector3d(0, 645, 140), 100, Eigen::Vector3d(0, 616, 129)),
            cgal && !quick, g_options);
  }
  GeneratedScanRows(cgal, quick, body_only);
  if (have_meshes && !body_only) {
    std::printf("\ngrowth: the 116k body cloud at four cell sizes (errors vs CGAL above)\n");
    PrintHeader();
    for (const double spacings : {6.0, 4.0, 3.0, 2.0}) {
      CloudGeodesicsOptions options = g_options;
      options.grid.auto_cell_spacings = spacings;
      double peak = 0;
      const auto r = VertexField(options, body.vertices, Eigen::MatrixX3d(0, 3), &peak);
      PrintRow("cell " + std::to_string(static_cast<int>(spacings)) + " spacings",
               body.num_vertices(), r[2], r[0], r[1], g_child_cpu_s, peak, 0, 0, 0,
               Compare(Tail(r, 3), body_exact));
      std::printf("%-26s %.1f us CPU per node (grid, propagation and evaluation)\n", "",
                  1e6 * g_child_cpu_s / r[2]);
    }
  }
  return 0;
}

}  // namespace
}  // namespace bespoke

int main(int argc, char** argv) {
  return bespoke::RunBenchMain("geodesic_bench", bespoke::Main, argc, argv);
}
