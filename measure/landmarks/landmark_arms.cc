// Arms: wrist (narrowest section before the hand), elbow (the arm's bend)
// and upper-arm points along the arm's principal axis.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>

#include "measure/landmarks/landmark_context.h"
#include "measure/landmarks/profile_extreme.h"
#include "scanners/core/errors.h"

namespace bespoke::landmarks {
namespace {

// Elbow position as a share of the shoulder-point-to-wrist distance along
// the arm. Adult survey proportions (upper arm, acromion-radiale, about
// 0.186 of stature; forearm, radiale-stylion, about 0.146) give 0.56 to the
// elbow joint's line; the olecranon sits a little above it, and 0.49
// matched the MakeHuman truth best (20-30 mm too low at 0.56, 17-30 mm at
// 0.52). The share is the fallback for a straight arm (BendStation).
constexpr double kElbowShare = 0.49;
// An arm whose centre line bends by at least this much has its elbow at
// the bend. Arms straight by construction (the parametric body) stay under
// it from the muscles' shape alone; relaxed MakeHuman arms bend well past it
// (the elbow methods of the accuracy sets, docs/landmarks.md step 7).
constexpr double kMinElbowBendDeg = 12;
constexpr double kStyloidPastNarrowest_mm = 15;
// Half thickness of the slab the wrist point is taken from, mm: one point
// spacing of the cleaned cloud (4 mm voxels) either side of the station.
constexpr double kWristSlabHalfMm = 4;
// The shortest shoulder-to-arm's-end distance, as a share of stature, that
// can hold a hand (shoulder to wrist is about 0.33, to the fingertips about
// 0.44; a complete T-posed arm of a heavy body whose shoulder point sits out
// on the deltoid reaches 0.29). Shorter, the arm was cut by the
// booth's view above the wrist whatever its end looks like.
constexpr double kMinArmShare = 0.25;
// The hand: the widest section of the arm between kHandOuterMm and
// kHandInnerMm from its end (adult hands are 160-210 mm long, so this is the
// palm or the fingers together). The wrist lies before it: spread fingers,
// or a bent arm's hand cut obliquely, can be narrower than the wrist.
constexpr double kHandOuterMm = 150;
constexpr double kHandInnerMm = 40;

// Below this share of outward-facing normals at the arm's end, the end may
// be a cut, not a hand (EndCapShare)...
constexpr double kMinEndCapShare = 0.05;
// ...unless the arm is a flat hand there (EndFlatness at least this).
constexpr double kMinHandFlatness = 2.0;
// The arm's seen part ends at its outermost 10 mm slab holding at least
// this share of the points of a typical slab of its middle (30-60 % of its
// length). Past the edge of the booth's view what is left of the arm is a
// thin trail of grazing and stray returns the cleaning kept: 0-5 % of that
// count on a T-posed parametric arm in the default booth. A T-posed flat
// hand seen edge-on keeps more: 11-40 % on MakeHuman hands in a 141 x 105
// px booth, under 10 % only in the fingertips' last 10-20 mm.
constexpr double kMinSeenShare = 0.10;
// A thinly seen end longer than this is the booth's view cutting the arm,
// not the rounding of the fingertips (a 10-20 mm cap).
constexpr double kMaxThinEndMm = 40;

struct ArmFrame {
  Eigen::Vector3d origin,
      axis;  // origin: the shoulder point (or armpit); axis: outwards along the arm
  std::vector<int> rows;
  std::vector<double> t;  // (p - origin) . axis per row
  double length = 0;      // max t
};

// A least-squares line through points[a, b): mean, unit direction, and the
// sum of squared distances from it (mm^2).
struct FittedLine {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), direction = Eigen::Vector3d::UnitZ();
  double residual_mm2 = 0;
};

FittedLine FitLine(const std::vector<Eigen::Vector3d>& points, size_t a, size_t b) {
  FittedLine l;
  for (size_t k = a; k < b; ++k) l.mean += points[k];
  l.mean /= static_cast<double>(b - a);
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (size_t k = a; k < b; ++k) cov += (points[k] - l.mean) * (points[k] - l.mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  l.direction = eig.eigenvectors().col(2);
  l.residual_mm2 = eig.eigenvalues()(0) + eig.eigenvalues()(1);
  return l;
}

bool MakeFrame(const Context& c, const ArmInfo& arm, const Eigen::Vector3d& origin, ArmFrame* f) {
  if (arm.centre_line.size() < 6 || arm.rows.empty()) return false;
  f->axis = FitLine(arm.centre_line, 0, arm.centre_line.size()).direction;
  if (f->axis.dot(arm.centre_line.back() - arm.centre_line.front()) < 0) f->axis = -f->axis;
  f->origin = origin;
  f->rows = arm.rows;
  std::sort(f->rows.begin(), f->rows.end());
  f->rows.erase(std::unique(f->rows.begin(), f->rows.end()), f->rows.end());
  for (int r : f->rows) {
    f->t.push_back((c.P(r) - origin).dot(f->axis));
    f->length = std::max(f->length, f->t.back());
  }
  return true;
}

// The component of `v` across the unit `axis` (mm or unitless, as `v`).
Eigen::Vector3d AcrossAxis(const Eigen::Vector3d& v, const Eigen::Vector3d& axis) {
  return v - v.dot(axis) * axis;
}

// Largest distance from the centroid, across the axis, of the rows within
// `half` of station t: the section's half-size (mm); inf when too few.
double SectionRadius(const Context& c, const ArmFrame& f, double t, double half) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> near;
  for (size_t i = 0; i < f.rows.size(); ++i) {
    if (std::abs(f.t[i] - t) > half) continue;
    const Eigen::Vector3d p = AcrossAxis(c.P(f.rows[i]), f.axis);
    near.push_back(p);
    sum += p;
  }
  if (near.size() < 8) return kInf;
  const Eigen::Vector3d centre = sum / static_cast<double>(near.size());
  double r = 0;
  for (const auto& p : near) r = std::max(r, (p - centre).norm());
  return r;
}

// How far along the axis (mm from the origin) the arm is seen in full: the
// outermost 10 mm slab with at least kMinSeenShare of the median count of
// the slabs over 30-60 % of the length. The length itself with too few
// slabs to judge.
double SeenLength(const ArmFrame& f) {
  const int slabs = static_cast<int>(f.length / 10) + 1;
  if (slabs < 10) return f.length;
  std::vector<int> count(static_cast<size_t>(slabs), 0);
  for (double t : f.t)
    if (t >= 0) ++count[static_cast<size_t>(std::min(slabs - 1, static_cast<int>(t / 10)))];
  std::vector<int> middle(count.begin() + static_cast<long>(0.3 * slabs),
                          count.begin() + static_cast<long>(0.6 * slabs));
  std::nth_element(middle.begin(), middle.begin() + static_cast<long>(middle.size() / 2),
                   middle.end());
  const double typical = middle[middle.size() / 2];
  for (int k = slabs - 1; k >= 0; --k)
    if (count[static_cast<size_t>(k)] >= kMinSeenShare * typical)
      return std::min(f.length, 10.0 * (k + 1));
  return f.length;
}

// The frame cut back to its first `length` mm (the rows past it dropped).
void CutFrame(double length, ArmFrame* f) {
  size_t kept = 0;
  for (size_t i = 0; i < f->rows.size(); ++i) {
    if (f->t[i] > length) continue;
    f->rows[kept] = f->rows[i], f->t[kept] = f->t[i], ++kept;
  }
  f->rows.resize(kept), f->t.resize(kept);
  f->length = 0;
  for (double t : f->t) f->length = std::max(f->length, t);
}

// Of the arm's points within 20 mm of its end, the share whose normal faces
// along the arm, outwards (n . axis > 0.5): the fingertips' round cap has
// them, an arm cut off by the edge of the booth's view (an open tube) has
// none. 1 without normals (not judged).
double EndCapShare(const Context& c, const ArmFrame& f) {
  if (!c.has_normals()) return 1;
  int end = 0, out = 0;
  for (size_t i = 0; i < f.rows.size(); ++i) {
    if (f.t[i] < f.length - 20) continue;
    ++end;
    out += c.normals.row(f.rows[i]).dot(f.axis) > 0.5;
  }
  return end > 0 ? static_cast<double>(out) / end : 0;
}

// How flat the arm is 40-100 mm before its end: the larger over the smaller
// SD of its points across the axis. A hand is a flat palm there (2.5-3.6
// measured on complete T-pose and A-pose arms of MakeHuman bodies); a forearm
// cut off by the edge of the booth's view is round (1.3). A flat hand's
// fingertips, seen from above and below, have no normal along the arm, so
// the cap alone would call complete arms cut (4 of 40 T-poses in the
// completeness set). 0 with fewer than 10 points there.
double EndFlatness(const Context& c, const ArmFrame& f) {
  std::vector<Eigen::Vector3d> across;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (size_t i = 0; i < f.rows.size(); ++i) {
    const double from_end = f.length - f.t[i];
    if (from_end < 40 || from_end >= 100) continue;
    const Eigen::Vector3d p = c.P(f.rows[i]) - f.origin;
    across.push_back(AcrossAxis(p, f.axis));
    mean += across.back();
  }
  if (across.size() < 10) return 0;
  mean /= static_cast<double>(across.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : across) cov += (p - mean) * (p - mean).transpose();
  // Across the axis the covariance has rank 2: eigenvalues 0, small, large.
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvalues();
  return ev(1) > 0 ? std::sqrt(ev(2) / ev(1)) : 0;
}

// The row in the slab |t - t0| < half most extreme along `direction`
// (noise averaged); -1 when the slab is empty.
int BestInSlab(const Context& c, const ArmFrame& f, double t0, double half,
               const Eigen::Vector3d& direction) {
  std::vector<int> candidates;
  for (size_t i = 0; i < f.rows.size(); ++i) {
    if (std::abs(f.t[i] - t0) <= half) candidates.push_back(f.rows[i]);
  }
  return c.SmoothExtreme(candidates, direction, 10);
}

// The wrist's station along the arm (mm from the frame's origin; -1 when
// the forearm has no section): the narrowest section between 260 and 90 mm
// from the arm's end and not past the hand's widest section (kHandOuterMm),
// the vertex of the radius profile's parabola round its smallest sample
// (profile_extreme.h).
double NarrowestBeforeTheHand(const Context& c, const ArmFrame& f) {
  std::vector<double> at, radius;
  std::vector<bool> hand, inside;
  for (double t = f.length - 275; t <= f.length - kHandInnerMm; t += 5) {
    at.push_back(t);
    radius.push_back(SectionRadius(c, f, t, 4));
    hand.push_back(t >= f.length - kHandOuterMm);
  }
  ProfileExtremeOptions widest;
  widest.minimum = false;
  const size_t palm = BestSample(widest, radius, hand);
  const double palm_t = palm < at.size() ? at[palm] : f.length;
  for (double t : at) inside.push_back(t >= f.length - 260 && t <= std::min(f.length - 90, palm_t));
  ProfileExtremeOptions narrowest;
  narrowest.half_window = 2;
  const size_t best = BestSample(narrowest, radius, inside);
  return best < at.size() ? ProfileExtreme(narrowest, at, radius, best) : -1;
}

// The station of the arm's bend (mm from the frame's origin), or -1 when the
// arm bends less than kMinElbowBendDeg (or has too few sections). The
// centroids of the arm's sections (10 mm slabs every 5 mm, from 0.15 of the
// wrist's station to 15 mm before it) are split in two where two straight
// lines fit them best, the split sought between 0.3 and 0.7 of the wrist's
// station and refined off the 5 mm grid (profile_extreme.h).
double BendStation(const Context& c, const ArmFrame& f, double wrist_t) {
  std::vector<double> at;
  std::vector<Eigen::Vector3d> centre;
  for (double t = 0.15 * wrist_t; t <= wrist_t - 15; t += 5) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    int n = 0;
    for (size_t i = 0; i < f.rows.size(); ++i)
      if (std::abs(f.t[i] - t) <= 5) sum += c.P(f.rows[i]), ++n;
    if (n >= 8) at.push_back(t), centre.push_back(sum / n);
  }
  // Residual of the two-line fit split at each section (each line keeps
  // at least five sections).
  std::vector<double> residual(at.size(), kNaN);
  std::vector<bool> eligible(at.size(), false);
  for (size_t k = 4; k + 4 < at.size(); ++k) {
    residual[k] =
        FitLine(centre, 0, k + 1).residual_mm2 + FitLine(centre, k, centre.size()).residual_mm2;
    eligible[k] = at[k] >= 0.3 * wrist_t && at[k] <= 0.7 * wrist_t;
  }
  const size_t split = BestSample(ProfileExtremeOptions{}, residual, eligible);
  if (split == at.size()) return -1;
  const Eigen::Vector3d upper = FitLine(centre, 0, split + 1).direction,
                        fore = FitLine(centre, split, centre.size()).direction;
  const double bend_deg = std::acos(std::min(1.0, std::abs(upper.dot(fore)))) * 180 / M_PI;
  if (bend_deg < kMinElbowBendDeg) return -1;
  ProfileExtremeOptions refine;
  refine.half_window = 2;
  return ProfileExtreme(refine, at, residual, split);
}

