#include "oracle/truth/reference_measurements.h"

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "measure/tape/convex_hull_2d.h"
#include "oracle/truth/cropped_geodesics.h"
#include "oracle/truth/mesh_section.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Vec = Eigen::Vector3d;

Vec Landmark(const Body& body, const std::string& name) {
  const auto it = body.landmarks.find(name);
  if (it == body.landmarks.end()) throw InputError("the body has no landmark '" + name + "'");
  return PositionOf(body.mesh, it->second);
}

// The first landmark `m` is measured from that the body lacks, or "".
std::string MissingLandmark(const MeasurementDef& m, const Body& body) {
  for (const std::string& name : ReferencedLandmarks(m))
    if (body.landmarks.find(name) == body.landmarks.end()) return name;
  return "";
}

// The hull polygon of a loop (3-D points on the plane), in hull order.
Eigen::MatrixX3d HullPolygon(const SectionLoop& loop, const Vec& normal) {
  const Vec helper = std::abs(normal.x()) < 0.9 ? Vec::UnitX() : Vec::UnitY();
  const Vec u = normal.cross(helper).normalized(), v = normal.cross(u);
  Eigen::MatrixX2d xy(loop.points.rows(), 2);
  xy.col(0) = loop.points * u;
  xy.col(1) = loop.points * v;
  const std::vector<int> hull = ConvexHullIndices(xy);
  Eigen::MatrixX3d polygon(static_cast<Eigen::Index>(hull.size()), 3);
  for (std::size_t i = 0; i < hull.size(); ++i)
    polygon.row(static_cast<Eigen::Index>(i)) = loop.points.row(hull[i]);
  return polygon;
}

// Index of the loop with the longest hull perimeter, or -1 when none.
int LargestLoop(const std::vector<SectionLoop>& loops, const Vec& normal) {
  int largest = -1;
  double best = 0;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const double perimeter = LoopHullPerimeter(loops[i], normal);
    if (perimeter > best) best = perimeter, largest = static_cast<int>(i);
  }
  return largest;
}

// The loop of the body part measured: with one datum point the loop through
// it; with several (a trunk girth) the loop enclosing their centroid. When
// no loop encloses it, a trunk girth takes the largest loop: breasts that
// hang clear of the chest wall are cut as loops of their own, with the bust
// points' centroid in the air between them, and the nearest loop would be
// one breast. Otherwise the loop nearest the first datum point.
int ChooseLoop(const std::vector<SectionLoop>& loops, const MeasurementDef& m, const Body& body,
               const Vec& normal, const Vec& datum) {
  int chosen = -1;
  if (m.datum.size() > 1) {
    Vec centroid = Vec::Zero();
    for (const std::string& name : m.datum) centroid += Landmark(body, name);
    chosen = EnclosingLoop(loops, centroid / static_cast<double>(m.datum.size()), normal);
    if (chosen < 0 && IsTrunkGirth(m)) chosen = LargestLoop(loops, normal);
  }
  return chosen >= 0 ? chosen : NearestLoop(loops, datum);
}

// True when the loop reaches more than 30 mm beyond the datum points' x
// range: an arm or hand has merged into the trunk's section.
bool ReachesPastDatum(const SectionLoop& loop, const MeasurementDef& m, const Body& body) {
  double lo = 0, hi = 0;
  for (const std::string& name : m.datum) {
    const double x = Landmark(body, name).x();
    lo = std::min(lo, x), hi = std::max(hi, x);
  }
  return loop.points.col(0).maxCoeff() > hi + 30 || loop.points.col(0).minCoeff() < lo - 30;
}

