// The measurement document, its CSV and the exports parse back: JSON fields
// of docs/contracts.md, the CSV header and rows, a well-formed .vit in cm
// with the catalogue's Valentina names, FreeSewing names in mm.
#include "measure/measurements/measurement_exports.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>
#include <vector>

#include "measure/measurements/measurement_document.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

MeasureResult Sample() {
  MeasureResult r;
  auto add = [&](const std::string& name, double value, std::vector<std::string> flags = {}) {
    const MeasurementDef& def = Catalogue::Builtin().Measurement(name);
    Measurement m;
    m.name = name, m.kind = def.kind, m.method = def.method, m.datum = def.datum;
    m.value_mm = value, m.flags = std::move(flags);
    m.geometry = Eigen::MatrixX3d::Random(4, 3);
    r.measurements.push_back(m);
  };
  add("bust_girth", 912.345, {"section_open"});
  add("waist_girth", 760.0);
  add("shoulder_width", 370.0);  // no Valentina name, no FreeSewing name
  add("stature", 1660.0);
  r.skipped.emplace_back("crotch_length", "no landmark 'crotch'");
  r.stages.push_back({"girths", 0.1, 0.2});
  return r;
}

LandmarkSet Landmarks() {
  LandmarkSet set;
  Landmark crown;
  crown.position_mm = {1.234, 2, 1660};
  crown.confidence = 0.4;
  crown.flags = {"in_hole"};
  set.points["crown"] = crown;
  set.missing["crotch"] = "legs not separated";
  return set;
}

TEST(MeasurementDocument, FollowsTheContract) {
  const nlohmann::json doc = MeasurementDocument(
      Sample(), Landmarks(), {{"settings", {{"x", 1}}}, {"timings", {{{"name", "read"}}}}});
  EXPECT_EQ(doc["format"], "bespoke-measurements");
  EXPECT_EQ(doc["version"], 1);
  EXPECT_EQ(doc["units"], "mm");
  EXPECT_EQ(doc["frame"], "body");
  EXPECT_DOUBLE_EQ(doc["landmarks"]["crown"][0].get<double>(), 1.23);
  EXPECT_EQ(doc["landmark_details"]["crown"]["flags"][0], "in_hole");
  EXPECT_EQ(doc["landmarks_missing"]["crotch"], "legs not separated");
  ASSERT_EQ(doc["measurements"].size(), 4u);
  const nlohmann::json& bust = doc["measurements"][0];
  EXPECT_EQ(bust["name"], "bust_girth");
  EXPECT_EQ(bust["kind"], "girth");
  EXPECT_DOUBLE_EQ(bust["value_mm"].get<double>(), 912.35);
  EXPECT_EQ(bust["flags"][0], "section_open");
  EXPECT_EQ(bust["method"], "section_hull");
  EXPECT_FALSE(bust.contains("geometry"));
  EXPECT_EQ(doc["skipped"][0]["name"], "crotch_length");
  EXPECT_EQ(doc["settings"]["x"], 1);
  ASSERT_EQ(doc["timings"].size(), 2u);  // the caller's first, then Measure's
  EXPECT_EQ(doc["timings"][0]["name"], "read");
  EXPECT_EQ(doc["timings"][1]["name"], "girths");
  const nlohmann::json with =
      MeasurementDocument(Sample(), Landmarks(), nlohmann::json::object(), true);
  EXPECT_EQ(with["measurements"][0]["geometry"].size(), 4u);

  const testing::TempDir dir;
  WriteMeasurementDocument(dir / "m.json", doc);
  EXPECT_EQ(ReadJsonFile(dir / "m.json"), doc);
  EXPECT_THROW(WriteMeasurementDocument(dir.path() / "missing" / "m.json", doc), InputError);
}

TEST(MeasurementDocument, CsvHasTheHeaderAndOneRowPerMeasurement) {
  const std::string csv = MeasurementsCsv(Sample());
  std::istringstream in(csv);
  std::string line;
  std::vector<std::string> lines;
  while (std::getline(in, line)) lines.push_back(line);
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0], "name,kind,method,value_mm,flags,datum");
  EXPECT_EQ(lines[1], "bust_girth,girth,section_hull,912.35,section_open,bust_right;bust_left");
  EXPECT_EQ(lines[4], "stature,height,height,1660.00,,crown");
}

// Tags of an XML text nest properly (a small well-formedness check: no
// stray '<' or '&', every open tag closed in order).
bool WellFormed(const std::string& xml) {
  std::vector<std::string> open;
  for (std::size_t i = 0; i < xml.size();) {
    if (xml[i] == '&') {
      const std::size_t semi = xml.find(';', i);
      if (semi == std::string::npos || semi - i > 6) return false;
      i = semi + 1;
      continue;
    }
    if (xml[i] != '<') {
      ++i;
      continue;
    }
    const std::size_t end = xml.find('>', i);
    if (end == std::string::npos) return false;
    const std::string tag = xml.substr(i + 1, end - i - 1);
    i = end + 1;
    if (tag.empty()) return false;
    if (tag[0] == '?' || tag[0] == '!') continue;
    if (tag.find('<') != std::string::npos) return false;
    if (tag[0] == '/') {
      if (open.empty() || open.back() != tag.substr(1)) return false;
      open.pop_back();
    } else if (tag.back() != '/') {
      open.push_back(tag.substr(0, tag.find(' ')));
    }
  }
  return open.empty();
}

TEST(MeasurementExports, ValentinaVitIsWellFormedInCentimetres) {
  const std::string vit = ValentinaVit(Sample(), Catalogue::Builtin());
  EXPECT_TRUE(WellFormed(vit)) << vit;
  EXPECT_NE(vit.find("<unit>cm</unit>"), std::string::npos);
  EXPECT_NE(vit.find("<m name=\"bust_circ\" value=\"91.23\""), std::string::npos) << vit;
  EXPECT_NE(vit.find("<m name=\"waist_circ\" value=\"76.00\""), std::string::npos);
  EXPECT_NE(vit.find("<m name=\"height\" value=\"166.00\""), std::string::npos);
  EXPECT_NE(vit.find("flags: section_open"), std::string::npos);
  const std::regex entry("<m name=\"[a-z_]+\" value=\"[0-9.]+\"");
  EXPECT_EQ(
      std::distance(std::sregex_iterator(vit.begin(), vit.end(), entry), std::sregex_iterator()),
      3);
  EXPECT_TRUE(WellFormed("<a><b/></a>"));
  EXPECT_FALSE(WellFormed("<a><b></a>"));
}

TEST(MeasurementExports, FreeSewingUsesItsNamesInMillimetres) {
  const nlohmann::json fs = FreeSewingMeasurements(Sample(), Catalogue::Builtin());
  EXPECT_EQ(fs["units"], "metric");
  EXPECT_DOUBLE_EQ(fs["measurements"]["chest"].get<double>(), 912.3);
  EXPECT_DOUBLE_EQ(fs["measurements"]["waist"].get<double>(), 760.0);
  EXPECT_EQ(fs["measurements"].size(), 2u);  // stature and shoulder width have no FreeSewing name
  const testing::TempDir dir;
  WriteFreeSewingJson(dir / "fs.json", Sample(), Catalogue::Builtin());
  EXPECT_EQ(ReadJsonFile(dir / "fs.json"), fs);
  WriteValentinaVit(dir / "m.vit", Sample(), Catalogue::Builtin());
  EXPECT_TRUE(std::filesystem::file_size(dir / "m.vit") > 100);
}

}  // namespace
}  // namespace bespoke
