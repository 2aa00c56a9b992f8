// The landmark detector on virtual scans of generated bodies, against their
// exact datum points (mm): parametric bodies in an A-pose, a T-pose and with
// the arms close to the torso, a scan with a big hole at the armpit, and
// (with ../shared) MakeHuman bodies. Tolerances are per landmark group, in
// mm, set from measured errors (docs/landmarks.md has the evaluation over
// more subjects: build/eval/bench/landmark_eval).
#include "measure/landmarks/landmarks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include "measure/catalogue/catalogue.h"
#include "measure/landmarks/landmark_slices.h"
#include "oracle/body/parametric_body.h"
#include "oracle/makehuman/makehuman_body.h"
#include "oracle/makehuman/makehuman_pose.h"
#include "oracle/scan_sim/scanned_body.h"
#include "oracle/synth/rule_landmarks.h"
#include "oracle/truth/defined_landmarks.h"
#include "oracle/truth/mesh_section.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

// A tolerance on the 3-D distance (`dz_only` false) or on the height
// difference (true), for the landmarks whose name starts with `prefix`.
struct Tolerance {
  const char* prefix;
  double mm;
  bool dz_only = false;
};

bool StartsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// Checks every truth landmark matched by a tolerance; prints every error.
void ExpectWithin(const LandmarkSet& set, const std::map<std::string, Eigen::Vector3d>& truth,
                  const std::vector<Tolerance>& tolerances, const std::string& what) {
  for (const auto& [name, point] : truth) {
    const auto tol = std::find_if(tolerances.begin(), tolerances.end(),
                                  [&](const Tolerance& t) { return StartsWith(name, t.prefix); });
    if (!set.Has(name)) {
      ADD_FAILURE() << what << ": " << name
                    << " missing: " << (set.missing.count(name) ? set.missing.at(name) : "?");
      continue;
    }
    const Eigen::Vector3d d = set.At(name).position_mm - point;
    std::printf("%s %-22s %6.1f mm (dz %6.1f) %s\n", what.c_str(), name.c_str(), d.norm(), d.z(),
                tol == tolerances.end() ? "(not checked)" : "");
    if (tol == tolerances.end()) continue;
    const double error = tol->dz_only ? std::abs(d.z()) : d.norm();
    EXPECT_LE(error, tol->mm) << what << ": " << name << (tol->dz_only ? " height" : "")
                              << " error (mm)";
  }
}

// Parametric bodies, their anatomical points placed by MakeHuman's rules
// (oracle/synth/rule_landmarks.h) and the points a level defines by that
// definition, as the oracle's subjects are. The tolerances of the points
// both models place by the same rule are MakeHuman's (kMakeHuman). Not
// checked: back neck (the construction's neck ring, 25 mm above where the
// detector puts it); the crotch only in height (the construction's crotch is
// the middle of the bridge vertices). The bust points stand out of the
// cleavage (MakeHuman's tolerance).
const std::vector<Tolerance> kParametricA = {
    {"crown", 15},      {"crotch", 10, true}, {"front_neck", 15},  {"armpit", 35},
    {"bust", 45},       {"under_bust", 50},   {"front_waist", 60}, {"back_waist", 60},
    {"side_waist", 60}, {"middle_hip", 35},   {"hip_back", 15},    {"hip_", 20},
    {"knee", 20},       {"ankle", 30},        {"wrist", 45},       {"elbow", 70},
    {"side_neck", 30},  {"shoulder", 40},     {"axilla", 35},      {"thigh", 40},
    {"upper_arm", 90},
};

struct ParametricCase {
  std::uint64_t seed;
  double arm_deg;
};

// The parametric body of `options`, scanned (`scan_seed`) and cleaned into
// the body frame, with its truth: the datum points the catalogue defines by
// a level placed by that definition, as the oracle's subjects are (a body
// without a waist narrowing has its construction waist elsewhere than the
// narrowest section in the band).
testing::ScannedBody ScannedParametricBody(const ParametricBodyOptions& options,
                                           std::uint64_t scan_seed, Body* out = nullptr) {
  ParametricBodyDetails details;
  Body body = GenerateParametricBody(options, &details);
  PlaceRuleLandmarks(RuleLandmarkOptions{}, options, details, &body);  // as oracle/synth does
  PlaceDefinedLandmarks(DefinedLandmarkOptions{}, {}, &body);
  testing::ScannedBodyOptions scan_options;
  scan_options.scan_seed = scan_seed;
  testing::ScannedBody scan = testing::ScanAndClean(scan_options, body);
  if (out) *out = std::move(body);
  return scan;
}

// The parametric body of `seed` (`population` as SeededOptions') with its
// arms at `arm_deg`, scanned with scanner seed = body seed.
testing::ScannedBody ScannedParametric(std::uint64_t seed, double arm_deg, Body* out = nullptr,
                                       const std::string& population = "default") {
  ParametricBodyOptions options;
  options.seed = seed;
  options = SeededOptions(options, population);
  options.arm_abduction_deg = arm_deg;
  return ScannedParametricBody(options, seed, out);
}

// The exact leg girth (hull of the mesh's leg loop, mm) at mesh height z,
// of the leg nearest `near` (mesh frame).
double MeshLegGirth(const Body& body, double z, const Eigen::Vector3d& near) {
  const std::vector<SectionLoop> loops =
      SectionLoops(body.mesh, Eigen::Vector3d(0, 0, z), Eigen::Vector3d::UnitZ());
  const int i = NearestLoop(loops, Eigen::Vector3d(near.x(), near.y(), z));
  return i < 0 ? 0 : LoopHullPerimeter(loops[static_cast<size_t>(i)], Eigen::Vector3d::UnitZ());
}

class ParametricLandmarks : public ::testing::TestWithParam<ParametricCase> {};

TEST_P(ParametricLandmarks, WithinToleranceOfTheTruth) {
  const ParametricCase c = GetParam();
  Body body;
  const testing::ScannedBody scan = ScannedParametric(c.seed, c.arm_deg, &body);
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  ExpectWithin(set, scan.truth, kParametricA, "parametric seed " + std::to_string(c.seed));
  // The calf is the level of the largest leg girth. The parametric leg's
  // girth rises to the knee and is flat within 3 mm over the band's top
  // 80 mm, so its level is not defined closer than that and is not held to
  // a distance: the leg's exact girth at the found level must be within 1 %
  // of the girth at the true level.
  for (const char* name : {"calf_right", "calf_left"}) {
    ASSERT_TRUE(set.Has(name)) << name;
    const Eigen::Vector3d mesh_calf = PositionOf(body.mesh, body.landmarks.at(name));
    const double z = set.At(name).position_mm.z() + (mesh_calf.z() - scan.truth.at(name).z());
    const double found = MeshLegGirth(body, z, mesh_calf),
                 truth = MeshLegGirth(body, mesh_calf.z(), mesh_calf);
    std::printf("parametric seed %d %s leg girth %.1f mm at the found level, %.1f at the true\n",
                static_cast<int>(c.seed), name, found, truth);
    EXPECT_GE(found, 0.99 * truth) << name << " (mm)";
  }
}

