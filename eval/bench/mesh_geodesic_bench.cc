// mesh_geodesic_bench: single source (vertex 0) to all vertices on the meshes
// of ../shared/data/meshes and on Loop-subdivided bodies made at run time:
// thesis Algorithm 3, Algorithm 2 (up to --accurate-max vertices) and CGAL's
// exact Surface_mesh_shortest_path (up to --cgal-max vertices: its memory
// grows about 48 kB per vertex, 5.6 GB at 116k). Every run is a forked child,
// so time and peak memory (ru_maxrss, mesh included) are its own.
// Prints a table (vertices, time, time per vertex, peak memory, CGAL time /
// time, mean and max relative error of the offset and projected distances
// against CGAL) and writes a PNG of time per vertex against vertices.
//   mesh_geodesic_bench [--shared DIR] [--plot FILE.png] [--quick]
//                       [--accurate-max N] [--cgal-max N] [--no-refine]
// Relative errors count vertices whose exact distance is at least 5 mean edge
// lengths (near the source a relative error says little); mean over those,
// max over those.
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "eval/bench/bench_main.h"
#include "eval/bench/child_run.h"
#include "measure/mesh_geodesic/mesh_geodesics.h"
#include "oracle/truth/exact_geodesics.h"
#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"
#include "scanners/render/plot.h"

