// Postures with MakeHuman's skeleton and skin weights, and the full-range
// population (tests skip without ../shared).
#include "oracle/makehuman/makehuman_pose.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

#include "measure/catalogue/catalogue.h"
#include "oracle/makehuman/makehuman_body.h"
#include "oracle/makehuman/makehuman_landmarks.h"
#include "oracle/makehuman/makehuman_model.h"
#include "oracle/makehuman/makehuman_population.h"
#include "oracle/truth/mesh_section.h"
#include "oracle/truth/reference_measurements.h"
#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

std::filesystem::path MakeHumanDir(const std::filesystem::path& shared) {
  return shared / "data" / "bodies" / "makehuman";
}

Eigen::Vector3d At(const Body& body, const std::string& name) {
  return PositionOf(body.mesh, body.landmarks.at(name));
}

Body Posed(MakeHumanModel* model, std::uint64_t seed, const std::string& posture,
           const std::string& population = "default") {
  MakeHumanBodyOptions o;
  o.seed = seed;
  o.population = population;
  o.posture = ParseMakeHumanPosture(posture);
  return GenerateMakeHumanBody(o, model);
}

// The bones at and below `bone` (their indices).
std::set<int> Subtree(const MakeHumanRig& rig, const std::string& bone) {
  std::set<int> out = {rig.BoneIndex(bone)};
  for (std::size_t i = 0; i < rig.bones.size(); ++i)  // parents come first
    if (out.count(rig.bones[i].parent)) out.insert(static_cast<int>(i));
  return out;
}

TEST(MakeHumanPose, ABoneTurnMovesItsVerticesRigidlyWhereTheirWeightIsOne) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  const MakeHumanRig& rig = model.Rig();
  EXPECT_EQ(rig.bones.size(), 163u);
  const Eigen::MatrixX3d all = model.MorphAll({});
  const auto joints = RigJoints(rig, all);
  const Eigen::MatrixX3d rest = model.SkinRows(all);
  const int bone = rig.BoneIndex("lowerarm01.R");
  const Eigen::Matrix3d r =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  const Eigen::MatrixX3d posed = SkinWithRotations(rig, rest, joints, {{bone, r}});
  const Eigen::Vector3d h = joints.at(rig.bones[static_cast<std::size_t>(bone)].head);
  const std::set<int> below = Subtree(rig, "lowerarm01.R");
  int rigid = 0, still = 0;
  for (Eigen::Index v = 0; v < rest.rows(); ++v) {
    double inside = 0;
    for (const auto& [b, w] : rig.weights[static_cast<std::size_t>(v)])
      if (below.count(b)) inside += w;
    const Eigen::Vector3d p = rest.row(v).transpose(), q = posed.row(v).transpose();
    if (inside > 1 - 1e-12) {
      EXPECT_LT((q - (h + r * (p - h))).norm(), 1e-12);
      ++rigid;
    } else if (inside < 1e-12) {
      EXPECT_LT((q - p).norm(), 1e-12);
      ++still;
    }
  }
  std::printf("lowerarm01.R turned: %d vertices rigid, %d still\n", rigid, still);
  EXPECT_GT(rigid, 300);
  EXPECT_GT(still, 10000);
}

TEST(MakeHumanPose, ArmsReachTheirAngleAndTheDatumPointsFollow) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  const Body rest = Posed(&model, 3, "rest");
  const Body t = Posed(&model, 3, "arms-90");
  EXPECT_NEAR(t.parameters.at("pose.arm_abduction_deg"), 90, 0.01);
  std::printf("rest arms %.1f deg; T-pose wrist - shoulder point height %.1f / %.1f mm\n",
              t.parameters.at("pose.rest_arm_abduction_deg"),
              At(t, "wrist_right").z() - At(t, "shoulder_right").z(),
              At(t, "wrist_left").z() - At(t, "shoulder_left").z());
  // The T-pose arm is horizontal: the wrist joint at the shoulder joint's height
  // (the frontal angle is exactly 90), the wrist datum point within a forearm's
  // thickness of the shoulder point's height, far out to the side.
  for (const char* side : {"right", "left"}) {
    const std::string s = side;
    EXPECT_LT(std::abs(At(t, "wrist_" + s).z() - At(t, "shoulder_" + s).z()), 80) << side;
    EXPECT_GT(std::abs(At(t, "wrist_" + s).x()), std::abs(At(t, "shoulder_" + s).x()) + 300);
    EXPECT_GT((At(t, "wrist_" + s) - At(rest, "wrist_" + s)).norm(), 300);
  }
  // What the arms do not move stays: the crotch and knees within 1 mm.
  for (const char* name : {"crotch", "knee_right", "ankle_inside_left"})
    EXPECT_LT((At(t, name) - At(rest, name)).norm(), 1.0) << name;
  EXPECT_EQ(t.parameters.at("pose.new_self_intersections"), 0);
}