// Arms at 30 deg (A-pose) and at 15 deg, the closest the parametric body
// allows (a gap of a few centimetres at the elbow).
INSTANTIATE_TEST_SUITE_P(APose, ParametricLandmarks,
                         ::testing::Values(ParametricCase{1, 30}, ParametricCase{2, 30},
                                           ParametricCase{4, 15}));

// The body parts that measuring uses to keep arms out of trunk girths: with
// the arms at 15 deg (hands a few centimetres from the hips), the points
// round the true wrists are the arms', those round the true waist and hip
// points the trunk's, and FindBodyParts gives what DetectLandmarks found.
TEST(ParametricLandmarks, ArmsBesideTheTrunkAreTheirOwnPart) {
  const testing::ScannedBody scan = ScannedParametric(4, 15);
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  ASSERT_EQ(set.parts.size(), static_cast<std::size_t>(scan.cloud.size()));
  EXPECT_TRUE(FindBodyParts(scan.cloud) == set.parts);
  // Share of the cloud's points within 25 mm of `name`'s true position that carry `part`.
  const auto share = [&](const std::string& name, ScanPart part) {
    int near = 0, hits = 0;
    for (Eigen::Index r = 0; r < scan.cloud.size(); ++r) {
      if ((scan.cloud.points.row(r).transpose() - scan.truth.at(name)).norm() > 25) continue;
      ++near, hits += set.parts[static_cast<std::size_t>(r)] == part;
    }
    return near > 0 ? static_cast<double>(hits) / near : 0.0;
  };
  EXPECT_GE(share("wrist_right", ScanPart::kArmRight), 0.9);
  EXPECT_GE(share("wrist_left", ScanPart::kArmLeft), 0.9);
  // Up to the armpit's height the arm's side of the armpit is all arm: the
  // outside of the upper arm too, whose geodesic distance from the hand
  // exceeds the armpit's.
  for (const auto& [name, part] : {std::pair{"armpit_right", ScanPart::kArmRight},
                                   std::pair{"armpit_left", ScanPart::kArmLeft}}) {
    const Eigen::Vector3d armpit = scan.truth.at(name);
    int lateral = 0, hits = 0;
    for (Eigen::Index r = 0; r < scan.cloud.size(); ++r) {
      const Eigen::Vector3d p = scan.cloud.points.row(r).transpose();
      if (p.z() < armpit.z() - 40 || p.z() > armpit.z() || p.x() * armpit.x() < 0 ||
          std::abs(p.x()) < std::abs(armpit.x()) + 40)
        continue;
      ++lateral, hits += set.parts[static_cast<std::size_t>(r)] == part;
    }
    ASSERT_GT(lateral, 50) << name;
    EXPECT_GE(static_cast<double>(hits) / lateral, 0.95)
        << name << ": " << hits << " of " << lateral;
  }
  for (const char* name : {"front_waist", "back_waist", "side_waist_right", "side_waist_left",
                           "hip_right", "hip_left", "bust_right", "bust_left"})
    EXPECT_GE(share(name, ScanPart::kTrunk), 0.9) << name;
}

TEST(ParametricLandmarks, TPose) {
  const testing::ScannedBody scan = ScannedParametric(3, 90);
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  // The T-posed hands are not in the cleaned cloud (it ends ~490 mm from the
  // shoulder; booth view or cleaning, not checked): the arm's end points must be
  // reported missing with the reason, not guessed.
  for (const char* name : {"wrist_right", "wrist_left", "elbow_right", "elbow_left"}) {
    EXPECT_FALSE(set.Has(name)) << name;
    ASSERT_TRUE(set.missing.count(name)) << name;
    EXPECT_NE(set.missing.at(name).find("not in the scan"), std::string::npos)
        << set.missing.at(name);
  }
  std::map<std::string, Eigen::Vector3d> truth = scan.truth;
  for (const char* name : {"wrist", "elbow", "upper_arm", "axilla"}) {
    for (auto it = truth.begin(); it != truth.end();)
      it = StartsWith(it->first, name) ? truth.erase(it) : std::next(it);
  }
  // First match wins. The T-pose armpit lies under the arm's bend; the
  // shoulder points must be on the shoulders, not out on the arms (a raised
  // arm keeps the construction's point, the armscye's top corner:
  // oracle/synth/rule_landmarks.h).
  std::vector<Tolerance> t_pose = {{"armpit", 60}, {"shoulder", 45}};
  t_pose.insert(t_pose.end(), kParametricA.begin(), kParametricA.end());
  ExpectWithin(set, truth, t_pose, "T-pose");
  for (const char* name : {"shoulder_right", "shoulder_left"}) {  // and at the shoulder's height
    if (set.Has(name)) {
      EXPECT_LE(std::abs(set.At(name).position_mm.z() - truth.at(name).z()), 15.0) << name;
    }
  }
}

// A T-posed arm reaching past the booth's view: beyond it the cleaned cloud
// keeps a thin trail of grazing and stray returns (0-5 % of the points per
// mm of the arm's middle). On body 1001, judged at the trail's end, one
// side's stray normals pass as a hand and its wrist lands 102 mm up the
// forearm at the edge of the view. The
// end is judged where the arm is still seen in full: each wrist is missing
// with the reason, or where the truth is.
TEST(ParametricLandmarks, TPosedArmsGrazedPastTheViewAreNotReadAsHands) {
  ParametricBodyOptions options;
  options.seed = 1001;
  options = SeededOptions(options, "default");
  options.arm_abduction_deg = 90;
  ParametricBodyDetails details;
  Body body = GenerateParametricBody(options, &details);
  PlaceRuleLandmarks(RuleLandmarkOptions{}, options, details, &body);
  PlaceDefinedLandmarks(DefinedLandmarkOptions{}, {}, &body);
  testing::ScannedBodyOptions scan_options;  // the default booth's depth images
  scan_options.scan_seed = 1001;
  scan_options.width_px = 240, scan_options.height_px = 180;
  scan_options.random_transform = false;
  const testing::ScannedBody scan = testing::ScanAndClean(scan_options, body);
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  for (const char* name : {"wrist_right", "wrist_left"}) {
    if (!set.Has(name)) {
      ASSERT_TRUE(set.missing.count(name)) << name;
      EXPECT_NE(set.missing.at(name).find("not in the scan"), std::string::npos)
          << set.missing.at(name);
      continue;
    }
    EXPECT_LE((set.At(name).position_mm - scan.truth.at(name)).norm(), 45.0) << name;
  }
}

// A big hole at the right armpit (every point within 40 mm removed, as a
// badly occluded scan would have): the armpit is still placed, within the
// hole's size of the truth, from the gap between arm and trunk below it.
TEST(ParametricLandmarks, HoleAtTheArmpit) {
  ParametricBodyOptions options;
  options.seed = 1;
  const Body body = GenerateParametricBody(options);
  testing::ScannedBodyOptions scan_options;
  scan_options.scan_seed = 1;
  testing::ScannedBody scan = testing::ScanAndClean(scan_options, body);
  const Eigen::Vector3d armpit = scan.truth.at("armpit_right");
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < scan.cloud.size(); ++i) {
    if ((scan.cloud.points.row(i).transpose() - armpit).norm() > 40) keep.push_back(i);
  }
  ASSERT_LT(keep.size(), static_cast<size_t>(scan.cloud.size()) - 50)
      << "the hole removed too few points";
  scan.cloud = scan.cloud.Select(keep);
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  ASSERT_TRUE(set.Has("armpit_right")) << set.missing.at("armpit_right");
  const Landmark& found = set.At("armpit_right");
  const double error = (found.position_mm - armpit).norm();
  std::printf("armpit in a 40 mm hole: error %.1f mm, flags %zu\n", error, found.flags.size());
  EXPECT_LE(error, 50.0) << "mm";
  EXPECT_LE(std::abs(found.position_mm.z() - armpit.z()), 40.0) << "mm, height";
  // The rest of the chest is unaffected.
  EXPECT_LE((set.At("bust_right").position_mm - scan.truth.at("bust_right")).norm(), 35.0);
  EXPECT_LE((set.At("armpit_left").position_mm - scan.truth.at("armpit_left")).norm(), 35.0);
}

