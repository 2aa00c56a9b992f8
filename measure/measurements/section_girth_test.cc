// Girths of known shapes sampled as clouds: circles and ellipses (2*pi*r and
// Ramanujan's perimeter), with scan holes, a second leg beside the thigh and
// a hand beside the hip. Tolerances in mm, stated per test.
#include "measure/measurements/section_girth.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <vector>

#include "measure/measurements/narrowest_section.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Points on a vertical prism z in [0, 200] mm with cross-section (x(t), y(t)),
// t in [0, 2pi), about `spacing` mm apart, skipping angles where `keep` is false.
struct Prism {
  std::function<Eigen::Vector2d(double)> curve;
  double perimeter_mm;
};

// Unit normals of the last Sample()d points, parallel to `points`.
std::vector<Eigen::Vector3d> g_normals;

void Sample(const Prism& prism, double spacing, const std::function<bool(double)>& keep,
            double noise_mm, std::vector<Eigen::Vector3d>* out, std::uint32_t seed = 1) {
  if (out->empty()) g_normals.clear();
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0, 1);
  const int around = static_cast<int>(prism.perimeter_mm / spacing);
  for (double z = 0; z <= 200; z += spacing)
    for (int k = 0; k < around; ++k) {
      const double t = 2 * kPi * (k + 0.5 * std::fmod(z / spacing, 2.0)) / around;
      if (!keep(t)) continue;
      const Eigen::Vector2d p = prism.curve(t);
      const Eigen::Vector2d d = (prism.curve(t + 1e-4) - p).normalized();
      const Eigen::Vector2d normal(d.y(), -d.x());
      const Eigen::Vector2d q = p + normal * noise_mm * n(rng);
      out->emplace_back(q.x(), q.y(), z + (noise_mm > 0 ? noise_mm * n(rng) : 0.0));
      g_normals.emplace_back(normal.x(), normal.y(), 0.0);
    }
}

Prism Circle(double r, double cx = 0, double cy = 0) {
  return {[=](double t) { return Eigen::Vector2d(cx + r * std::cos(t), cy + r * std::sin(t)); },
          2 * kPi * r};
}

Prism Ellipse(double a, double b, double cx = 0) {
  const double h = (a - b) * (a - b) / ((a + b) * (a + b));
  return {[=](double t) { return Eigen::Vector2d(cx + a * std::cos(t), b * std::sin(t)); },
          kPi * (a + b) * (1 + 3 * h / (10 + std::sqrt(4 - 3 * h)))};
}