// The acromion belongs to the shoulder blade, but its skin vertex weighs
// mostly the upper arm: lowering the arms from MakeHuman's rest (44 deg) to
// 30 deg carries that vertex down and out with the arm, while the datum point
// is carried by the shoulder blade's bone and stays; a lean moves both alike.
TEST(MakeHumanPose, TheAcromionStaysWithTheShoulderBlade) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  int vertex = -1;
  for (const MakeHumanLandmark& l : MakeHumanLandmarkTable())
    if (std::string(l.name) == "shoulder_right") vertex = l.vertex;
  ASSERT_GE(vertex, 0);
  const Body rest = Posed(&model, 1001, "rest", "full");
  const Body a = Posed(&model, 1001, "arms-30", "full");
  const auto moved = [&](const Body& b) {
    return (At(b, "shoulder_right") - At(rest, "shoulder_right")).norm();
  };
  const double skin_moved = (a.mesh.vertices.row(vertex) - rest.mesh.vertices.row(vertex)).norm();
  std::printf("arms-30: skin vertex moved %.1f mm, acromion %.1f mm\n", skin_moved, moved(a));
  EXPECT_GT(skin_moved, 8);
  EXPECT_LT(moved(a), 3);
  EXPECT_LT(a.parameters.at("pose.bone_carried_off_skin_mm"), 3);
  const Body lean = Posed(&model, 1001, "lean-5", "full");
  EXPECT_GT(moved(lean), 20);
  EXPECT_LT(lean.parameters.at("pose.bone_carried_off_skin_mm"), 1);
}

TEST(MakeHumanPose, ArmsPressedToTheSidesStopAtContact) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  MakeHumanBodyOptions o;
  o.seed = 3;
  o.weight = 0.9;  // a heavy body: the arms meet the sides before 5 deg
  o.posture = ParseMakeHumanPosture("arms-5");
  const Body stopped = GenerateMakeHumanBody(o, &model);
  o.posture.stop_at_contact = false;
  const Body pressed = GenerateMakeHumanBody(o, &model);
  std::printf(
      "arms-5 on a heavy body: stopped at %.2f deg (rest %.2f); pressed to %.2f deg "
      "with %g new crossing face pairs\n",
      stopped.parameters.at("pose.arm_abduction_deg"),
      stopped.parameters.at("pose.rest_arm_abduction_deg"),
      pressed.parameters.at("pose.arm_abduction_deg"),
      pressed.parameters.at("pose.new_self_intersections"));
  EXPECT_EQ(stopped.parameters.at("pose.arms_stopped_at_contact"), 1);
  EXPECT_EQ(stopped.parameters.at("pose.new_self_intersections"), 0);
  EXPECT_GT(stopped.parameters.at("pose.arm_abduction_deg"), 5.5);
  EXPECT_NEAR(pressed.parameters.at("pose.arm_abduction_deg"), 5, 0.01);
  EXPECT_GT(pressed.parameters.at("pose.new_self_intersections"), 0);
}

