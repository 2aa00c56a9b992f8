// Geodesic paths across a scan's holes. The fixture: two flat plates 45 mm
// apart in height, joined by a ramp at both ends of a 100 mm wide, 300 mm
// long slot between them that no sensor saw (as the skin under a crotch).
// The datum points lie on either edge of the slot. A tape crosses the slot;
// the way round it over the scan is three times longer.
#include "measure/measurements/geodesic_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bespoke {
namespace {

struct Plates {
  Eigen::MatrixX3d points, normals;  // #P x 3 each: mm, outward unit normals
};

// z = 0 for x <= -50 mm, z = 45 mm for x >= 50 mm, and between them the ramp
// z = 45 (x + 50) / 100 where |y| >= slot_mm (the slot's half length); x in
// [-200, x_max_mm], y in [-200, 200] mm, points 3 mm apart.
Plates SteppedPlates(double slot_mm = 150, double x_max_mm = 200) {
  std::vector<Eigen::Vector3d> p, n;
  const Eigen::Vector3d ramp_normal = Eigen::Vector3d(-0.45, 0, 1).normalized();
  for (double x = -200; x <= x_max_mm; x += 3) {
    for (double y = -200; y <= 200; y += 3) {
      if (x <= -50) {
        p.emplace_back(x, y, 0), n.push_back(Eigen::Vector3d::UnitZ());
      } else if (x >= 50) {
        p.emplace_back(x, y, 45), n.push_back(Eigen::Vector3d::UnitZ());
      } else if (std::abs(y) >= slot_mm) {
        p.emplace_back(x, y, 0.45 * (x + 50)), n.push_back(ramp_normal);
      }
    }
  }
  Plates out;
  out.points.resize(static_cast<Eigen::Index>(p.size()), 3);
  out.normals.resize(out.points.rows(), 3);
  for (size_t i = 0; i < p.size(); ++i) {
    out.points.row(static_cast<Eigen::Index>(i)) = p[i];
    out.normals.row(static_cast<Eigen::Index>(i)) = n[i];
  }
  return out;
}

// The path from (-51, 0, 0) to (52, 0, 45): a chord of 112 mm across the
// slot, meeting both plates at 24 deg.
GeodesicPath AcrossTheSlot(const GeodesicPathOptions& options) {
  const Plates plates = SteppedPlates();
  CloudGeodesics geodesics(CloudGeodesicsOptions{}, plates.points);
  LandmarkSet set;
  set.points["low"].position_mm = Eigen::Vector3d(-51, 0, 0);
  set.points["high"].position_mm = Eigen::Vector3d(52, 0, 45);
  GeodesicPaths paths;
  paths.Need("low", "high");
  paths.Solve(options, geodesics, plates.normals, set, nullptr);
  const GeodesicPath* path = paths.Get("low", "high");
  EXPECT_NE(path, nullptr);
  return path ? *path : GeodesicPath();
}

// The rim test off (a mean unit direction is never longer than 1), as at a
// crotch whose scanned skin lies on both thighs and in front of the datum
// point: only the detour sends the path across. The bridge is the arc that
// meets both plates at 24 deg: 3 % longer than its chord (the path from
// the datum point to the slot's edge adds 1 mm).
TEST(GeodesicPaths, DetourCrossesTheHoleOnAnArc) {
  GeodesicPathOptions options;
  options.rim_offset = 1.01;
  const GeodesicPath path = AcrossTheSlot(options);
  ASSERT_TRUE(path.error.empty()) << path.error;
  EXPECT_GT(path.bridged_mm, 100.0);
  EXPECT_NEAR(path.length_mm, 116.7, 1.5);
}

// Without the detour rule and without a rim the path keeps to the scan and
// runs round the slot's end: a length no tape would read.
TEST(GeodesicPaths, WithoutEitherRuleThePathRunsRoundTheHole) {
  GeodesicPathOptions options;
  options.rim_offset = 1.01;
  options.detour_ratio = 1e9;
  const GeodesicPath path = AcrossTheSlot(options);
  ASSERT_TRUE(path.error.empty()) << path.error;
  EXPECT_GT(path.length_mm, 250.0);
  EXPECT_EQ(path.bridged_mm, 0.0);
}

// A slot 120 mm long (|y| < 60) and the high plate out to x = 1000 mm: from
// (-51, 0, 0) to (990, 0, 45) the way round the slot's end over the ramp
// (1089.5 mm, 1.05 chords) is no detour as a whole, but near the datum
// point it runs 60 mm sideways and up the ramp before it turns: round the
// hole at the datum point, as the inside leg from a crotch between the
// thighs. The path seeks a bridge into the datum point and takes it.
TEST(GeodesicPaths, DetourRoundAnEndCrossesTheHole) {
  const Plates plates = SteppedPlates(60, 1000);
  CloudGeodesics geodesics(CloudGeodesicsOptions{}, plates.points);
  LandmarkSet set;
  set.points["low"].position_mm = Eigen::Vector3d(-51, 0, 0);
  set.points["far"].position_mm = Eigen::Vector3d(990, 0, 45);
  GeodesicPathOptions options;
  options.rim_offset = 1.01;  // the rim test off, as in DetourCrossesTheHoleOnAnArc
  GeodesicPaths paths;
  paths.Need("low", "far");
  paths.Solve(options, geodesics, plates.normals, set, nullptr);
  const GeodesicPath* path = paths.Get("far", "low");
  ASSERT_NE(path, nullptr);
  ASSERT_TRUE(path->error.empty()) << path->error;
  EXPECT_GT(path->bridged_mm, 50.0);
  EXPECT_LT(path->length_mm, 1085.0);  // mm: 1081.4 with the bridge, 1089.5 round
}

}  // namespace
}  // namespace bespoke
