#include "measure/measurements/geodesic_paths.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <thread>
#include <vector>

#include "measure/measurements/geodesic_plan.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Vec = Eigen::Vector3d;

// Whether the straight chord from p to x crosses unscanned skin: its points
// at a quarter, half and three quarters lie farther than `off_mm` from every
// scan point, and (with normals) along the surface from the nearest one
// (within 30 deg of its tangent plane), as over a hole; a chord over a
// hollow of scanned skin lies along the skin's normal and is no bridge.
bool CrossesHole(const PointIndex& index, const Eigen::MatrixX3d& normals, const Vec& p,
                 const Vec& x, double off_mm) {
  if ((x - p).norm() < 3 * off_mm) return false;
  for (double t : {0.25, 0.5, 0.75}) {
    const Vec m = p + t * (x - p);
    double d2 = 0;
    const int q = index.Nearest(m, &d2);
    if (d2 <= off_mm * off_mm) return false;
    if (normals.rows() == index.size()) {
      const Vec d = m - index.point(q);
      if (std::abs(d.dot(normals.row(q).transpose())) > 0.5 * d.norm()) return false;
    }
  }
  return true;
}

// The skin under a bridge from scan point `p` to `datum` (mm): the circular
// arc whose chord meets the tangent planes at the mean of its angles to
// them - p's plane (unit normal n_p) and the hidden skin's (the mean normal
// of the scan around the datum point, n_datum; left out when shorter than
// 0.5: skins facing each other, as both thighs round a crotch). A circle's
// chord meets its tangent at half the arc's angle a, so the arc is
// chord * a / sin(a): across a crease that turns the skin by 90 deg, 11 %
// longer than the chord that cuts through it. The chord without normals.
double ArcOver(const Vec& p, const Vec& n_p, const Vec& datum, const Vec& n_datum) {
  const double chord = (datum - p).norm();
  if (chord < 1e-9 || n_p.norm() < 0.5) return chord;
  const Vec d = (datum - p) / chord;
  double angle = std::asin(std::min(1.0, std::abs(d.dot(n_p.normalized()))));
  if (n_datum.norm() >= 0.5)
    angle = 0.5 * (angle + std::asin(std::min(1.0, std::abs(d.dot(n_datum.normalized())))));
  return angle < 1e-6 ? chord : chord * angle / std::sin(angle);
}

// The mean of the unit normals of the 32 scan points nearest x (zero
// without normals).
Vec MeanNormalNear(const PointIndex& index, const Eigen::MatrixX3d& normals, const Vec& x) {
  if (normals.rows() != index.size()) return Vec::Zero();
  std::vector<int> near;
  std::vector<double> d2;
  index.Knn(x, 32, &near, &d2);
  Vec sum = Vec::Zero();
  for (int q : near) sum += normals.row(q).transpose();
  return near.empty() ? Vec::Zero() : Vec(sum / static_cast<double>(near.size()));
}

// Whether a way of length_mm between a and b runs more than detour_ratio
// times their chord: round a limb or a buttock, where a hole in the scan
// (the crotch between touching thighs) cut the way a tape would take.
bool IsDetour(const GeodesicPathOptions& o, double length_mm, const Vec& a, const Vec& b) {
  return length_mm > o.detour_ratio * (a - b).norm();
}

// Scan points that may start a bridge into `datum`, nearest first: within
// max_bridge_mm (with `must_cross`, only those whose chord crosses a hole),
// each with its distance and the arc over the hole (ArcOver).
struct BridgeCandidates {
  std::vector<int> rows;
  std::vector<double> distance_mm, arc_mm;
};

BridgeCandidates CandidatesInto(const PointIndex& index, const Eigen::MatrixX3d& normals,
                                const Vec& datum, const GeodesicPathOptions& o, bool must_cross) {
  std::vector<int> near;
  std::vector<double> d2;
  index.Knn(datum, 4096, &near, &d2);
  const bool with_normals = normals.rows() == index.size();
  const Vec n_datum = MeanNormalNear(index, normals, datum);
  BridgeCandidates c;
  for (size_t k = 0; k < near.size(); ++k) {
    if (d2[k] > o.max_bridge_mm * o.max_bridge_mm) break;
    if (must_cross && !CrossesHole(index, normals, index.point(near[k]), datum, o.off_surface_mm))
      continue;
    const Vec n_p = with_normals ? Vec(normals.row(near[k]).transpose()) : Vec::Zero();
    c.rows.push_back(near[k]);
    c.distance_mm.push_back(std::sqrt(d2[k]));
    c.arc_mm.push_back(ArcOver(index.point(near[k]), n_p, datum, n_datum));
  }
  return c;
}