TEST(MakeHumanPose, StanceLeanTwistAndHead) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  const Body rest = Posed(&model, 5, "rest");
  const Body wide = Posed(&model, 5, "feet-40");
  EXPECT_NEAR(wide.parameters.at("pose.stance_mm"), 400, 0.5);
  // The malleoli follow the ankle joints (the feet are carried, not turned).
  const auto spread = [](const Body& b) {
    return At(b, "ankle_outside_right").x() - At(b, "ankle_outside_left").x();
  };
  const double joints_moved = 400 - wide.parameters.at("pose.rest_stance_mm");
  std::printf("feet-40: rest stance %.1f mm; malleoli spread %.1f -> %.1f mm\n",
              wide.parameters.at("pose.rest_stance_mm"), spread(rest), spread(wide));
  EXPECT_NEAR(spread(wide) - spread(rest), joints_moved, 15);
  const Body lean = Posed(&model, 5, "lean-5");
  const double forward = At(lean, "back_neck").y() - At(rest, "back_neck").y();
  const Body twist = Posed(&model, 5, "twist-5");
  const double right = At(twist, "shoulder_right").y() - At(rest, "shoulder_right").y();
  const double left = At(twist, "shoulder_left").y() - At(rest, "shoulder_left").y();
  const Body head = Posed(&model, 5, "head-turn");
  std::printf(
      "lean-5: back neck %.1f mm forward; twist-5: shoulders %.1f / %.1f mm; "
      "head-turn: shoulder %.2f mm\n",
      forward, right, left, (At(head, "shoulder_right") - At(rest, "shoulder_right")).norm());
  EXPECT_GT(forward, 25);  // about sin(5 deg) x the neck's height above the pelvis
  EXPECT_GT(right, 5);     // turning left brings the right shoulder forward
  EXPECT_LT(left, -5);
  EXPECT_LT((At(head, "shoulder_right") - At(rest, "shoulder_right")).norm(), 1);
  EXPECT_THROW(ParseMakeHumanPosture("arms-7"), InputError);
}

TEST(MakeHumanPopulation, FullRangeCoversTheRangeWithHardCasesInNumbers) {
  MakeHumanBodyOptions o;
  o.population = "full";
  double g_lo = 1, g_hi = 0, age_lo = 100, age_hi = 0, w_lo = 1, w_hi = 0, s_lo = 1e4, s_hi = 0;
  int between = 0, cases[5] = {};
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    o.seed = seed;
    const MakeHumanParameters p = MakeHumanDraw(o);
    g_lo = std::min(g_lo, p.gender), g_hi = std::max(g_hi, p.gender);
    between += p.gender > 0.2 && p.gender < 0.8;
    age_lo = std::min(age_lo, p.age_years), age_hi = std::max(age_hi, p.age_years);
    w_lo = std::min(w_lo, p.weight), w_hi = std::max(w_hi, p.weight);
    s_lo = std::min(s_lo, p.stature_mm), s_hi = std::max(s_hi, p.stature_mm);
    ++cases[p.hard_case];
  }
  std::printf(
      "200 draws: gender %.2f-%.2f (%d between 0.2 and 0.8), age %.0f-%.0f, weight "
      "%.2f-%.2f, stature %.0f-%.0f; hard cases none %d, thighs %d, belly %d, breasts "
      "%d, arms %d\n",
      g_lo, g_hi, between, age_lo, age_hi, w_lo, w_hi, s_lo, s_hi, cases[0], cases[1], cases[2],
      cases[3], cases[4]);
  EXPECT_LT(g_lo, 0.02);
  EXPECT_GT(g_hi, 0.98);
  EXPECT_GT(between, 15);
  EXPECT_LT(age_lo, 22);
  EXPECT_GT(age_hi, 85);
  EXPECT_LT(w_lo, 0.05);
  EXPECT_GT(w_hi, 0.95);
  EXPECT_LT(s_lo, 1480);
  EXPECT_GT(s_hi, 1950);
  for (int c = 0; c < 5; ++c) EXPECT_GT(cases[c], 20) << c;
  // The default population is untouched by the full one's existence.
  MakeHumanBodyOptions d;
  d.seed = 7;
  EXPECT_TRUE(MakeHumanDraw(d).shape.empty());
  EXPECT_EQ(MakeHumanDraw(d).hard_case, 0);
}

TEST(MakeHumanPopulation, HardCaseThighsTouch) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  // The gap between the thighs 20-100 mm below the crotch: right-leg
  // vertices' smallest x minus left-leg vertices' largest x (<= 0: touching).
  const auto thigh_gap = [&](const Body& body) {
    const double crotch = At(body, "crotch").z();
    double right = 1e9, left = -1e9;
    for (Eigen::Index v = 0; v < body.mesh.num_vertices(); ++v) {
      const double z = body.mesh.vertices(v, 2);
      if (z > crotch - 20 || z < crotch - 100) continue;
      const bool is_right = model.base_body().vertices(v, 0) < 0;  // MakeHuman's -x is the right
      (is_right ? right : left) = is_right ? std::min(right, body.mesh.vertices(v, 0))
                                           : std::max(left, body.mesh.vertices(v, 0));
    }
    return right - left;
  };
  int touching_hard = 0, hard = 0, touching_other = 0, other = 0;
  MakeHumanBodyOptions o;
  o.population = "full";
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    o.seed = seed;
    const Body body = GenerateMakeHumanBody(o, &model);
    const bool is_hard = body.parameters.at("hard_case") == 1;
    const bool touching = thigh_gap(body) <= 1.0;
    (is_hard ? hard : other) += 1;
    (is_hard ? touching_hard : touching_other) += touching;
  }
  std::printf(
      "full population seeds 1-40: thighs touching in %d of %d 'thighs_touch' bodies, "
      "%d of %d others\n",
      touching_hard, hard, touching_other, other);
  ASSERT_GT(hard, 3);
  EXPECT_GE(touching_hard, hard * 3 / 4);
}

