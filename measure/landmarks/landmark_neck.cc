// Neck and shoulders: back neck point (C7), front neck point (jugulare),
// side neck points, shoulder points (acromion) and the axilla folds.
#include <algorithm>
#include <cmath>
#include <limits>

#include "measure/landmarks/landmark_context.h"
#include "measure/landmarks/profile_extreme.h"
#include "measure/tape/convex_hull_2d.h"
#include "scanners/core/errors.h"

namespace bespoke::landmarks {
namespace {

// Cervicale below the narrowest neck section, as a share of stature.
constexpr double kBackNeckBelowNarrowest = 0.015;

// A flat top (the side neck's corner profile, an axilla fold's pocket): the
// samples within this depth (mm) of the deepest, weighted by how far they
// pass that line (TopCentre, PocketBottom). A frame tilted by 1 deg changes
// depths 30 mm apart by 0.5 mm, so the deepest sample alone jumps between
// the bumps of a rounded corner.
constexpr double kFlatTopMm = 2;

// How far out past the armpit an axilla fold is sought, mm. The front fold
// (the pectoral's edge, running onto the arm) can end a little outside the
// armpit's apex (up to 18 mm on the oracle's bodies). The back fold lies on
// the trunk's side of it (from 1 mm outside to 63 mm inside on both body
// models, A- and T-posed); farther out lies the arm, whose underside a section above a
// raised arm's armpit cuts along its length, leaving a pocket between arm
// and back that is no fold.
constexpr double kFrontFoldPastArmpitMm = 40;
constexpr double kBackFoldPastArmpitMm = 5;

struct Neck {
  double z = 0;  // narrowest section above the shoulders
  double y = 0;  // its centroid's y
};

Neck NarrowestNeck(const Context& c, double from_z) {
  Neck neck;
  double best = kInf;
  for (double z = from_z; z < c.crown_z - 0.08 * c.crown_z; z += c.step) {
    const std::vector<int> rows = c.TrunkRows(c.At(z));
    if (rows.size() < 10) continue;
    const double girth = HullPerimeter(c.points, rows);
    if (girth < best) {
      best = girth;
      neck.z = z;
      double y = 0;
      for (int r : rows) y += c.points(r, 1);
      neck.y = y / static_cast<double>(rows.size());
    }
  }
  if (!std::isfinite(best)) throw InputError("landmarks: no neck found above the shoulders");
  return neck;
}

// The shoulder point of one side; false when the arm was not found.
bool Shoulder(Context* c, int sign, Eigen::Vector3d* out) {
  const ArmInfo& arm = c->arm[sign > 0 ? 0 : 1];
  if (!arm.found) return false;
  const double ax = sign * arm.armpit.x();
  // The shoulder's coronal plane: mean y of the section 40 mm above the armpit near its side.
  double yc = 0;
  int n = 0;
  for (int r : c->At(arm.armpit_z + 40).rows) {
    if (std::abs(sign * c->points(r, 0) - ax) < 30) yc += c->points(r, 1), ++n;
  }
  if (n == 0) return false;
  yc /= n;
  std::vector<int> candidates;
  for (Eigen::Index r = 0; r < c->points.rows(); ++r) {
    const Eigen::Vector3d p = c->P(static_cast<int>(r));
    const double x = sign * p.x();
    if (std::abs(p.y() - yc) > 25 || p.z() < arm.armpit_z + 30 ||
        p.z() > arm.armpit_z + 0.14 * c->crown_z || x < 0.6 * ax) {
      continue;
    }
    // T-pose: the top of the shoulder over the armpit.
    if (arm.t_pose && std::abs(x - ax) >= 6) continue;
    candidates.push_back(static_cast<int>(r));
  }
  // A-pose: the upper-outer corner, the extreme along x + z (the arm falls
  // away steeper than 45 deg); the centre of its cap, as the corner is
  // rounded (Context::CapCentre).
  const Eigen::Vector3d dir =
      arm.t_pose ? Eigen::Vector3d::UnitZ() : Eigen::Vector3d(sign, 0, 1).normalized();
  const int best = c->CapCentre(candidates, dir);
  if (best < 0) return false;
  *out = c->P(best);
  return true;
}

// The depth below a chord of the points `tz` (#N x 2: distance along the
// chord and depth below it, mm), as a profile of `bins` stations every
// bin_mm: the median per bin (empty bins are gaps), then the mean over
// three bins of those not in a gap where at least two are not (NaN
// elsewhere).
std::vector<double> DepthProfile(const std::vector<Eigen::Vector2d>& tz, size_t bins,
                                 double bin_mm) {
  std::vector<std::vector<double>> depths(bins);
  for (const Eigen::Vector2d& q : tz)
    if (q.x() >= 0 && q.x() / bin_mm < static_cast<double>(bins))
      depths[static_cast<size_t>(q.x() / bin_mm)].push_back(q.y());
  std::vector<double> median(bins, kNaN);
  for (size_t k = 0; k < bins; ++k) {
    std::vector<double>& d = depths[k];
    if (d.empty()) continue;
    std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
    median[k] = d[d.size() / 2];
  }
  return WindowMean(median, 1, 2);
}

// Side neck point: in the coronal band through the neck, the contour point
// farthest below the chord from the neck's side (3 % of stature above the
// back neck point's height) to the shoulder point. The corner is rounded, so
// its depth below the chord is flat over a few centimetres and single noisy
// points would pick any of them: the depth is taken as the median per 3 mm
// of chord, smoothed over three bins (DepthProfile), and the corner is the
// centre of that profile's top (TopCentre, profile_extreme.h): the deepest
// bin alone jumps between the bumps of the flat top.
bool SideNeck(const Context& c, int sign, const Neck& neck, double top_z,
              const Eigen::Vector3d& acromion, Eigen::Vector3d* out) {
  double top_x = -kInf;
  for (int r : c.At(top_z).rows) {
    if (std::abs(c.points(r, 1) - neck.y) < 10) top_x = std::max(top_x, sign * c.points(r, 0));
  }
  if (!std::isfinite(top_x)) return false;
  const Eigen::Vector2d p1(top_x, top_z), p2(sign * acromion.x(), acromion.z());
  const Eigen::Vector2d along = (p2 - p1).normalized();
  Eigen::Vector2d down(-along.y(), along.x());
  if (down.y() > 0) down = -down;
  // Only the inner 40 % of the way out to the shoulder point: the base of
  // the neck, not a dip where the shoulder line meets the arm.
  const double reach = top_x + 0.4 * (p2.x() - top_x);
  std::vector<Eigen::Vector2d> tz;
  for (Eigen::Index r = 0; r < c.points.rows(); ++r) {
    const Eigen::Vector3d p = c.P(static_cast<int>(r));
    const double x = sign * p.x();
    if (std::abs(p.y() - neck.y) > 8 || x < top_x - 10 || x > reach || p.z() < p2.y() - 5 ||
        p.z() > top_z + 5)
      continue;
    const Eigen::Vector2d q = Eigen::Vector2d(x, p.z()) - p1;
    tz.emplace_back(q.dot(along), q.dot(down));
  }
  constexpr double kBinMm = 3;
  const size_t bins = static_cast<size_t>(std::ceil((p2 - p1).norm() / kBinMm)) + 1;
  const std::vector<double> depth = DepthProfile(tz, bins, kBinMm);
  ProfileExtremeOptions corner;
  corner.minimum = false;
  const size_t best = BestSample(corner, depth, std::vector<bool>(bins, true));
  if (best == bins) return false;
  std::vector<double> at(bins);
  for (size_t k = 0; k < bins; ++k) at[k] = (static_cast<double>(k) + 0.5) * kBinMm;
  const double t = TopCentre(corner, at, depth, kFlatTopMm);
  const size_t k = std::min(bins - 2, static_cast<size_t>(t / kBinMm));
  const double d = std::isfinite(depth[k]) ? depth[k] : depth[best];
  const Eigen::Vector2d xz = p1 + t * along + d * down;
  *out = Eigen::Vector3d(sign * xz.x(), neck.y, xz.y());
  return true;
}

// T-pose side neck point: raised arms leave no corner between the neck and
// the shoulder (the coronal contour flares steadily from the neck down to
// the arm's flat top, and the corner below the chord lands 25-45 mm low on
// that top). The point is where the plane through the front and back neck
// points, level from side to side, meets the side of the neck in its
// coronal band: height `z`, the band's innermost points there. False when
// the band holds none.
bool TPoseSideNeck(const Context& c, int sign, const Neck& neck, double z, Eigen::Vector3d* out) {
  std::vector<double> xs;
  for (int r : c.At(z).rows) {
    const double x = sign * c.points(r, 0);
    if (std::abs(c.points(r, 1) - neck.y) < 8 && std::abs(c.points(r, 2) - z) < 3 && x > 10)
      xs.push_back(x);
  }
  if (xs.empty()) return false;
  const double inner = *std::min_element(xs.begin(), xs.end());
  double sum = 0;
  int n = 0;
  for (double x : xs)
    if (x < inner + 5) sum += x, ++n;
  *out = Eigen::Vector3d(sign * sum / n, neck.y, z);
  return true;
}

// The pocket's bottom: of `points` (with their `depths` inside the hull),
// the one nearest the centre of those within kFlatTopMm of the deepest,
// each weighted by how far it passes that line (as TopCentre does for a
// profile: the deepest single point of a flat-bottomed pocket is noise).
Eigen::Vector3d PocketBottom(const std::vector<Eigen::Vector3d>& points,
                             const std::vector<double>& depths) {
  const double line = *std::max_element(depths.begin(), depths.end()) - kFlatTopMm;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double weight = 0;
  for (size_t i = 0; i < points.size(); ++i)
    if (depths[i] > line) centre += (depths[i] - line) * points[i], weight += depths[i] - line;
  centre /= weight;
  size_t nearest = 0;
  double nearest_d2 = kInf;
  for (size_t i = 0; i < points.size(); ++i) {
    const double d2 = (points[i] - centre).squaredNorm();
    if (depths[i] > line && d2 < nearest_d2) nearest = i, nearest_d2 = d2;
  }
  return points[nearest];
}

// Axilla fold: in the section a quarter of the way from the armpit up to
// the shoulder point, the bottom of the pocket inside the section's convex
// hull near the armpit (PocketBottom), in front of it (front) or behind it
// (back).
void AxillaFolds(Context* c, int sign, const Eigen::Vector3d& acromion) {
  const ArmInfo& arm = c->arm[sign > 0 ? 0 : 1];
  const double z = arm.armpit_z + 0.25 * (acromion.z() - arm.armpit_z);
  // The section with the arm: the folds are pockets between arm and trunk.
  std::vector<int> rows = c->TrunkRows(c->At(z));
  const Part arm_part = sign > 0 ? Part::kArmRight : Part::kArmLeft;
  for (int r : c->At(z).rows)
    if (c->structure.ok && c->PartOf(r) == arm_part) rows.push_back(r);
  Eigen::MatrixX2d xy(static_cast<Eigen::Index>(rows.size()), 2);
  for (size_t i = 0; i < rows.size(); ++i)
    xy.row(static_cast<Eigen::Index>(i)) = c->points.row(rows[i]).head<2>();
  const std::vector<int> hull = ConvexHullIndices(xy);
  if (hull.size() < 3) return;
  const double ax = sign * arm.armpit.x();
  for (bool front : {true, false}) {
    std::vector<Eigen::Vector3d> points;
    std::vector<double> depths;
    for (size_t i = 0; i < rows.size(); ++i) {
      const Eigen::Vector3d p = c->P(rows[i]);
      const double x = sign * p.x();
      if (x < ax - 70 || x > ax + (front ? kFrontFoldPastArmpitMm : kBackFoldPastArmpitMm) ||
          (front ? p.y() <= arm.armpit.y() : p.y() >= arm.armpit.y()))
        continue;
      points.push_back(p);
      depths.push_back(DepthInsideHull(xy, hull, p.head<2>()));
    }
    const std::string name = std::string(front ? "axilla_front" : "axilla_back") + Side(sign);
    if (points.empty())
      c->Missing(name, "no armpit fold in the section above the armpit");
    else
      c->Put(name, PocketBottom(points, depths), arm.touching ? 0.3 : 0.7, "hull_pocket_bottom");
  }
}

}  // namespace

void FindNeckAndShoulders(Context* c) {
  double armpit_z = 0;
  for (const ArmInfo& arm : c->arm) armpit_z = std::max(armpit_z, arm.found ? arm.armpit_z : 0.0);
  if (armpit_z <= 0) armpit_z = c->crotch_z + 0.56 * (c->crown_z - c->crotch_z);
  const Neck neck = NarrowestNeck(*c, armpit_z + 60);
  // C7 from the back profile's bend is unreliable on scans (the back of the
  // neck curves gradually); its height is taken 1.5 % of stature below the
  // narrowest neck section, which matched the MakeHuman bodies' cervicale
  // (22-26 mm below) better than the bend (docs/landmarks.md).
  const double back_z = neck.z - kBackNeckBelowNarrowest * c->crown_z;
  PutSeam(c, "back_neck", back_z, false, 0.6, "below_narrowest_neck");
  // Jugulare: the most backward front centre-line point between the
  // armpits and the narrowest neck (the notch above the breastbone, where
  // the chest's front turns up into the throat).
  // Its height is the vertex of the profile's parabola round the most
  // backward slice (ProfileExtreme): the slices are 5 mm apart, and the
  // notch's bottom is flat enough for the noise to pick any of them.
  std::vector<double> zs, ys;
  for (double z = armpit_z + 40; z <= neck.z; z += c->step) {
    Eigen::Vector3d p;
    zs.push_back(z);
    ys.push_back(SeamPoint(*c, z, true, &p) ? p.y() : kNaN);
  }
  const size_t best = BestSample(ProfileExtremeOptions{}, ys, std::vector<bool>(ys.size(), true));
  if (best < ys.size())
    PutSeam(c, "front_neck", ProfileExtreme(ProfileExtremeOptions{}, zs, ys, best), true, 0.6,
            "front_profile_notch");
  else
    c->Missing("front_neck", "no front centre-line points below the neck");
  for (int sign : {+1, -1}) {
    Eigen::Vector3d acromion;
    if (!Shoulder(c, sign, &acromion)) {
      c->Missing("shoulder" + Side(sign), "the arm or the shoulder's top was not found");
      continue;
    }
    const ArmInfo& arm = c->arm[sign > 0 ? 0 : 1];
    c->Put("shoulder" + Side(sign), acromion, arm.touching ? 0.4 : 0.75,
           arm.t_pose ? "shoulder_top_over_armpit" : "shoulder_upper_outer_corner");
    Eigen::Vector3d side;
    // The neck's coronal plane: 40 % of the way from the back neck point
    // to the front neck point (the cervical spine lies behind the middle).
    Neck plane = neck;
    if (c->Has("back_neck") && c->Has("front_neck")) {
      plane.y =
          c->Pos("back_neck").y() + 0.4 * (c->Pos("front_neck").y() - c->Pos("back_neck").y());
    }
    const bool ring = arm.t_pose && c->Has("back_neck") && c->Has("front_neck");
    const double ring_z =
        ring ? c->Pos("back_neck").z() + 0.4 * (c->Pos("front_neck").z() - c->Pos("back_neck").z())
             : 0;
    if (ring && TPoseSideNeck(*c, sign, plane, ring_z, &side)) {
      c->Put("side_neck" + Side(sign), side, 0.5, "t_pose_level_neck_ring");
    } else if (SideNeck(*c, sign, plane, back_z + 0.03 * c->crown_z, acromion, &side)) {
      c->Put("side_neck" + Side(sign), side, 0.7, "coronal_neck_shoulder_corner");
    } else {
      c->Missing("side_neck" + Side(sign), "no neck side in the coronal band");
    }
    AxillaFolds(c, sign, acromion);
  }
}

}  // namespace bespoke::landmarks