Eigen::MatrixX3d ToMatrix(const std::vector<Eigen::Vector3d>& p) {
  Eigen::MatrixX3d m(static_cast<Eigen::Index>(p.size()), 3);
  for (std::size_t i = 0; i < p.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = p[i].transpose();
  return m;
}

auto All = [](double) { return true; };
const Eigen::Vector3d kPlane(0, 0, 100), kUp(0, 0, 1);

SectionGirth Girth(const std::vector<Eigen::Vector3d>& cloud, const Eigen::MatrixX3d& anchors,
                   SectionGirthOptions options = {}) {
  return MeasureSectionGirth(options, ToMatrix(cloud), ToMatrix(g_normals), kPlane, kUp, anchors);
}

TEST(SectionGirth, CircleIsTwoPiR) {
  std::vector<Eigen::Vector3d> cloud;
  Sample(Circle(150), 4, All, 0, &cloud);
  const SectionGirth g = Girth(cloud, Eigen::RowVector3d(150, 0, 100));
  EXPECT_NEAR(g.girth_mm, 2 * kPi * 150, 0.5);  // mm; the inscribed polygon loses < 0.1 mm
  EXPECT_FALSE(g.open);
  EXPECT_EQ(g.pieces, 1);
}

TEST(SectionGirth, EllipsePrismMatchesRamanujan) {
  std::vector<Eigen::Vector3d> cloud;
  const Prism e = Ellipse(180, 120);
  Sample(e, 4, All, 0, &cloud);
  const SectionGirth g = Girth(cloud, Eigen::RowVector3d(180, 0, 100));
  EXPECT_NEAR(g.girth_mm, e.perimeter_mm, 0.5);  // mm
}

TEST(SectionGirth, TiltedPlaneThroughACylinderIsAnEllipse) {
  std::vector<Eigen::Vector3d> cloud;
  Sample(Circle(50), 2, All, 0, &cloud);  // an arm-sized cylinder along z
  const double tilt = 30 * kPi / 180;
  const Eigen::Vector3d normal(std::sin(tilt), 0, std::cos(tilt));
  const Eigen::RowVector3d anchor(50, 0, 100);
  const double truth = Ellipse(50 / std::cos(tilt), 50).perimeter_mm;
  SectionGirthOptions raw;
  raw.smooth_arc_mm = 0;
  const SectionGirth g =
      MeasureSectionGirth(raw, ToMatrix(cloud), ToMatrix(g_normals), kPlane, normal, anchor);
  EXPECT_NEAR(g.girth_mm, truth, 1.0);  // mm
  // Projected without normals, the slab's sloping surface pushes the hull out.
  const SectionGirth flat =
      MeasureSectionGirth(raw, ToMatrix(cloud), Eigen::MatrixX3d(0, 3), kPlane, normal, anchor);
  EXPECT_GT(flat.girth_mm - truth, 2.0);  // mm
}

TEST(SectionGirth, HoleSplittingTheLoopIsBridged) {
  // Two 20-degree holes on opposite sides cut the loop into two arcs.
  std::vector<Eigen::Vector3d> cloud;
  auto keep = [](double t) {
    const double deg = t * 180 / kPi;
    return !((deg > 80 && deg < 100) || (deg > 260 && deg < 280));
  };
  Sample(Circle(150), 4, keep, 0, &cloud);
  const SectionGirth g = Girth(cloud, Eigen::RowVector3d(150, 0, 100));
  // The tape spans each hole with a chord: 2 * (arc - chord) shorter.
  const double arc = 150 * 20 * kPi / 180, chord = 2 * 150 * std::sin(10 * kPi / 180);
  EXPECT_EQ(g.pieces, 2);
  EXPECT_EQ(g.pieces_joined, 1);
  EXPECT_NEAR(g.girth_mm, 2 * kPi * 150 - 2 * (arc - chord),
              2.0);  // mm (chord ends sampled 4 mm apart)
  EXPECT_TRUE(g.open);
  EXPECT_GT(g.largest_gap_mm, 45);
}

// An upper arm (an elliptic prism 48 x 38 mm, 1 mm noise) whose inner side
// the booth did not see (110 deg of its loop): as a limb's section, the tape
// passes over the skin round the hole, not across its chord, which falls
// more than 5 mm short; a trunk's section (the flag off) keeps the chord.
TEST(SectionGirth, ALimbsTapeFollowsItsSkinOverAHole) {
  std::vector<Eigen::Vector3d> cloud;
  const Prism arm = Ellipse(48, 38, 250);
  auto keep = [](double t) { return t < 2.2 || t > 4.1; };
  Sample(arm, 2, keep, 1.0, &cloud);
  const Eigen::RowVector3d anchor(298, 0, 100);
  SectionMembers limb;
  limb.skin_over_holes = true;
  const SectionGirth skin =
      MeasureSectionGirth({}, ToMatrix(cloud), ToMatrix(g_normals), kPlane, kUp, anchor, limb);
  const SectionGirth chord = Girth(cloud, anchor);
  EXPECT_TRUE(skin.open);
  EXPECT_GT(skin.bridged_mm, 60.0);  // mm: the hole's arc is 76 mm
  EXPECT_EQ(chord.bridged_mm, 0.0);
  EXPECT_LT(chord.girth_mm, arm.perimeter_mm - 5.0) << "mm";
  EXPECT_NEAR(skin.girth_mm, arm.perimeter_mm, 1.5) << "mm";
}

// The trunk's sides under the arms unscanned (50-degree holes on either
// side): the tape still passes over the armpits, given as tape points off
// the plane (5 mm below and above it), and spans each hole with two chords
// through them; without them, one chord across. Where the loop is scanned
// the skin decides: a tape point inside it or 20 mm outside changes nothing.
TEST(SectionGirth, TapePassesOverItsPointsAcrossAHole) {
  std::vector<Eigen::Vector3d> cloud;
  auto keep = [](double t) {
    const double deg = t * 180 / kPi;
    return !(deg < 25 || deg > 335 || (deg > 155 && deg < 205));
  };
  Sample(Circle(150), 4, keep, 0, &cloud);
  const Eigen::Matrix<double, 2, 3> anchors{{150, 0, 95}, {-150, 0, 105}};
  SectionMembers members;
  members.tape_points = anchors;
  const SectionGirth with =
      MeasureSectionGirth({}, ToMatrix(cloud), ToMatrix(g_normals), kPlane, kUp, anchors, members);
  const SectionGirth without =
      MeasureSectionGirth({}, ToMatrix(cloud), ToMatrix(g_normals), kPlane, kUp, anchors);
  const double arc = 150 * 50 * kPi / 180, half_chord = 2 * 150 * std::sin(12.5 * kPi / 180);
  const double chord = 2 * 150 * std::sin(25 * kPi / 180);
  EXPECT_NEAR(with.girth_mm, 2 * kPi * 150 - 2 * (arc - 2 * half_chord),
              2.0);  // mm (chord ends sampled 4 mm apart)
  EXPECT_NEAR(without.girth_mm, 2 * kPi * 150 - 2 * (arc - chord), 2.0);  // mm
  EXPECT_TRUE(with.open);  // the scan's hole is still reported
  std::vector<Eigen::Vector3d> full;
  Sample(Circle(150), 4, All, 0, &full);
  members.tape_points = Eigen::Matrix<double, 2, 3>{{100, 0, 100}, {-170, 0, 100}};
  const SectionGirth whole = MeasureSectionGirth({}, ToMatrix(full), ToMatrix(g_normals), kPlane,
                                                 kUp, Eigen::RowVector3d(150, 0, 100), members);
  EXPECT_NEAR(whole.girth_mm, 2 * kPi * 150, 0.5);  // mm
  members.tape_points(0, 0) = std::nan("");
  EXPECT_THROW(MeasureSectionGirth({}, ToMatrix(full), ToMatrix(g_normals), kPlane, kUp,
                                   Eigen::RowVector3d(150, 0, 100), members),
               InputError);
}

TEST(SectionGirth, ThighIgnoresTheOtherLeg) {
  std::vector<Eigen::Vector3d> cloud;
  Sample(Circle(80, 100), 4, All, 0, &cloud);
  Sample(Circle(80, -100), 4, All, 0, &cloud);  // 40 mm apart
  const SectionGirth g = Girth(cloud, Eigen::RowVector3d(180, 0, 100));
  EXPECT_EQ(g.pieces, 2);
  EXPECT_NEAR(g.girth_mm, 2 * kPi * 80, 0.5);  // mm
  EXPECT_GT(g.part.col(0).minCoeff(), 15);     // only the right leg
}

Eigen::MatrixX3d HipAnchors() {
  return (Eigen::MatrixX3d(3, 3) << 0, -130, 100, 180, 0, 100, -180, 0, 100).finished();
}

TEST(SectionGirth, HipExcludesTheHandBesideIt) {
  std::vector<Eigen::Vector3d> cloud;
  const Prism hip = Ellipse(180, 130);
  Sample(hip, 4, All, 1.0, &cloud);
  Sample(Circle(40, 235), 4, All, 1.0, &cloud, 2);  // 15 mm from the hip's side
  const SectionGirth g = Girth(cloud, HipAnchors());
  EXPECT_TRUE(g.anchor_enclosed);
  EXPECT_LT(g.part.col(0).maxCoeff(), 190);
  EXPECT_NEAR(g.girth_mm, hip.perimeter_mm, 8.0);  // mm; 1 mm noise pushes the raw hull out
}

TEST(SectionGirth, HipWithTheHandsShadowStillExcludesTheHand) {
  // The hand hides the hip's side from view (a hole in the hip facing it);
  // first the whole hand, then only its outer half (what a sensor sees).
  const Prism hip = Ellipse(180, 130);
  auto hip_keep = [](double t) {
    const double deg = std::remainder(t * 180 / kPi, 360.0);
    return std::abs(deg) > 25;
  };
  auto outer_half = [](double t) { return std::cos(t) > 0; };
  // The tape spans the hole (-25..25 degrees) with a chord.
  const double t0 = 25 * kPi / 180;
  const double chord = (hip.curve(t0) - hip.curve(-t0)).norm();
  double arc = 0;
  for (int k = 0; k < 1000; ++k)
    arc += (hip.curve(-t0 + 2 * t0 * (k + 1) / 1000) - hip.curve(-t0 + 2 * t0 * k / 1000)).norm();
  for (bool whole_hand : {true, false}) {
    std::vector<Eigen::Vector3d> cloud;
    Sample(hip, 4, hip_keep, 0, &cloud);
    Sample(Circle(40, 250), 4, whole_hand ? std::function<bool(double)>(All) : outer_half, 0,
           &cloud);
    const SectionGirth g = Girth(cloud, HipAnchors());
    EXPECT_LT(g.part.col(0).maxCoeff(), 190) << "whole hand " << whole_hand;
    EXPECT_NEAR(g.girth_mm, hip.perimeter_mm - arc + chord, 2.0)
        << "whole hand " << whole_hand;  // mm
    EXPECT_TRUE(g.open);
  }
}

// A cylinder trunk with two cylinder arms resting on its sides, 2 mm apart
// (closer than the piece gap: the slab alone joins them), 1 mm noise.
TEST(SectionGirth, TrunkLeavesOutTheArmsRestingOnIt) {
  const Prism trunk = Circle(150);
  std::vector<Eigen::Vector3d> cloud;
  Sample(trunk, 4, All, 1.0, &cloud);
  const Eigen::MatrixX3d sides = (Eigen::MatrixX3d(2, 3) << 150, 0, 100, -150, 0, 100).finished();
  const double alone_mm = Girth(cloud, sides).girth_mm;  // the same noisy trunk, no arms
  const std::size_t trunk_points = cloud.size();
  Sample(Circle(45, 197), 4, All, 1.0, &cloud, 2);
  Sample(Circle(45, -197), 4, All, 1.0, &cloud, 3);
  EXPECT_GT(Girth(cloud, sides).girth_mm, alone_mm + 100);  // the slab alone: arms included
  std::vector<bool> arms(cloud.size(), false);
  std::fill(arms.begin() + static_cast<std::ptrdiff_t>(trunk_points), arms.end(), true);
  const SectionGirth g = MeasureSectionGirth({}, ToMatrix(cloud), ToMatrix(g_normals), kPlane, kUp,
                                             sides, {arms, {}, true, {}});
  EXPECT_NEAR(g.girth_mm, alone_mm, 0.5);    // mm
  EXPECT_LT(g.part.col(0).maxCoeff(), 156);  // mm: the trunk's side plus the noise
}

// The same trunk where the arms hide its sides: holes of +-40 deg at both
// sides cut it into a front and a back arc. With the arms left out as
// `one_part`, the tape spans both holes with chords.
TEST(SectionGirth, TrunkCutByHolesUnderTheArmsIsOnePart) {
  const double r = 150, hole = 40 * kPi / 180;
  auto arcs = [&](double t) { return std::abs(std::sin(t)) > std::sin(hole); };
  std::vector<Eigen::Vector3d> cloud;
  Sample(Circle(r), 4, arcs, 0, &cloud);
  const std::size_t trunk_points = cloud.size();
  Sample(Circle(45, 197), 4, All, 0, &cloud, 2);
  Sample(Circle(45, -197), 4, All, 0, &cloud, 3);
  std::vector<bool> arms(cloud.size(), false);
  std::fill(arms.begin() + static_cast<std::ptrdiff_t>(trunk_points), arms.end(), true);
  const Eigen::MatrixX3d sides = (Eigen::MatrixX3d(2, 3) << 150, 0, 100, -150, 0, 100).finished();
  const double expected = 2 * (kPi - 2 * hole) * r + 2 * 2 * r * std::sin(hole);  // arcs + chords
  const SectionGirth g = MeasureSectionGirth({}, ToMatrix(cloud), ToMatrix(g_normals), kPlane, kUp,
                                             sides, {arms, {}, true, {}});
  // Each arc's end lies up to one spacing (4 mm of arc) inside its hole's
  // edge, which shortens the tape by up to 4 * 4 mm * (1 - cos 40 deg) = 3.7 mm.
  EXPECT_LT(g.girth_mm, expected + 0.5);  // mm
  EXPECT_GT(g.girth_mm, expected - 3.8);  // mm
  EXPECT_GE(g.pieces, 2);
}

// An arm (r 50 mm, centre x `arm_x`) beside a trunk (r 150), 1 mm noise;
// each skin's points inside the other are hidden. The arm's inner side
// (within 50 deg of the trunk) is labelled trunk, as the body structure
// does where the two touch, or not scanned at all (`inner_scanned` false).
// The trunk's points and those labelled trunk are the arm girth's gap points.
struct ArmBesideTrunk {
  std::vector<Eigen::Vector3d> cloud;
  std::vector<bool> trunk;  // labelled trunk
  SectionGirth Measure(bool gap_points) const {
    SectionMembers members;
    (gap_points ? members.gap_only : members.leave_out) = trunk;
    return MeasureSectionGirth({}, ToMatrix(cloud), ToMatrix(g_normals), kPlane, kUp,
                               Eigen::RowVector3d(cloud[0].x(), 0, 100), members);
  }
};

ArmBesideTrunk Arm(double arm_x, bool inner_scanned) {
  const double inner_x = arm_x - 50 * std::cos(50 * kPi / 180);
  ArmBesideTrunk a;
  Sample(
      Circle(50, arm_x), 3,
      [&](double t) {
        const double x = arm_x + 50 * std::cos(t);
        return x > 150 && (inner_scanned || x > inner_x);
      },
      1.0, &a.cloud, 2);
  for (const Eigen::Vector3d& p : a.cloud) a.trunk.push_back(p.x() < inner_x);
  auto outside_arm = [&](double t) {
    return std::hypot(150 * std::cos(t) - arm_x, 150 * std::sin(t)) > 50;
  };
  Sample(Circle(150), 4, outside_arm, 1.0, &a.cloud, 3);
  a.trunk.resize(a.cloud.size(), true);
  return a;
}

TEST(SectionGirth, ArmPressedOnTheTrunkTakesBackItsInnerSide) {
  const ArmBesideTrunk a = Arm(197, true);
  const double arm_mm = 2 * kPi * 50;  // less the 3 mm deep cap the trunk hides: under 1 mm
  const SectionGirth left_out = a.Measure(false), g = a.Measure(true);
  std::printf("arm pressed on the trunk: %.1f mm with gap points, %.1f mm without; 2 pi r %.1f\n",
              g.girth_mm, left_out.girth_mm, arm_mm);
  EXPECT_LT(left_out.girth_mm, arm_mm - 8);  // mm: a chord over the inner 100 deg
  EXPECT_NEAR(g.girth_mm, arm_mm, 2.0);      // mm
  EXPECT_GT(g.gap_points_joined, 10);
  EXPECT_LT(g.part.col(0).minCoeff(), 152);  // mm: the inner side is back
  EXPECT_GT(g.part.col(0).minCoeff(), 140);  // mm: the trunk (out to x = -150) is not
}

// The arm hanging 20 mm from the trunk, its inner side a scan hole: the
// trunk's skin across the hole is farther out than the arm and faces it, so
// the tape spans the hole with a chord, as with the trunk left out.
TEST(SectionGirth, TrunkBesideAnArmsHoleStaysOutside) {
  const ArmBesideTrunk a = Arm(220, false);
  const SectionGirth left_out = a.Measure(false);
  EXPECT_LT(left_out.girth_mm, 2 * kPi * 50 - 8);  // mm: the chord
  const SectionGirth g = a.Measure(true);
  EXPECT_EQ(g.gap_points_joined, 0);
  EXPECT_NEAR(g.girth_mm, left_out.girth_mm, 0.01);  // mm
}

TEST(SectionGirth, SmoothingRemovesTheNoiseBias) {
  std::vector<Eigen::Vector3d> cloud;
  Sample(Circle(150), 2, All, 1.0, &cloud);
  SectionGirthOptions off;
  off.smooth_arc_mm = 0;
  const SectionGirth raw = Girth(cloud, Eigen::RowVector3d(150, 0, 100), off);
  const SectionGirth denoised = Girth(cloud, Eigen::RowVector3d(150, 0, 100));  // default 6 mm bins
  const double truth = 2 * kPi * 150;
  EXPECT_GT(raw.girth_mm - truth, 4.0);                 // mm: the hull rides the noise outwards
  EXPECT_LT(std::abs(denoised.girth_mm - truth), 3.0);  // mm
}

// A limb scanned sparsely: points at random on a cylinder, one per
// spacing^2 of skin (no rows), with their normals in g_normals.
std::vector<Eigen::Vector3d> SparseCylinder(double r_mm, double spacing_mm, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const int n = static_cast<int>(2 * kPi * r_mm * 200 / (spacing_mm * spacing_mm));
  std::vector<Eigen::Vector3d> cloud;
  g_normals.clear();
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * u(rng);
    cloud.emplace_back(r_mm * std::cos(t), r_mm * std::sin(t), 200 * u(rng));
    g_normals.emplace_back(std::cos(t), std::sin(t), 0);
  }
  return cloud;
}