// Thighs that touch: the scan's thighs moved together until they meet along
// a contact no sensor sees (testing::SqueezeThighs). The feet's path then
// crosses the contact at mid-thigh; the crotch must still be found at the
// top of the contact, flagged, and the trunk's levels must not follow it
// down. Seeds other than those the rule was developed on.
TEST(ParametricLandmarks, ThighsThatTouch) {
  for (std::uint64_t seed : {5, 6}) {
    ParametricBodyOptions options;
    options.seed = seed;
    testing::ScannedBodyOptions scan_options;
    scan_options.scan_seed = seed;
    testing::ScannedBody scan =
        testing::ScanAndClean(scan_options, GenerateParametricBody(options));
    testing::SqueezeThighs(40, &scan);
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    const Landmark& crotch = set.At("crotch");
    const double dz = crotch.position_mm.z() - scan.truth.at("crotch").z();
    std::printf("seed %d touching thighs: crotch dz %.1f mm, confidence %.2f\n",
                static_cast<int>(seed), dz, crotch.confidence);
    EXPECT_LE(std::abs(dz), 15.0) << "mm";
    EXPECT_LT(crotch.confidence, 0.5);
    EXPECT_NE(std::find(crotch.flags.begin(), crotch.flags.end(), "thighs_touching"),
              crotch.flags.end());
    for (const char* name : {"hip_back", "front_waist"})
      EXPECT_LE(std::abs(set.At(name).position_mm.z() - scan.truth.at(name).z()), 30.0) << name;
  }
}

// Sparse scans: the booth at 120 x 90 px per sensor (about 50k-80k cleaned
// points, half of the default). In a thin slice the trunk's section then breaks
// up near the armpit, and the piece nearest the trunk's side was a fragment of
// the armpit fold (seeds 13 and 15 here: the left arm was lost; with
// `bespoke scan-sim --resolution 120x90 --seed 2` the arm's piece also held a
// part of the back). Every arm landmark must be found, within the dense
// scan's tolerances; the wrist across its forearm only (on this arm, at its
// end): its station along the parametric body's level forearm is the
// noise's (docs/landmarks.md, known limits: 34 mm apart over ten dense
// scans of one body; 45 mm up the forearm on seed 15 here).
TEST(ParametricLandmarks, SparseScanKeepsBothArms) {
  for (std::uint64_t seed : {2, 13, 15}) {
    ParametricBodyOptions options;
    options.seed = seed;
    const Body body = GenerateParametricBody(options);
    testing::ScannedBodyOptions scan_options;
    scan_options.scan_seed = seed;
    scan_options.width_px = 120;
    scan_options.height_px = 90;
    const testing::ScannedBody scan = testing::ScanAndClean(scan_options, body);
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    const std::string what =
        "seed " + std::to_string(seed) + ", " + std::to_string(scan.cloud.size()) + " points";
    std::map<std::string, Eigen::Vector3d> arms;  // missing ones fail; upper_arm unchecked in mm
    for (const auto& [name, p] : scan.truth)
      for (const char* part : {"upper_arm", "elbow", "armpit"})
        if (StartsWith(name, part)) arms[name] = p;
    ExpectWithin(set, arms, kParametricA, what);
    for (const char* side : {"_right", "_left"}) {
      const std::string wrist = std::string("wrist") + side, elbow = std::string("elbow") + side;
      ASSERT_TRUE(set.Has(wrist)) << what << " " << wrist;
      const Eigen::Vector3d axis = (scan.truth.at(wrist) - scan.truth.at(elbow)).normalized();
      const Eigen::Vector3d d = set.At(wrist).position_mm - scan.truth.at(wrist);
      std::printf("%s %s: %.1f mm across the forearm, %+.1f along\n", what.c_str(), wrist.c_str(),
                  (d - d.dot(axis) * axis).norm(), d.dot(axis));
      EXPECT_LE((d - d.dot(axis) * axis).norm(), 15.0) << what << " " << wrist;  // on this forearm
    }
  }
}

// A MakeHuman body of the full population in `posture`, scanned (scanner
// seed = body seed; `width_px` x `height_px` per sensor, 0: the default
// booth's) and cleaned into the body frame, with its truth.
testing::ScannedBody ScannedFullMakeHuman(MakeHumanModel* model, std::uint64_t seed,
                                          const char* posture, int width_px = 0,
                                          int height_px = 0) {
  MakeHumanBodyOptions options;
  options.seed = seed;
  options.population = "full";
  options.posture = ParseMakeHumanPosture(posture);
  testing::ScannedBodyOptions scan_options;
  scan_options.scan_seed = seed;
  if (width_px > 0) scan_options.width_px = width_px, scan_options.height_px = height_px;
  return testing::ScanAndClean(scan_options, GenerateMakeHumanBody(options, model));
}

// Sparse scans of MakeHuman bodies over the full range (the 60k booth: 99 x
// 75 px per sensor). On the pubis a strip 6 mm either side of x = 0 then
// holds fewer than three points as often as not, which read as the crease
// between touching thighs, and the crotch climbed. The strip widens until it
// holds three. Of seeds 1013-1040, the five where the two rules differ or the
// thighs do touch (1038): with the 6 mm strip alone the crotch was 76, 49,
// 29, 48 and -1 mm off in height; now 16, 6, 11, 25 and -1 mm.
TEST(MakeHumanLandmarks, SparseScanKeepsTheCrotch) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  for (std::uint64_t seed : {1019, 1025, 1027, 1035, 1038}) {
    const testing::ScannedBody scan = ScannedFullMakeHuman(&model, seed, "arms-30", 99, 75);
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    ASSERT_TRUE(set.Has("crotch")) << seed;
    const double dz = set.At("crotch").position_mm.z() - scan.truth.at("crotch").z();
    std::printf("seed %d, %ld points: crotch dz %.1f mm (%s)\n", static_cast<int>(seed),
                static_cast<long>(scan.cloud.size()), dz, set.At("crotch").method.c_str());
    EXPECT_LE(std::abs(dz), 30.0) << seed << " (mm)";
  }
}