// The section of a right-side limb girth on its limb's own faces (those
// whose three vertices are that limb's, Body::limbs): every loop of it
// within 100 mm of `datum` (datum[0], or raised to the plane by
// "narrowest_up_to"), merged. A posed limb that passes into the trunk or the
// other leg makes one loop with it on the whole mesh; its own surface still
// goes round it. False without limb labels, or when the datum point's vertex
// is the trunk's or no loop is near.
bool LimbSection(const Body& body, const Vec& point, const Vec& normal, const Vec& datum,
                 SectionLoop* out) {
  if (body.limbs.size() != static_cast<std::size_t>(body.mesh.num_vertices())) return false;
  Eigen::Index nearest = 0;
  (body.mesh.vertices.rowwise() - datum.transpose()).rowwise().squaredNorm().minCoeff(&nearest);
  const BodyLimb limb = body.limbs[static_cast<std::size_t>(nearest)];
  if (limb == BodyLimb::kTrunk) return false;
  TriangleMesh own;
  own.vertices = body.mesh.vertices;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index f = 0; f < body.mesh.num_faces(); ++f) {
    bool all = true;
    for (int k = 0; k < 3; ++k)
      all = all && body.limbs[static_cast<std::size_t>(body.mesh.faces(f, k))] == limb;
    if (all) kept.push_back(f);
  }
  own.faces.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i)
    own.faces.row(static_cast<Eigen::Index>(i)) = body.mesh.faces.row(kept[i]);
  const std::vector<SectionLoop> loops = SectionLoops(own, point, normal);
  std::vector<int> near;
  for (std::size_t i = 0; i < loops.size(); ++i)
    if (DistanceToLoop(loops[i], datum) < 100) near.push_back(static_cast<int>(i));
  if (near.empty()) return false;
  *out = MergedLoops(loops, near);
  return true;
}

// The loop a girth measures in the plane (point, normal), with `datum` the
// point it passes by (datum[0], raised to the plane by "narrowest_up_to").
struct GirthLoop {
  SectionLoop loop;
  double datum_distance = 0;
  bool limb_only = false;
};

GirthLoop LoopOf(const MeasurementDef& m, const Body& body, Vec point, const Vec& normal,
                 const Vec& datum) {
  std::vector<SectionLoop> loops = SectionLoops(body.mesh, point, normal);
  if (loops.empty()) throw InternalError("reference " + m.name + ": the plane misses the body");
  int chosen = ChooseLoop(loops, m, body, normal, datum);
  // "lower": step down until the trunk's section is free of the arms.
  for (int step = 0; m.arms == "lower" && step < 100 &&
                     ReachesPastDatum(loops[static_cast<std::size_t>(chosen)], m, body);
       ++step) {
    point.z() -= 1;
    loops = SectionLoops(body.mesh, point, normal);
    chosen = ChooseLoop(loops, m, body, normal, datum);
  }
  // Round the trunk the tape also passes over the loops the plane cuts
  // apart in front of or behind it (a heavy breast hanging over the chest).
  const std::vector<int> parts =
      IsTrunkGirth(m) ? TrunkLoopIndices(loops, chosen) : std::vector<int>{chosen};
  GirthLoop out;
  out.loop = MergedLoops(loops, parts);
  out.datum_distance = std::numeric_limits<double>::infinity();
  for (int i : parts)
    out.datum_distance =
        std::min(out.datum_distance, DistanceToLoop(loops[static_cast<std::size_t>(i)], datum));
  if (m.side == "right" && out.loop.points.col(0).minCoeff() <= 0 &&
      LimbSection(body, point, normal, datum, &out.loop)) {
    out.limb_only = true;
    out.datum_distance =
        (out.loop.points.rowwise() - datum.transpose()).rowwise().norm().minCoeff();
  }
  return out;
}

// "narrowest_up_to": the height of the smallest section from datum[0]'s
// height up to that landmark's, every 1 mm on the exact mesh, then refined
// to 0.01 mm within the millimetre either side (a ternary search).
double NarrowestZ(const MeasurementDef& m, const Body& body, const Vec& normal) {
  const Vec datum = Landmark(body, m.datum[0]);
  const double top = Landmark(body, m.narrowest_up_to).z();
  auto girth = [&](double z) {
    const Vec at(datum.x(), datum.y(), z);
    return LoopHullPerimeter(LoopOf(m, body, at, normal, at).loop, normal);
  };
  double best = std::numeric_limits<double>::infinity(), best_z = datum.z();
  for (double z = datum.z(); z <= top; z += 1) {
    const double g = girth(z);
    if (g < best) best = g, best_z = z;
  }
  double lo = std::max(datum.z(), best_z - 1), hi = std::min(top, best_z + 1);
  while (hi - lo > 0.01) {
    const double a = lo + (hi - lo) / 3, b = hi - (hi - lo) / 3;
    if (girth(a) < girth(b))
      hi = b;
    else
      lo = a;
  }
  const double refined = 0.5 * (lo + hi);
  return girth(refined) < best ? refined : best_z;
}

