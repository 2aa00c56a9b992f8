// CloudGeodesics where a query point lies in an unscanned region (a hole of
// the scan: the crotch, an armpit no sensor saw): the test that tells a hole
// from the air off the skin, the hole's rim, a propagation seeded over that
// rim, and paths with an end in a hole (cloud_geodesics.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "measure/cloud_geodesic/cloud_geodesics.h"
#include "scanners/core/errors.h"

namespace bespoke {

// Whether `x` (`distance` from the nearest scan point, in node `node`) lies
// in a hole of the scan rather than in the air off the skin or inside the
// body: either the scan points of the node's piece around it (at least 20
// within `distance` plus a margin, or where fewer, within twice `distance`
// plus the margin) lie on all sides of it - the mean of the unit directions
// to them is short - or it lies along the surface from the
// nearest scanned skin (within 20 degrees of that node's tangent plane), as
// a point in a crease no sensor saw (the crotch, an armpit) does. A point in
// the air or inside the body lies along the normal and sees the scan on one
// side (mean length 0.8-1 off a plane at the radius used; 0.6 is the cut).
bool CloudGeodesics::InUnscannedRegion(const Eigen::Vector3d& x, double distance, int node) const {
  const TangentPlane plane = grid_.surface(node).PlaneAt(grid_.site(node));
  const Eigen::Vector3d away = x - plane.point;
  if (away.norm() > 0 && std::abs(plane.normal.dot(away)) <= 0.35 * away.norm())
    return true;  // 20 deg
  const int component = grid_.component(node);
  std::vector<int> near;
  std::vector<double> d2;
  grid_.index().Knn(x, 1024, &near, &d2);
  // Whether at least 20 points of the piece within `radius` lie on all sides.
  const auto surrounded_within = [&](double radius, bool* enough) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int count = 0;
    for (size_t i = 0; i < near.size(); ++i) {
      if (d2[i] > radius * radius || d2[i] <= 0) continue;
      if (grid_.component(grid_.node_of_point(near[i])) != component) continue;
      sum += (grid_.index().points().row(near[i]).transpose() - x) / std::sqrt(d2[i]);
      ++count;
    }
    *enough = count >= 20;
    return *enough && sum.norm() / count < 0.6;
  };
  const double margin = std::max(2 * grid_.cell_size_mm(), 0.5 * distance);
  bool enough = false;
  const bool surrounded = surrounded_within(distance + margin, &enough);
  if (enough) return surrounded;
  // A sparse scan round a deep hole (a light booth under the crotch): too
  // few points that near to judge; the rim up to twice as far.
  return surrounded_within(2 * distance + margin, &enough);
}

std::vector<int> CloudGeodesics::RimNodes(const Eigen::Vector3d& x, double distance,
                                          int node) const {
  const double radius = distance + std::max(2 * grid_.cell_size_mm(), 0.5 * distance);
  std::vector<int> near, rim = {node};
  std::vector<double> d2;
  grid_.index().Knn(x, 4096, &near, &d2);
  for (size_t i = 0; i < near.size() && d2[i] <= radius * radius; ++i) {
    const int n = grid_.node_of_point(near[i]);
    if (grid_.component(n) == grid_.component(node) &&
        std::find(rim.begin(), rim.end(), n) == rim.end())
      rim.push_back(n);
  }
  return rim;
}

Propagation& CloudGeodesics::HolePropagationFrom(const Eigen::Vector3d& source, double distance,
                                                 int node) {
  if (!cached_ || cached_->source_node() != node || cached_->source() != source)
    cached_ = std::make_unique<Propagation>(options_.propagation, grid_, source,
                                            RimNodes(source, distance, node), TakeCachedPool());
  return *cached_;
}

