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
#include <utility>

#include "measure/measurements/geodesic_paths.h"
#include "measure/measurements/narrowest_section.h"
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

// The first referenced point the set lacks, with the detector's reason, or "".
std::string MissingReason(const MeasurementDef& m, const LandmarkSet& set) {
  for (const std::string& name : ReferencedLandmarks(m)) {
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
  for (const std::string& name : ReferencedLandmarks(m)) {
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

// The x range (mm) of the datum points, widened to take in x = 0.
std::pair<double, double> DatumXRange(const MeasurementDef& m, const LandmarkSet& set) {
  double lo = 0, hi = 0;
  for (const std::string& name : m.datum) {
    const double x = Position(set, name).x();
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  return {lo, hi};
}

bool ReachesPastDatum(const Eigen::MatrixX3d& part, const MeasurementDef& m, const LandmarkSet& set,
                      double margin_mm) {
  const auto [lo, hi] = DatumXRange(m, set);
  return part.rows() > 0 &&
         (part.col(0).maxCoeff() > hi + margin_mm || part.col(0).minCoeff() < lo - margin_mm);
}

double DistanceToPoints(const Eigen::MatrixX3d& points, const Vec& x) {
  if (points.rows() == 0) return std::numeric_limits<double>::infinity();
  return std::sqrt((points.rowwise() - x.transpose()).rowwise().squaredNorm().minCoeff());
}

double Sigma(const UncertaintyOptions& u, const LandmarkSet& set, const std::string& name) {
  return LandmarkSigma(name, set.points.at(name), u.scale);
}

// SD (mm) of a girth from its datum points: the plane moved along its
// normal by their SD (probed at most 10 mm either way and scaled up), the
// girth remeasured; the larger change. A probe whose section jumps by more
// than a fifth (into the arms, the shoulders) is not a measure of the
// datum's effect and is left out.
double GirthSd(const MeasureOptions& o, const MeasurementDef& m, const PointCloud& cloud,
               const LandmarkSet& set, const Vec& point, const Vec& normal,
               const Eigen::MatrixX3d& anchors, const SectionMembers& members, double girth_mm) {
  double var = 0;
  for (const std::string& name : m.datum)
    var += Sigma(o.uncertainty, set, name) * Sigma(o.uncertainty, set, name);
  double sd = std::sqrt(var);
  // A plane at the points' mean height, or through the points, moves at
  // their centroid by the SD of their mean (a tilt adds little to a girth).
  if (m.plane == GirthPlane::kHorizontal || m.plane == GirthPlane::kThroughPoints)
    sd /= static_cast<double>(m.datum.size());
  if (m.plane == GirthPlane::kPerpendicularToAxis) sd = Sigma(o.uncertainty, set, m.datum[0]);
  const double probe = std::min(sd, 10.0);
  double change = 0;
  for (double sign : {-1.0, 1.0}) {
    const SectionGirth s =
        MeasureSectionGirth(o.section, cloud.points, cloud.normals, point + sign * probe * normal,
                            normal, anchors, members);
    const double d = std::abs(s.girth_mm - girth_mm);
    if (s.points > 0 && d < 0.2 * girth_mm) change = std::max(change, d);
  }
  return probe > 0 ? change * sd / probe : 0;
}

bool IsArm(ScanPart part) { return part == ScanPart::kArmRight || part == ScanPart::kArmLeft; }

// The points a girth may hold, from the body structure's parts: a trunk
// girth (horizontal, round the body: side centre or both) keeps the trunk's
// points only, so arms and hands resting on it never join its section
// however close they lie, and all that is left is its section (`one_part`),
// however the scan's holes cut it: the piece at a single datum point (under-
// bust, middle hip) can be a sliver between two holes of a sparse scan
// (a 9 mm middle hip girth at 60k points). An arm's girth (a datum point on
// an arm) keeps that arm's points, and the trunk's as gap points: an upper
// arm resting on the trunk is one skin with it in the scan, and the
// structure's boundary (closer to the hand than the armpit) can give the
// arm's inner side to the trunk. Another girth (a leg's) leaves out the
// arms, and a leg's the other leg: thighs that touch are one section.
// Empty (every point may join) without a structure.
SectionMembers Members(const MeasurementDef& m, const PointCloud& cloud,
                       const std::vector<ScanPart>& parts, const Eigen::MatrixX3d& anchors) {
  SectionMembers out;
  if (parts.size() != static_cast<std::size_t>(cloud.size()) || cloud.size() == 0) return out;
  const bool trunk = IsTrunkGirth(m);
  out.leave_out.resize(parts.size());
  ScanPart other_leg = ScanPart::kNone;
  for (Eigen::Index a = 0; a < anchors.rows() && !trunk; ++a) {
    Eigen::Index nearest = 0;
    (cloud.points.rowwise() - anchors.row(a)).rowwise().squaredNorm().minCoeff(&nearest);
    const ScanPart part = parts[static_cast<std::size_t>(nearest)];
    if (part == ScanPart::kLegRight) other_leg = ScanPart::kLegLeft;
    if (part == ScanPart::kLegLeft) other_leg = ScanPart::kLegRight;
    if (!IsArm(part)) continue;
    out.gap_only.resize(parts.size());
    for (std::size_t i = 0; i < parts.size(); ++i) {
      out.gap_only[i] = parts[i] == ScanPart::kTrunk;
      out.leave_out[i] = parts[i] != part && !out.gap_only[i];
    }
    return out;
  }
  // A right-side limb girth whose datum point lies on the trunk's side of
  // the part boundary (a thigh point at the crotch's level) still never
  // takes in the left leg.
  if (!trunk && other_leg == ScanPart::kNone && m.side == "right") other_leg = ScanPart::kLegLeft;
  for (std::size_t i = 0; i < parts.size(); ++i)
    out.leave_out[i] =
        trunk ? parts[i] != ScanPart::kTrunk : IsArm(parts[i]) || parts[i] == other_leg;
  out.one_part = trunk;
  return out;
}

// Arms "lower" (chest, just under the armpits): the section keeps the points
// between the datum points' x (the armpits), so the tape's sides pass under
// them, and the tape passes over the armpits themselves. Where arm and trunk
// meet, the scan shows one skin over the armpit folds and the structure's
// boundary runs 15-20 mm out along them; moving the plane down until the
// trunk's part is free of the arms would go down to where a heavy body's
// arms stop touching it (68 mm on MakeHuman full seed 1 subject 5, +65 mm of
// girth at the true datum points). A booth sees little of the trunk's sides
// under the arms: where the section has a hole at an armpit, the tape still
// reaches it (MakeHuman default body seed 1027: a 165 mm hole, the section's
// sides 30 mm inside the armpits, 37 mm short at the true datum points);
// where the skin there is scanned, the skin decides (a found armpit lies a
// few mm off it).
void KeepBetweenDatums(const MeasurementDef& m, const LandmarkSet& set, const PointCloud& cloud,
                       const Eigen::MatrixX3d& anchors, SectionMembers* members) {
  const auto [lo, hi] = DatumXRange(m, set);
  members->leave_out.resize(static_cast<std::size_t>(cloud.size()), false);
  for (Eigen::Index i = 0; i < cloud.size(); ++i)
    if (cloud.points(i, 0) > hi || cloud.points(i, 0) < lo)
      members->leave_out[static_cast<std::size_t>(i)] = true;
  members->tape_points = anchors;
}

Measurement Girth(const MeasureOptions& o, const MeasurementDef& m, const PointCloud& cloud,
                  const LandmarkSet& set, const std::vector<ScanPart>& parts,
                  const ScanSampling& scan) {
  Measurement out = Start(m);
  auto [point, normal] = GirthPlane(m, set);
  Eigen::MatrixX3d anchors(static_cast<Eigen::Index>(m.datum.size()), 3);
  for (std::size_t i = 0; i < m.datum.size(); ++i)
    anchors.row(static_cast<Eigen::Index>(i)) = Position(set, m.datum[i]);
  SectionMembers members = Members(m, cloud, parts, anchors);
  if (m.arms == "lower") KeepBetweenDatums(m, set, cloud, anchors, &members);
  members.skin_over_holes = !IsTrunkGirth(m) && m.arms.empty();
  if (!m.narrowest_up_to.empty()) {
    point.z() = NarrowestSectionZ(o.section, cloud.points, cloud.normals, point.z(),
                                  Position(set, m.narrowest_up_to).z(), o.narrowest_step_mm,
                                  o.narrowest_window, anchors, members);
    anchors.col(2).setConstant(point.z());
  }
  const SectionGirth s =
      MeasureSectionGirth(o.section, cloud.points, cloud.normals, point, normal, anchors, members);
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
  out.uncertainty_mm = Uncertainty95(
      o.uncertainty, GirthSd(o, m, cloud, set, point, normal, anchors, members, s.girth_mm),
      scan.noise_mm, scan.spacing_mm, 0);
  return out;
}

// The path a -> b of `paths`: length, bridged part, points; Skip when none.
GeodesicPath PathBetween(const GeodesicPaths& paths, const std::string& a, const std::string& b,
                         const LandmarkSet& set) {
  GeodesicPath out;
  if (a == b) {
    out.points = Position(set, a).transpose();
    return out;
  }
  const GeodesicPath* p = paths.Get(a, b);
  if (p == nullptr) throw Skip{"no geodesic " + a + " -> " + b + " was computed"};
  if (!p->error.empty())
    throw Skip{"no geodesic " + a + " -> " + b + " over the scan: " + p->error};
  out = *p;
  if (a > b) out.points = out.points.colwise().reverse().eval();
  return out;
}

Eigen::MatrixX3d Stack(const std::vector<Eigen::MatrixX3d>& pieces) {
  Eigen::Index rows = 0;
  for (const auto& p : pieces) rows += p.rows();
  Eigen::MatrixX3d out(rows, 3);
  rows = 0;
  for (const auto& p : pieces) out.middleRows(rows, p.rows()) = p, rows += p.rows();
  return out;
}

// Unit direction of a polyline at its start (towards its inside), from
// its first `reach_mm`; zero when too short.
Vec StartDirection(const Eigen::MatrixX3d& path, double reach_mm = 20) {
  for (Eigen::Index i = 1; i < path.rows(); ++i) {
    const Vec d = path.row(i) - path.row(0);
    if (d.norm() >= reach_mm || i + 1 == path.rows())
      return d.norm() > 0 ? Vec(d.normalized()) : Vec::Zero();
  }
  return Vec::Zero();
}

// SD (mm) of a geodesic chain from its datum points: each end moves the
// length by its SD along the path; an inner point by its SD times the turn
// of the path there (|direction in - direction out|).
// A closed chain (a girth over the skin) has no ends: its first point is
// an inner point, counted once.
double ChainSd(const MeasureOptions& o, const MeasurementDef& m, const LandmarkSet& set,
               const std::vector<Eigen::MatrixX3d>& pieces) {
  const bool closed = IsClosedChain(m);
  const std::size_t n = m.datum.size() - (closed ? 1 : 0);
  double var = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double sigma = Sigma(o.uncertainty, set, m.datum[i]);
    double weight = 1;
    const bool inner = closed || (i > 0 && i + 1 < m.datum.size());
    if (inner && i < pieces.size()) {
      const std::size_t before = i > 0 ? i - 1 : pieces.size() - 1;
      const Vec out = StartDirection(pieces[i]);
      const Vec in = -StartDirection(pieces[before].colwise().reverse());
      weight = (out - in).norm();
    }
    var += weight * weight * sigma * sigma;
  }
  return std::sqrt(var);
}

Measurement Length(const MeasureOptions& o, const MeasurementDef& m, const LandmarkSet& set,
                   const GeodesicPaths& paths, const PointIndex* index, const ScanSampling& scan) {
  Measurement out = Start(m);
  double sd = 0;
  const Vec a = Position(set, m.datum[0]);
  if (m.method == MeasurementMethod::kBreadth) {
    const Vec b = Position(set, m.datum[1]);
    out.value_mm = (a - b).head<2>().norm();
    out.geometry = (Eigen::MatrixX3d(2, 3) << a.transpose(), b.transpose()).finished();
    sd = std::hypot(Sigma(o.uncertainty, set, m.datum[0]), Sigma(o.uncertainty, set, m.datum[1]));
  } else if (m.method == MeasurementMethod::kPointToLine) {
    const Vec b = Position(set, m.datum[1]), c = Position(set, m.datum[2]);
    if (!((c - b).norm() > 0)) throw Skip{"the line's two points coincide"};
    const Vec d = (c - b).normalized();
    const Vec foot = b + (a - b).dot(d) * d;
    out.value_mm = (a - foot).norm();
    out.geometry = (Eigen::MatrixX3d(2, 3) << a.transpose(), foot.transpose()).finished();
    sd = std::sqrt(
        Sigma(o.uncertainty, set, m.datum[0]) * Sigma(o.uncertainty, set, m.datum[0]) +
        0.5 * (Sigma(o.uncertainty, set, m.datum[1]) * Sigma(o.uncertainty, set, m.datum[1]) +
               Sigma(o.uncertainty, set, m.datum[2]) * Sigma(o.uncertainty, set, m.datum[2])));
  } else {
    std::vector<Eigen::MatrixX3d> pieces;
    for (std::size_t i = 0; i + 1 < m.datum.size(); ++i) {
      GeodesicPath path = PathBetween(paths, m.datum[i], m.datum[i + 1], set);
      out.value_mm += path.length_mm;
      out.bridged_mm += path.bridged_mm;
      pieces.push_back(std::move(path.points));
    }
    sd = ChainSd(o, m, set, pieces);
    const Vec last = Position(set, m.datum.back());
    if (m.to_floor) {
      sd = std::hypot(sd, Sigma(o.uncertainty, set, m.datum.back()));
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
    if (out.bridged_mm > 0) out.flags.push_back("bridged");
  }
  if (!o.keep_geometry) out.geometry.resize(0, 3);
  out.uncertainty_mm =
      Uncertainty95(o.uncertainty, sd, scan.noise_mm, scan.spacing_mm, out.bridged_mm);
  return out;
}

Measurement Height(const MeasureOptions& o, const MeasurementDef& m, const LandmarkSet& set,
                   const ScanSampling& scan) {
  Measurement out = Start(m);
  const Vec a = Position(set, m.datum[0]);
  out.value_mm = a.z();
  Vec foot(a.x(), a.y(), 0.0);
  double sd = Sigma(o.uncertainty, set, m.datum[0]);
  if (m.datum.size() == 2) {
    out.value_mm -= Position(set, m.datum[1]).z();
    foot.z() = Position(set, m.datum[1]).z();
    sd = std::hypot(sd, Sigma(o.uncertainty, set, m.datum[1]));
  }
  out.uncertainty_mm = Uncertainty95(o.uncertainty, sd, scan.noise_mm, scan.spacing_mm, 0);
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
  uncertainty.Check();
  if (!(datum_tolerance_mm > 0)) throw InputError("measure: datum_tolerance_mm must be > 0");
  if (!(arms_margin_mm >= 0)) throw InputError("measure: arms_margin_mm must be >= 0");
  if (!(narrowest_step_mm > 0) || narrowest_window < 1)
    throw InputError("measure: need narrowest_step_mm > 0, narrowest_window >= 1");
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
  GeodesicPaths paths;
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

  // The geodesic grid, when a length needs one; its point index serves the
  // scan's noise below, so the cloud is indexed once.
  std::unique_ptr<CloudGeodesics> geodesics;
  if (!paths.empty()) {
    StageClock grid_clock("geodesic_grid");
    geodesics = std::make_unique<CloudGeodesics>(options.geodesics, body_cloud.points, progress);
    result.stages.push_back(grid_clock.Stop());
  }
  // The scan's noise and spacings (uncertainty_mm), and the slab they give
  // a sparse scan's girths (SlabForSpacing).
  ScanSampling& scan = result.sampling;
  {
    std::unique_ptr<PointIndex> own;
    if (!geodesics) own = std::make_unique<PointIndex>(body_cloud.points);
    const PointIndex& index = geodesics ? geodesics->grid().index() : *own;
    scan.noise_mm = ScanNoise(index, &scan.spacing_mm, &scan.surface_spacing_mm);
  }
  MeasureOptions girth_options = options;
  girth_options.section = SlabForSpacing(options.section, scan.surface_spacing_mm);
  scan.slab_half_thickness_mm = girth_options.section.half_thickness_mm;
  scan.piece_gap_mm = girth_options.section.piece_gap_mm;
  StageClock girth_clock("girths");
  // The body parts: the detector's, else (datum points from a file) found
  // here; none when separate_arms is off or the structure fails.
  std::vector<ScanPart> parts;
  if (options.separate_arms)
    parts = landmarks.parts.size() == static_cast<std::size_t>(body_cloud.size())
                ? landmarks.parts
                : FindBodyParts(body_cloud);
  std::int64_t girths = 0, n_girths = 0;
  for (const MeasurementDef* m : todo) n_girths += m->method == MeasurementMethod::kSectionHull;
  ProgressBegin(progress, "girths", n_girths);
  for (const MeasurementDef* m : todo) {
    if (m->method != MeasurementMethod::kSectionHull) continue;
    attempt(*m, [&] { return Girth(girth_options, *m, body_cloud, landmarks, parts, scan); });
    ProgressUpdate(progress, ++girths);
  }
  ProgressEnd(progress);
  result.stages.push_back(girth_clock.Stop());

  if (geodesics) {
    StageClock path_clock("geodesics");
    GeodesicPathOptions path_options;
    path_options.tolerance_mm = options.datum_tolerance_mm;
    path_options.max_bridge_mm = options.max_bridge_mm;
    path_options.threads = options.geodesic_threads;
    paths.Solve(path_options, *geodesics, body_cloud.normals, landmarks, progress);
    result.stages.push_back(path_clock.Stop());
  }
  StageClock other_clock("lengths_heights");
  const PointIndex* index = geodesics ? &geodesics->grid().index() : nullptr;
  for (const MeasurementDef* m : todo) {
    if (m->kind == MeasurementKind::kHeight)
      attempt(*m, [&] { return Height(options, *m, landmarks, scan); });
    else if (m->method != MeasurementMethod::kSectionHull)
      attempt(*m, [&] { return Length(options, *m, landmarks, paths, index, scan); });
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