ReferenceMeasurement Girth(const ReferenceOptions& options, const MeasurementDef& m,
                           const Body& body) {
  ReferenceMeasurement out{m.name, m.kind, 0, {}, {}};
  auto [point, normal] = GirthPlaneOf(m, body);
  Vec datum = Landmark(body, m.datum[0]);
  if (!m.narrowest_up_to.empty()) point.z() = datum.z() = NarrowestZ(m, body, normal);
  const GirthLoop g = LoopOf(m, body, point, normal, datum);
  if (g.limb_only) out.flags.push_back("section_limb_only");
  out.value_mm = LoopHullPerimeter(g.loop, normal);
  if (!g.loop.closed) out.flags.push_back("section_open");
  if (g.datum_distance > options.datum_tolerance_mm) out.flags.push_back("datum_off_section");
  if (!m.arms.empty() && ReachesPastDatum(g.loop, m, body))
    out.flags.push_back("section_includes_arms");
  if (m.side == "right" && g.loop.points.col(0).minCoeff() <= 0)
    out.flags.push_back("section_crosses_midline");
  if (options.keep_geometry) out.geometry = HullPolygon(g.loop, normal);
  return out;
}

// Exact geodesic lengths between landmark pairs, each on a crop of the mesh
// that provably holds its shortest path (cropped_geodesics.h): the same
// values as one CGAL propagation per source over the whole mesh, several
// times faster on a body (docs/oracle.md has the timings).
class GeodesicCache {
 public:
  GeodesicCache(const Body& body, bool keep_paths, Progress* progress)
      : body_(body), keep_paths_(keep_paths), progress_(progress) {}

  void Need(const std::string& a, const std::string& b) {
    if (a != b) pending_.insert(std::minmax(a, b));
  }

  void Solve() {
    if (pending_.empty()) return;
    CroppedExactGeodesics geodesics(body_.mesh);
    ProgressBegin(progress_, "exact geodesics", static_cast<std::int64_t>(pending_.size()));
    std::int64_t done = 0;
    for (const auto& pair : pending_) {  // stored from pair.first to pair.second
      solved_[pair] = geodesics.Path(body_.landmarks.at(pair.first),
                                     body_.landmarks.at(pair.second), keep_paths_);
      ProgressUpdate(progress_, ++done);
    }
    pending_.clear();
    ProgressEnd(progress_);
  }

  // The path from `a` to `b` (solved before).
  GeodesicPath Get(const std::string& a, const std::string& b) const {
    GeodesicPath p;
    if (a == b) {
      p.points = Landmark(body_, a).transpose();
      return p;
    }
    p = solved_.at(std::minmax(a, b));
    if (a > b) p.points = p.points.colwise().reverse().eval();
    return p;
  }

 private:
  const Body& body_;
  bool keep_paths_;
  Progress* progress_;
  std::set<std::pair<std::string, std::string>> pending_;
  std::map<std::pair<std::string, std::string>, GeodesicPath> solved_;
};

ReferenceMeasurement Length(const ReferenceOptions& options, const MeasurementDef& m,
                            const Body& body, const GeodesicCache& geodesics) {
  ReferenceMeasurement out{m.name, m.kind, 0, {}, {}};
  const Vec a = Landmark(body, m.datum[0]);
  if (m.method == MeasurementMethod::kBreadth) {
    const Vec b = Landmark(body, m.datum[1]);
    out.value_mm = (a - b).head<2>().norm();
    if (options.keep_geometry)
      out.geometry = (Eigen::MatrixX3d(2, 3) << a.transpose(), b.transpose()).finished();
  } else if (m.method == MeasurementMethod::kPointToLine) {
    const Vec b = Landmark(body, m.datum[1]), c = Landmark(body, m.datum[2]);
    const Vec d = (c - b).normalized();
    const Vec foot = b + (a - b).dot(d) * d;
    out.value_mm = (a - foot).norm();
    if (options.keep_geometry)
      out.geometry = (Eigen::MatrixX3d(2, 3) << a.transpose(), foot.transpose()).finished();
  } else {  // geodesic chain
    std::vector<Eigen::MatrixX3d> pieces;
    for (std::size_t i = 0; i + 1 < m.datum.size(); ++i) {
      const GeodesicPath p = geodesics.Get(m.datum[i], m.datum[i + 1]);
      out.value_mm += p.length;
      pieces.push_back(p.points);
    }
    const Vec last = Landmark(body, m.datum.back());
    if (m.to_floor) {
      out.value_mm += last.z();
      pieces.push_back(
          (Eigen::MatrixX3d(2, 3) << last.transpose(), last.x(), last.y(), 0.0).finished());
    }
    if (options.keep_geometry) {
      Eigen::Index rows = 0;
      for (const auto& piece : pieces) rows += piece.rows();
      out.geometry.resize(rows, 3);
      rows = 0;
      for (const auto& piece : pieces)
        out.geometry.middleRows(rows, piece.rows()) = piece, rows += piece.rows();
    }
  }
  return out;
}

