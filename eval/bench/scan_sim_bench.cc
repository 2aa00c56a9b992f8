// Speed of the oracle's generators (Google Benchmark), as ratios within one
// run: the parametric body, a default booth scan, and the ray caster (CGAL
// AABB tree over OpenMP threads) against a brute-force reference
// (Moller-Trumbore over every face, one thread) on the same rays.
//
//   build/eval/bench/scan_sim_bench [--benchmark_filter=Rays]
//
// Items per second are rays (Rays*) or scan points (SimulateScan).
#include <benchmark/benchmark.h>
#include <omp.h>

#include <limits>

#include "oracle/body/parametric_body.h"
#include "oracle/scan_sim/booth.h"
#include "oracle/scan_sim/raycaster.h"
#include "oracle/scan_sim/scan_sim.h"

namespace bespoke {
namespace {

const Body& DefaultBody() {
  static const Body body = GenerateParametricBody(ParametricBodyOptions());
  return body;
}

// `n` rays of the default booth's front-middle sensor, spread over its image.
void SensorRays(int n, Eigen::MatrixX3d* origins, Eigen::MatrixX3d* directions) {
  const std::vector<DepthSensor> sensors = MakeBooth(BoothOptions());
  const DepthSensor& s = sensors[3];  // front column, fourth height (about 1.1 m)
  origins->resize(n, 3);
  directions->resize(n, 3);
  for (int i = 0; i < n; ++i) {
    const std::int64_t k = i;
    const int u = static_cast<int>((k * 7919) % s.width_px),
              v = static_cast<int>((k * 104729 / s.width_px) % s.height_px);
    origins->row(i) = s.position();
    directions->row(i) = s.Ray(u, v);
  }
}

double BruteForceFirstHit(const TriangleMesh& m, const Eigen::Vector3d& o,
                          const Eigen::Vector3d& d) {
  double best = std::numeric_limits<double>::infinity();
  for (Eigen::Index f = 0; f < m.num_faces(); ++f) {
    const Eigen::Vector3d a = m.vertices.row(m.faces(f, 0)), b = m.vertices.row(m.faces(f, 1)),
                          c = m.vertices.row(m.faces(f, 2));
    const Eigen::Vector3d e1 = b - a, e2 = c - a, p = d.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-12) continue;
    const Eigen::Vector3d t = o - a;
    const double u = t.dot(p) / det;
    if (u < 0 || u > 1) continue;
    const Eigen::Vector3d q = t.cross(e1);
    const double v = d.dot(q) / det;
    if (v < 0 || u + v > 1) continue;
    const double dist = e2.dot(q) / det;
    if (dist > 0 && dist < best) best = dist;
  }
  return best;
}

void BM_ParametricBody(benchmark::State& state) {
  for (auto _ : state)
    benchmark::DoNotOptimize(GenerateParametricBody(ParametricBodyOptions()).mesh.num_faces());
  state.counters["vertices"] = static_cast<double>(DefaultBody().mesh.num_vertices());
}
BENCHMARK(BM_ParametricBody)->Unit(benchmark::kMillisecond);

void BM_SimulateScan(benchmark::State& state) {
  const Body& body = DefaultBody();
  std::int64_t points = 0;
  for (auto _ : state) points += SimulateScan(ScanSimOptions(), body.mesh).cloud.size();
  state.SetItemsProcessed(points);
  state.counters["threads"] = omp_get_max_threads();
}
BENCHMARK(BM_SimulateScan)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RaysAabb(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  Eigen::MatrixX3d o, d;
  SensorRays(100000, &o, &d);
  MeshRaycaster caster;
  caster.AddMesh(DefaultBody().mesh);
  caster.Cast(o.topRows(1), d.topRows(1));  // builds the tree outside the timing
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  for (auto _ : state) benchmark::DoNotOptimize(caster.Cast(o, d).distance.sum());
  omp_set_num_threads(before);
  state.SetItemsProcessed(state.iterations() * o.rows());
}
BENCHMARK(BM_RaysAabb)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_RaysBruteForce(benchmark::State& state) {
  Eigen::MatrixX3d o, d;
  SensorRays(200, &o, &d);
  const TriangleMesh& m = DefaultBody().mesh;
  for (auto _ : state) {
    double sum = 0;
    for (Eigen::Index i = 0; i < o.rows(); ++i) {
      const double t = BruteForceFirstHit(m, o.row(i).transpose(), d.row(i).transpose());
      if (std::isfinite(t)) sum += t;
    }
    benchmark::DoNotOptimize(sum);
  }
  state.SetItemsProcessed(state.iterations() * o.rows());
}
BENCHMARK(BM_RaysBruteForce)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace bespoke

BENCHMARK_MAIN();
