#include "measure/catalogue/catalogue.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using nlohmann::json;

TEST(Catalogue, UnsidedLandmarkNameDropsOnlyTheSideSuffix) {
  EXPECT_EQ(UnsidedLandmarkName("shoulder_right"), "shoulder");
  EXPECT_EQ(UnsidedLandmarkName("ankle_inside_left"), "ankle_inside");
  EXPECT_EQ(UnsidedLandmarkName("crotch"), "crotch");
  EXPECT_EQ(UnsidedLandmarkName("_left"), "_left");  // nothing would be left
  EXPECT_EQ(UnsidedLandmarkName("left_hand"), "left_hand");
}

TEST(Catalogue, BuiltinParsesWithEnoughEntries) {
  const Catalogue& c = Catalogue::Builtin();
  EXPECT_GE(c.measurements().size(), 40u);
  EXPECT_GE(c.landmarks().size(), 40u);  // paired landmarks count twice
}

// docs/contracts.md: names other stages bind to.
TEST(Catalogue, HasEveryCoreNameOfTheContracts) {
  const Catalogue& c = Catalogue::Builtin();
  for (const char* name :
       {"stature",          "neck_girth",      "bust_girth",       "chest_girth",
        "under_bust_girth", "waist_girth",     "middle_hip_girth", "hip_girth",
        "upper_arm_girth",  "wrist_girth",     "thigh_girth",      "knee_girth",
        "calf_girth",       "ankle_girth",     "back_length",      "front_length",
        "shoulder_length",  "across_shoulder", "back_width",       "front_width",
        "armhole_length",   "arm_length",      "sleeve_length",    "waist_to_hip",
        "crotch_length",    "inside_leg",      "outseam",          "waist_to_knee",
        "waist_height"})
    EXPECT_TRUE(c.HasMeasurement(name)) << name;
}

// The canonical landmark list shared with the parametric body.
TEST(Catalogue, HasTheCanonicalLandmarks) {
  const Catalogue& c = Catalogue::Builtin();
  for (const char* name : {"crown", "back_neck", "front_neck", "under_bust", "front_waist",
                           "back_waist", "middle_hip_front", "hip_back", "crotch"})
    EXPECT_TRUE(c.HasLandmark(name)) << name;
  for (const char* paired : {"side_neck", "shoulder", "axilla_front", "axilla_back", "armpit",
                             "bust", "side_waist", "hip", "upper_arm", "elbow", "wrist", "thigh",
                             "knee", "calf", "ankle_inside", "ankle_outside"})
    for (const char* side : {"_left", "_right"})
      EXPECT_TRUE(c.HasLandmark(std::string(paired) + side)) << paired << side;
}

TEST(Catalogue, NamesAreUniqueSnakeCaseAndDatumPointsExist) {
  const Catalogue& c = Catalogue::Builtin();
  std::set<std::string> names;
  auto snake = [](const std::string& s) {
    if (s.empty() || !std::islower(static_cast<unsigned char>(s[0]))) return false;
    for (const char ch : s)
      if (!(std::islower(static_cast<unsigned char>(ch)) ||
            std::isdigit(static_cast<unsigned char>(ch)) || ch == '_'))
        return false;
    return true;
  };
  for (const LandmarkDef& l : c.landmarks()) {
    EXPECT_TRUE(names.insert(l.name).second) << l.name;
    EXPECT_TRUE(snake(l.name)) << l.name;
  }
  std::set<std::string> valentina, freesewing;
  for (const MeasurementDef& m : c.measurements()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name;  // also distinct from landmarks
    EXPECT_TRUE(snake(m.name)) << m.name;
    for (const std::string& d : m.datum) EXPECT_TRUE(c.HasLandmark(d)) << m.name << ": " << d;
    for (const std::string& d : m.axis) EXPECT_TRUE(c.HasLandmark(d)) << m.name << ": " << d;
    if (!m.valentina.empty()) {
      EXPECT_TRUE(valentina.insert(m.valentina).second) << m.valentina;
    }
    if (!m.freesewing.empty()) {
      EXPECT_TRUE(freesewing.insert(m.freesewing).second) << m.freesewing;
    }
  }
}

TEST(Catalogue, EveryThesisTable34MeasurementIsMapped) {
  std::set<std::string> thesis;
  for (const MeasurementDef& m : Catalogue::Builtin().measurements())
    if (!m.thesis.empty()) thesis.insert(m.thesis);
  for (const char* name :
       {"Bust Girth", "Chest Girth", "Waist Girth", "Middle Hip Girth", "Hip Girth", "Neck girth",
        "Cuff Girth", "Height", "Back Length", "Sleeve Length", "Arm Hole Length", "Sleeve Top",
        "Waist length", "Crotch Depth", "Inside-Leg Length"})
    EXPECT_TRUE(thesis.count(name)) << name;
}