ReferenceMeasurement Height(const MeasurementDef& m, const Body& body) {
  ReferenceMeasurement out{m.name, m.kind, Landmark(body, m.datum[0]).z(), {}, {}};
  if (m.datum.size() == 2) out.value_mm -= Landmark(body, m.datum[1]).z();
  return out;
}

}  // namespace

void ReferenceOptions::Check() const {
  if (!(datum_tolerance_mm > 0))
    throw InputError("reference measurements: datum_tolerance_mm must be > 0");
}

std::pair<Eigen::Vector3d, Eigen::Vector3d> GirthPlaneOf(const MeasurementDef& m,
                                                         const Body& body) {
  if (m.method != MeasurementMethod::kSectionHull)
    throw InputError("'" + m.name + "' is not a girth measured on a section");
  switch (m.plane) {
    case GirthPlane::kHorizontal: {
      double z = 0;
      for (const std::string& name : m.datum) z += Landmark(body, name).z();
      return {Vec(0, 0, z / static_cast<double>(m.datum.size())), Vec::UnitZ()};
    }
    case GirthPlane::kPerpendicularToAxis: {
      const Vec axis = Landmark(body, m.axis[1]) - Landmark(body, m.axis[0]);
      if (!(axis.norm() > 0)) throw InputError("'" + m.name + "': its axis points coincide");
      return {Landmark(body, m.datum[0]), axis.normalized()};
    }
    case GirthPlane::kThroughPoints: {
      const Vec a = Landmark(body, m.datum[0]), b = Landmark(body, m.datum[1]);
      const Vec c = Landmark(body, m.datum[2]);
      const Vec normal = (b - a).cross(c - a);
      if (!(normal.norm() > 1e-9 * (b - a).squaredNorm()))
        throw InputError("'" + m.name + "': its three datum points are collinear");
      return {a, normal.z() < 0 ? -normal.normalized() : normal.normalized()};
    }
    case GirthPlane::kNone:
      break;
  }
  throw InputError("'" + m.name + "' has no girth plane");
}

ReferenceMeasurements ComputeReferenceMeasurements(const ReferenceOptions& options,
                                                   const Catalogue& catalogue, const Body& body,
                                                   Progress* progress) {
  options.Check();
  ReferenceMeasurements result;
  GeodesicCache geodesics(body, options.keep_geometry, progress);
  std::vector<const MeasurementDef*> todo;
  for (const MeasurementDef& m : catalogue.measurements()) {
    const std::string missing = MissingLandmark(m, body);
    if (!missing.empty()) {
      result.skipped.emplace_back(m.name, "the body has no landmark '" + missing + "'");
      continue;
    }
    todo.push_back(&m);
    if (m.method == MeasurementMethod::kGeodesic)
      for (std::size_t i = 0; i + 1 < m.datum.size(); ++i)
        geodesics.Need(m.datum[i], m.datum[i + 1]);
  }
  geodesics.Solve();
  // As Measure dispatches: a section, a height, else a chain or a straight
  // distance (a girth over the skin is a closed chain).
  for (const MeasurementDef* m : todo) {
    if (m->method == MeasurementMethod::kSectionHull)
      result.measurements.push_back(Girth(options, *m, body));
    else if (m->kind == MeasurementKind::kHeight)
      result.measurements.push_back(Height(*m, body));
    else
      result.measurements.push_back(Length(options, *m, body, geodesics));
  }
  return result;
}

}  // namespace bespoke