// Between() when an end lies in an unscanned region. Geodesic distance is
// symmetric, so the wavefront starts at the end in a hole (seeded over its
// rim, Propagation's hole constructor); when the other end is in a hole too,
// the answer is the best of its rim nodes plus the chord into it. No final
// flow: it would pull the chord across the hole onto the rim's surfaces.
// With one end on the scan, the way from that end to the best rim node
// (flowed, its ends held) plus the chord is tried too, and the shorter kept.
CloudGeodesicPath CloudGeodesics::BetweenAcrossHoles(const Eigen::Vector3d& from,
                                                     const Eigen::Vector3d& to, int node_a,
                                                     int node_b, double snap_a, double snap_b,
                                                     bool hole_a, bool hole_b) {
  if (!hole_a) {  // start from the end in the hole, then reverse the path
    CloudGeodesicPath back =
        BetweenAcrossHoles(to, from, node_b, node_a, snap_b, snap_a, true, false);
    back.points = back.points.colwise().reverse().eval();
    std::swap(back.from_snap_mm, back.to_snap_mm);
    std::swap(back.from_unscanned, back.to_unscanned);
    return back;
  }
  Propagation& propagation = HolePropagationFrom(from, snap_a, node_a);
  std::vector<int> targets = {node_b};
  Eigen::Vector3d end = to;
  if (hole_b) {
    targets = RimNodes(to, snap_b, node_b);
  } else {
    end = grid_.surface(node_b).PlaneAt(to).point;
  }
  int best = -1;
  double best_length = std::numeric_limits<double>::infinity();
  for (const int target : targets) {
    propagation.Run(target);
    if (!propagation.settled(target)) continue;
    const double length = hole_b
                              ? propagation.distance_mm(target) + (grid_.site(target) - to).norm()
                              : propagation.DistanceNear(target, end);
    if (length < best_length) best_length = length, best = target;
  }
  if (best < 0)
    throw InputError("from " + FormatPoint(from) + " to " + FormatPoint(to) +
                     ": no path over the scanned surface connects the two points");
  CloudGeodesicPath result;
  result.length_mm = best_length;
  result.propagated_length_mm = best_length;
  result.nodes_settled = propagation.stats().settled;
  Eigen::MatrixX3d path = propagation.Path(best);
  path.conservativeResize(path.rows() + 1, 3);
  path.row(path.rows() - 1) = end.transpose();
  result.points = std::move(path);
  result.from_snap_mm = snap_a;
  result.to_snap_mm = snap_b;
  result.from_unscanned = hole_a;
  result.to_unscanned = hole_b;
  if (hole_b) return result;
  // The way from the scanned end too: the rim-seeded wavefront's windowed
  // flow can leave a kink in a long way that no final flow removes (an
  // extra 6-11 mm from the crotch to the front waist on some light-booth
  // scans), and both are ways over the skin, so the shorter stands.
  CloudGeodesicPath other = FromScannedEnd(end, node_b, from, snap_a, node_a);
  if (other.length_mm >= result.length_mm) return result;
  other.points = other.points.colwise().reverse().eval();
  other.from_snap_mm = snap_a;
  other.to_snap_mm = snap_b;
  other.from_unscanned = true;
  return other;
}

CloudGeodesicPath CloudGeodesics::FromScannedEnd(const Eigen::Vector3d& start, int node,
                                                 const Eigen::Vector3d& x, double distance,
                                                 int x_node) {
  Propagation& propagation = PropagationFrom(start, node);
  int best = -1;
  double best_length = std::numeric_limits<double>::infinity();
  for (const int rim : RimNodes(x, distance, x_node)) {
    propagation.Run(rim);
    if (!propagation.settled(rim)) continue;
    const double length = propagation.distance_mm(rim) + (grid_.site(rim) - x).norm();
    if (length < best_length) best_length = length, best = rim;
  }
  CloudGeodesicPath out;
  out.length_mm = best_length;
  if (best < 0) return out;
  out.propagated_length_mm = best_length;
  out.nodes_settled = propagation.stats().settled;
  std::vector<int> hints;
  Eigen::MatrixX3d skin = propagation.Path(best, &hints);
  if (skin.rows() < 2) return out;  // the scanned end is on the rim: the hole-seeded way holds
  out.length_mm = Polished(&skin, &hints, &out) + (skin.bottomRows<1>().transpose() - x).norm();
  out.points.resize(skin.rows() + 1, 3);
  out.points << skin, x.transpose();
  return out;
}

}  // namespace bespoke