TEST(SectionGirth, SparseScanTakesAWiderSlab) {
  const SectionGirthOptions defaults;
  // A dense scan keeps the options; 6 mm spacing needs a 2.5 * 6 = 15 mm
  // piece gap and a 4 * 36 / (2 * 15) = 4.8 mm slab.
  const SectionGirthOptions dense = SlabForSpacing(defaults, 3);
  EXPECT_EQ(dense.half_thickness_mm, defaults.half_thickness_mm);
  EXPECT_EQ(dense.piece_gap_mm, defaults.piece_gap_mm);
  const SectionGirthOptions wide = SlabForSpacing(defaults, 6);
  EXPECT_NEAR(wide.piece_gap_mm, 15.0, 1e-9);
  EXPECT_NEAR(wide.half_thickness_mm, 4.8, 1e-9);
  EXPECT_NEAR(wide.max_slide_mm, defaults.max_slide_mm * 4.8 / 2.5, 1e-9);
  EXPECT_EQ(SlabForSpacing(defaults, 30).half_thickness_mm, defaults.max_half_thickness_mm);
  // A knee of 55 mm radius at 6 mm spacing, over ten scans: the 2.5 mm slab
  // breaks its loop into pieces and keeps one; the wider slab holds the loop.
  const double truth = 2 * kPi * 55;
  double worst_fixed = 0, worst_wide = 0;
  for (std::uint32_t seed = 1; seed <= 10; ++seed) {
    const std::vector<Eigen::Vector3d> cloud = SparseCylinder(55, 6, seed);
    const Eigen::RowVector3d anchor(55, 0, 100);
    worst_fixed = std::max(worst_fixed, std::abs(Girth(cloud, anchor).girth_mm - truth));
    worst_wide = std::max(worst_wide, std::abs(Girth(cloud, anchor, wide).girth_mm - truth));
  }
  EXPECT_GT(worst_fixed, 50.0);  // mm
  EXPECT_LT(worst_wide, 4.0);    // mm
}