// The back of the hip on a sparse scan: seed 1066 (of 1041-1090 at the 60k
// booth, the one where it happened) has no point within 10 mm of x = 0 in the
// gluteal cleft at the hip's level, and the hip girth went unmeasured. A
// 20 mm strip places it; its height is what the girth needs.
TEST(MakeHumanLandmarks, SparseScanFindsTheBackOfTheHip) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  const testing::ScannedBody scan = ScannedFullMakeHuman(&model, 1066, "arms-30", 99, 75);
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  ASSERT_TRUE(set.Has("hip_back")) << set.missing.at("hip_back");
  const double dz = set.At("hip_back").position_mm.z() - scan.truth.at("hip_back").z();
  std::printf("seed 1066 hip_back dz %.1f mm, confidence %.2f\n", dz,
              set.At("hip_back").confidence);
  EXPECT_LE(std::abs(dz), 30.0) << "mm";
}

// An obese body with its arms 5 deg out, on the 250k booth (203 x 152 px):
// its left leg's part (the nodes nearer the foot than the crotch is) reaches
// up the hip's side above the crotch, and the hip point was placed 75 mm
// inside the hip, at its back. The hip's sides are the pelvis section's.
TEST(MakeHumanLandmarks, HipSidesOfAWidePelvis) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  const testing::ScannedBody scan = ScannedFullMakeHuman(&model, 1071, "arms-5", 203, 152);
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  for (const char* name : {"hip_right", "hip_left"}) {
    ASSERT_TRUE(set.Has(name)) << name;
    const double dx = set.At(name).position_mm.x() - scan.truth.at(name).x();
    std::printf("seed 1071 %s dx %.1f mm\n", name, dx);
    EXPECT_LE(std::abs(dx), 15.0) << name << " (mm)";
  }
}

// T-posed MakeHuman bodies of the full range on the 120k booth (141 x 105
// px): the hands are in the scan and every arm point must be found. Seed
// 1206's flat hand has no normal along the arm at its fingertips (the cap
// alone called the arm cut); seed 1207's shoulder point sits out on a heavy
// deltoid, 0.29 of stature from the fingertips.
TEST(MakeHumanLandmarks, TPosedHandsAreInTheScan) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  for (std::uint64_t seed : {1206, 1207}) {
    const LandmarkSet set = DetectLandmarks(
        LandmarkOptions{}, ScannedFullMakeHuman(&model, seed, "arms-90", 141, 105).cloud);
    for (const char* name : {"upper_arm_right", "upper_arm_left", "elbow_right", "elbow_left",
                             "wrist_right", "wrist_left"})
      EXPECT_TRUE(set.Has(name)) << seed << " " << name << ": "
                                 << (set.missing.count(name) ? set.missing.at(name) : "");
  }
}

// MakeHuman bodies (../shared): every catalogue landmark checked.
const std::vector<Tolerance> kMakeHuman = {
    {"crown", 15},      {"crotch", 80},     {"back_neck", 25},   {"front_neck", 25},
    {"side_neck", 30},  {"shoulder", 40},   {"armpit", 35},      {"axilla", 35},
    {"bust", 45},       {"under_bust", 25}, {"front_waist", 30}, {"back_waist", 40},
    {"side_waist", 35}, {"middle_hip", 35}, {"hip_back", 30},    {"hip_", 50},
    {"thigh", 40},      {"knee", 50},       {"calf", 55},        {"ankle", 35},
    {"upper_arm", 90},  {"elbow", 75},      {"wrist", 30},
};

TEST(MakeHumanLandmarks, WithinToleranceOfTheTruth) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  std::vector<double> errors;
  for (std::uint64_t seed : {1001, 1002}) {
    MakeHumanBodyOptions options;
    options.seed = seed;
    const Body body = GenerateMakeHumanBody(options, &model);
    testing::ScannedBodyOptions scan_options;
    scan_options.scan_seed = seed;
    const testing::ScannedBody scan = testing::ScanAndClean(scan_options, body);
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    ExpectWithin(set, scan.truth, kMakeHuman, "makehuman seed " + std::to_string(seed));
    for (const auto& [name, point] : scan.truth) {
      if (set.Has(name)) errors.push_back((set.At(name).position_mm - point).norm());
    }
  }
  std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(errors.size() / 2),
                   errors.end());
  const double median = errors[errors.size() / 2];
  std::printf("MakeHuman median landmark error %.1f mm\n", median);
  // The target is 10 mm; measured 13.0 mm on these two subjects and
  // 12.9 mm over ten (docs/landmarks.md): the gap is stated, not hidden.
  EXPECT_LE(median, 18.0) << "mm";
}

// A heavy body (MakeHuman full population, seed 1007: weight 0.78) whose
// upper arms rest on the trunk's sides in the A-pose: at the bust, 30 mm
// under the armpit, the arm's outside is the arm's (the hand's distance
// alone left it to the trunk, and the bust girth took both arms in, 136 mm
// long). No trunk point lies more than 20 mm beyond the true armpit.
TEST(MakeHumanLandmarks, UpperArmsRestingOnAHeavyTrunkAreTheArms) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  const testing::ScannedBody scan = ScannedFullMakeHuman(&model, 1007, "arms-30");
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  const double bust_z = scan.truth.at("bust_right").z();
  for (const char* name : {"armpit_right", "armpit_left"}) {
    const Eigen::Vector3d armpit = scan.truth.at(name);
    ASSERT_LT(bust_z, armpit.z()) << name;
    int lateral = 0, trunk = 0;
    for (Eigen::Index r = 0; r < scan.cloud.size(); ++r) {
      const Eigen::Vector3d p = scan.cloud.points.row(r).transpose();
      if (std::abs(p.z() - bust_z) > 5 || p.x() * armpit.x() < 0 ||
          std::abs(p.x()) < std::abs(armpit.x()) + 20)
        continue;
      ++lateral, trunk += set.parts[static_cast<std::size_t>(r)] == ScanPart::kTrunk;
    }
    ASSERT_GT(lateral, 50) << name;
    EXPECT_LE(trunk, lateral / 50) << name << ": " << trunk << " of " << lateral << " are trunk";
  }
}

// The bust point on hard cases of the full population (arms 30 deg): a
// heavy woman whose breast hangs just under an armpit found 70 mm low (seed
// 1006; a window below that armpit finds the belly, 180 mm low), a man with a
// belly under a flat chest (seed 1028; the belly's front, 145 mm low) and a
// heavy body whose breast peaks 10 % of stature under the armpit (seed 1058:
// with the fold sought only above 10 % it reads as a belly and the point
// goes 3 % under the armpit, 103 mm off).
TEST(MakeHumanLandmarks, BustPointOverABellyAndUnderALowArmpit) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  for (const auto& [seed, method, tolerance_mm] : {std::tuple{1006, "breast_front_max", 15.0},
                                                   std::tuple{1028, "proportion_above_belly", 40.0},
                                                   std::tuple{1058, "breast_front_max", 15.0}}) {
    const testing::ScannedBody scan = ScannedFullMakeHuman(&model, seed, "arms-30");
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    ASSERT_TRUE(set.Has("bust_right")) << seed;
    EXPECT_EQ(set.At("bust_right").method, method) << seed;
    EXPECT_LE(std::abs(set.At("bust_right").position_mm.z() - scan.truth.at("bust_right").z()),
              tolerance_mm)
        << seed;
  }
}