void FindArm(Context* c, int sign) {
  const ArmInfo& arm = c->arm[sign > 0 ? 0 : 1];
  const std::string side = Side(sign);
  const bool has_shoulder = c->Has("shoulder" + side);
  ArmFrame f;
  if (!arm.found ||
      !MakeFrame(*c, arm, has_shoulder ? c->Pos("shoulder" + side) : arm.armpit, &f)) {
    for (const char* n : {"upper_arm", "elbow", "wrist"}) {
      c->Missing(n + side, arm.touching ? "the arm touches the torso" : "the arm was not found");
    }
    return;
  }
  std::vector<std::string> flags;
  double confidence = 0.75;
  // Past the booth's view the arm is only grazed: its end, and any hand
  // there, is judged where it is still seen in full.
  const double seen = SeenLength(f);
  if (f.length - seen > kMaxThinEndMm) CutFrame(seen, &f);
  const double cap = EndCapShare(*c, f);
  if (f.length < kMinArmShare * c->crown_z ||
      (cap < kMinEndCapShare && EndFlatness(*c, f) < kMinHandFlatness)) {
    // The hand is not in the scan (out of the booth's view, or merged with
    // the thigh): its end is no reference for the wrist.
    for (const char* n : {"upper_arm", "elbow", "wrist"}) {
      c->Missing(n + side, "the arm's end is not in the scan (arm " +
                               std::to_string(static_cast<int>(f.length)) +
                               " mm from the shoulder, " +
                               std::to_string(static_cast<int>(100 * cap)) +
                               " % of its end facing outwards)");
    }
    return;
  }
  if (arm.touching) flags.push_back("arm_touching_torso"), confidence = 0.3;
  double wrist_t = NarrowestBeforeTheHand(*c, f);
  if (wrist_t < 0) {
    for (const char* n : {"upper_arm", "elbow", "wrist"})
      c->Missing(n + side, "the forearm was not found");
    return;
  }
  const Eigen::Vector3d back = -Eigen::Vector3d::UnitY();
  // The ulnar styloid sits at the forearm's distal end, just past the
  // narrowest section (about 15 mm towards the hand).
  wrist_t += kStyloidPastNarrowest_mm;
  // The back of the section at that station, across the arm: in a thick
  // slab the tapering forearm's most backward point is at the slab's upper
  // edge, up to a slab's half thickness short of the station.
  Eigen::Vector3d across = AcrossAxis(back, f.axis);
  across = across.norm() > 0.3 ? across.normalized() : back;  // an arm pointing backwards
  const int wrist = BestInSlab(*c, f, wrist_t, kWristSlabHalfMm, across);
  if (wrist >= 0) c->Put("wrist" + side, c->P(wrist), confidence, "arm_section_min_back", flags);
  // The elbow: the arm's bend, or a share of the arm when it is straight.
  const double bend_t = BendStation(*c, f, wrist_t);
  const bool at_bend = bend_t >= 0;
  const double elbow_t = at_bend ? bend_t : kElbowShare * wrist_t;
  const int elbow = BestInSlab(*c, f, elbow_t, 15, back);
  if (elbow < 0) {
    c->Missing("elbow" + side, "no arm points at the elbow");
    c->Missing("upper_arm" + side, "needs the elbow");
    return;
  }
  c->Put("elbow" + side, c->P(elbow), confidence * 0.8,
         at_bend ? "arm_bend_back" : "arm_length_share_back", flags);
  // Upper arm: along the upper arm's own axis (shoulder point to elbow
  // point), halfway, the point farthest outwards across that axis.
  const Eigen::Vector3d to_elbow = c->P(elbow) - f.origin;
  const Eigen::Vector3d upper_axis = to_elbow.normalized();
  const double half = 0.5 * to_elbow.norm();
  const Eigen::Vector3d lateral = Eigen::Vector3d(sign, 0, 0);
  const Eigen::Vector3d outward = AcrossAxis(lateral, upper_axis).normalized();
  std::vector<int> slab;
  for (int r : f.rows) {
    const Eigen::Vector3d d = c->P(r) - f.origin;
    const double t = d.dot(upper_axis);
    if (std::abs(t - half) < 10 && (d - t * upper_axis).norm() < 90) slab.push_back(r);
  }
  const int upper = c->SmoothExtreme(slab, outward, 10);
  if (upper >= 0)
    c->Put("upper_arm" + side, c->P(upper), confidence * 0.8, "mid_upper_arm_outside", flags);
  else
    c->Missing("upper_arm" + side, "no arm points midway to the elbow");
}

}  // namespace

void FindArms(Context* c) {
  for (int sign : {+1, -1}) FindArm(c, sign);
}

}  // namespace bespoke::landmarks
