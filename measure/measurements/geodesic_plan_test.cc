#include "measure/measurements/geodesic_plan.h"

#include <gtest/gtest.h>

namespace bespoke {
namespace {

// A stick figure of sites 5 mm apart: a trunk (z 800-1400 mm) with a leg
// (z 0-800, x = 100) and an arm (x 0-600 at z 1300); a hip at the leg's top.
Eigen::MatrixX3d StickSites() {
  std::vector<Eigen::Vector3d> s;
  for (double z = 0; z < 800; z += 5) s.emplace_back(100, 0, z);  // leg
  for (double z = 800; z <= 1400; z += 5)                         // trunk, 4 columns
    for (double x : {-100.0, -33.0, 33.0, 100.0}) s.emplace_back(x, 0, z);
  for (double x = 105; x <= 700; x += 5) s.emplace_back(x, 0, 1300);  // arm
  Eigen::MatrixX3d m(static_cast<Eigen::Index>(s.size()), 3);
  for (size_t i = 0; i < s.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = s[i].transpose();
  return m;
}

std::map<std::string, PlanEnd> StickEnds() {
  return {{"ankle", {{100, 0, 50}, false}},      {"hip", {{100, 0, 850}, false}},
          {"waist", {{100, 0, 1050}, false}},    {"wrist", {{700, 0, 1300}, false}},
          {"shoulder", {{100, 0, 1350}, false}}, {"crotch", {{0, 0, 800}, true}},
          {"knee", {{100, 0, 450}, false}}};
}

const SourceGroup* GroupOf(const std::vector<SourceGroup>& groups, const std::string& a,
                           const std::string& b) {
  for (const SourceGroup& g : groups)
    for (const auto& p : g.pairs)
      if (p == std::make_pair(a, b)) return &g;
  return nullptr;
}

// The long leg length is solved from the ankle, whose ball holds the leg
// and the pelvis only, not from the hip, whose ball holds nearly everything.
TEST(GeodesicPlan, LongPairsFromTheEndWithLessSkinAround) {
  const std::set<std::pair<std::string, std::string>> pairs = {{"ankle", "hip"}};
  const auto groups = PlanSources(StickSites(), StickEnds(), pairs);
  ASSERT_EQ(groups.size(), 1u);
  EXPECT_EQ(groups[0].source, "ankle");
  EXPECT_NEAR(groups[0].radius_mm, 800, 1e-9);
}

// Short pairs join a source already planned far enough; an end at a hole is
// a source only when the other end is one too; every pair is planned once;
// groups come costliest first.
TEST(GeodesicPlan, SharesSourcesAndKeepsHoleEndsAsTargets) {
  const std::set<std::pair<std::string, std::string>> pairs = {{"ankle", "hip"},
                                                               {"ankle", "knee"},
                                                               {"hip", "waist"},
                                                               {"ankle", "crotch"},
                                                               {"shoulder", "wrist"}};
  const auto groups = PlanSources(StickSites(), StickEnds(), pairs);
  size_t planned = 0;
  for (const SourceGroup& g : groups) planned += g.pairs.size();
  EXPECT_EQ(planned, pairs.size());
  EXPECT_EQ(GroupOf(groups, "ankle", "crotch")->source, "ankle");
  EXPECT_EQ(GroupOf(groups, "ankle", "hip")->source, "ankle");
  EXPECT_EQ(GroupOf(groups, "ankle", "knee")->source, "ankle");  // inside its 800 mm: free
  EXPECT_EQ(GroupOf(groups, "shoulder", "wrist")->source, "wrist");
  // hip-waist (200 mm): the hip's ball holds the trunk's foot and the leg's
  // top (about 230 sites), the waist's more of the trunk (about 320).
  EXPECT_EQ(GroupOf(groups, "hip", "waist")->source, "hip");
  for (size_t i = 1; i < groups.size(); ++i) EXPECT_GE(groups[i - 1].cost, groups[i].cost);
  const std::set<std::pair<std::string, std::string>> holes = {{"crotch", "hip"}};
  auto ends = StickEnds();
  ends["hip"].at_hole = true;
  EXPECT_EQ(PlanSources(StickSites(), ends, holes).size(), 1u);  // both at holes: one of them
}

}  // namespace
}  // namespace bespoke
