#include "oracle/truth/defined_landmarks.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>

#include "oracle/truth/mesh_section.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

const Eigen::Vector3d kUp = Eigen::Vector3d::UnitZ();
// The smallest narrowing above a calf's level that makes it a bulge, mm of
// girth (the detector's rule, measure/landmarks/landmark_legs.cc).
constexpr double kCalfDipMm = 3;

double LoopArea(const SectionLoop& loop) {
  double a = 0;
  const Eigen::Index n = loop.points.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index j = (i + 1) % n;
    a += loop.points(i, 0) * loop.points(j, 1) - loop.points(j, 0) * loop.points(i, 1);
  }
  return std::abs(0.5 * a);
}

// The trunk's section at height z: the closed loop of largest area with the
// loops a tape round it also passes over (TrunkLoopIndices: a heavy breast
// the plane cuts apart from the chest wall), main loop first.
std::vector<SectionLoop> TrunkSection(const TriangleMesh& mesh, double z) {
  const std::vector<SectionLoop> loops = SectionLoops(mesh, Eigen::Vector3d(0, 0, z), kUp);
  int best = -1;
  double best_area = 0;
  for (int i = 0; i < static_cast<int>(loops.size()); ++i) {
    const SectionLoop& l = loops[static_cast<std::size_t>(i)];
    const double a = l.closed ? LoopArea(l) : 0;
    if (a > best_area) best = i, best_area = a;
  }
  if (best < 0) throw InputError("defined landmarks: no trunk section at z = " + std::to_string(z));
  std::vector<SectionLoop> out;
  for (int i : TrunkLoopIndices(loops, best)) out.push_back(loops[static_cast<std::size_t>(i)]);
  return out;
}

// The section's crossings with the plane x = x0, as points; front =
// largest y.
std::vector<Eigen::Vector3d> CrossingsAtX(const std::vector<SectionLoop>& section, double x0) {
  std::vector<Eigen::Vector3d> out;
  for (const SectionLoop& loop : section) {
    const Eigen::Index n = loop.points.rows();
    for (Eigen::Index i = 0; i < n; ++i) {
      const Eigen::Vector3d a = loop.points.row(i), b = loop.points.row((i + 1) % n);
      if ((a.x() - x0) * (b.x() - x0) > 0 || a.x() == b.x()) continue;
      const double t = (x0 - a.x()) / (b.x() - a.x());
      out.push_back(a + t * (b - a));
    }
  }
  if (out.empty())
    throw InputError("defined landmarks: a trunk section misses x = " + std::to_string(x0));
  return out;
}

Eigen::Vector3d FrontAt(const std::vector<SectionLoop>& section, double x0) {
  const auto c = CrossingsAtX(section, x0);
  return *std::max_element(c.begin(), c.end(),
                           [](const auto& a, const auto& b) { return a.y() < b.y(); });
}

Eigen::Vector3d BackAt(const std::vector<SectionLoop>& section, double x0) {
  const auto c = CrossingsAtX(section, x0);
  return *std::min_element(c.begin(), c.end(),
                           [](const auto& a, const auto& b) { return a.y() < b.y(); });
}

// The section's point farthest along `sign` * axis.
Eigen::Vector3d Extreme(const std::vector<SectionLoop>& section, int axis, double sign) {
  Eigen::Vector3d best = section.front().points.row(0);
  for (const SectionLoop& loop : section)
    for (Eigen::Index i = 0; i < loop.points.rows(); ++i)
      if (sign * loop.points(i, axis) > sign * best(axis)) best = loop.points.row(i);
  return best;
}