// Found minus true height (mm) of each of `names` on `scan`, printed with
// the method; a missing point fails the test and gives NaN.
std::vector<double> HeightErrors(const testing::ScannedBody& scan,
                                 const std::vector<const char*>& names, const std::string& what) {
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  std::vector<double> dz;
  for (const char* name : names) {
    EXPECT_TRUE(set.Has(name)) << what << " " << name;
    dz.push_back(set.Has(name) ? set.At(name).position_mm.z() - scan.truth.at(name).z() : kNaN);
    std::printf("%s %s dz %.1f mm (%s)\n", what.c_str(), name, dz.back(),
                set.Has(name) ? set.At(name).method.c_str() : "missing");
  }
  return dz;
}

// Every point of `names` within limit_mm of its true height on the
// full-range MakeHuman bodies of `seeds` in `posture` (default booth).
void ExpectHeightsWithin(MakeHumanModel* model, const std::vector<std::uint64_t>& seeds,
                         const char* posture, const std::vector<const char*>& names,
                         double limit_mm) {
  for (std::uint64_t seed : seeds) {
    const std::string what = "seed " + std::to_string(seed);
    for (double dz : HeightErrors(ScannedFullMakeHuman(model, seed, posture), names, what))
      EXPECT_LE(std::abs(dz), limit_mm) << what << " (mm)";
  }
}

// A heavy body in a T-pose (seed 1068 on the 500k booth, 287 x 215 px): the
// structure's corner lies 118 mm under the true armpit (12-133 mm on the 40
// T-posed bodies of the completeness set), and a search window reaching 100
// mm above it put the armpits 70 mm low, the bust points (sought below them)
// 150 mm low and the under-bust with them. The window reaches 160 mm. The
// bust points, placed by proportion, are still 20-25 mm low, and the fold
// then sits at the top of the under-bust's window: the fitted front's bend
// read only as a strict peak there (FoldOnBends) put it 75 mm low.
TEST(MakeHumanLandmarks, HeavyTPosedArmpitAboveTheStructuresCorner) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  const std::vector<const char*> names = {"armpit_right", "armpit_left", "bust_right", "bust_left",
                                          "under_bust"};
  const std::vector<double> dz =
      HeightErrors(ScannedFullMakeHuman(&model, 1068, "arms-90", 287, 215), names, "seed 1068");
  for (size_t i = 0; i < names.size(); ++i)
    EXPECT_LE(std::abs(dz[i]), i < 2 ? 60.0 : 30.0) << names[i] << " (mm)";
}

// The knee from the leg's front profile: the shin lies behind the kneecap,
// and mid-patella sits a little above where the front climbs fastest. From
// the proportion of crotch height alone the knees of these MakeHuman bodies
// (full population, seeds not looked at while choosing the rule) are 0-52
// mm off in height (median 21); from the front profile 2-59 (median 9). The
// parametric bodies hold the knee within 10 mm either way (3-7 mm by
// proportion, 1-6 from the profile): the check that the cue holds on a
// second body model.
TEST(MakeHumanLandmarks, KneeFromTheFrontOfTheLeg) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  std::vector<double> errors;
  for (std::uint64_t seed : {1101, 1102, 1103, 1104, 1105, 1106}) {
    for (double dz : HeightErrors(ScannedFullMakeHuman(&model, seed, "arms-30"),
                                  {"knee_right", "knee_left"}, "seed " + std::to_string(seed)))
      errors.push_back(std::abs(dz));
  }
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  EXPECT_LE(errors[errors.size() / 2], 15.0) << "median knee height error (mm)";
}

TEST(ParametricLandmarks, KneeFromTheFrontOfTheLeg) {
  for (std::uint64_t seed : {5, 6, 7}) {
    const std::string what = "seed " + std::to_string(seed);
    for (double dz : HeightErrors(ScannedParametric(seed, 30), {"knee_right", "knee_left"}, what))
      EXPECT_LE(std::abs(dz), 10.0) << what << " (mm)";
  }
}

// The under-bust is the first strong bend of the front profile below the
// bust point. Taken as the foremost point of each slice near the bust
// point's vertical, the profile moves a few mm from slice to slice on a
// breast's steep underside, and its second difference had noise peaks: on
// these full-range bodies (A-pose, default booth) that profile put the
// under-bust 12 and 31 mm over the fold (seeds 1013, 1027) and, on a flat
// chest, at a noise "fold" 32 mm over the truth's 4 % of stature under the
// bust (seed 2023). A plane fitted to the slice's front points does not.
TEST(ParametricLandmarks, UnderBustAtTheFoldNotANoisePeakAboveIt) {
  for (std::uint64_t seed : {1013, 1027, 2023}) {
    const std::string what = "full-range seed " + std::to_string(seed);
    for (double dz :
         HeightErrors(ScannedParametric(seed, 30, nullptr, "full"), {"under_bust"}, what))
      EXPECT_LE(std::abs(dz), 15.0) << what << " (mm)";
  }
}

// The average woman's bust grown 10 mm at a time from 850 to 890 mm: the
// fold under it sharpens from a bend under 1 mm to over 3 mm on the exact
// mesh (DefinedUnderBust.AFoldThatSharpensMovesTheLevelSmoothly), and
// the scan reads its bend a little differently. The level moves with the
// bend on both sides, so the found under-bust stays near the truth's across
// the change; a single threshold can put one side at the fold and the
// other at the flat chest's level under it.
TEST(ParametricLandmarks, UnderBustFollowsAFoldThatSharpens) {
  for (double girth = 850; girth <= 890; girth += 10) {
    ParametricBodyOptions options;
    options.bust_girth_mm = girth;
    options.arm_abduction_deg = 30;
    const std::string what = "bust girth " + std::to_string(static_cast<int>(girth)) + " mm";
    for (double dz : HeightErrors(ScannedParametricBody(options, 1), {"under_bust"}, what))
      EXPECT_LE(std::abs(dz), 8.0) << what << " (mm)";
  }
}

// The malleoli: no bump on either body model's scan marks them, so each
// is placed at its own share of the crotch height, the inner one higher.
// The leg widens towards the foot, and the most medial point of a band 24 mm
// high lies at the band's bottom: taken there, the inner ankle is 18.6 mm
// low (median) on the parametric full-range set of seed 1. Bodies of seeds not
// looked at while choosing the shares: the median height error of the four
// ankle points within 15 mm, none beyond 25 mm, on both body models.
void ExpectAnklesAtTheirLevels(const std::vector<testing::ScannedBody>& scans) {
  std::vector<double> errors;
  for (size_t i = 0; i < scans.size(); ++i) {
    for (double dz : HeightErrors(scans[i],
                                  {"ankle_inside_right", "ankle_inside_left", "ankle_outside_right",
                                   "ankle_outside_left"},
                                  "body " + std::to_string(i))) {
      EXPECT_LE(std::abs(dz), 25.0) << "body " << i << " (mm)";
      errors.push_back(std::abs(dz));
    }
  }
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  EXPECT_LE(errors[errors.size() / 2], 15.0) << "median ankle height error (mm)";
}

TEST(ParametricLandmarks, AnklePointsAtTheirLevels) {
  std::vector<testing::ScannedBody> scans;
  for (std::uint64_t seed = 4001; seed <= 4005; ++seed)
    scans.push_back(ScannedParametric(seed, 30, nullptr, "full"));
  ExpectAnklesAtTheirLevels(scans);
}

