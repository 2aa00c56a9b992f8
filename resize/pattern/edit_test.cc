// Import edits on small patterns built in code with known answers.
#include "resize/pattern/edit.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "resize/io/measurements_io.h"
#include "resize/io/pattern_io.h"
#include "resize/pattern/geometry.h"
#include "resize/pattern/measurements.h"
#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

Outline Rect(double w, double h, bool clockwise) {
  Outline o(4, 2);
  o << 0, 0, w, 0, w, h, 0, h;
  if (clockwise) o = o.colwise().reverse().eval();
  return o;
}

// Two rectangles sewn along an edge: a's right edge (2 points) to b's left
// edge, which has an extra vertex at a quarter of its height (3 points).
Pattern TwoPieces() {
  Pattern p;
  Piece a{"a"}, b{"b"};
  a.outline = Rect(100, 200, false);
  b.outline.resize(5, 2);
  b.outline << 0, 0, 50, 0, 50, 200, 0, 200, 0, 50;
  p.pieces = {a, b};
  Seam s;
  s.name = "edge";
  s.a = {"a", 1, 2, true};
  s.b = {"b", 0, 3, false};  // 0 -> 4 -> 3: up b's left edge
  p.seams = {s};
  return p;
}

TEST(PatternEdit, ClockwiseOutlineIsTurnedAndIndicesFollow) {
  Pattern p;
  Piece piece{"r"};
  piece.outline = Rect(100, 50, true);  // (0,50) (100,50) (100,0) (0,0)
  piece.landmarks.push_back({"corner", "", 2, {}});
  p.pieces = {piece};
  MakeCounterClockwise(&p);
  EXPECT_GT(SignedArea(p.pieces[0].outline), 0);
  EXPECT_EQ(p.pieces[0].outline.row(p.pieces[0].landmarks[0].vertex), Eigen::RowVector2d(100, 0));
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("counter-clockwise"), std::string::npos);
}

TEST(PatternEdit, SeamSidesGetEqualCountsWithoutChangingOutlines) {
  Pattern p = TwoPieces();
  const double perimeter_a = Perimeter(p.pieces[0].outline);
  EqualizeSeamCounts(&p);
  const auto ia = SeamIndices(p.seams[0].a, p.pieces[0].num_vertices());
  const auto ib = SeamIndices(p.seams[0].b, p.pieces[1].num_vertices());
  ASSERT_EQ(ia.size(), ib.size());
  EXPECT_EQ(ia.size(), 3u);
  EXPECT_NEAR(Perimeter(p.pieces[0].outline), perimeter_a, 1e-9);
  // The new point on a's edge sits where b's extra vertex is: 50 mm up.
  EXPECT_NEAR(p.pieces[0].outline(ia[1], 1), 50, 1e-9);
  EXPECT_NO_THROW(ValidatePattern(p, "test"));
  EXPECT_EQ(p.notes.size(), 1u);
}

TEST(PatternEdit, InfersStraightRunsFoldAndSquareCorners) {
  Pattern p;
  Piece piece{"half"};
  piece.outline.resize(6, 2);  // a centre line with two inner vertices, on the fold
  piece.outline << 0, 0, 100, 0, 80, 300, 0, 300, 0, 200, 0, 100;  // a slanted side seam
  piece.on_fold = true;
  p.pieces = {piece};
  InferStructure(StructureOptions{}, &p);
  const Piece& q = p.pieces[0];
  ASSERT_EQ(q.straight.size(), 1u);
  EXPECT_EQ(q.straight[0].from, 3);
  EXPECT_EQ(q.straight[0].to, 0);
  EXPECT_TRUE(q.straight[0].fold);
  EXPECT_EQ(q.right_angles, (std::vector<int>{3, 0}));  // the fold's two ends
}

TEST(Measurements, ValentinaFileIsReadUnderCatalogueNames) {
  const std::string vit =
      "<vit><unit>cm</unit><body-measurements><m name=\"bust_circ\" value=\"102\"/>"
      "<m name=\"neck_back_to_waist_b\" value=\"50 \"/><m name=\"hand_circ\" value=\"24\"/>"
      "</body-measurements></vit>";
  std::vector<std::string> skipped;
  const MeasurementSet m = MeasurementsFromVit(vit, "t.vit", &skipped);
  EXPECT_DOUBLE_EQ(m.at("bust_girth"), 1020);
  EXPECT_DOUBLE_EQ(m.at("back_length"), 500);
  ASSERT_EQ(skipped.size(), 1u);
  EXPECT_EQ(skipped[0], "hand_circ");
  EXPECT_THROW(MeasurementsFromVit("<vit><m name=\"x\" value=\"a+b\"/></vit>", "t", nullptr),
               InputError);
}

TEST(Measurements, PercentAndKeptEase) {
  Pattern p = TwoPieces();
  p.pieces[0].landmarks = {{"l", "", 0, {}}, {"r", "", 1, {}}};
  MeasurementBinding b;
  b.id = "w";
  b.measurement = "waist_girth";
  b.terms = {{"a", "l", "r", BindingTerm::Path::kStraight, 4}};
  b.keep_ease = "percent";
  p.bindings = {b};
  p.base_body = {{"waist_girth", 320}};
  ResolveKeptEase("t", &p);
  EXPECT_NEAR(p.bindings[0].ease_percent, 25, 1e-9);  // 400 mm of pattern for 320 of body
  EXPECT_NEAR(BindingTarget(p.bindings[0], {{"waist_girth", 400}}), 500, 1e-9);
  EXPECT_TRUE(IsBindableMeasurement("waist_to_armpit"));
  EXPECT_TRUE(IsBindableMeasurement("upper_arm_length"));
  EXPECT_FALSE(IsBindableMeasurement("elbow_to_nowhere"));
}

// The Valentina shirt with its documented sidecar imports: every seam has
// equal counts, the import says what it did, and the back panel has its
// fold.
TEST(PatternEdit, ValentinaShirtSidecarImports) {
  BESPOKE_REQUIRE_SHARED(shared);
  const auto dir = shared / "data/patterns/valentina";
  const Pattern p = LoadPattern(
      dir / "maleshirt_std_AAMA_R12.dxf",
      std::filesystem::path(BESPOKE_SOURCE_DIR) / "eval/resize/data/maleshirt.sidecar.json");
  EXPECT_NO_THROW(ValidatePattern(p, "shirt"));
  EXPECT_FALSE(p.notes.empty());
  const Piece& back = p.pieces[p.FindPiece("BACKPANEL")];
  EXPECT_TRUE(std::any_of(back.straight.begin(), back.straight.end(),
                          [](const StraightRun& r) { return r.fold; }));
  for (const MeasurementBinding& b : p.bindings) EXPECT_TRUE(b.keep_ease.empty()) << b.id;
}

}  // namespace
}  // namespace bespoke
