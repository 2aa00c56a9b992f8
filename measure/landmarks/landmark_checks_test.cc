#include "measure/landmarks/landmark_checks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

namespace bespoke::landmarks {
namespace {

constexpr double kStatureMm = 1700;

bool HasFlag(const LandmarkSet& set, const std::string& name, const std::string& flag) {
  const std::vector<std::string>& f = set.points.at(name).flags;
  return std::find(f.begin(), f.end(), flag) != f.end();
}

// A plausible adult: every point at its survey height (share of stature),
// x = +-100 mm for the paired points.
LandmarkSet PlausibleBody() {
  const std::map<std::string, double> shares = {{"crotch", 0.47},      {"armpit", 0.73},
                                                {"shoulder", 0.82},    {"back_neck", 0.85},
                                                {"front_neck", 0.81},  {"side_neck", 0.84},
                                                {"bust", 0.71},        {"under_bust", 0.68},
                                                {"front_waist", 0.61}, {"back_waist", 0.61},
                                                {"side_waist", 0.61},  {"hip_back", 0.50},
                                                {"hip", 0.50},         {"middle_hip_front", 0.555},
                                                {"thigh", 0.46},       {"knee", 0.28},
                                                {"calf", 0.20},        {"ankle_inside", 0.04},
                                                {"upper_arm", 0.70}};
  LandmarkSet set;
  for (const auto& [name, share] : shares) {
    Landmark l;
    l.confidence = 0.8;
    l.position_mm = Eigen::Vector3d(0, 0, share * kStatureMm);
    const bool centre = name == "crotch" || name == "back_neck" || name == "front_neck" ||
                        name == "under_bust" || name == "front_waist" || name == "back_waist" ||
                        name == "hip_back" || name == "middle_hip_front";
    if (centre) {
      set.points[name] = l;
      continue;
    }
    for (int sign : {+1, -1}) {
      l.position_mm.x() = sign * 100.0;
      set.points[name + (sign > 0 ? "_right" : "_left")] = l;
    }
  }
  return set;
}

TEST(LandmarkChecks, APlausibleBodyKeepsEveryPoint) {
  LandmarkSet set = PlausibleBody();
  CheckLandmarks(&set, kStatureMm);
  for (const auto& [name, l] : set.points) {
    EXPECT_TRUE(l.flags.empty()) << name;
    EXPECT_DOUBLE_EQ(l.confidence, 0.8) << name;
  }
}

// A crotch at 0.38 of stature (found at mid-thigh) is implausible, and so
// is everything placed from it: the thighs 20 mm under it, the knees from
// its height, the calves from the knees, the hip level searched above it
// and the hip's sides at that level. The arms and the bust do not depend
// on it.
TEST(LandmarkChecks, PointsPlacedFromAnImplausibleCrotchAreFlagged) {
  LandmarkSet set = PlausibleBody();
  set.points.at("crotch").position_mm.z() = 0.38 * kStatureMm;
  CheckLandmarks(&set, kStatureMm);
  EXPECT_TRUE(HasFlag(set, "crotch", "implausible"));
  EXPECT_LE(set.points.at("crotch").confidence, 0.3);
  for (const char* name : {"thigh_right", "thigh_left", "knee_right", "knee_left", "calf_right",
                           "calf_left", "hip_back", "hip_right", "hip_left", "middle_hip_front",
                           "front_waist", "back_waist", "side_waist_right"}) {
    EXPECT_TRUE(HasFlag(set, name, "from_implausible")) << name;
    EXPECT_LE(set.points.at(name).confidence, 0.4) << name;
  }
  // Each names the point it was placed from.
  EXPECT_NE(set.points.at("thigh_right").method.find("implausible crotch"), std::string::npos);
  EXPECT_NE(set.points.at("hip_left").method.find("implausible hip_back"), std::string::npos);
  EXPECT_NE(set.points.at("calf_left").method.find("implausible knee_left"), std::string::npos);
  for (const char* name : {"bust_right", "armpit_left", "shoulder_right", "under_bust",
                           "ankle_inside_right", "upper_arm_left"})
    EXPECT_TRUE(set.points.at(name).flags.empty()) << name;
}

// A shoulder point out of its range takes the side neck and the upper-arm
// point (placed along the arm from it) of its side along, not the other side.
TEST(LandmarkChecks, AnImplausibleShoulderFlagsItsOwnSide) {
  LandmarkSet set = PlausibleBody();
  set.points.at("shoulder_right").position_mm.z() = 0.74 * kStatureMm;
  CheckLandmarks(&set, kStatureMm);
  EXPECT_TRUE(HasFlag(set, "shoulder_right", "implausible"));
  EXPECT_TRUE(HasFlag(set, "side_neck_right", "from_implausible"));
  EXPECT_TRUE(HasFlag(set, "upper_arm_right", "from_implausible"));
  EXPECT_TRUE(set.points.at("upper_arm_left").flags.empty());
  // 0.08 of stature (136 mm) apart: the pair is also lopsided.
  EXPECT_TRUE(HasFlag(set, "shoulder_left", "asymmetric"));
}

TEST(LandmarkChecks, LopsidedPairsAreFlaggedOnBothSides) {
  LandmarkSet set = PlausibleBody();
  set.points.at("knee_left").position_mm.z() += 45;
  CheckLandmarks(&set, kStatureMm);
  EXPECT_TRUE(HasFlag(set, "knee_left", "asymmetric"));
  EXPECT_TRUE(HasFlag(set, "knee_right", "asymmetric"));
  EXPECT_LE(set.points.at("knee_right").confidence, 0.4);
  EXPECT_TRUE(set.points.at("calf_right").flags.empty());
}

}  // namespace
}  // namespace bespoke::landmarks