TEST(SectionGirth, EmptySlabAndBadOptions) {
  std::vector<Eigen::Vector3d> cloud;
  Sample(Circle(150), 4, All, 0, &cloud);
  const SectionGirth g =
      MeasureSectionGirth({}, ToMatrix(cloud), ToMatrix(g_normals), Eigen::Vector3d(0, 0, 900), kUp,
                          Eigen::RowVector3d(0, 0, 900));
  EXPECT_EQ(g.points, 0);
  EXPECT_EQ(g.girth_mm, 0);
  SectionGirthOptions bad;
  bad.half_thickness_mm = 0;
  EXPECT_THROW(Girth(cloud, Eigen::RowVector3d(150, 0, 100), bad), InputError);
  EXPECT_THROW(MeasureSectionGirth({}, ToMatrix(cloud), ToMatrix(g_normals), kPlane,
                                   Eigen::Vector3d(0, 0, 2), Eigen::RowVector3d(0, 0, 0)),
               InputError);
}

// A shank as a surface of revolution, radius 40 + 0.004 (z - 120)^2 mm
// (narrowest, 2 pi 40 mm round, at z = 120), sampled every 2 mm with 1 mm of
// radial noise, and a thinner leg 200 mm beside it that the anchor leaves
// out. The smallest section from z = 20 to z = 280 is found at its height
// within the 6 mm a 5-level window spans either way of a flat minimum.
TEST(SectionGirth, NarrowestSectionOfAShank) {
  std::mt19937 rng(5);
  std::normal_distribution<double> noise(0, 1);
  std::vector<Eigen::Vector3d> cloud;
  for (double z = 0; z <= 300; z += 2) {
    const double r = 40 + 0.004 * (z - 120) * (z - 120);
    for (int k = 0; k < 150; ++k) {
      const double t = 2 * kPi * k / 150, rn = r + noise(rng);
      cloud.emplace_back(rn * std::cos(t), rn * std::sin(t), z);
      cloud.emplace_back(200 + 30 * std::cos(t), 30 * std::sin(t), z);
    }
  }
  Eigen::MatrixX3d anchor(1, 3);
  anchor << 45, 0, 20;
  const double z = NarrowestSectionZ(SectionGirthOptions{}, ToMatrix(cloud), Eigen::MatrixX3d(0, 3),
                                     20, 280, 2, 5, anchor);
  EXPECT_NEAR(z, 120, 6) << "mm";
  anchor(0, 2) = z;
  const SectionGirth s =
      MeasureSectionGirth(SectionGirthOptions{}, ToMatrix(cloud), Eigen::MatrixX3d(0, 3),
                          Eigen::Vector3d(0, 0, z), kUp, anchor);
  EXPECT_NEAR(s.girth_mm, 2 * kPi * 40, 3) << "mm";
  // No band to search: the start.
  EXPECT_EQ(NarrowestSectionZ(SectionGirthOptions{}, ToMatrix(cloud), Eigen::MatrixX3d(0, 3), 50,
                              40, 2, 5, anchor),
            50);
}