// Of the candidates within reach_mm, the one minimising geodesic(from, p) +
// its arc; -1 when none. At most 256 candidates, evenly spread.
int BestBridge(CloudGeodesics& geodesics, const BridgeCandidates& c, const Vec& from,
               double reach_mm, double* cost) {
  size_t n = 0;
  while (n < c.rows.size() && c.distance_mm[n] <= reach_mm) ++n;
  const size_t step = n / 256 + 1;
  std::vector<int> some;
  std::vector<double> some_arcs;
  for (size_t k = 0; k < n; k += step) some.push_back(c.rows[k]), some_arcs.push_back(c.arc_mm[k]);
  *cost = kInf;
  if (some.empty()) return -1;
  const int best = geodesics.NearestOf(from, some, some_arcs, cost);
  return best < 0 ? -1 : some[static_cast<size_t>(best)];
}

// The best bridge within first_bridge_mm, and within max_bridge_mm when that
// finds none or the way is still a detour: a tape lies on the skin wherever
// there is skin, and the arc, which cannot know the hidden skin's shape,
// would otherwise favour the longest bridge on offer.
int ReachBridge(CloudGeodesics& geodesics, const Eigen::MatrixX3d& normals, const Vec& from,
                const Vec& datum, const GeodesicPathOptions& o, bool must_cross, double* cost) {
  const BridgeCandidates c =
      CandidatesInto(geodesics.grid().index(), normals, datum, o, must_cross);
  const int near = BestBridge(geodesics, c, from, o.first_bridge_mm, cost);
  if (near >= 0 && !IsDetour(o, *cost, datum, from)) return near;
  double far_cost = kInf;
  const int far = BestBridge(geodesics, c, from, o.max_bridge_mm, &far_cost);
  if (far < 0 || far_cost >= *cost) return near;
  *cost = far_cost;
  return far;
}

// The path `from` -> scan point `to` plus the bridge `to` -> `datum`, the
// arc over the hidden skin (ArcOver).
GeodesicPath Bridged(CloudGeodesics& geodesics, const Eigen::MatrixX3d& normals, const Vec& from,
                     int to_row, const Vec& datum) {
  const PointIndex& index = geodesics.grid().index();
  const Vec to = index.point(to_row);
  const CloudGeodesicPath p = geodesics.Between(from, to);
  const Vec n_to =
      normals.rows() == index.size() ? Vec(normals.row(to_row).transpose()) : Vec::Zero();
  GeodesicPath out;
  out.bridged_mm = ArcOver(to, n_to, datum, MeanNormalNear(index, normals, datum));
  out.length_mm = p.length_mm + out.bridged_mm;
  out.points.resize(p.points.rows() + 1, 3);
  out.points << p.points, datum.transpose();
  return out;
}

// Whether the part of a path (#K x 3, mm) up to first_bridge_mm (straight)
// from either end runs more than detour_ratio times that reach: round a hole
// at the datum point (the crotch between the thighs), too short a part of
// a long path (the inside leg) to make all of it a detour.
bool EndDetours(const GeodesicPathOptions& o, const Eigen::MatrixX3d& points) {
  const Eigen::Index n = points.rows();
  for (const bool from_end : {false, true}) {
    const auto at = [&](Eigen::Index k) { return points.row(from_end ? n - 1 - k : k); };
    double along = 0;
    for (Eigen::Index k = 1; k < n; ++k) {
      along += (at(k) - at(k - 1)).norm();
      if ((at(k) - at(0)).norm() < o.first_bridge_mm) continue;
      if (IsDetour(o, along, at(k).transpose(), at(0).transpose())) return true;
      break;
    }
  }
  return false;
}