// The hull perimeter (mm) of the horizontal loop at height z that encloses
// (`enclosing`) or lies nearest to `at`'s (x, y); 0 when there is none.
double HullGirthAt(const Body& body, double z, const Eigen::Vector3d& at, bool enclosing) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitZ(), p(at.x(), at.y(), z);
  const auto loops = SectionLoops(body.mesh, Eigen::Vector3d(0, 0, z), up);
  const int i = enclosing ? EnclosingLoop(loops, p, up) : NearestLoop(loops, p);
  return i < 0 ? 0 : LoopHullPerimeter(loops[static_cast<std::size_t>(i)], up);
}

// The trunk's hull perimeter at height z (the loop around the midpoint of the
// front and back waist points).
double TrunkGirthAt(const Body& body, double z) {
  return HullGirthAt(body, z, 0.5 * (At(body, "front_waist") + At(body, "back_waist")), true);
}

TEST(DefinedLandmarks, TheWaistIsTheNarrowestSectionAndMovesWithTheBelly) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  MakeHumanBodyOptions o;
  o.seed = 2;
  o.shape["stomach-pregnant"] = -0.3;
  const Body flat = GenerateMakeHumanBody(o, &model);
  o.shape["stomach-pregnant"] = 1;
  const Body belly = GenerateMakeHumanBody(o, &model);
  o.defined_landmarks = false;
  const Body table = GenerateMakeHumanBody(o, &model);
  for (const Body* body : {&flat, &belly}) {
    const double z = body->parameters.at("level.waist_mm");
    EXPECT_NEAR(At(*body, "front_waist").z(), z, 1.5);
    const double hip = body->parameters.at("level.hip_mm");
    const double top = At(*body, "under_bust").z();
    const double span = top - hip, at = TrunkGirthAt(*body, z);
    // No level of the band is narrower (the search refines to 0.5 mm).
    for (double zz = hip + 0.3 * span; zz <= hip + 0.85 * span; zz += 1)
      EXPECT_GE(TrunkGirthAt(*body, zz), at - 0.5) << zz;
  }
  const double moved = belly.parameters.at("level.waist_mm") - flat.parameters.at("level.waist_mm");
  std::printf("waist level: flat belly %.1f mm, big belly %.1f mm; table vertex at %.1f mm\n",
              flat.parameters.at("level.waist_mm"), belly.parameters.at("level.waist_mm"),
              At(table, "front_waist").z());
  EXPECT_GT(std::abs(moved), 10);  // the definition decides, not a vertex
  // Calf: the calf point is at its level.
  const double calf = belly.parameters.at("level.calf_right_mm");
  EXPECT_NEAR(At(belly, "calf_right").z(), calf, 1.5);
}

// The under-bust goes just below the breasts. On these full-range bodies
// (arms 30 deg) the fold read on the bust points' verticals lies on the
// breasts' lower part: seed 2028's breasts hang inwards, their lowest
// point 4-5 mm below that fold; seed 1003's underside slopes down to the
// chest wall. At that fold the girth is 65 and 37 mm over the section's
// 5 mm lower (827.5 / 762.5, 950.1 / 913.0 mm). At the level the girth
// must not rise over the 5 mm below it more than 10 mm (2 mm per mm)
// faster than over the 5 mm below those, which the chest wall's own
// widening does not reach.
TEST(DefinedLandmarks, TheUnderBustIsJustBelowTheBreasts) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  for (std::uint64_t seed : {2028, 1003}) {
    const Body body = Posed(&model, seed, "arms-30", "full");
    const double z = body.parameters.at("level.under_bust_mm");
    const double g0 = TrunkGirthAt(body, z), g5 = TrunkGirthAt(body, z - 5),
                 g10 = TrunkGirthAt(body, z - 10);
    std::printf("seed %d: under-bust %.1f mm, girths %.1f / %.1f / %.1f mm at 0 / -5 / -10 mm\n",
                static_cast<int>(seed), z, g0, g5, g10);
    EXPECT_LE(g0 - g5, g5 - g10 + 10) << "seed " << seed << " (mm)";
  }
}

