#include "measure/measurements/measure.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <exception>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <thread>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Vec = Eigen::Vector3d;

// A measurement that cannot be taken on this scan (the reason goes to `skipped`).
struct Skip {
  std::string reason;
};

const Vec& Position(const LandmarkSet& set, const std::string& name) {
  const auto it = set.points.find(name);
  if (it == set.points.end()) throw Skip{"no landmark '" + name + "'"};
  return it->second.position_mm;
}

// The first datum/axis point the set lacks, with the detector's reason, or "".
std::string MissingReason(const MeasurementDef& m, const LandmarkSet& set) {
  for (const auto* list : {&m.datum, &m.axis})
    for (const std::string& name : *list) {
      if (set.points.count(name)) continue;
      const auto why = set.missing.find(name);
      return "no landmark '" + name + "'" +
             (why == set.missing.end() ? "" : " (" + why->second + ")");
    }
  return "";
}

// Datum and axis points placed with doubt: "landmark_uncertain".
void FlagUncertain(const MeasureOptions& o, const MeasurementDef& m, const LandmarkSet& set,
                   Measurement* out) {
  std::set<std::string> seen;
  for (const auto* list : {&m.datum, &m.axis})
    for (const std::string& name : *list) {
      const Landmark& l = set.points.at(name);
      bool doubtful = l.confidence < o.uncertain_confidence;
      for (const std::string& f : l.flags) doubtful |= f != "override";
      if (doubtful && seen.insert(name).second) out->uncertain_landmarks.push_back(name);
    }
  if (!out->uncertain_landmarks.empty()) out->flags.push_back("landmark_uncertain");
}

Measurement Start(const MeasurementDef& m) {
  Measurement out;
  out.name = m.name, out.kind = m.kind, out.method = m.method, out.datum = m.datum;
  return out;
}