// Whether a solved path is a detour between its datum points: all of it
// (IsDetour), or round either end (EndDetours).
bool Detour(const GeodesicPathOptions& o, const GeodesicPath& path, const Vec& a, const Vec& b) {
  return path.error.empty() && (IsDetour(o, path.length_mm, a, b) || EndDetours(o, path.points));
}

}  // namespace

GeodesicPaths::End GeodesicPaths::Classify(const GeodesicPathOptions& o,
                                           const CloudGeodesics& geodesics,
                                           const Eigen::MatrixX3d& normals, const Vec& x) const {
  const PointIndex& index = geodesics.grid().index();
  double d2 = 0;
  const int nearest = index.Nearest(x, &d2);
  End end;
  end.start = x;
  if (nearest < 0) return end;
  const double d = std::sqrt(d2);
  if (d > o.tolerance_mm && d <= o.max_bridge_mm) {
    end.start = index.point(nearest), end.bridge_mm = d, end.in_hole = true;
    return end;
  }
  // A hole's rim: the scan around x lies on one side of it (the mean of the
  // unit directions to the neighbours, in the tangent plane, is long).
  std::vector<int> near;
  std::vector<double> near_d2;
  index.Knn(x, 96, &near, &near_d2);
  const bool with_normals = normals.rows() == index.size();
  const Vec n = with_normals ? Vec(normals.row(nearest).transpose()) : Vec::Zero();
  Vec sum = Vec::Zero();
  int count = 0;
  for (size_t k = 0; k < near.size(); ++k) {
    if (near_d2[k] > o.rim_radius_mm * o.rim_radius_mm || near_d2[k] < 1) continue;
    Vec u = index.point(near[k]) - x;
    u -= u.dot(n) * n;
    if (u.norm() < 1e-9) continue;
    sum += u.normalized(), ++count;
  }
  end.at_rim = count >= 8 && sum.norm() / count > o.rim_offset;
  return end;
}

GeodesicPath GeodesicPaths::SolvePair(const GeodesicPathOptions& o, CloudGeodesics& geodesics,
                                      const LandmarkSet& set, const std::string& source,
                                      const std::pair<std::string, std::string>& pair) const {
  const std::string& target = pair.first == source ? pair.second : pair.first;
  GeodesicPath out;
  try {
    const End a = ends_.at(source), b = ends_.at(target);
    const Vec& xa = set.points.at(source).position_mm;
    const Vec& xb = set.points.at(target).position_mm;
    bool reversed = false;  // out runs from target to source
    if (a.in_hole && b.in_hole) {
      const CloudGeodesicPath p = geodesics.Between(a.start, b.start);
      out.bridged_mm = a.bridge_mm + b.bridge_mm;
      out.length_mm = p.length_mm + out.bridged_mm;
      out.points.resize(p.points.rows() + 2, 3);
      out.points << xa.transpose(), p.points, xb.transpose();
    } else if (a.in_hole || b.in_hole) {
      // From the end on the scan, the best way into the hole.
      const End& on = a.in_hole ? b : a;
      const Vec& datum = a.in_hole ? xa : xb;
      double cost = 0;
      const int p = ReachBridge(geodesics, normals_, on.start, datum, o, false, &cost);
      const int exit = p >= 0 ? p : geodesics.grid().index().Nearest(datum);
      out = Bridged(geodesics, normals_, on.start, exit, datum);
      reversed = a.in_hole;
    } else {
      const CloudGeodesicPath path = geodesics.Between(a.start, b.start);
      out.length_mm = path.length_mm;
      out.points = path.points;
      if (b.at_rim || Detour(o, out, xa, xb))  // from the source's propagation
        BridgeInto(o, geodesics, a.start, xb, &out);
    }
    // Stored from pair.first to pair.second.
    const bool forward = (pair.first == source) != reversed;
    if (!forward) out.points = out.points.colwise().reverse().eval();
  } catch (const InputError& e) {
    out = GeodesicPath();
    out.error = e.what();
  }
  return out;
}

void GeodesicPaths::BridgeInto(const GeodesicPathOptions& o, CloudGeodesics& geodesics,
                               const Vec& from, const Vec& datum, GeodesicPath* path) const {
  double cost = kInf;
  const int p = ReachBridge(geodesics, normals_, from, datum, o, true, &cost);
  if (p < 0 || cost >= path->length_mm) return;
  GeodesicPath bridged = Bridged(geodesics, normals_, from, p, datum);
  if (bridged.length_mm < path->length_mm) *path = std::move(bridged);
}