// The crotch is the bottom of the mid-sagittal seam's U. That bottom is
// flat over 60-90 mm front to back on many bodies, and its lowest vertex
// flips between a front and a back dip a few mm apart in height. The
// vertex of a parabola through the U's bottom stays near its middle: over
// these eight bodies its front-to-back spread is under half the lowest
// vertex's, and it lies within 8 mm above that vertex.
TEST(DefinedLandmarks, TheCrotchIsTheBottomOfTheSeamsU) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  std::vector<int> seam;
  const Eigen::MatrixX3d& base = model.base_body().vertices;
  for (Eigen::Index v = 0; v < base.rows(); ++v)
    if (std::abs(base(v, 0)) < 1e-5) seam.push_back(static_cast<int>(v));
  std::vector<double> crotch_y, lowest_y;
  for (std::uint64_t seed = 1001; seed <= 1008; ++seed) {
    const Body body = Posed(&model, seed, "arms-30", "full");
    const Eigen::Vector3d crotch = At(body, "crotch");
    int lowest = seam.front();
    for (int v : seam)
      if (body.mesh.vertices(v, 2) < body.mesh.vertices(lowest, 2)) lowest = v;
    const Eigen::Vector3d low = body.mesh.vertices.row(lowest).transpose();
    std::printf("seed %d: crotch y %.1f z %.1f mm; lowest seam vertex y %.1f z %.1f mm\n",
                static_cast<int>(seed), crotch.y(), crotch.z(), low.y(), low.z());
    EXPECT_GE(crotch.z(), low.z() - 0.5) << seed;
    EXPECT_LE(crotch.z(), low.z() + 8) << seed;
    crotch_y.push_back(crotch.y()), lowest_y.push_back(low.y());
  }
  const auto spread = [](const std::vector<double>& v) {
    return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
  };
  std::printf("front-to-back spread: crotch %.1f mm, lowest vertex %.1f mm\n", spread(crotch_y),
              spread(lowest_y));
  EXPECT_LT(spread(crotch_y), 0.5 * spread(lowest_y));
}

// A leg's hull perimeter at height z (the loop nearest the point).
double LegGirthAt(const Body& body, double z, const Eigen::Vector3d& near) {
  return HullGirthAt(body, z, near, false);
}

// The calf by definition is the bulge of the lower leg: seed 1035 (full
// population) has a leg whose girth widens again under the knee beyond the
// calf's, and the band's largest girth puts the calf 113 mm higher, 28 mm
// under the knee point. Its level has a narrower section above it in the
// band, and no level below that narrowing is wider.
TEST(DefinedLandmarks, TheCalfIsTheBulgeOfTheLowerLeg) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  MakeHumanBodyOptions o;
  o.seed = 1035;
  o.population = "full";
  const Body body = GenerateMakeHumanBody(o, &model);
  const double knee = At(body, "knee_right").z(), ankle = At(body, "ankle_inside_right").z();
  const double top = ankle + 0.9 * (knee - ankle), low = ankle + 0.25 * (knee - ankle);
  const double calf = body.parameters.at("level.calf_right_mm");
  const Eigen::Vector3d near = At(body, "calf_right");
  const double girth = LegGirthAt(body, calf, near);
  double narrowest = girth, narrowest_z = calf;
  for (double z = calf; z <= top; z += 1) {
    const double g = LegGirthAt(body, z, near);
    if (g < narrowest) narrowest = g, narrowest_z = z;
  }
  std::printf(
      "calf level %.1f mm (band %.1f-%.1f), girth %.1f mm; narrowest above %.1f mm at %.1f\n", calf,
      low, top, girth, narrowest, narrowest_z);
  EXPECT_LT(calf, top - 20);
  EXPECT_GE(girth - narrowest, 3 - 0.5);
  for (double z = low; z <= narrowest_z; z += 1)
    EXPECT_LE(LegGirthAt(body, z, near), girth + 0.5) << z;
}