// The shank of NarrowestSectionOfAShank without noise (radius 40 + 0.004
// (z - 120)^2 mm, rings 2 mm apart of 150 points), less the points at
// height z and angle t (rad) that `drop` names.
std::vector<Eigen::Vector3d> Shank(const std::function<bool(double, double)>& drop) {
  std::vector<Eigen::Vector3d> cloud;
  for (double z = 0; z <= 300; z += 2) {
    const double r = 40 + 0.004 * (z - 120) * (z - 120);
    for (int k = 0; k < 150; ++k) {
      const double t = 2 * kPi * k / 150;
      if (!drop(z, t)) cloud.emplace_back(r * std::cos(t), r * std::sin(t), z);
    }
  }
  return cloud;
}

// The narrowest level (mm) of `cloud` between `from` and `to`, anchored on
// the shank's side, 2 mm steps, a 5-level window.
double NarrowestOfShank(const std::vector<Eigen::Vector3d>& cloud, double from, double to) {
  Eigen::MatrixX3d anchor(1, 3);
  anchor << 45, 0, from;
  return NarrowestSectionZ(SectionGirthOptions{}, ToMatrix(cloud), Eigen::MatrixX3d(0, 3), from, to,
                           2, 5, anchor);
}

// The same shank where a sparse scan saw only a short arc of the loop,
// by the anchor, over 14 mm of height (z = 60-72): those levels' part is a
// sliver whose hull is a fraction of the loop's, and the median window
// alone takes a run of them longer than itself for the narrowest section.
TEST(SectionGirth, NarrowestSectionIgnoresARunOfSlivers) {
  const std::vector<Eigen::Vector3d> cloud = Shank([](double z, double t) {
    return z >= 60 && z <= 72 && std::abs(std::remainder(t, 2 * kPi)) > 0.3;
  });
  EXPECT_NEAR(NarrowestOfShank(cloud, 20, 280), 120, 6) << "mm";
}

// The same shank where a scan saw only the front half of the loop just
// below its narrowest level (z = 100-116): those sections are open, and the
// hull of a half loop is 0.82 of the loop's, smaller than the true minimum.
// Where enough levels close their loop only those are compared.
TEST(SectionGirth, NarrowestSectionPrefersClosedLoops) {
  const std::vector<Eigen::Vector3d> cloud =
      Shank([](double z, double t) { return z >= 100 && z <= 116 && std::sin(t) < 0; });
  EXPECT_NEAR(NarrowestOfShank(cloud, 80, 160), 120, 6) << "mm";
}

}  // namespace
}  // namespace bespoke
