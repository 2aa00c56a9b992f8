#include "measure/geodesic/point_field.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

#include "scanners/core/errors.h"

namespace bespoke {

void PointFieldOptions::Check() const {
  if (neighbours < 2 || neighbours > 64)
    throw InputError("geodesics: point field neighbours must be in [2, 64]");
  if (!(max_chord_angle_deg > 0 && max_chord_angle_deg <= 90))
    throw InputError("geodesics: point field max_chord_angle_deg must be in (0, 90]");
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

// Each scan point as the distance sweep sees it: moved onto its node's
// fitted surface (when `project`, which removes scan noise from the chord
// lengths) and its unit normal (the given oriented one, else the surface's).
struct Surfels {
  std::vector<Eigen::Vector3d> position, normal;
};

Surfels MakeSurfels(const CloudGrid& grid, bool project) {
  const Eigen::Index n = grid.index().size();
  Surfels s{std::vector<Eigen::Vector3d>(static_cast<size_t>(n)),
            std::vector<Eigen::Vector3d>(static_cast<size_t>(n))};
  const bool given = grid.point_normals().rows() > 0;
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d x = grid.index().point(i);
    const TangentPlane plane = grid.surface(grid.node_of_point(i)).PlaneAt(x);
    s.position[static_cast<size_t>(i)] = project ? plane.point : x;
    s.normal[static_cast<size_t>(i)] = given && grid.point_normals().row(i).squaredNorm() > 0
                                           ? Eigen::Vector3d(grid.point_normals().row(i))
                                           : plane.normal.normalized();
  }
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
  const Surfels surfels = MakeSurfels(grid, options.project_to_surface);
  const double sin_max = std::sin(options.max_chord_angle_deg * M_PI / 180);
  std::vector<char> done(static_cast<size_t>(n), 0);
  std::vector<int> near, settled;
  std::vector<double> d2;
  while (!queue.empty()) {
    const auto [dp, p] = queue.top();
    queue.pop();
    if (done[static_cast<size_t>(p)] || dp > d[p]) continue;  // stale entry
    done[static_cast<size_t>(p)] = 1;
    const Eigen::Vector3d& xp = surfels.position[static_cast<size_t>(p)];
    index.Knn(index.point(p), options.neighbours + 1, &near, &d2);
    settled.clear();
    for (const int r : near)
      if (r != p && done[static_cast<size_t>(r)] && Join(grid, surfels, sin_max, p, r))
        settled.push_back(r);
    for (const int q : near) {
      if (done[static_cast<size_t>(q)] || !Join(grid, surfels, sin_max, p, q)) continue;
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