double SectionGirth(const std::vector<SectionLoop>& section) {
  std::vector<int> all(section.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return LoopHullPerimeter(MergedLoops(section, all), kUp);
}

// The fold under the breast, the same rule as the detector's
// (measure/landmarks/landmark_under_bust.cc, which reads a scan's front
// through a fitted plane; here the exact section's): the front profile's
// bend (second difference over +-kFoldHalfSpanMm) searched
// kFoldTop-kFoldBottom of stature under the bust point; going down, its
// first local peak that is positive and reaches half the band's sharpest
// bend (a flat chest's pectoral edge is a weak fold, a belly's top lower
// down can bend more). A flat chest has no fold: its level is kNoFoldDrop of
// stature under the bust point. Between the two the level moves
// continuously (FoldWeight) with the fold's strength, the band's largest
// bend averaged over +-kFoldStrengthHalfMm (the detector's three slices):
// under kNoFoldBendMm (a slope change of 0.1, 6 deg) the flat chest's level,
// over kFoldBendMm (0.3, 17 deg) the fold's, in between the point between
// them in proportion. A single threshold would move the level the whole way
// from the fold to the flat chest's for a bend read 0.1 mm flatter on a
// scan.
constexpr double kFoldHalfSpanMm = 10, kFoldTop = 0.01, kFoldBottom = 0.08;
constexpr double kNoFoldBendMm = 1, kFoldBendMm = 3, kNoFoldDrop = 0.04, kFoldStrengthHalfMm = 5;
// A breast's lower part below the fold's level (a step of the truth's own:
// the detector does not take it, docs/landmarks.md step 5): the girth's
// rise per mm of height over the kUndersideRunMm above a level, and the
// chest wall's over 10-20 mm below it; the level is on the breast while the
// first passes the second by more than kUndersideExcess (mm of girth per mm),
// and follows it down at most kUndersideMaxDropMm. On the two bodies of
// DefinedLandmarks.TheUnderBustIsJustBelowTheBreasts the breasts' lower edge
// rises 6-16 mm per mm, and the chest wall's rate (1 and 3) changes by less
// than 1 over the 30 mm below it.
constexpr double kUndersideRunMm = 2, kUndersideExcess = 2, kUndersideMaxDropMm = 40;
// The crotch's U: the part within this height of its lowest point that the
// parabola is fitted to, mm (the detector's).
constexpr double kCrotchBottomMm = 25;

// The fold's weight (0-1) in the under-bust's level for a fold of strength
// strength_mm.
double FoldWeight(double strength_mm) {
  return std::clamp((strength_mm - kNoFoldBendMm) / (kFoldBendMm - kNoFoldBendMm), 0.0, 1.0);
}

// The level from `level_mm` down to just below the breasts: a breast whose
// lower part hangs below the fold's level on the bust points' verticals
// (it hangs inwards, or its underside slopes down to the chest wall) is
// still in that section, where the girth rises many times faster with height
// than along the chest wall (kUndersideExcess). The level moves down in
// 0.5 mm steps while it does.
double BelowTheBreasts(const TriangleMesh& mesh, double level_mm) {
  std::map<long long, double> girths;
  const auto girth = [&](double z) {
    const auto [it, fresh] = girths.try_emplace(std::llround(z * 1000), 0.0);
    if (fresh) it->second = SectionGirth(TrunkSection(mesh, z));
    return it->second;
  };
  for (double drop = 0; drop < kUndersideMaxDropMm; drop += 0.5, level_mm -= 0.5) {
    const double rise = (girth(level_mm) - girth(level_mm - kUndersideRunMm)) / kUndersideRunMm;
    // A belly below that narrows upwards is no chest wall: its rate counts
    // as a vertical wall's (0).
    const double wall = std::max(0.0, (girth(level_mm - 10) - girth(level_mm - 20)) / 10);
    if (rise <= wall + kUndersideExcess) break;
  }
  return level_mm;
}

// The crotch on the mid-sagittal seam's vertices `seam` below `below_mm`:
// the seam there is a U (rising to the pubis in front and the buttocks
// behind) whose bottom is flat over 60-90 mm on many bodies, and its lowest
// vertex flips between a front and a back dip a few mm apart in height. The
// lowest point is the vertex of a least-squares parabola z(y) through the
// U's bottom kCrotchBottomMm, the U sampled every mm of y between its
// vertices (the detector's rule, measure/landmarks/landmark_trunk.cc), at
// the U's height there. The lowest vertex where the bottom holds fewer
// than three samples or does not curve up.
Eigen::Vector3d SeamCrotch(const TriangleMesh& mesh, const std::vector<int>& seam,
                           double below_mm) {
  std::vector<Eigen::Vector2d> u;  // (y, z), sorted by y
  for (const int v : seam)
    if (mesh.vertices(v, 2) < below_mm) u.emplace_back(mesh.vertices(v, 1), mesh.vertices(v, 2));
  if (u.empty()) throw InputError("defined landmarks: no seam vertex below the hip level");
  std::sort(u.begin(), u.end(), [](const auto& a, const auto& b) { return a.x() < b.x(); });
  const auto lowest = std::min_element(u.begin(), u.end(),
                                       [](const auto& a, const auto& b) { return a.y() < b.y(); });
  const auto height = [&u](double y) {  // the U's height at y (linear between vertices)
    const auto hi = std::lower_bound(u.begin(), u.end(), y,
                                     [](const Eigen::Vector2d& p, double v) { return p.x() < v; });
    if (hi == u.begin()) return hi->y();
    if (hi == u.end()) return u.back().y();
    const auto lo = hi - 1;
    return hi->x() == lo->x() ? lo->y()
                              : lo->y() + (y - lo->x()) / (hi->x() - lo->x()) * (hi->y() - lo->y());
  };
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  double y_lo = std::numeric_limits<double>::infinity(), y_hi = -y_lo;
  int n = 0;
  for (double y = std::ceil(u.front().x()); y <= u.back().x(); y += 1) {
    const double z = height(y);
    if (z > lowest->y() + kCrotchBottomMm) continue;
    const Eigen::Vector3d a(1, y, y * y);
    ata += a * a.transpose(), atb += a * z, ++n;
    y_lo = std::min(y_lo, y), y_hi = std::max(y_hi, y);
  }
  const Eigen::Vector3d k = ata.ldlt().solve(atb);
  if (n < 3 || !(k(2) > 1e-5)) return {0, lowest->x(), lowest->y()};
  const double y = std::clamp(-k(1) / (2 * k(2)), y_lo, y_hi);
  return {0, y, height(y)};
}

// The z in [lo, hi] maximising score(z): a scan in `step` steps, then one
// refinement to step / 8 around the best.
double ArgMax(double lo, double hi, double step, const std::function<double(double)>& score) {
  if (!(hi > lo)) throw InputError("defined landmarks: an empty search band");
  double best = lo, best_score = -std::numeric_limits<double>::infinity();
  const auto visit = [&](double z) {
    const double s = score(z);
    if (s > best_score) best_score = s, best = z;
  };
  for (double z = lo; z <= hi; z += step) visit(z);
  const double centre = best;
  for (double z = std::max(lo, centre - step); z <= std::min(hi, centre + step); z += step / 8)
    visit(z);
  return best;
}

// Going down from hi, the first local maximum of `bend` in [lo, hi] (sampled
// in `step` steps, one step beyond each end for its neighbours) that is at
// least half the band's largest; refined to step / 8 around it. Its level
// (NaN when the band's largest is not positive), the band's largest and the
// fold's strength.
struct Corner {
  double level_mm = std::numeric_limits<double>::quiet_NaN();
  double sharpest_mm = 0;
  double strength_mm = 0;  // the largest of bend averaged at z and z +- kFoldStrengthHalfMm
};
Corner FirstCorner(double lo, double hi, double step, const std::function<double(double)>& bend) {
  std::vector<double> at, value;
  for (double z = lo - step; z <= hi + step; z += step) at.push_back(z), value.push_back(bend(z));
  Corner corner;
  for (std::size_t k = 1; k + 1 < at.size(); ++k) {
    corner.sharpest_mm = std::max(corner.sharpest_mm, value[k]);
    const double h = kFoldStrengthHalfMm;
    corner.strength_mm =
        std::max(corner.strength_mm, (bend(at[k] - h) + value[k] + bend(at[k] + h)) / 3);
  }
  for (std::size_t k = at.size() - 2; k >= 1 && corner.sharpest_mm > 0; --k) {
    if (value[k] >= 0.5 * corner.sharpest_mm && value[k] >= value[k - 1] &&
        value[k] >= value[k + 1]) {
      corner.level_mm =
          ArgMax(std::max(lo, at[k] - step), std::min(hi, at[k] + step), step / 8, bend);
      break;
    }
  }
  return corner;
}

// The calf's level in [lo, hi]: like ArgMax, but only among the levels
// with a girth at least dip_mm smaller somewhere above them in the band (a
// bulge, not the widening below the knee); ArgMax when there is none.
double BulgeArgMax(double lo, double hi, double step, double dip_mm,
                   const std::function<double(double)>& girth) {
  std::vector<double> at, value;
  for (double z = lo; z <= hi; z += step) at.push_back(z), value.push_back(girth(z));
  double above = std::numeric_limits<double>::infinity(), best_value = -above;
  int best = -1;
  for (int k = static_cast<int>(at.size()) - 1; k >= 0; --k) {
    const double g = value[static_cast<std::size_t>(k)];
    if (g > above + dip_mm && g > best_value) best = k, best_value = g;
    if (g > 0) above = std::min(above, g);
  }
  if (best < 0) return ArgMax(lo, hi, step, girth);
  const double centre = at[static_cast<std::size_t>(best)];
  return ArgMax(std::max(lo, centre - step), std::min(hi, centre + step), step / 8, girth);
}

void Place(Body* body, const std::string& name, const Eigen::Vector3d& position) {
  body->landmarks[name] = ClosestSurfacePoint(body->mesh, position);
}

Eigen::Vector3d At(const Body& body, const std::string& name) {
  const auto it = body.landmarks.find(name);
  if (it == body.landmarks.end())
    throw InputError("defined landmarks: the body has no datum point '" + name + "'");
  return PositionOf(body.mesh, it->second);
}

// The leg loop at z nearest the given point (the calf of that side).
double LegGirth(const TriangleMesh& mesh, double z, const Eigen::Vector3d& near,
                Eigen::Vector3d* back) {
  const std::vector<SectionLoop> loops = SectionLoops(mesh, Eigen::Vector3d(0, 0, z), kUp);
  const int i = NearestLoop(loops, Eigen::Vector3d(near.x(), near.y(), z));
  if (i < 0) return -1;
  const SectionLoop& loop = loops[static_cast<std::size_t>(i)];
  if (back) *back = Extreme({loop}, 1, -1);
  return LoopHullPerimeter(loop, kUp);
}

// The upper-arm point of `side` ("right" / "left"): in the plane through the
// midpoint of the shoulder point and the elbow, perpendicular to that axis,
// the arm's loop (enclosing the midpoint, else the nearest) and its point
// farthest outwards (lateral, across the axis).
Eigen::Vector3d UpperArmPoint(const Body& body, const std::string& side) {
  const Eigen::Vector3d shoulder = At(body, "shoulder_" + side), elbow = At(body, "elbow_" + side);
  const Eigen::Vector3d axis = (elbow - shoulder).normalized(), mid = 0.5 * (shoulder + elbow);
  const Eigen::Vector3d lateral(side == "right" ? 1 : -1, 0, 0);
  const Eigen::Vector3d outward = (lateral - lateral.dot(axis) * axis).normalized();
  const std::vector<SectionLoop> loops = SectionLoops(body.mesh, mid, axis);
  int arm = EnclosingLoop(loops, mid, axis);
  if (arm < 0) arm = NearestLoop(loops, mid);
  if (arm < 0) throw InputError("defined landmarks: no section of the " + side + " upper arm");
  const Eigen::MatrixX3d& p = loops[static_cast<std::size_t>(arm)].points;
  Eigen::Index best = 0;
  ((p.rowwise() - mid.transpose()) * outward).maxCoeff(&best);
  return p.row(best).transpose();
}

}  // namespace