TEST(MakeHumanLandmarks, AnklePointsAtTheirLevels) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  std::vector<testing::ScannedBody> scans;
  for (std::uint64_t seed = 4001; seed <= 4005; ++seed)
    scans.push_back(ScannedFullMakeHuman(&model, seed, "arms-30"));
  ExpectAnklesAtTheirLevels(scans);
}

// Where the front of a heavy leg climbs steadily from the shin into the
// thigh, its steepest point lies anywhere in the search window: on two
// full-range sets of 29 and 30 bodies the front cue alone put 14 and 16
// knees more than 30 mm off in height, up to 107 mm, in the lower thigh. The
// back cue (where the recession above the calf slows) joins it: their mean
// where they agree, else their median with the proportion of crotch height.
// Seeds 3001-3010 are the first ten of a set the rule was checked on after
// it was chosen: the front cue alone leaves seed 3002's knees 107 mm high
// and seed 3006's 46 mm.
TEST(MakeHumanLandmarks, KneeWhereTheFrontClimbsSteadily) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  std::vector<double> errors;
  for (std::uint64_t seed = 3001; seed <= 3010; ++seed) {
    const std::string what = "seed " + std::to_string(seed);
    for (double dz : HeightErrors(ScannedFullMakeHuman(&model, seed, "arms-30"),
                                  {"knee_right", "knee_left"}, what)) {
      EXPECT_LE(std::abs(dz), 50.0) << what << " (mm)";
      errors.push_back(std::abs(dz));
    }
  }
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  EXPECT_LE(errors[errors.size() / 2], 15.0) << "median knee height error (mm)";
}

// Feet set together touch toe to toe, where the fronts of both feet face
// forward and the surface graph linked them: the feet were one end of the
// body and the structure failed on 4 of these 8 default-population bodies
// (1005-1008); the slices' fallback put seed 1008's crotch 16 mm low here
// and 97 mm low, at the bottom of the thighs' contact, in the posture test's
// scan of the same body (`bespoke accuracy --posture-test feet-together`).
// Below 0.3 of stature no link crosses x = 0.
TEST(MakeHumanLandmarks, FeetTogetherKeepTheStructure) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  for (std::uint64_t seed = 1001; seed <= 1008; ++seed) {
    MakeHumanBodyOptions options;
    options.seed = seed;
    options.posture = ParseMakeHumanPosture("arms-30+feet-together");
    testing::ScannedBodyOptions scan_options;
    scan_options.scan_seed = seed;
    const testing::ScannedBody scan =
        testing::ScanAndClean(scan_options, GenerateMakeHumanBody(options, &model));
    EXPECT_FALSE(FindBodyParts(scan.cloud).empty()) << "seed " << seed << ": no structure";
    const std::string what = "seed " + std::to_string(seed);
    for (double dz : HeightErrors(scan, {"crotch"}, what))
      EXPECT_LE(std::abs(dz), 15.0) << what << " (mm)";
  }
}

// Arms resting on a heavy body, forearms bent forward: the arm leaves the
// trunk's outline at the elbow, and the surface graph crosses the elbow's
// contact with the trunk, so the structure's corner lies there too. Taken
// there, seed 7002's armpits are 285-290 mm low, with every trunk level built
// under them (front waist 202 mm low, under-bust 350). The armpit is where
// the notch between the resting arm and the trunk ends, going up. Every
// armpit of these six bodies within 50 mm (seed 7003's, 34-39 mm low in
// this scan, keep the join's level: the sections above it show no notch).
TEST(MakeHumanLandmarks, ArmpitAboveArmsRestingOnTheBody) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  ExpectHeightsWithin(&model, {7001, 7002, 7003, 7004, 7005, 7006}, "arms-5",
                      {"armpit_right", "armpit_left"}, 50.0);
  ExpectHeightsWithin(&model, {7002}, "arms-5", {"under_bust", "front_waist"}, 40.0);
}

// An obese body whose upper arms rest on the trunk well below the armpits
// (MakeHuman full seed 2030, arms at 30 deg, the default booth): the crease
// between arm and trunk weakens for 15 mm (the notch's ratio 0.72-0.74,
// just past its 0.7) and comes back up to the true armpit. A climb that
// stops at the weak stretch leaves both armpits 32-47 mm low, and the chest
// girth's section there takes in the arms.
TEST(MakeHumanLandmarks, RestingArmsCreaseClimbsPastAWeakStretch) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  MakeHumanBodyOptions options;
  options.seed = 2030;
  options.population = "full";
  options.posture = ParseMakeHumanPosture("arms-30");
  testing::ScannedBodyOptions scan_options;  // the accuracy run's scan of it
  scan_options.scan_seed = 2030;
  scan_options.width_px = 240, scan_options.height_px = 180;
  scan_options.random_transform = false;
  const testing::ScannedBody scan =
      testing::ScanAndClean(scan_options, GenerateMakeHumanBody(options, &model));
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  for (const char* name : {"armpit_right", "armpit_left"}) {
    ASSERT_TRUE(set.Has(name)) << name;
    const double dz = set.At(name).position_mm.z() - scan.truth.at(name).z();
    std::printf("%s dz %.1f mm (%s)\n", name, dz, set.At(name).method.c_str());
    EXPECT_LE(std::abs(dz), 15.0) << name << " (mm)";
  }
}

// A T-posed arm is no arm resting on the trunk: the sections above its
// armpit cut the raised arm lengthwise and show a lobe beside the trunk
// all the way up the arm, so the notch is not climbed there. Climbed, the
// armpits of these full-range bodies (the completeness run's subjects 112,
// 122 and 132) went to the top of the arm, 450-520 mm off.
TEST(MakeHumanLandmarks, TPosedArmpitIsNotClimbed) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  for (std::uint64_t seed : {1113, 1133}) {  // the 60k booth (99 x 75 px per sensor)
    const std::string what = "seed " + std::to_string(seed);
    for (double dz : HeightErrors(ScannedFullMakeHuman(&model, seed, "arms-90", 99, 75),
                                  {"armpit_right", "armpit_left"}, what))
      EXPECT_LE(std::abs(dz), 60.0) << what << " (mm)";
  }
}

// T-posed MakeHuman bodies turn the forearm forward at the elbow, and their
// spread fingers, or a bent arm's hand cut across one axis through the whole
// arm, can be narrower than the wrist: the narrowest section within 90 mm of
// the fingertips then put the wrist on the hand (seeds 1402 and 1406: wrists
// 95-118 mm off, elbows 85-94). The wrist is sought before the hand's widest
// section: every wrist here 13-43 mm off, every elbow 7-37 mm at its share
// of the arm (the other seeds unchanged) and 3-27 mm at the arm's bend.
TEST(MakeHumanLandmarks, TPosedWristIsBeforeTheHand) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  for (std::uint64_t seed : {1401, 1402, 1403, 1404, 1405, 1406}) {
    const testing::ScannedBody scan = ScannedFullMakeHuman(&model, seed, "arms-90");
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    for (const char* name : {"wrist_right", "wrist_left", "elbow_right", "elbow_left"}) {
      ASSERT_TRUE(set.Has(name)) << "seed " << seed << " " << name;
      const double error = (set.At(name).position_mm - scan.truth.at(name)).norm();
      std::printf("seed %d %s %.1f mm\n", static_cast<int>(seed), name, error);
      // A wrist on the hand lies 90-120 mm along the arm from the truth.
      EXPECT_LE(error, StartsWith(name, "wrist") ? 80.0 : 60.0) << "seed " << seed << " " << name;
    }
  }
}

