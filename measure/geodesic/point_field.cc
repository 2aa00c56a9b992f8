#include "measure/geodesic/point_field.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <queue>
#include <system_error>
#include <thread>
#include <utility>

#include "measure/geodesic/local_surface.h"
#include "scanners/core/errors.h"

namespace bespoke {

void PointFieldOptions::Check() const {
  if (neighbours < 2 || neighbours > 64)
    throw InputError("geodesics: point field neighbours must be in [2, 64]");
  if (!(max_chord_angle_deg > 0 && max_chord_angle_deg <= 90))
    throw InputError("geodesics: point field max_chord_angle_deg must be in (0, 90]");
  if (fit_points != 0 && (fit_points < 10 || fit_points > 256))
    throw InputError("geodesics: point field fit_points must be 0 or in [10, 256]");
  if (!(seed_radius_cells >= 0) || !std::isfinite(seed_radius_cells))
    throw InputError("geodesics: point field seed_radius_cells must be >= 0");
  if (!(agree_fraction >= 0 && agree_fraction < 1))
    throw InputError("geodesics: point field agree_fraction must be in [0, 1)");
}

namespace {

// min over s on [a, b] of  da + (db - da) |s - a| / |b - a| + |q - s|.
double SegmentOffer(const Eigen::Vector3d& a, double da, const Eigen::Vector3d& b, double db,
                    const Eigen::Vector3d& q) {
  const double at_ends = std::min(da + (q - a).norm(), db + (q - b).norm());
  const Eigen::Vector3d ab = b - a;
  const double length = ab.norm();
  if (length <= 0) return at_ends;
  const double slope = (db - da) / length;
  if (std::abs(slope) >= 1) return at_ends;
  const Eigen::Vector3d u = ab / length, w = q - a;
  const double along = w.dot(u), across = (w - along * u).norm();
  const double root = std::sqrt(1 - slope * slope);
  const double x = along - slope * across / root;  // where the derivative vanishes
  if (x <= 0 || x >= length) return at_ends;
  return da + slope * along + across * root;
}

// Each scan point as the distance sweep sees it: its k nearest points (itself
// first), and its foot and unit normal on a surface fitted to its own
// nearest points (the given oriented normal when there is one). The fit uses
// the `fit_points` nearest that lie in the point's node or a node linked to
// it (not another sheet), as a quadric through their PCA plane; with fewer
// than 10 of them, the node's surface. Node surfaces span a cell: on coarse
// cells they blur what lies within one (a toe, the mouth's inside behind the
// lips), and a point projected onto them lands on the wrong sheet.
struct Surfels {
  std::vector<Eigen::Vector3d> position, normal;
  std::vector<int> near;  // #P x k row-major, nearest first
  int k = 0;
  const int* near_begin(Eigen::Index i) const { return near.data() + i * k; }
};

TangentPlane PointPlane(const CloudGrid& grid, int node, const Eigen::Vector3d& x,
                        const std::vector<int>& near, int fit_points) {
  const TangentPlane cell = grid.surface(node).PlaneAt(x);
  Eigen::MatrixX3d pts(std::min<Eigen::Index>(fit_points, near.size()), 3);
  Eigen::Index m = 0;
  for (size_t j = 0; j < near.size() && m < pts.rows(); ++j)
    if (grid.WithinHops(node, grid.node_of_point(near[j]), 1))
      pts.row(m++) = grid.index().point(near[j]);
  if (m < 10) return cell;
  const Eigen::MatrixX3d kept = pts.topRows(m);
  LocalSurface seed = PcaPlane(kept);
  if (seed.normal().dot(cell.normal) < 0) seed.frame.col(1) *= -1, seed.frame.col(2) *= -1;
  return FitLocalSurface(SurfaceFit::kQuadric, kept, seed, 0.5 * grid.sheet_gap_mm()).PlaneAt(x);
}

// Point i's neighbour list, foot and normal; `near`, `d2`: scratch.
void FillSurfel(const PointFieldOptions& options, const CloudGrid& grid, Eigen::Index i,
                std::vector<int>* near, std::vector<double>* d2, Surfels* s) {
  const Eigen::Vector3d x = grid.index().point(i);
  grid.index().Knn(x, std::max(s->k, options.fit_points), near, d2);
  std::copy_n(near->begin(), std::min<size_t>(s->k, near->size()), s->near.begin() + i * s->k);
  const int node = grid.node_of_point(i);
  const TangentPlane plane = options.fit_points > 0
                                 ? PointPlane(grid, node, x, *near, options.fit_points)
                                 : grid.surface(node).PlaneAt(x);
  s->position[static_cast<size_t>(i)] = options.project_to_surface ? plane.point : x;
  const bool given =
      grid.point_normals().rows() > 0 && grid.point_normals().row(i).squaredNorm() > 0;
  s->normal[static_cast<size_t>(i)] =
      given ? Eigen::Vector3d(grid.point_normals().row(i)) : plane.normal.normalized();
}

// All points, in blocks over a few threads (std::thread, not OpenMP: a
// process that forks after using OpenMP, like geodesic_bench's timed
// children, deadlocks in the child's first parallel region).
Surfels MakeSurfels(const PointFieldOptions& options, const CloudGrid& grid) {
  const Eigen::Index n = grid.index().size();
  Surfels s;
  s.k = static_cast<int>(std::min<Eigen::Index>(options.neighbours + 1, n));
  s.position.resize(static_cast<size_t>(n));
  s.normal.resize(static_cast<size_t>(n));
  s.near.assign(static_cast<size_t>(n * s.k), -1);
  constexpr Eigen::Index kBlock = 1024;
  std::atomic<Eigen::Index> next{0};
  std::mutex failed_mutex;
  std::exception_ptr failed;
  const auto work = [&] {
    std::vector<int> near;
    std::vector<double> d2;
    try {
      for (Eigen::Index b; (b = next.fetch_add(kBlock)) < n;)
        for (Eigen::Index i = b; i < std::min(n, b + kBlock); ++i)
          FillSurfel(options, grid, i, &near, &d2, &s);
    } catch (...) {
      const std::lock_guard<std::mutex> lock(failed_mutex);
      if (!failed) failed = std::current_exception();
      next = n;  // the others stop at their next block
    }
  };
  std::vector<std::thread> pool;
  const unsigned threads = std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
  try {
    for (unsigned t = 1; t < threads && n > 4 * kBlock; ++t) pool.emplace_back(work);
  } catch (const std::system_error&) {  // no more threads: the ones started do it
  }
  work();
  for (std::thread& t : pool) t.join();
  if (failed) std::rethrow_exception(failed);
  return s;
}

bool ChordAlongSurface(const Eigen::Vector3d& e, const Eigen::Vector3d& np,
                       const Eigen::Vector3d& nq, double sin_max) {
  const double limit = sin_max * e.norm();
  return std::abs(np.dot(e)) <= limit && std::abs(nq.dot(e)) <= limit;
}

// The chord test, then: with oriented normals, the two points' normals
// within a right angle (points facing each other across a gap or back to
// back across thin tissue are not joined); without, the grid's test that the
// points' nodes lie on one surface (sheets apart by the sheet gap are not).
bool Join(const CloudGrid& grid, const Surfels& s, double sin_max, int p, int q) {
  const Eigen::Vector3d& np = s.normal[static_cast<size_t>(p)];
  const Eigen::Vector3d& nq = s.normal[static_cast<size_t>(q)];
  if (!ChordAlongSurface(s.position[static_cast<size_t>(q)] - s.position[static_cast<size_t>(p)],
                         np, nq, sin_max))
    return false;
  if (grid.oriented() && grid.point_normals().row(p).squaredNorm() > 0 &&
      grid.point_normals().row(q).squaredNorm() > 0)
    return np.dot(nq) >= 0;
  return grid.StepOnSurface(grid.node_of_point(p), grid.index().point(p), grid.node_of_point(q),
                            grid.index().point(q));
}

}  // namespace

Eigen::VectorXd PointDistanceField(const PointFieldOptions& options, const CloudGrid& grid,
                                   const std::vector<PointSeed>& seeds) {
  options.Check();
  const PointIndex& index = grid.index();
  const Eigen::Index n = index.size();
  Eigen::VectorXd d = Eigen::VectorXd::Constant(n, std::numeric_limits<double>::infinity());
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (const PointSeed& seed : seeds) {
    if (seed.point < 0 || seed.point >= n || !(seed.distance_mm >= 0) ||
        !std::isfinite(seed.distance_mm))
      throw InputError("geodesics: a point-field seed is not a scan point with a distance >= 0");
    if (seed.distance_mm < d[seed.point]) {
      d[seed.point] = seed.distance_mm;
      queue.emplace(seed.distance_mm, seed.point);
    }
  }
  const Surfels surfels = MakeSurfels(options, grid);
  const double sin_max = std::sin(options.max_chord_angle_deg * M_PI / 180);
  std::vector<char> done(static_cast<size_t>(n), 0);
  std::vector<int> settled;
  while (!queue.empty()) {
    const auto [dp, p] = queue.top();
    queue.pop();
    if (done[static_cast<size_t>(p)] || dp > d[p]) continue;  // stale entry
    done[static_cast<size_t>(p)] = 1;
    const Eigen::Vector3d& xp = surfels.position[static_cast<size_t>(p)];
    const int* near = surfels.near_begin(p);
    settled.clear();
    for (int j = 0; j < surfels.k; ++j) {
      const int r = near[j];
      if (r >= 0 && r != p && done[static_cast<size_t>(r)] && Join(grid, surfels, sin_max, p, r))
        settled.push_back(r);
    }
    for (int j = 0; j < surfels.k; ++j) {
      const int q = near[j];
      if (q < 0 || done[static_cast<size_t>(q)] || !Join(grid, surfels, sin_max, p, q)) continue;
      const Eigen::Vector3d& xq = surfels.position[static_cast<size_t>(q)];
      double offer = dp + (xq - xp).norm();
      for (const int r : settled)
        if (Join(grid, surfels, sin_max, r, q))
          offer = std::min(
              offer, SegmentOffer(xp, dp, surfels.position[static_cast<size_t>(r)], d[r], xq));
      if (offer < d[q]) {
        d[q] = offer;
        queue.emplace(offer, q);
      }
    }
  }
  return d;
}

}  // namespace bespoke