bool ReachesPastDatum(const Eigen::MatrixX3d& part, const MeasurementDef& m, const LandmarkSet& set,
                      double margin_mm) {
  double lo = 0, hi = 0;
  for (const std::string& name : m.datum) {
    const double x = Position(set, name).x();
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  return part.rows() > 0 &&
         (part.col(0).maxCoeff() > hi + margin_mm || part.col(0).minCoeff() < lo - margin_mm);
}

double DistanceToPoints(const Eigen::MatrixX3d& points, const Vec& x) {
  if (points.rows() == 0) return std::numeric_limits<double>::infinity();
  return std::sqrt((points.rowwise() - x.transpose()).rowwise().squaredNorm().minCoeff());
}

Measurement Girth(const MeasureOptions& o, const MeasurementDef& m, const PointCloud& cloud,
                  const LandmarkSet& set) {
  Measurement out = Start(m);
  auto [point, normal] = GirthPlane(m, set);
  Eigen::MatrixX3d anchors(static_cast<Eigen::Index>(m.datum.size()), 3);
  for (std::size_t i = 0; i < m.datum.size(); ++i)
    anchors.row(static_cast<Eigen::Index>(i)) = Position(set, m.datum[i]);
  SectionGirth s =
      MeasureSectionGirth(o.section, cloud.points, cloud.normals, point, normal, anchors);
  while (m.arms == "lower" && out.lowered_mm + o.lower_step_mm <= o.max_lower_mm && s.points > 0 &&
         ReachesPastDatum(s.part, m, set, o.arms_margin_mm)) {
    point.z() -= o.lower_step_mm;
    out.lowered_mm += o.lower_step_mm;
    s = MeasureSectionGirth(o.section, cloud.points, cloud.normals, point, normal, anchors);
  }
  if (s.points == 0) throw Skip{"the girth plane misses the scan"};
  out.value_mm = s.girth_mm;
  out.plane_point = point, out.plane_normal = normal;
  out.largest_gap_mm = s.largest_gap_mm;
  if (s.open) out.flags.push_back("section_open");
  if (DistanceToPoints(s.part, anchors.row(0).transpose()) > o.datum_tolerance_mm)
    out.flags.push_back("datum_off_section");
  if (!m.arms.empty() && ReachesPastDatum(s.part, m, set, o.arms_margin_mm))
    out.flags.push_back("section_includes_arms");
  if (m.side == "right" && s.part.col(0).minCoeff() <= 0)
    out.flags.push_back("section_crosses_midline");
  if (o.keep_geometry) out.geometry = s.hull;
  return out;
}

// Geodesic paths between landmark pairs over one CloudGeodesics, sharing the
// propagation of a start point: sources are taken greedily (the landmark in
// most pending pairs first), every pair touching it solved from it.
class PathCache {
  struct Entry {
    double length_mm = 0;
    Eigen::MatrixX3d points;
    std::string error;
  };
  struct End {
    Vec start;             // where the path starts on the scan
    double bridge_mm = 0;  // straight bridge from there to the datum point
    bool in_hole = false;
  };

 public:
  void Need(const std::string& a, const std::string& b) {
    if (a != b) pending_.insert(std::minmax(a, b));
  }
  bool empty() const { return pending_.empty(); }

  // A datum point in a scan hole (farther than tolerance_mm from every scan
  // point, at most max_bridge_mm) is reached by the shortest surface path
  // plus a straight bridge across the hole: from the other end's distance
  // field, the scan point p within max_bridge_mm of the datum point that
  // minimises geodesic(other, p) + |p - datum| (a tape bridging the crotch).
  // With both ends in holes, each bridges from its nearest scan point.
  void Solve(CloudGeodesics& geodesics, const LandmarkSet& set, double tolerance_mm,
             double max_bridge_mm, int threads, Progress* progress) {
    for (const auto& pair : pending_)
      for (const std::string& name : {pair.first, pair.second}) {
        if (ends_.count(name)) continue;
        const Vec& x = set.points.at(name).position_mm;
        double d2 = 0;
        const int nearest = geodesics.grid().index().Nearest(x, &d2);
        End end{x, 0.0, false};
        if (nearest >= 0 && std::sqrt(d2) > tolerance_mm && std::sqrt(d2) <= max_bridge_mm)
          end = {geodesics.grid().index().point(nearest), std::sqrt(d2), true};
        ends_[name] = end;
      }
    ProgressBegin(progress, "geodesics", static_cast<std::int64_t>(pending_.size()));
    // Plan: source groups, greedily (the landmark in most pending pairs first).
    std::vector<std::pair<std::string, std::vector<std::pair<std::string, std::string>>>> groups;
    while (!pending_.empty()) {
      std::map<std::string, int> degree;
      for (const auto& [a, b] : pending_) ++degree[a], ++degree[b];
      const std::string source =
          std::max_element(degree.begin(), degree.end(), [](const auto& x, const auto& y) {
            return x.second < y.second;
          })->first;
      groups.emplace_back(source, std::vector<std::pair<std::string, std::string>>());
      for (auto it = pending_.begin(); it != pending_.end();) {
        if (it->first != source && it->second != source) {
          ++it;
          continue;
        }
        groups.back().second.push_back(*it);
        it = pending_.erase(it);
      }
    }
    // Groups to workers (largest first, to the least loaded); worker 0 uses
    // `geodesics`, the others build their own grid (CloudGeodesics keeps a
    // per-object cache and is not thread-safe).
    const int workers = std::max(1, std::min<int>(threads, static_cast<int>(groups.size())));
    std::vector<std::vector<std::size_t>> assigned(static_cast<std::size_t>(workers));
    std::vector<std::size_t> load(static_cast<std::size_t>(workers), 0);
    std::vector<std::size_t> order(groups.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
      return groups[x].second.size() > groups[y].second.size();
    });
    for (std::size_t g : order) {
      const auto w =
          static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
      assigned[w].push_back(g), load[w] += groups[g].second.size();
    }
    std::vector<std::map<std::pair<std::string, std::string>, Entry>> results(
        static_cast<std::size_t>(workers));
    std::vector<std::exception_ptr> errors(static_cast<std::size_t>(workers));
    auto work = [&](std::size_t w) {
      try {
        std::unique_ptr<CloudGeodesics> own;
        if (w > 0)
          own = std::make_unique<CloudGeodesics>(geodesics.options(),
                                                 geodesics.grid().index().points());
        CloudGeodesics& g = w > 0 ? *own : geodesics;
        for (std::size_t k : assigned[w])
          for (const auto& pair : groups[k].second)
            results[w][pair] = SolvePair(g, set, groups[k].first, pair, max_bridge_mm);
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

  Entry SolvePair(CloudGeodesics& geodesics, const LandmarkSet& set, const std::string& source,
                  const std::pair<std::string, std::string>& pair, double max_bridge_mm) const {
    const std::string& target = pair.first == source ? pair.second : pair.first;
    Entry entry;
    try {
      End from = ends_.at(source), to = ends_.at(target);
      const bool flip = from.in_hole && !to.in_hole;  // solve from the end on the scan
      if (flip) std::swap(from, to);
      if (to.in_hole && !from.in_hole)
        to = BestExit(geodesics, from, set.points.at(flip ? source : target).position_mm,
                      max_bridge_mm);
      CloudGeodesicPath p = geodesics.Between(from.start, to.start);
      entry.length_mm = p.length_mm + from.bridge_mm + to.bridge_mm;
      const Vec& a = set.points.at(flip ? target : source).position_mm;
      const Vec& b = set.points.at(flip ? source : target).position_mm;
      Eigen::MatrixX3d points(p.points.rows() + 2, 3);
      points << a.transpose(), p.points, b.transpose();     // from `a` to `b`
      const bool forward = (pair.first == source) != flip;  // stored from pair.first
      entry.points = forward ? points : Eigen::MatrixX3d(points.colwise().reverse());
    } catch (const InputError& e) {
      entry.error = e.what();
    }
    return entry;
  }

  // Length and path from a to b; Skip when there is no path.
  std::pair<double, Eigen::MatrixX3d> Get(const std::string& a, const std::string& b,
                                          const LandmarkSet& set) const {
    if (a == b) return {0.0, Eigen::MatrixX3d(Position(set, a).transpose())};
    const Entry& e = solved_.at(std::minmax(a, b));
    if (!e.error.empty())
      throw Skip{"no geodesic " + a + " -> " + b + " over the scan: " + e.error};
    return {e.length_mm, a < b ? e.points : Eigen::MatrixX3d(e.points.colwise().reverse())};
  }

 private:
  static End BestExit(CloudGeodesics& geodesics, const End& from, const Vec& datum,
                      double max_bridge_mm) {
    const CloudDistanceField field = geodesics.DistancesFrom(from.start);
    const Eigen::MatrixX3d& points = geodesics.grid().index().points();
    End best{datum, 0, true};
    double cost = std::numeric_limits<double>::infinity();
    if (field.point_distance_mm.size() != points.rows()) return best;
    for (Eigen::Index i = 0; i < points.rows(); ++i) {
      const double bridge = (points.row(i).transpose() - datum).norm();
      if (bridge > max_bridge_mm || !std::isfinite(field.point_distance_mm(i))) continue;
      if (field.point_distance_mm(i) + bridge < cost)
        cost = field.point_distance_mm(i) + bridge,
        best = {points.row(i).transpose(), bridge, true};
    }
    return best;
  }
  std::set<std::pair<std::string, std::string>> pending_;
  std::map<std::pair<std::string, std::string>, Entry> solved_;
  std::map<std::string, End> ends_;
};

Eigen::MatrixX3d Stack(const std::vector<Eigen::MatrixX3d>& pieces) {
  Eigen::Index rows = 0;
  for (const auto& p : pieces) rows += p.rows();
  Eigen::MatrixX3d out(rows, 3);
  rows = 0;
  for (const auto& p : pieces) out.middleRows(rows, p.rows()) = p, rows += p.rows();
  return out;
}

Measurement Length(const MeasureOptions& o, const MeasurementDef& m, const LandmarkSet& set,
                   const PathCache& paths, const PointIndex* index) {
  Measurement out = Start(m);
  const Vec a = Position(set, m.datum[0]);
  if (m.method == MeasurementMethod::kBreadth) {
    const Vec b = Position(set, m.datum[1]);
    out.value_mm = (a - b).head<2>().norm();
    out.geometry = (Eigen::MatrixX3d(2, 3) << a.transpose(), b.transpose()).finished();
  } else if (m.method == MeasurementMethod::kPointToLine) {
    const Vec b = Position(set, m.datum[1]), c = Position(set, m.datum[2]);
    if (!((c - b).norm() > 0)) throw Skip{"the line's two points coincide"};
    const Vec d = (c - b).normalized();
    const Vec foot = b + (a - b).dot(d) * d;
    out.value_mm = (a - foot).norm();
    out.geometry = (Eigen::MatrixX3d(2, 3) << a.transpose(), foot.transpose()).finished();
  } else {
    std::vector<Eigen::MatrixX3d> pieces;
    for (std::size_t i = 0; i + 1 < m.datum.size(); ++i) {
      auto [length, points] = paths.Get(m.datum[i], m.datum[i + 1], set);
      out.value_mm += length;
      pieces.push_back(std::move(points));
    }
    const Vec last = Position(set, m.datum.back());
    if (m.to_floor) {
      out.value_mm += last.z();
      pieces.push_back(
          (Eigen::MatrixX3d(2, 3) << last.transpose(), last.x(), last.y(), 0.0).finished());
    }
    out.geometry = Stack(pieces);
    for (const std::string& name : m.datum) {
      double d2 = 0;
      if (index && index->Nearest(Position(set, name), &d2) >= 0 &&
          std::sqrt(d2) > o.datum_tolerance_mm) {
        out.flags.push_back("datum_off_scan");
        break;
      }
    }
  }
  if (!o.keep_geometry) out.geometry.resize(0, 3);
  return out;
}

Measurement Height(const MeasureOptions& o, const MeasurementDef& m, const LandmarkSet& set) {
  Measurement out = Start(m);
  const Vec a = Position(set, m.datum[0]);
  out.value_mm = a.z();
  Vec foot(a.x(), a.y(), 0.0);
  if (m.datum.size() == 2) {
    out.value_mm -= Position(set, m.datum[1]).z();
    foot.z() = Position(set, m.datum[1]).z();
  }
  if (o.keep_geometry)
    out.geometry = (Eigen::MatrixX3d(2, 3) << a.transpose(), foot.transpose()).finished();
  return out;
}

class StageClock {
 public:
  explicit StageClock(std::string name) : name_(std::move(name)) {}
  MeasureStage Stop() const {
    return {name_, std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count(),
            static_cast<double>(std::clock() - cpu_) / CLOCKS_PER_SEC};
  }

 private:
  std::string name_;
  std::chrono::steady_clock::time_point wall_ = std::chrono::steady_clock::now();
  std::clock_t cpu_ = std::clock();
};

}  // namespace

void MeasureOptions::Check() const {
  section.Check();
  geodesics.Check();
  if (!(datum_tolerance_mm > 0)) throw InputError("measure: datum_tolerance_mm must be > 0");
  if (!(arms_margin_mm >= 0)) throw InputError("measure: arms_margin_mm must be >= 0");
  if (!(lower_step_mm > 0) || !(max_lower_mm >= 0))
    throw InputError("measure: need lower_step_mm > 0, max_lower_mm >= 0");
  if (geodesic_threads < 1) throw InputError("measure: geodesic_threads must be >= 1");
  if (!(uncertain_confidence >= 0 && uncertain_confidence <= 1))
    throw InputError("measure: uncertain_confidence must be in [0, 1]");
}

const Measurement* MeasureResult::Find(const std::string& name) const {
  for (const Measurement& m : measurements)
    if (m.name == name) return &m;
  return nullptr;
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> GirthPlane(const MeasurementDef& m,
                                                       const LandmarkSet& set) {
  if (m.method != MeasurementMethod::kSectionHull)
    throw InputError("'" + m.name + "' is not a girth measured on a section");
  try {
    switch (m.plane) {
      case GirthPlane::kHorizontal: {
        double z = 0;
        for (const std::string& name : m.datum) z += Position(set, name).z();
        return {Vec(0, 0, z / static_cast<double>(m.datum.size())), Vec::UnitZ()};
      }
      case GirthPlane::kPerpendicularToAxis: {
        const Vec axis = Position(set, m.axis[1]) - Position(set, m.axis[0]);
        if (!(axis.norm() > 0)) throw InputError("'" + m.name + "': its axis points coincide");
        return {Position(set, m.datum[0]), axis.normalized()};
      }
      case GirthPlane::kThroughPoints: {
        const Vec a = Position(set, m.datum[0]), b = Position(set, m.datum[1]),
                  c = Position(set, m.datum[2]);
        const Vec normal = (b - a).cross(c - a);
        if (!(normal.norm() > 1e-9 * (b - a).squaredNorm()))
          throw InputError("'" + m.name + "': its three datum points are collinear");
        return {a, normal.z() < 0 ? Vec(-normal.normalized()) : Vec(normal.normalized())};
      }
      case GirthPlane::kNone:
        break;
    }
  } catch (const Skip& skip) {
    throw InputError("'" + m.name + "': " + skip.reason);
  }
  throw InputError("'" + m.name + "' has no girth plane");
}

MeasureResult Measure(const MeasureOptions& options, const Catalogue& catalogue,
                      const PointCloud& body_cloud, const LandmarkSet& landmarks,
                      Progress* progress) {
  options.Check();
  if (body_cloud.empty()) throw InputError("measure: the cloud is empty");
  const auto start = std::chrono::steady_clock::now();
  MeasureResult result;
  std::vector<const MeasurementDef*> todo;
  PathCache paths;
  for (const std::string& name : options.only)
    catalogue.Measurement(name);  // InputError when unknown
  for (const MeasurementDef& m : catalogue.measurements()) {
    if (!options.only.empty() &&
        std::find(options.only.begin(), options.only.end(), m.name) == options.only.end())
      continue;
    const std::string missing = MissingReason(m, landmarks);
    if (!missing.empty()) {
      result.skipped.emplace_back(m.name, missing);
      continue;
    }
    todo.push_back(&m);
    if (m.method == MeasurementMethod::kGeodesic)
      for (std::size_t i = 0; i + 1 < m.datum.size(); ++i) paths.Need(m.datum[i], m.datum[i + 1]);
  }
  std::map<std::string, Measurement> done;
  std::map<std::string, std::string> failed;
  auto attempt = [&](const MeasurementDef& m, auto&& take) {
    try {
      Measurement out = take();
      FlagUncertain(options, m, landmarks, &out);
      done.emplace(m.name, std::move(out));
    } catch (const Skip& skip) {
      failed.emplace(m.name, skip.reason);
    } catch (const InputError& e) {
      failed.emplace(m.name, e.what());
    }
  };

  StageClock girth_clock("girths");
  std::int64_t girths = 0, n_girths = 0;
  for (const MeasurementDef* m : todo) n_girths += m->kind == MeasurementKind::kGirth;
  ProgressBegin(progress, "girths", n_girths);
  for (const MeasurementDef* m : todo) {
    if (m->method != MeasurementMethod::kSectionHull) continue;
    attempt(*m, [&] { return Girth(options, *m, body_cloud, landmarks); });
    ProgressUpdate(progress, ++girths);
  }
  ProgressEnd(progress);
  result.stages.push_back(girth_clock.Stop());

  std::unique_ptr<CloudGeodesics> geodesics;
  if (!paths.empty()) {
    StageClock grid_clock("geodesic_grid");
    geodesics = std::make_unique<CloudGeodesics>(options.geodesics, body_cloud.points, progress);
    result.stages.push_back(grid_clock.Stop());
    StageClock path_clock("geodesics");
    paths.Solve(*geodesics, landmarks, options.datum_tolerance_mm, options.max_bridge_mm,
                options.geodesic_threads, progress);
    result.stages.push_back(path_clock.Stop());
  }
  StageClock other_clock("lengths_heights");
  const PointIndex* index = geodesics ? &geodesics->grid().index() : nullptr;
  for (const MeasurementDef* m : todo) {
    if (m->kind == MeasurementKind::kHeight)
      attempt(*m, [&] { return Height(options, *m, landmarks); });
    else if (m->kind == MeasurementKind::kLength)
      attempt(*m, [&] { return Length(options, *m, landmarks, paths, index); });
  }
  result.stages.push_back(other_clock.Stop());

  for (const MeasurementDef* m : todo) {  // catalogue order
    if (done.count(m->name))
      result.measurements.push_back(std::move(done.at(m->name)));
    else
      result.skipped.emplace_back(m->name, failed.at(m->name));
  }
  result.total_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace bespoke