// A horizontal section just above a T-posed armpit cuts the raised arm's
// underside along its length, and the hull over trunk and arm leaves a
// pocket between the arm and the back out on the arm: the back fold was
// sought up to 40 mm past the armpit and landed there (10 T-posed bodies of
// the default population: 54 mm from the truth, median; 27 mm sought on the
// trunk's side). The folds are the walls of the armpit's hollow, on the
// trunk's side of its apex. Seed 1501's folds were 54 and 61 mm off, 6 and
// 14 mm past the armpit; now 40 and 37 mm (the other seeds unchanged).
TEST(MakeHumanLandmarks, TPosedBackFoldIsOnTheTrunk) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  for (std::uint64_t seed : {1501, 1502, 1503, 1504}) {
    const testing::ScannedBody scan = ScannedFullMakeHuman(&model, seed, "arms-90");
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    for (const char* side : {"right", "left"}) {
      const std::string fold = std::string("axilla_back_") + side;
      ASSERT_TRUE(set.Has(fold)) << "seed " << seed << " " << fold;
      const double error = (set.At(fold).position_mm - scan.truth.at(fold)).norm();
      const double sign = side[0] == 'r' ? 1 : -1;
      const double past_armpit =
          sign * (set.At(fold).position_mm.x() - scan.truth.at(std::string("armpit_") + side).x());
      std::printf("seed %d %s %.1f mm from the truth, %.1f mm past the armpit\n",
                  static_cast<int>(seed), fold.c_str(), error, past_armpit);
      EXPECT_LE(error, 45.0) << "seed " << seed << " " << fold;
    }
  }
}

// The wrist point is the back of the forearm's section at the wrist's
// station. Taken as the most backward point of a slab 20 mm thick along
// the world's back, it sat at the slab's upper edge, where the tapering
// forearm is thicker: on 30 default-population bodies 9-10 mm too high and
// 7 mm too far back (median), arm and sleeve lengths 12 and 15 mm short.
// Now across the arm's axis, from a slab of one point spacing either side:
// on these seeds (not looked at before) the median 15.1 -> 7.7 mm.
TEST(MakeHumanLandmarks, WristAtItsStationNotUpTheForearm) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  std::vector<double> errors;
  for (std::uint64_t seed : {1601, 1602, 1603, 1604, 1605, 1606}) {
    MakeHumanBodyOptions options;
    options.seed = seed;
    testing::ScannedBodyOptions scan_options;
    scan_options.scan_seed = seed;
    const testing::ScannedBody scan =
        testing::ScanAndClean(scan_options, GenerateMakeHumanBody(options, &model));
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    for (const char* name : {"wrist_right", "wrist_left"}) {
      ASSERT_TRUE(set.Has(name)) << "seed " << seed << " " << name;
      const Eigen::Vector3d d = set.At(name).position_mm - scan.truth.at(name);
      std::printf("seed %d %s %.1f mm (up %.1f)\n", static_cast<int>(seed), name, d.norm(), d.z());
      errors.push_back(d.norm());
    }
  }
  std::nth_element(errors.begin(), errors.begin() + 6, errors.end());
  std::printf("median %.1f mm\n", errors[6]);
  EXPECT_LE(errors[6], 9.0);
}

// Relaxed MakeHuman arms bend at the elbow, and the elbow is that bend. At a fixed share of the
// shoulder-to-wrist distance the elbows of these bodies (full population, seeds not looked at while
// choosing the rule) were 4.9-19.1 mm off, median 13.3; at the bend of the arm's centre
// line 3.2-22.9 mm, median 8.7.
TEST(MakeHumanLandmarks, ElbowAtTheArmsBend) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  std::vector<double> errors;
  for (std::uint64_t seed : {1501, 1502, 1503, 1504, 1505, 1506}) {
    const testing::ScannedBody scan = ScannedFullMakeHuman(&model, seed, "arms-30");
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    for (const char* name : {"elbow_right", "elbow_left"}) {
      ASSERT_TRUE(set.Has(name)) << "seed " << seed << " " << name;
      EXPECT_EQ(set.At(name).method, "arm_bend_back") << "seed " << seed << " " << name;
      errors.push_back((set.At(name).position_mm - scan.truth.at(name)).norm());
      std::printf("seed %d %s %.1f mm\n", static_cast<int>(seed), name, errors.back());
    }
  }
  std::sort(errors.begin(), errors.end());
  EXPECT_LE(errors[errors.size() / 2], 11.0) << "median elbow error (mm)";
  EXPECT_LE(errors.back(), 35.0) << "largest elbow error (mm)";
}

// Arms straight by construction (the parametric body) have no bend to find:
// the elbow stays at its share of the arm, where it matches that model's
// elbow (within 25 mm).
TEST(ParametricLandmarks, StraightArmKeepsTheElbowShare) {
  for (std::uint64_t seed : {5, 6, 7}) {
    const testing::ScannedBody scan = ScannedParametric(seed, 30);
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    for (const char* name : {"elbow_right", "elbow_left"}) {
      ASSERT_TRUE(set.Has(name)) << "seed " << seed << " " << name;
      EXPECT_EQ(set.At(name).method, "arm_length_share_back") << "seed " << seed << " " << name;
      EXPECT_LE((set.At(name).position_mm - scan.truth.at(name)).norm(), 25.0)
          << "seed " << seed << " " << name;
    }
  }
}

// T-posed MakeHuman bodies: the raised shoulders leave no corner between
// neck and shoulder, and the corner below the chord puts the side neck
// points on the arm's flat top, 25-45 mm low (the neck girth's plane then
// takes the shoulders in, +150 to +290 mm). The level ring through the
// front and back neck points holds their height within 20 mm.
TEST(MakeHumanLandmarks, TPosedSideNeckOnTheNeck) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  ExpectHeightsWithin(&model, {1301, 1302, 1303}, "arms-90", {"side_neck_right", "side_neck_left"},
                      20.0);
}

// Heavy thighs pressed together from the crotch to mid-thigh (full
// population). The crease between them is too tight for the sensors, its
// rounded bottom faces forward, and a normal estimated across it averages
// its two walls: by the walls' normals alone the contact ended at its
// bottom and the crotch landed 127 and 184 mm low on these seeds (not those
// the notch rule was developed on). The crease is also a notch behind the
// thighs' fronts either side.
TEST(MakeHumanLandmarks, CrotchAboveThighsPressedTogether) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  ExpectHeightsWithin(&model, {2023, 3016}, "arms-30", {"crotch"}, 20.0);
}

