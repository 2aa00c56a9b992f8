// The parametric body's anatomical points by MakeHuman's rules: each point
// is checked against its rule's definition on the body itself (extremes and
// levels found here by brute force over the mesh), not against the code's
// own numbers.
#include "oracle/synth/rule_landmarks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "oracle/truth/mesh_section.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

struct Placed {
  Body construction, rule;
  ParametricBodyDetails details;
};

Placed Place(std::uint64_t seed, double arm_deg) {
  ParametricBodyOptions options;
  options.seed = seed;
  options.arm_abduction_deg = arm_deg;
  options = SeededOptions(options, "full");
  Placed p;
  p.construction = GenerateParametricBody(options, &p.details);
  p.rule = p.construction;
  PlaceRuleLandmarks(RuleLandmarkOptions{}, options, p.details, &p.rule);
  return p;
}

Eigen::Vector3d At(const Body& body, const std::string& name) {
  return PositionOf(body.mesh, body.landmarks.at(name));
}

TEST(RuleLandmarks, ShoulderIsTheCapsOutwardUpExtreme) {
  const Placed p = Place(3, 30);
  const Eigen::Vector3d s = p.details.joints.at("r-shoulder");
  const Eigen::Vector3d acromion = At(p.rule, "shoulder_right");
  // No vertex of the rule's region (near the joint's coronal plane, above
  // 20 mm under the joint) lies further along the outward-up diagonal.
  double best = -1e9;
  for (Eigen::Index v = 0; v < p.rule.mesh.vertices.rows(); ++v) {
    const Eigen::Vector3d q = p.rule.mesh.vertices.row(v).transpose();
    if (std::abs(q.y() - s.y()) < 25 && q.z() > s.z() - 20 && q.x() > s.x() - 60)
      best = std::max(best, q.x() + q.z());
  }
  EXPECT_NEAR(acromion.x() + acromion.z(), best, 1e-6);
  // It lies on the arm's cap, outward of the construction's point on the
  // torso's side and below it.
  const Eigen::Vector3d built = At(p.construction, "shoulder_right");
  EXPECT_GT(acromion.x(), built.x() + 20);
  EXPECT_LT(acromion.z(), built.z());
  const Eigen::Vector3d left = At(p.rule, "shoulder_left");
  EXPECT_LT((left - Eigen::Vector3d(-acromion.x(), acromion.y(), acromion.z())).norm(), 1.0);
}

TEST(RuleLandmarks, ThighIsTheLegsLateralExtremeUnderTheCrotch) {
  const Placed p = Place(5, 30);
  const Eigen::Vector3d crotch = At(p.rule, "crotch"), thigh = At(p.rule, "thigh_right");
  EXPECT_NEAR(thigh.z(), crotch.z() - 20, 0.5);
  // The right leg's section at that level: of the loops right of the
  // midline, the most medial (a hanging hand may be cut further out).
  double x_min = 1e9, x_max = 0;
  for (const SectionLoop& loop :
       SectionLoops(p.rule.mesh, Eigen::Vector3d(0, 0, thigh.z()), Eigen::Vector3d::UnitZ())) {
    const double lo = loop.points.col(0).minCoeff();
    if (lo > 0 && lo < x_min) x_min = lo, x_max = loop.points.col(0).maxCoeff();
  }
  EXPECT_NEAR(thigh.x(), x_max, 0.5);
}

TEST(RuleLandmarks, AxillaFoldsAreAboveTheArmpitInFrontAndBehind) {
  const Placed p = Place(7, 30);
  const Eigen::Vector3d armpit = At(p.rule, "armpit_right"),
                        shoulder = At(p.rule, "shoulder_right");
  const Eigen::Vector3d front = At(p.rule, "axilla_front_right"),
                        back = At(p.rule, "axilla_back_right");
  EXPECT_NEAR(front.z(), back.z(), 0.5);  // one section
  // A quarter of the way up from the saddle, which lies within 15 mm above
  // the construction's armpit.
  const double quarter = armpit.z() + 0.25 * (shoulder.z() - armpit.z());
  EXPECT_GT(front.z(), quarter - 1);
  EXPECT_LT(front.z(), quarter + 15);
  EXPECT_GT(front.y(), armpit.y());
  EXPECT_LT(back.y(), armpit.y());
  const Eigen::Vector3d left = At(p.rule, "axilla_front_left");
  EXPECT_LT((left - Eigen::Vector3d(-front.x(), front.y(), front.z())).norm(), 1.0);
}

// The rules run on the A-pose; the torso does not move with the arms, so a
// raised arm keeps the torso's points. A T-posed body keeps the
// construction's shoulder point; one at 45 deg takes the rule's.
TEST(RuleLandmarks, RaisedArmsKeepTheTorsosPoints) {
  const Placed a = Place(3, 30), t = Place(3, 90), mid = Place(3, 45);
  for (const char* name : {"thigh_right", "thigh_left"})
    EXPECT_LT((At(a.rule, name) - At(t.rule, name)).norm(), 1.0) << name;
  EXPECT_LT((At(t.rule, "shoulder_right") - At(t.construction, "shoulder_right")).norm(), 1e-9);
  EXPECT_LT((At(mid.rule, "shoulder_right") - At(a.rule, "shoulder_right")).norm(), 15);
  EXPECT_GT((At(mid.rule, "shoulder_right") - At(mid.construction, "shoulder_right")).norm(), 30);
  // The folds lie where the arm's root meets the chest and the back, whose
  // arm-side faces turn with the arm: each stays within a ring spacing
  // (15 mm) of the A-pose's.
  for (const char* name : {"axilla_front_right", "axilla_back_right"})
    EXPECT_LT((At(a.rule, name) - At(t.rule, name)).norm(), 15) << name;
}

TEST(RuleLandmarks, BadRestPoseIsAnInputError) {
  RuleLandmarkOptions o;
  o.rest_abduction_deg = 60;
  EXPECT_THROW(o.Check(), InputError);
  o = RuleLandmarkOptions{};
  o.max_shoulder_abduction_deg = 20;  // below the rest pose
  EXPECT_THROW(o.Check(), InputError);
}

}  // namespace
}  // namespace bespoke