// The upper-arm point by definition: midway between the shoulder point and
// the elbow along that axis, the outermost point of the arm's section
// perpendicular to it. The table's vertex (1704 / 8376) drifts along the arm
// with its shape and posture.
TEST(DefinedLandmarks, TheUpperArmPointIsMidwayOnTheArmsOutside) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  MakeHumanBodyOptions o;
  for (const auto& [seed, population] :
       {std::pair<int, const char*>{2, "default"}, {1005, "full"}}) {
    o.seed = static_cast<std::uint64_t>(seed), o.population = population;
    o.defined_landmarks = true;
    const Body body = GenerateMakeHumanBody(o, &model);
    o.defined_landmarks = false;
    const Body table = GenerateMakeHumanBody(o, &model);
    for (const std::string side : {"right", "left"}) {
      SCOPED_TRACE(std::to_string(seed) + " " + side);
      const Eigen::Vector3d shoulder = At(body, "shoulder_" + side),
                            elbow = At(body, "elbow_" + side);
      const Eigen::Vector3d axis = (elbow - shoulder).normalized(),
                            p = At(body, "upper_arm_" + side);
      const double half = 0.5 * (elbow - shoulder).norm();
      EXPECT_NEAR((p - shoulder).dot(axis), half, 0.5);  // mm
      const Eigen::Vector3d lateral(side == "right" ? 1 : -1, 0, 0);
      const Eigen::Vector3d outward = (lateral - lateral.dot(axis) * axis).normalized();
      const auto loops = SectionLoops(body.mesh, p, axis);
      const int arm = NearestLoop(loops, p);
      ASSERT_GE(arm, 0);
      const SectionLoop& loop = loops[static_cast<std::size_t>(arm)];
      EXPECT_LT(DistanceToLoop(loop, p), 0.5);                              // mm
      EXPECT_LE((loop.points * outward).maxCoeff(), p.dot(outward) + 0.5);  // mm
      // Outside the axis (the acromion sits on the shoulder's outer edge, so
      // the axis runs just inside the arm's outside).
      EXPECT_GT((p - shoulder - (p - shoulder).dot(axis) * axis).dot(outward), 0);
      const double table_t = (At(table, "upper_arm_" + side) - shoulder).dot(axis);
      std::printf("seed %d %s: upper arm %.1f mm down the %.1f mm axis; the table's vertex %.1f\n",
                  seed, side.c_str(), (p - shoulder).dot(axis), 2 * half, table_t);
    }
  }
}

// The ankle girth by ISO 8559-1 is the minimum girth above the malleoli. On
// these bodies the leg's section narrows for 40-80 mm above the outer ankle
// bone (at the bone the horizontal plane also cuts the heel and instep and
// its girth changes 2-4 mm per mm of height); the truth is the smallest
// section of the band up to the calf, every millimetre.
TEST(DefinedLandmarks, TheAnkleGirthIsTheNarrowestAboveTheMalleoli) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  for (std::uint64_t seed : {1035, 1041}) {
    MakeHumanBodyOptions o;
    o.seed = seed;
    o.population = "full";
    const Body body = GenerateMakeHumanBody(o, &model);
    const ReferenceMeasurements r =
        ComputeReferenceMeasurements(ReferenceOptions(), Catalogue::Builtin(), body);
    double truth = 0;
    for (const ReferenceMeasurement& m : r.measurements)
      if (m.name == "ankle_girth") truth = m.value_mm;
    const Eigen::Vector3d ankle = At(body, "ankle_outside_right");
    const double at_bone = LegGirthAt(body, ankle.z(), ankle);
    double narrowest = at_bone;
    for (double z = ankle.z(); z <= At(body, "calf_right").z(); z += 5)
      narrowest =
          std::min(narrowest, LegGirthAt(body, z, Eigen::Vector3d(ankle.x(), ankle.y(), z)));
    std::printf("seed %d: ankle girth %.1f mm, at the bone %.1f, narrowest of a 5 mm sweep %.1f\n",
                static_cast<int>(seed), truth, at_bone, narrowest);
    EXPECT_LE(truth, narrowest + 0.01);
    EXPECT_GT(at_bone - truth, 20);
  }
}

}  // namespace
}  // namespace bespoke
