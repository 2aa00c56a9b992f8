#include "measure/cloud_geodesic/point_field.h"

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

#include "measure/cloud_geodesic/local_surface.h"
#include "scanners/core/errors.h"

namespace bespoke {

void PointFieldOptions::Check() const {
  if (neighbours < 2 || neighbours > 64)
    throw InputError("geodesics: point field neighbours must be in [2, 64]");
  if (!(max_chord_angle_deg > 0 && max_chord_angle_deg <= 90))
    throw InputError("geodesics: point field max_chord_angle_deg must be in (0, 90]");
  if (fit_points != 0 && (fit_points < 10 || fit_points > 256))
    throw InputError("geodesics: point field fit_points must be 0 or in [10, 256]");
  if (!(fit_wedge_deg >= 5 && fit_wedge_deg <= 60))
    throw InputError("geodesics: point field fit_wedge_deg must be in [5, 60]");
  if (!(surface_offset_fraction >= 0 && surface_offset_fraction <= 1))
    throw InputError("geodesics: point field surface_offset_fraction must be in [0, 1]");
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
// nearest points (the given oriented normal when there is one), with that
// surface and its RMS residual for the join test. The fit (FitOwnSheet) uses
// the `fit_points` nearest, whatever node they lie in, and keeps to the
// point's own sheet by geometry: a cell can straddle two sheets closer than
// itself (the lips), so "in a node linked to the point's" picked the other
// face. With fewer than 10 points, or fit_points = 0, the node's surface.
struct Surfels {
  std::vector<Eigen::Vector3d> position, normal;
  std::vector<LocalSurface> surface;  // empty when fit_points = 0
  std::vector<double> rms_mm;         // of each fit; empty when fit_points = 0
  std::vector<int> near;              // #P x k row-major, nearest first
  int k = 0;
  const int* near_begin(Eigen::Index i) const { return near.data() + i * k; }
};

// Point i's neighbour list, fit, foot and normal; `near`, `d2`: scratch.
void FillSurfel(const PointFieldOptions& options, const CloudGrid& grid, Eigen::Index i,
                std::vector<int>* near, std::vector<double>* d2, Surfels* s) {
  const size_t at = static_cast<size_t>(i);
  const Eigen::Vector3d x = grid.index().point(i);
  grid.index().Knn(x, std::max(s->k, options.fit_points), near, d2);
  std::copy_n(near->begin(), std::min<size_t>(s->k, near->size()), s->near.begin() + i * s->k);
  const LocalSurface& cell = grid.surface(grid.node_of_point(i));
  TangentPlane plane = cell.PlaneAt(x);
  if (options.fit_points > 0) {
    const Eigen::Index m = std::min<Eigen::Index>(options.fit_points, near->size());
    const Eigen::MatrixX3d pts =
        grid.index().points()(Eigen::Map<const Eigen::VectorXi>(near->data(), m), Eigen::all);
    if (FitOwnSheet(pts, options.fit_wedge_deg, 0.5 * grid.sheet_gap_mm(), plane.normal,
                    &s->surface[at], &s->rms_mm[at]))
      plane = s->surface[at].PlaneAt(x);
    else
      s->surface[at] = cell, s->rms_mm[at] = 0;
  }
  s->position[at] = options.project_to_surface ? plane.point : x;
  const bool given =
      grid.point_normals().rows() > 0 && grid.point_normals().row(i).squaredNorm() > 0;
  s->normal[at] = given ? Eigen::Vector3d(grid.point_normals().row(i)) : plane.normal.normalized();
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
  if (options.fit_points > 0) {
    s.surface.resize(static_cast<size_t>(n));
    s.rms_mm.resize(static_cast<size_t>(n));
  }
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

struct JoinLimits {
  double sin_max = 0;    // of the chord's angle to either tangent plane
  double offset_mm = 0;  // OnOneSurface's tolerance before the fits' residuals
};

bool ChordAlongSurface(const Eigen::Vector3d& e, const Eigen::Vector3d& np,
                       const Eigen::Vector3d& nq, double sin_max) {
  const double limit = sin_max * e.norm();
  return std::abs(np.dot(e)) <= limit && std::abs(nq.dot(e)) <= limit;
}

// One of p, q lies on the other's fitted surface: within `offset_mm` plus
// three times that fit's RMS residual (the scan's noise). Two sheets closer
// than the sheet gap that a chord still joins along both tangent planes
// (the lips pressed together) are millimetres off each other's surfaces;
// neighbours on one sheet a fraction of a millimetre.
bool OnOneSurface(const CloudGrid& grid, const Surfels& s, double offset_mm, int p, int q) {
  const auto on = [&](int a, int b) {
    const size_t i = static_cast<size_t>(a);
    return std::abs(s.surface[i].Offset(grid.index().point(b))) <= offset_mm + 3 * s.rms_mm[i];
  };
  return on(p, q) || on(q, p);
}

// The chord test and the surface test, then: with oriented normals, the two
// points' normals within a right angle (points facing each other across a gap
// or back to back across thin tissue are not joined); without, the grid's test
// that the points' nodes lie on one surface (sheets apart by the sheet gap are
// not).
bool Join(const CloudGrid& grid, const Surfels& s, const JoinLimits& limits, int p, int q) {
  const Eigen::Vector3d& np = s.normal[static_cast<size_t>(p)];
  const Eigen::Vector3d& nq = s.normal[static_cast<size_t>(q)];
  if (!ChordAlongSurface(s.position[static_cast<size_t>(q)] - s.position[static_cast<size_t>(p)],
                         np, nq, limits.sin_max))
    return false;
  if (!s.surface.empty() && !OnOneSurface(grid, s, limits.offset_mm, p, q)) return false;
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
  const JoinLimits limits{std::sin(options.max_chord_angle_deg * M_PI / 180),
                          options.surface_offset_fraction * grid.sheet_gap_mm()};
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
      if (r >= 0 && r != p && done[static_cast<size_t>(r)] && Join(grid, surfels, limits, p, r))
        settled.push_back(r);
    }
    for (int j = 0; j < surfels.k; ++j) {
      const int q = near[j];
      if (q < 0 || done[static_cast<size_t>(q)] || !Join(grid, surfels, limits, p, q)) continue;
      const Eigen::Vector3d& xq = surfels.position[static_cast<size_t>(q)];
      double offer = dp + (xq - xp).norm();
      for (const int r : settled)
        if (Join(grid, surfels, limits, r, q))
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