void DefinedLandmarkOptions::Check() const {
  if (!(step_mm >= 0.5 && step_mm <= 20))
    throw InputError("defined landmarks: step_mm must be in [0.5, 20]");
}

DefinedLevels PlaceDefinedLandmarks(const DefinedLandmarkOptions& options,
                                    const std::vector<int>& seam, Body* body) {
  options.Check();
  const TriangleMesh& mesh = body->mesh;
  const double step = options.step_mm;
  DefinedLevels levels;
  // Under-bust: the fold under the bust points (FirstCorner), the section's
  // front taken over every loop a tape passes (a heavy breast's loop
  // included), so a hanging breast gives its underside.
  const Eigen::Vector3d bust_r = At(*body, "bust_right"), bust_l = At(*body, "bust_left");
  const double bust_z = 0.5 * (bust_r.z() + bust_l.z());
  // Each level's depth once (keyed to the micrometre): the bends at the
  // step grid, their +-10 mm stations and the strength's +-5 mm neighbours
  // land on the same levels many times.
  std::map<long long, double> depths;
  const auto depth = [&](double z) {
    const auto [it, fresh] = depths.try_emplace(std::llround(z * 1000), 0.0);
    if (!fresh) return it->second;
    const std::vector<SectionLoop> section = TrunkSection(mesh, z);
    // In the bust points' sagittal planes, kept within the main loop's width.
    const Eigen::MatrixX3d& main = section.front().points;
    const double lo = 0.8 * main.col(0).minCoeff(), hi = 0.8 * main.col(0).maxCoeff();
    it->second = 0.5 * (FrontAt(section, std::clamp(bust_r.x(), lo, hi)).y() +
                        FrontAt(section, std::clamp(bust_l.x(), lo, hi)).y());
    return it->second;
  };
  const double stature = mesh.vertices.col(2).maxCoeff(), h = kFoldHalfSpanMm;
  const Corner fold =
      FirstCorner(bust_z - kFoldBottom * stature, bust_z - kFoldTop * stature, step,
                  [&](double z) { return depth(z + h) + depth(z - h) - 2 * depth(z); });
  const double flat = bust_z - kNoFoldDrop * stature;
  levels.under_bust_mm = std::isfinite(fold.level_mm)
                             ? flat + FoldWeight(fold.strength_mm) * (fold.level_mm - flat)
                             : flat;
  // A hanging breast: the bend lies within `h` of its underside and its tip
  // can still be in the section; the tape goes just below it.
  for (int k = 0; k < 120 && TrunkSection(mesh, levels.under_bust_mm).size() > 1; ++k)
    levels.under_bust_mm -= 0.5;
  levels.under_bust_mm = BelowTheBreasts(mesh, levels.under_bust_mm);
  Place(body, "under_bust", FrontAt(TrunkSection(mesh, levels.under_bust_mm), 0));
  const double crotch = At(*body, "crotch").z(), under_bust = levels.under_bust_mm;
  // Hip: the section reaching furthest back, from just above the crotch to
  // the middle of the crotch-to-under-bust span.
  levels.hip_mm = ArgMax(crotch + 20, crotch + 0.5 * (under_bust - crotch), step,
                         [&](double z) { return -Extreme(TrunkSection(mesh, z), 1, -1).y(); });
  const std::vector<SectionLoop> hip = TrunkSection(mesh, levels.hip_mm);
  Place(body, "hip_back", BackAt(hip, 0));
  Place(body, "hip_right", Extreme(hip, 0, 1));
  Place(body, "hip_left", Extreme(hip, 0, -1));
  // Waist: the narrowest trunk section between the iliac crest and the
  // lowest rib, placed at 30 % and 85 % of the hip-to-under-bust height.
  const double span = under_bust - levels.hip_mm;
  levels.waist_mm = ArgMax(levels.hip_mm + 0.3 * span, levels.hip_mm + 0.85 * span, step,
                           [&](double z) { return -SectionGirth(TrunkSection(mesh, z)); });
  const std::vector<SectionLoop> waist = TrunkSection(mesh, levels.waist_mm);
  Place(body, "front_waist", FrontAt(waist, 0));
  Place(body, "back_waist", BackAt(waist, 0));
  Place(body, "side_waist_right", Extreme(waist, 0, 1));
  Place(body, "side_waist_left", Extreme(waist, 0, -1));
  levels.middle_hip_mm = 0.5 * (levels.hip_mm + levels.waist_mm);
  Place(body, "middle_hip_front", FrontAt(TrunkSection(mesh, levels.middle_hip_mm), 0));
  if (!seam.empty()) Place(body, "crotch", SeamCrotch(mesh, seam, levels.hip_mm));
  for (const char* side : {"right", "left"})
    Place(body, std::string("upper_arm_") + side, UpperArmPoint(*body, side));
  // Calves: the largest leg girth between ankle and knee that lies below a
  // narrower section (the calf's bulge; BulgeArgMax).
  for (const char* side : {"right", "left"}) {
    const std::string s = side;
    const Eigen::Vector3d knee = At(*body, "knee_" + s), ankle = At(*body, "ankle_inside_" + s);
    const Eigen::Vector3d near = At(*body, "calf_" + s);
    const double z = BulgeArgMax(ankle.z() + 0.25 * (knee.z() - ankle.z()),
                                 ankle.z() + 0.9 * (knee.z() - ankle.z()), step, kCalfDipMm,
                                 [&](double zz) { return LegGirth(mesh, zz, near, nullptr); });
    Eigen::Vector3d back;
    LegGirth(mesh, z, near, &back);
    Place(body, "calf_" + s, back);
    (s == "right" ? levels.calf_right_mm : levels.calf_left_mm) = z;
  }
  return levels;
}

}  // namespace bespoke
