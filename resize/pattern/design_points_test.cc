// Notch runs, sleeve cap height and armhole depth on pieces built in code
// with known answers.
#include "resize/pattern/design_points.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bespoke {
namespace {

Outline FromPoints(const std::vector<Eigen::Vector2d>& points) {
  Outline o(static_cast<Eigen::Index>(points.size()), 2);
  for (size_t i = 0; i < points.size(); ++i) o.row(static_cast<Eigen::Index>(i)) = points[i];
  return o;
}

// A 300 x 100 mm panel with corner landmarks and a notch on its top edge,
// 100 mm from the top right corner (a third of the edge).
Pattern NotchedPanel() {
  Piece piece;
  piece.name = "panel";
  piece.outline = FromPoints({{0, 0}, {300, 0}, {300, 100}, {200, 100}, {0, 100}});
  piece.landmarks = {{"bl", "", 0, {}}, {"br", "", 1, {}}, {"tr", "", 2, {}}, {"tl", "", 4, {}}};
  piece.notches = {3};
  Pattern p;
  p.pieces = {piece};
  return p;
}

TEST(DesignPoints, NotchRunIsBoundByTheNearestStructurePoints) {
  const Pattern p = NotchedPanel();
  const std::vector<NotchRun> runs = NotchRuns(p, 0);
  ASSERT_EQ(runs.size(), 1u);
  EXPECT_EQ(runs[0].from, 2);
  EXPECT_EQ(runs[0].to, 4);
  EXPECT_NEAR(runs[0].fraction, 1.0 / 3, 1e-12);
  EXPECT_NEAR(NotchShift(p.pieces[0].outline, runs[0]), 0, 1e-9);
  // Stretch the left part only (x < 200 doubled): the notch, now 100 of
  // 500 mm from the right, is 500 / 3 - 100 mm short of its third.
  Outline stretched = p.pieces[0].outline;
  for (Eigen::Index v = 0; v < stretched.rows(); ++v)
    stretched(v, 0) = stretched(v, 0) < 200 ? 2 * stretched(v, 0) : stretched(v, 0) + 200;
  EXPECT_NEAR(NotchShift(stretched, runs[0]), 100 - 500.0 / 3, 1e-9);
}

TEST(DesignPoints, NotchAtAStructurePointHasNoRun) {
  Pattern p = NotchedPanel();
  p.pieces[0].landmarks.push_back({"notch", "", 3, {}});
  EXPECT_TRUE(NotchRuns(p, 0).empty());
}

// A sleeve: underarm points 400 mm apart, a cap of 17 points on a half
// ellipse 150 mm high, the sleeve 500 mm long below; and a bodice whose
// armhole (underarm to shoulder, 200 mm apart along the grain) is sewn to
// the cap.
Pattern SleeveAndBodice(double rotate_deg) {
  const double a = rotate_deg * M_PI / 180;
  const Eigen::Matrix2d r =
      (Eigen::Matrix2d() << std::cos(a), -std::sin(a), std::sin(a), std::cos(a)).finished();
  std::vector<Eigen::Vector2d> s = {{80, -500}, {320, -500}};
  for (int k = 0; k <= 16; ++k) {
    const double t = M_PI * k / 16;  // front underarm (400, 0) over the top to (0, 0)
    s.push_back(r * Eigen::Vector2d(200 + 200 * std::cos(t), 150 * std::sin(t)));
  }
  s[0] = r * s[0];
  s[1] = r * s[1];
  Piece sleeve;
  sleeve.name = "sleeve";
  sleeve.outline = FromPoints(s);
  sleeve.landmarks = {{"front_underarm", "", 2, {}}, {"back_underarm", "", 18, {}}};
  Piece bodice;
  bodice.name = "bodice";
  bodice.outline = FromPoints({{0, 0}, {200, 0}, {200, 250}, {150, 300}, {140, 450}, {0, 450}});
  bodice.has_grain = true;
  bodice.grain_start = {50, 50};
  bodice.grain_end = {50, 400};
  Pattern p;
  p.pieces = {sleeve, bodice};
  Seam seam;
  seam.name = "armhole";
  seam.a = {"sleeve", 2, 4, true};
  seam.b = {"bodice", 2, 4, true};
  p.seams = {seam};
  return p;
}

TEST(DesignPoints, CapHeightAndArmholeDepthOfAKnownSleeve) {
  for (double rotate_deg : {0.0, 30.0}) {
    const Pattern p = SleeveAndBodice(rotate_deg);
    const std::vector<DesignDimension> d = FindDesignDimensions(p);
    ASSERT_EQ(d.size(), 2u);
    EXPECT_EQ(d[0].kind, DesignDimension::Kind::kCapHeight);
    EXPECT_EQ(d[0].piece, "sleeve");
    EXPECT_EQ(d[0].vertices.size(), 17u);  // the cap, not the 500 mm sleeve below
    EXPECT_NEAR(MeasureDesignDimension(p, d[0]), 150, 1e-9) << rotate_deg;
    EXPECT_EQ(d[1].kind, DesignDimension::Kind::kArmholeDepth);
    EXPECT_EQ(d[1].piece, "bodice");
    EXPECT_NEAR(MeasureDesignDimension(p, d[1]), 200, 1e-9);
  }
}

TEST(DesignPoints, CapHeightInferredFromTheShapeAlone) {
  for (double rotate_deg : {0.0, 30.0}) {
    const Pattern named = SleeveAndBodice(rotate_deg);
    const Eigen::Vector2d up = CapDirection(named, FindDesignDimensions(named)[0]);
    const double a = rotate_deg * M_PI / 180;
    EXPECT_NEAR(up.x(), -std::sin(a), 1e-9);
    EXPECT_NEAR(up.y(), std::cos(a), 1e-9);
    Piece sleeve = named.pieces[0];
    sleeve.landmarks.clear();
    EXPECT_NEAR(InferredCapHeight(sleeve, up), 150, 1e-9) << rotate_deg;
    EXPECT_NEAR(InferredCapHeight(sleeve, -up), 500, 1e-9) << rotate_deg;  // the arm side
  }
}

TEST(DesignPoints, NamedCapTopChoosesTheCapRun) {
  // A sleeve whose cap (300 mm high) bulges more than its 200 mm long
  // arm part: only the named cap top tells them apart.
  Pattern p = SleeveAndBodice(0);
  Outline& o = p.pieces[0].outline;
  o.row(0) << 80, -200;
  o.row(1) << 320, -200;
  for (Eigen::Index v = 2; v <= 18; ++v) o(v, 1) *= 2;
  EXPECT_EQ(FindDesignDimensions(p)[0].vertices.size(), 4u);  // the arm part, wrongly
  p.pieces[0].landmarks.push_back({"cap_top", "", -1, {200, 290}});
  const std::vector<DesignDimension> d = FindDesignDimensions(p);
  EXPECT_EQ(d[0].vertices.size(), 17u);
  EXPECT_NEAR(MeasureDesignDimension(p, d[0]), 300, 1e-9);
}

}  // namespace
}  // namespace bespoke