namespace bespoke {
namespace {

double Now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// CPU seconds (user + system) of the last child: other jobs on the machine
// inflate wall times much more than CPU times.
double g_child_cpu_s = 0;

// Runs `work` in a forked child; returns what it returned (doubles through a
// pipe) and its peak resident memory in MB. Empty on failure.
std::vector<double> InChild(const std::function<std::vector<double>()>& work, double* peak_mb) {
  ChildUsage usage;
  std::vector<double> out = RunInChild(work, &usage);
  *peak_mb = usage.peak_mb;
  g_child_cpu_s = usage.cpu_s;
  return out;
}

TriangleMesh LoopSubdivide(const TriangleMesh& in, int times) {
  using Mesh = CGAL::Surface_mesh<CGAL::Simple_cartesian<double>::Point_3>;
  Mesh m;
  for (Eigen::Index v = 0; v < in.num_vertices(); ++v)
    m.add_vertex({in.vertices(v, 0), in.vertices(v, 1), in.vertices(v, 2)});
  for (Eigen::Index f = 0; f < in.num_faces(); ++f)
    m.add_face(Mesh::Vertex_index(in.faces(f, 0)), Mesh::Vertex_index(in.faces(f, 1)),
               Mesh::Vertex_index(in.faces(f, 2)));
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(times));
  TriangleMesh out;
  out.vertices.resize(static_cast<Eigen::Index>(m.number_of_vertices()), 3);
  out.faces.resize(static_cast<Eigen::Index>(m.number_of_faces()), 3);
  for (const auto v : m.vertices())
    out.vertices.row(v.idx()) << m.point(v).x(), m.point(v).y(), m.point(v).z();
  Eigen::Index row = 0;
  for (const auto f : m.faces()) {
    int k = 0;
    for (const auto v : CGAL::vertices_around_face(m.halfedge(f), m))
      out.faces(row, k++) = static_cast<int>(v.idx());
    ++row;
  }
  return out;
}

struct Errors {
  double mean = NAN, max = NAN;
};

Errors Compare(const double* d, const std::vector<double>& exact, double floor) {
  Errors e;
  double sum = 0, worst = 0;
  std::int64_t count = 0;
  for (size_t i = 0; i < exact.size(); ++i) {
    if (!std::isfinite(exact[i]) || exact[i] < floor || !std::isfinite(d[i])) continue;
    const double r = std::abs(d[i] - exact[i]) / exact[i];
    sum += r;
    worst = std::max(worst, r);
    ++count;
  }
  if (count > 0) e = {sum / static_cast<double>(count), worst};
  return e;
}

struct Row {
  std::string mesh, algorithm;
  std::int64_t vertices = 0;
  double time_s = NAN, cpu_s = NAN, peak_mb = NAN, ratio = NAN;
  Errors offset, projected;
  double bound_ratio = NAN;  // mean Eq 3.24 bound / mean actual offset error
};

void Print(const Row& r) {
  auto pct = [](double x) { return std::isfinite(x) ? 100 * x : NAN; };
  std::printf("%-26s %-5s %9lld %8.2f %8.2f %8.2f %8.0f %7.1f  %6.3f %6.2f  %6.3f %6.2f  %6.2f\n",
              r.mesh.c_str(), r.algorithm.c_str(), static_cast<long long>(r.vertices), r.time_s,
              r.cpu_s, 1e6 * r.cpu_s / static_cast<double>(r.vertices), r.peak_mb, r.ratio,
              pct(r.offset.mean), pct(r.offset.max), pct(r.projected.mean), pct(r.projected.max),
              r.bound_ratio);
  std::fflush(stdout);
}

struct Config {
  std::filesystem::path shared;
  std::filesystem::path plot = "mesh_geodesic_bench.png";
  std::int64_t accurate_max = 60000;
  std::int64_t cgal_max = 200000;
  bool quick = false, refine = true;
};

void BenchMesh(const Config& config, const std::string& name, const TriangleMesh& mesh,
               std::vector<Row>* rows) {
  const std::int64_t n = mesh.num_vertices();
  std::vector<double> exact;
  double cgal_time = NAN;
  if (n <= config.cgal_max) {
    Row r;
    r.mesh = name;
    r.algorithm = "CGAL";
    r.vertices = n;
    const auto out = InChild(
        [&] {
          const double t0 = Now();
          ExactGeodesics geodesics(mesh);
          const Eigen::VectorXd d = geodesics.DistancesToVertices(geodesics.AtVertex(0));
          std::vector<double> v(d.data(), d.data() + d.size());
          v.push_back(Now() - t0);
          return v;
        },
        &r.peak_mb);
    if (!out.empty()) {
      exact.assign(out.begin(), out.end() - 1);
      r.time_s = out.back();
      r.cpu_s = cgal_time = g_child_cpu_s;
      r.ratio = 1;
    }
    Print(r);
    rows->push_back(r);
  }
  for (const bool accurate : {false, true}) {
    if (accurate && n > config.accurate_max) continue;
    Row r;
    r.mesh = name;
    r.algorithm = accurate ? "Alg2" : "Alg3";
    r.vertices = n;
    double floor = 0;
    const auto out = InChild(
        [&] {
          const double t0 = Now();
          MeshSurface surface(MeshPrepOptions{}, mesh, name);
          MeshGeodesicsOptions options;
          options.wavefront.whole_path = accurate;
          MeshGeodesics geodesics(options, surface, 0);
          geodesics.Run();
          std::vector<double> v;
          v.reserve(3 * static_cast<size_t>(n) + 2);
          for (int i = 0; i < n; ++i) v.push_back(geodesics.offset_distance(i));
          for (int i = 0; i < n; ++i) v.push_back(geodesics.projected_distance(i));
          for (int i = 0; i < n; ++i) v.push_back(geodesics.error_bound(i));
          v.push_back(surface.mean_edge_length());
          v.push_back(Now() - t0);
          const auto& s = geodesics.stats();
          std::fprintf(
              stderr,
              "  %s %s: flows %lld, iterations/flow %.2f, unconverged %lld, held %lld, "
              "projection fallbacks %lld, rounds %lld, peak window samples %lld\n",
              name.c_str(), accurate ? "Alg2" : "Alg3", static_cast<long long>(s.flows),
              s.flows ? static_cast<double>(s.flow_iterations) / static_cast<double>(s.flows) : 0.0,
              static_cast<long long>(s.unconverged), static_cast<long long>(s.undone),
              static_cast<long long>(s.projection_fallbacks), static_cast<long long>(s.rounds),
              static_cast<long long>(s.peak_window_samples));
          return v;
        },
        &r.peak_mb);
    if (!out.empty()) {
      r.time_s = out.back();
      r.cpu_s = g_child_cpu_s;
      floor = 5 * out[out.size() - 2];
      r.ratio = cgal_time / r.cpu_s;
      if (!exact.empty()) {
        r.offset = Compare(out.data(), exact, floor);
        r.projected = Compare(out.data() + n, exact, floor);
        double bound = 0, actual = 0;
        for (std::int64_t i = 0; i < n; ++i)
          if (std::isfinite(exact[size_t(i)]) && exact[size_t(i)] >= floor &&
              std::isfinite(out[size_t(i)])) {
            bound += out[size_t(2 * n + i)];
            actual += std::abs(out[size_t(i)] - exact[size_t(i)]);
          }
        if (!accurate && actual > 0) r.bound_ratio = bound / actual;
      }
    }
    Print(r);
    rows->push_back(r);
  }
}

void WritePlot(const Config& config, const std::vector<Row>& rows) {
  Chart chart;
  chart.title = "Single-source mesh geodesics: time per vertex";
  chart.x_label = "vertices";
  chart.y_label = "CPU time per vertex (us)";
  chart.log_x = chart.log_y = true;
  for (const char* algorithm : {"Alg3", "Alg2", "CGAL"}) {
    Series s;
    s.label = std::string(algorithm) == "Alg3"   ? "Algorithm 3 (w = 30)"
              : std::string(algorithm) == "Alg2" ? "Algorithm 2"
                                                 : "CGAL exact";
    s.style = Series::Style::kPoints;
    for (const Row& r : rows)
      if (r.algorithm == algorithm && std::isfinite(r.time_s)) {
        s.x.push_back(static_cast<double>(r.vertices));
        s.y.push_back(1e6 * r.cpu_s / static_cast<double>(r.vertices));
      }
    if (!s.x.empty()) chart.series.push_back(s);
  }
  WriteChart(chart, config.plot);
  std::printf("plot: %s\n", config.plot.string().c_str());
}

int Main(int argc, char** argv) {
  Config config;
  config.shared = BESPOKE_DEFAULT_SHARED_DIR;
  if (const char* env = std::getenv("BESPOKE_SHARED_DIR")) config.shared = env;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw InputError(a + " needs a value");
      return argv[++i];
    };
    if (a == "--shared")
      config.shared = value();
    else if (a == "--plot")
      config.plot = value();
    else if (a == "--accurate-max")
      config.accurate_max = std::stoll(value());
    else if (a == "--cgal-max")
      config.cgal_max = std::stoll(value());
    else if (a == "--quick")
      config.quick = true;
    else if (a == "--no-refine")
      config.refine = false;
    else
      throw InputError("unknown option " + a);
  }
  const auto dir = config.shared / "data" / "meshes";
  std::vector<std::string> files = {"makehuman-body-tri-13k.off", "bunny-35k.off",
                                    "makehuman-body-loop1-54k.off", "bunny-remesh-109k.off",
                                    "makehuman-body-remesh-116k.off"};
  if (config.quick) files.resize(2);
  std::printf("%-26s %-5s %9s %8s %8s %8s %8s %7s  %6s %6s  %6s %6s  %6s\n", "mesh", "alg",
              "vertices", "wall_s", "cpu_s", "us/vert", "peak_MB", "CGAL/x", "off%", "offmx%",
              "proj%", "projmx%", "bound");
  std::vector<Row> rows;
  for (const auto& file : files) {
    const Mesh m = ReadMesh(ReadOptions{}, dir / file);
    BenchMesh(config, file, m.mesh, &rows);
  }
  if (config.refine && !config.quick) {
    const Mesh body116 = ReadMesh(ReadOptions{}, dir / "makehuman-body-remesh-116k.off");
    const Mesh body54 = ReadMesh(ReadOptions{}, dir / "makehuman-body-loop1-54k.off");
    BenchMesh(config, "body-116k-loop1 (0.5M)", LoopSubdivide(body116.mesh, 1), &rows);
    BenchMesh(config, "body-54k-loop2 (0.9M)", LoopSubdivide(body54.mesh, 2), &rows);
    BenchMesh(config, "body-54k-loop3 (3.4M)", LoopSubdivide(body54.mesh, 3), &rows);
  }
  WritePlot(config, rows);
  return 0;
}

}  // namespace
}  // namespace bespoke

int main(int argc, char** argv) {
  return bespoke::RunBenchMain("mesh_geodesic_bench", bespoke::Main, argc, argv);
}