TEST(Catalogue, LookupsOfUnknownNamesAreInputErrors) {
  const Catalogue& c = Catalogue::Builtin();
  EXPECT_EQ(c.Measurement("wrist_girth").plane, GirthPlane::kPerpendicularToAxis);
  EXPECT_EQ(c.Landmark("back_neck").region, "neck");
  EXPECT_THROW(c.Measurement("wrist_girht"), InputError);
  EXPECT_THROW(c.Landmark("shoulder"), InputError);  // only _left / _right exist
}

TEST(Catalogue, MalformedDocumentsAreInputErrors) {
  const json good = json::parse(BuiltinCatalogueJson());
  EXPECT_NO_THROW(Catalogue::FromJson(good, "good"));
  json bad = good;
  bad["measurements"][0]["datum"] = {"no_such_point"};
  EXPECT_THROW(Catalogue::FromJson(bad, "bad"), InputError);
  bad = good;
  bad["measurements"].push_back(good["measurements"][0]);
  EXPECT_THROW(Catalogue::FromJson(bad, "dup"), InputError);
  bad = good;
  bad["measurements"][0]["kind"] = "volume";
  EXPECT_THROW(Catalogue::FromJson(bad, "kind"), InputError);
  bad = good;
  bad["measurements"][0].erase("method");
  EXPECT_THROW(Catalogue::FromJson(bad, "method"), InputError);
  bad = good;
  bad["landmarks"][0].erase("definition");
  EXPECT_THROW(Catalogue::FromJson(bad, "definition"), InputError);
  EXPECT_THROW(Catalogue::FromJson(json::array(), "array"), InputError);
  // "narrowest_up_to": a known landmark, on a horizontal right-side girth.
  std::size_t ankle = 0;
  while (good["measurements"][ankle]["name"] != "ankle_girth") ++ankle;
  EXPECT_EQ(Catalogue::Builtin().Measurement("ankle_girth").narrowest_up_to, "calf_right");
  bad = good;
  bad["measurements"][ankle]["narrowest_up_to"] = "no_such_point";
  EXPECT_THROW(Catalogue::FromJson(bad, "unknown top"), InputError);
  bad = good;
  bad["measurements"][ankle]["side"] = "centre";
  EXPECT_THROW(Catalogue::FromJson(bad, "not a limb"), InputError);
  // A girth over the skin is a closed chain of at least three points.
  std::size_t neck = 0;
  while (good["measurements"][neck]["name"] != "neck_girth") ++neck;
  const MeasurementDef& loop = Catalogue::Builtin().Measurement("neck_girth");
  EXPECT_EQ(loop.method, MeasurementMethod::kGeodesic);
  EXPECT_EQ(loop.datum.front(), loop.datum.back());
  bad = good;
  bad["measurements"][neck]["datum"].erase(bad["measurements"][neck]["datum"].size() - 1);
  EXPECT_THROW(Catalogue::FromJson(bad, "open loop"), InputError);
  bad = good;
  bad["measurements"][neck]["datum"] = {"front_neck", "back_neck", "front_neck"};
  EXPECT_THROW(Catalogue::FromJson(bad, "two-point loop"), InputError);
}

// docs/measurements.md is generated from the catalogue; this fails when it is
// stale. Regenerate: BESPOKE_UPDATE_DOCS=1 catalogue_tests --gtest_filter=<this>.
// The path is the source tree's (CMake), so the test finds the doc from any
// working directory.
TEST(Catalogue, MarkdownDocIsCurrent) {
  const std::filesystem::path doc = BESPOKE_MEASUREMENTS_DOC;
  const std::string expected = Catalogue::Builtin().ToMarkdown();
  if (const char* update = std::getenv("BESPOKE_UPDATE_DOCS"); update && *update == '1') {
    std::ofstream(doc, std::ios::binary) << expected;
  }
  std::ifstream in(doc, std::ios::binary);
  if (!in) GTEST_SKIP() << doc << " not found (source tree not beside the build)";
  std::stringstream actual;
  actual << in.rdbuf();
  EXPECT_TRUE(actual.str() == expected)
      << doc << " is stale: run BESPOKE_UPDATE_DOCS=1 catalogue_tests "
      << "--gtest_filter=Catalogue.MarkdownDocIsCurrent";
}

}  // namespace
}  // namespace bespoke
