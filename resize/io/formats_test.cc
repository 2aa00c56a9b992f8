#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "resize/designs/designs.h"
#include "resize/io/garmentcode.h"
#include "resize/io/pattern_dxf.h"
#include "resize/io/pattern_io.h"
#include "resize/io/pattern_json.h"
#include "resize/io/pattern_svg.h"
#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

Pattern Shirt() { return DraftDesign("shirt", BaseMeasurements("shirt")); }

TEST(PatternJson, RoundTripKeepsEverything) {
  testing::TempDir dir;
  const Pattern p = Shirt();
  WritePatternJson(p, dir / "shirt.json");
  const Pattern q = ReadPatternJson(dir / "shirt.json");
  ASSERT_EQ(p.pieces.size(), q.pieces.size());
  for (size_t i = 0; i < p.pieces.size(); ++i) {
    EXPECT_EQ((p.pieces[i].outline - q.pieces[i].outline).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(p.pieces[i].landmarks.size(), q.pieces[i].landmarks.size());
    EXPECT_EQ(p.pieces[i].critical, q.pieces[i].critical);
  }
  ASSERT_EQ(p.bindings.size(), q.bindings.size());
  for (size_t b = 0; b < p.bindings.size(); ++b)
    EXPECT_NEAR(BindingValue(p, p.bindings[b]), BindingValue(q, q.bindings[b]), 1e-9);
  EXPECT_EQ(p.seams.size(), q.seams.size());
}

TEST(PatternJson, BadInputIsAClearInputError) {
  nlohmann::json doc = PatternToJson(Shirt());
  auto expect_error = [](const nlohmann::json& d, const std::string& fragment) {
    try {
      PatternFromJson(d, "p.json");
      ADD_FAILURE() << "no error for " << fragment;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  nlohmann::json crossed = doc;  // a bow-tie outline
  crossed["pieces"][3]["outline"] = {{0, 0}, {100, 100}, {100, 0}, {0, 100}};
  crossed["pieces"][3]["critical"] = nlohmann::json::array();
  crossed["pieces"][3]["notches"] = nlohmann::json::array();
  crossed["pieces"][3]["landmarks"] = nlohmann::json::array();
  crossed["seams"] = nlohmann::json::array();
  crossed["bindings"] = nlohmann::json::array();
  expect_error(crossed, "self-intersects");
  nlohmann::json seam = doc;
  seam["seams"][0]["a"]["to"] = seam["seams"][0]["a"]["to"].get<int>() + 1;
  expect_error(seam, "different point counts");
  nlohmann::json binding = doc;
  binding["bindings"][0]["terms"][0]["from"] = "nowhere";
  expect_error(binding, "unknown landmark");
}

TEST(PatternSvg, IsMillimetreScaledAndLabelled) {
  const std::string svg = PatternToSvg(SvgOptions{}, Shirt());
  EXPECT_NE(svg.find("mm\" height=\""), std::string::npos);
  EXPECT_NE(svg.find(">sleeve<"), std::string::npos);
  EXPECT_NE(svg.find("cut 2"), std::string::npos);
}

TEST(PatternDxf, RoundTripThroughOurReader) {
  for (DxfFlavor flavor : {DxfFlavor::kAstm, DxfFlavor::kAama}) {
    DxfWriteOptions options;
    options.flavor = flavor;
    const Pattern p = Shirt();
    const Pattern q = PatternFromDxf(PatternToDxf(options, p), "roundtrip.dxf");
    ASSERT_EQ(q.pieces.size(), p.pieces.size());
    for (size_t i = 0; i < p.pieces.size(); ++i) {
      const Piece &a = p.pieces[i], &b = q.pieces[i];
      ASSERT_EQ(a.num_vertices(), b.num_vertices()) << a.name;
      // Same shape, moved by the layout: compare after removing the offset.
      const Eigen::RowVector2d shift = b.outline.row(0) - a.outline.row(0);
      EXPECT_LT(((b.outline.rowwise() - shift) - a.outline).cwiseAbs().maxCoeff(), 1e-5);
      EXPECT_EQ(a.notches, b.notches) << a.name;
      EXPECT_EQ(a.cut_count, b.cut_count);
      EXPECT_TRUE(b.has_grain);
      EXPECT_EQ(b.name, a.name);
    }
  }
}

TEST(PatternDxf, ReadsTheValentinaSamples) {
  BESPOKE_REQUIRE_SHARED(shared);
  const auto dir = shared / "data/patterns/valentina";
  for (const char* name : {"smart_pattern_145_AAMA_R12.dxf", "smart_pattern_145_ASTM_R12.dxf",
                           "maleshirt_std_AAMA_R12.dxf", "maleshirt_std_AAMA_2000.dxf",
                           "maleshirt_std_ASTM_R12.dxf", "maleshirt_big_AAMA_R12.dxf",
                           "steampunk_trousers_AAMA_R12.dxf", "steampunk_trousers_ASTM_R12.dxf"}) {
    const Pattern p = ReadPatternDxf(dir / name);
    EXPECT_GE(p.pieces.size(), 1u) << name;
    for (const Piece& piece : p.pieces) EXPECT_GT(SignedArea(piece.outline), 0) << name;
  }
  // The small pattern: one piece, cut 2, a grain line and one notch.
  const Pattern small = ReadPatternDxf(dir / "smart_pattern_145_ASTM_R12.dxf");
  ASSERT_EQ(small.pieces.size(), 1u);
  EXPECT_EQ(small.pieces[0].cut_count, 2);
  EXPECT_TRUE(small.pieces[0].has_grain);
  EXPECT_EQ(small.pieces[0].notches.size(), 1u);
  // Layer 14: 34 vertices, the first repeated; one added where the notch
  // (on the cut line) meets the sew line between two vertices.
  EXPECT_EQ(small.pieces[0].num_vertices(), 34);
  EXPECT_EQ(std::count_if(small.notes.begin(), small.notes.end(),
                          [](const std::string& n) { return n.find("1 notch") != n.npos; }),
            1);
  // The same pattern written by us and read back keeps its sew line.
  const Pattern again = PatternFromDxf(PatternToDxf(DxfWriteOptions{}, small), "again.dxf");
  EXPECT_EQ(again.pieces[0].num_vertices(), small.pieces[0].num_vertices());
}

TEST(PatternDxf, NotchesGoToTheNearestPointOfTheSewLine) {
  // A 100 mm square sew line; a notch 10 mm outside the right edge at
  // height 37 (no vertex there: one is added) and one 10 mm above the top
  // right corner (taken by that vertex).
  std::string dxf = "0\nSECTION\n2\nBLOCKS\n0\nBLOCK\n2\nP1\n0\nLWPOLYLINE\n8\n14\n70\n1\n";
  for (const char* xy : {"0\n20\n0", "100\n20\n0", "100\n20\n100", "0\n20\n100"})
    dxf += std::string("10\n") + xy + "\n";
  dxf += "0\nPOINT\n8\n4\n10\n110\n20\n37\n0\nPOINT\n8\n4\n10\n100.3\n20\n110\n";
  dxf += "0\nENDBLK\n0\nENDSEC\n0\nEOF\n";
  const Pattern p = PatternFromDxf(dxf, "square.dxf");
  ASSERT_EQ(p.pieces.size(), 1u);
  const Piece& piece = p.pieces[0];
  ASSERT_EQ(piece.num_vertices(), 5);
  EXPECT_EQ(piece.outline.row(2), Eigen::RowVector2d(100, 37));
  EXPECT_EQ(piece.notches, (std::vector<int>{2, 3}));
  EXPECT_EQ(piece.outline.row(3), Eigen::RowVector2d(100, 100));
  ASSERT_EQ(p.notes.size(), 1u);
  EXPECT_NE(p.notes[0].find("1 notch"), std::string::npos);
}

TEST(PatternDxf, MalformedFilesAreInputErrors) {
  EXPECT_THROW(PatternFromDxf("  0\nSECTION\n  2\nBLOCKS\n", "cut.dxf"), InputError);
  EXPECT_THROW(PatternFromDxf("abc\nSECTION\n", "bad.dxf"), InputError);
  EXPECT_THROW(PatternFromDxf("  0\nEOF\n", "empty.dxf"), InputError);
}

TEST(GarmentCode, ImportsTheSamples) {
  BESPOKE_REQUIRE_SHARED(shared);
  const auto dir = shared / "data/patterns/garmentcode";
  for (const char* name : {"tee.json", "shirt_mean_specification.json", "pants_straight_sides.json",
                           "hoody_mean_specification.json", "dress_pencil_specification.json",
                           "js_mean_all_specification.json", "template_spec_with_comments.json"}) {
    const Pattern p = LoadPattern(dir / name, {});
    EXPECT_GE(p.pieces.size(), 2u) << name;
    EXPECT_GE(p.seams.size(), 1u) << name;
  }
  // The template's front panel is 110 units wide at the top: units_in_meter 300 -> 366.7 mm.
  const Pattern t = LoadPattern(dir / "template_spec_with_comments.json", {});
  const Piece& back = t.pieces[t.FindPiece("back")];
  EXPECT_NEAR(back.outline.col(0).maxCoeff() - back.outline.col(0).minCoeff(), 264 * 1000.0 / 300,
              1e-6);
}

TEST(GarmentCode, SidecarAddsBindings) {
  testing::TempDir dir;
  std::ofstream(dir / "p.json") << R"({"pattern": {"panels": {"a": {
      "vertices": [[0,0],[10,0],[10,20],[0,20]],
      "edges": [{"endpoints":[0,1]},{"endpoints":[1,2]},{"endpoints":[2,3]},{"endpoints":[3,0]}]}},
      "stitches": []}, "properties": {"units_in_meter": 100}})";
  std::ofstream(dir / "s.json") << R"({"pieces": [{"name": "a", "landmarks": [
      {"name": "bl", "near": [0, 0]}, {"name": "tl", "near": [0, 200]}]}],
      "bindings": [{"id": "h", "measurement": "back_length", "ease_mm": 5,
                    "terms": [{"piece": "a", "from": "bl", "to": "tl"}]}]})";
  const Pattern p = LoadPattern(dir / "p.json", dir / "s.json");
  ASSERT_EQ(p.bindings.size(), 1u);
  EXPECT_NEAR(BindingValue(p, p.bindings[0]), 200.0, 1e-9);  // 20 cm
}

}  // namespace
}  // namespace bespoke