// A raised arm meets the trunk through a fillet of skin that the body
// structure's armpit corner (where the side turns vertical, 50-90 mm under
// the apex on these bodies) leaves to the arm; the chest's section just under
// the armpits then lost its sides (155-170 mm of girth on T-posed bodies of
// another seed range). Under and medial of each found armpit the fillet is
// the trunk's again: the slab under the armpits has a trunk-only hull within
// 25 mm of the hull of all its points near the trunk.
TEST(MakeHumanLandmarks, TPosedChestSectionKeepsItsSides) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  for (std::uint64_t seed : {1301, 1302, 1303}) {
    const testing::ScannedBody scan = ScannedFullMakeHuman(&model, seed, "arms-90");
    const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
    ASSERT_TRUE(set.Has("armpit_right") && set.Has("armpit_left")) << seed;
    ASSERT_EQ(set.parts.size(), static_cast<size_t>(scan.cloud.size())) << seed;
    const Eigen::Vector3d r = set.At("armpit_right").position_mm,
                          l = set.At("armpit_left").position_mm;
    const double z = 0.5 * (r.z() + l.z()) - 5, reach = std::max(r.x(), -l.x()) + 40;
    std::vector<int> all, trunk;
    for (Eigen::Index i = 0; i < scan.cloud.points.rows(); ++i) {
      const Eigen::Vector3d p = scan.cloud.points.row(i);
      if (std::abs(p.z() - z) > 2.5 || std::abs(p.x()) > reach) continue;
      all.push_back(static_cast<int>(i));
      if (set.parts[static_cast<size_t>(i)] == ScanPart::kTrunk)
        trunk.push_back(static_cast<int>(i));
    }
    const double whole = landmarks::HullPerimeter(scan.cloud.points, all),
                 kept = landmarks::HullPerimeter(scan.cloud.points, trunk);
    std::printf("seed %d: slab at %.0f mm, hull %.1f mm, trunk's %.1f mm\n", static_cast<int>(seed),
                z, whole, kept);
    EXPECT_LE(whole - kept, 25.0) << "seed " << seed << " (mm)";
  }
}

// The calf is the bulge of the lower leg. On many heavy legs the girth
// widens again under the knee and outgrows the calf; with the band's largest
// girth the calf lands 99-126 mm high on these seeds (of the completeness
// set's far points), to the top of a band that reaches further up than the
// truth's because the knee is found high.
TEST(MakeHumanLandmarks, CalfIsTheBulgeNotTheWideningUnderTheKnee) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  ExpectHeightsWithin(&model, {1017, 1025, 1036, 1039}, "arms-30", {"calf_right", "calf_left"},
                      30.0);
}

// One body scanned six times (other noise seeds and rigid poses): the
// points defined on a flat stretch of a profile (the side neck on a
// neck-shoulder line nearly parallel to its chord, the rounded shoulder
// corner, the waist's flat girth minimum, the bottom of the front neck's
// notch) stay put instead of following the noise. Measured ranges over these
// six scans: side neck x 3-6 mm and height 3-4 mm (the deepest station of
// its corner profile instead of the centre of its top: x 12-15, height 7-8),
// axilla folds x 6-8 mm (the single deepest point of the pocket: 10-13),
// shoulder height 2-3, waist 8, front neck 4 (shoulder x range 4 mm), hip
// level 2; taking the single best sample or point instead of a fit gave
// shoulder 17-24, waist 16, front neck 10 and hip level 7 (shoulder x range
// 21-24 mm). The repeatability
// target itself (SD <= 1 mm per height) is measured by
// `bespoke accuracy --repeat-body`.
TEST(MakeHumanLandmarks, SameBodyScannedAgainKeepsItsPoints) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  MakeHumanBodyOptions options;
  options.seed = 1001;
  const Body body = GenerateMakeHumanBody(options, &model);
  std::map<std::string, std::vector<Eigen::Vector3d>> found;
  const std::vector<std::string> names = {
      "side_neck_right",    "side_neck_left",    "shoulder_right",    "shoulder_left",
      "front_waist",        "armpit_left",       "armpit_right",      "front_neck",
      "axilla_front_right", "axilla_front_left", "axilla_back_right", "axilla_back_left",
      "hip_back",           "bust_right",        "bust_left"};
  for (std::uint64_t scan_seed = 11; scan_seed <= 16; ++scan_seed) {
    testing::ScannedBodyOptions scan_options;
    scan_options.scan_seed = scan_seed;
    const LandmarkSet set =
        DetectLandmarks(LandmarkOptions{}, testing::ScanAndClean(scan_options, body).cloud);
    for (const std::string& name : names) {
      ASSERT_TRUE(set.Has(name)) << name << ", scan seed " << scan_seed;
      found[name].push_back(set.At(name).position_mm);
    }
  }
  for (const std::string& name : names) {
    Eigen::Vector3d lo = found[name].front(), hi = lo;
    for (const Eigen::Vector3d& p : found[name]) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    std::printf("%-16s range x %5.1f  y %5.1f  z %5.1f mm\n", name.c_str(), hi.x() - lo.x(),
                hi.y() - lo.y(), hi.z() - lo.z());
    EXPECT_LE(hi.z() - lo.z(), 11.0) << name << " height range (mm)";
    // The shoulder's corner runs along x as much as along z.
    // So does the side neck's, along the slope of the shoulder.
    if (StartsWith(name, "shoulder") || StartsWith(name, "side_neck")) {
      EXPECT_LE(hi.x() - lo.x(), 8.0) << name << " x range (mm)";
    }
    // An axilla fold's pocket bottom runs along x.
    if (StartsWith(name, "axilla")) {
      EXPECT_LE(hi.x() - lo.x(), 9.0) << name << " x range (mm)";
    }
    // The hip level (a height, whose target SD is 1 mm: about 2.5 mm of
    // range over six scans, the rest the luck of six draws).
    if (name == "hip_back") EXPECT_LE(hi.z() - lo.z(), 4.0) << name << " height range (mm)";
  }
}

TEST(Landmarks, EveryCatalogueLandmarkIsPlacedOrMissingWithAReason) {
  ParametricBodyOptions options;
  options.seed = 2;
  const Body body = GenerateParametricBody(options);
  const testing::ScannedBody scan = testing::ScanAndClean(testing::ScannedBodyOptions{}, body);
  const LandmarkSet set = DetectLandmarks(LandmarkOptions{}, scan.cloud);
  for (const LandmarkDef& def : Catalogue::Builtin().landmarks()) {
    EXPECT_TRUE(set.Has(def.name))
        << def.name << ": " << (set.missing.count(def.name) ? set.missing.at(def.name) : "");
    if (!set.Has(def.name)) continue;
    const Landmark& l = set.At(def.name);
    EXPECT_FALSE(l.method.empty()) << def.name;
    EXPECT_GE(l.confidence, 0.0);
    EXPECT_LE(l.confidence, 1.0);
  }
  // `only` keeps the listed points.
  LandmarkOptions some;
  some.only = {"crown", "wrist_left"};
  const LandmarkSet two = DetectLandmarks(some, scan.cloud);
  EXPECT_EQ(two.points.size() + two.missing.size(), 2u);
  EXPECT_TRUE(two.Has("crown"));
}

TEST(Landmarks, RejectsWhatCannotBeAStandingPerson) {
  PointCloud few;
  few.points = Eigen::MatrixX3d::Random(100, 3);
  EXPECT_THROW(DetectLandmarks(LandmarkOptions{}, few), InputError);
  PointCloud metres;  // a body left in metres: 1.7 units tall
  metres.points = Eigen::MatrixX3d::Random(5000, 3) * 0.85;
  EXPECT_THROW(DetectLandmarks(LandmarkOptions{}, metres), InputError);
}

}  // namespace
}  // namespace bespoke