void GeodesicPaths::Solve(const GeodesicPathOptions& o, CloudGeodesics& geodesics,
                          const Eigen::MatrixX3d& normals, const LandmarkSet& set,
                          Progress* progress) {
  normals_ = normals;
  for (const auto& pair : pending_)
    for (const std::string& name : {pair.first, pair.second})
      if (!ends_.count(name))
        ends_[name] = Classify(o, geodesics, normals, set.points.at(name).position_mm);
  ProgressBegin(progress, "geodesics", static_cast<std::int64_t>(pending_.size()));
  // Plan: the end each pair is solved from, grouped by source (geodesic_plan.h).
  std::map<std::string, PlanEnd> plan_ends;
  for (const auto& [name, end] : ends_)
    plan_ends[name] = {set.points.at(name).position_mm, end.at_rim || end.in_hole};
  Eigen::MatrixX3d sites(geodesics.grid().num_nodes(), 3);
  for (int i = 0; i < geodesics.grid().num_nodes(); ++i)
    sites.row(i) = geodesics.grid().site(i).transpose();
  const std::vector<SourceGroup> groups = PlanSources(sites, plan_ends, pending_);
  pending_.clear();
  // Groups to workers as they come free, largest estimated cost first. Worker
  // 0 uses `geodesics`, the others a fork of it on the same grid
  // (CloudGeodesics keeps a per-object cache and is not thread-safe). A path
  // does not depend on the worker that solves it.
  const int workers = std::max(1, std::min<int>(o.threads, static_cast<int>(groups.size())));
  std::atomic<std::size_t> next{0};
  std::vector<std::map<std::pair<std::string, std::string>, GeodesicPath>> results(
      static_cast<std::size_t>(workers));
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(workers));
  auto work = [&](std::size_t w) {
    try {
      std::unique_ptr<CloudGeodesics> own;
      if (w > 0) own = geodesics.Fork();
      CloudGeodesics& g = w > 0 ? *own : geodesics;
      // The pairs, then bridges into their sources at a hole, from the
      // other ends (grouped so each propagation serves its pairs).
      std::vector<std::pair<std::string, std::pair<std::string, std::string>>> reverse;
      for (std::size_t k = next++; k < groups.size(); k = next++) {
        const std::string& source = groups[k].source;
        for (const auto& pair : groups[k].pairs) {
          results[w][pair] = SolvePair(o, g, set, source, pair);
          const std::string& other = pair.first == source ? pair.second : pair.first;
          if (!ends_.at(source).in_hole && !ends_.at(other).in_hole &&
              (ends_.at(source).at_rim ||
               Detour(o, results[w][pair], set.points.at(pair.first).position_mm,
                      set.points.at(pair.second).position_mm)))
            reverse.emplace_back(other, pair);
        }
      }
      std::sort(reverse.begin(), reverse.end());
      for (const auto& [from, pair] : reverse) {
        GeodesicPath& path = results[w][pair];
        if (!path.error.empty()) continue;
        const std::string& into = pair.first == from ? pair.second : pair.first;
        const bool first_is_into = pair.first == into;
        if (first_is_into) path.points = path.points.colwise().reverse().eval();  // from -> into
        try {
          BridgeInto(o, g, set.points.at(from).position_mm, set.points.at(into).position_mm, &path);
        } catch (const InputError&) {
        }
        if (first_is_into) path.points = path.points.colwise().reverse().eval();
      }
    } catch (...) {
      errors[w] = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < static_cast<std::size_t>(workers); ++w) pool.emplace_back(work, w);
  work(0);
  for (std::thread& t : pool) t.join();
  for (const std::exception_ptr& e : errors)
    if (e) std::rethrow_exception(e);
  std::int64_t done = 0;
  for (auto& r : results) done += static_cast<std::int64_t>(r.size()), solved_.merge(r);
  ProgressUpdate(progress, done);
  ProgressEnd(progress);
}

const GeodesicPath* GeodesicPaths::Get(const std::string& a, const std::string& b) const {
  const auto it = solved_.find(std::minmax(a, b));
  return it == solved_.end() ? nullptr : &it->second;
}

}  // namespace bespoke
