// Real subjects: scans matched to subjects by name, and the comparison with
// the reference on a small fixture built here (two scans for some subjects,
// failed scans), against figures computed by hand.
#include "eval/accuracy/reference_compare.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bespoke {
namespace {

using nlohmann::json;

ScanEntry Scan(const std::string& file) { return {"id_" + file, "/scans/" + file, "", "", {}}; }

TEST(MatchScans, SubjectsRepeatsAndLeftovers) {
  const ScanMatch m =
      MatchScans({"anna", "ben", "anna_2", "dora"},
                 {Scan("anna_1.ply"), Scan("anna_10.pcd"), Scan("anna_2.ply"), Scan("ben.obj"),
                  Scan("ben_x.ply"), Scan("carl_1.ply"), Scan("anna_.ply")});
  std::vector<std::pair<std::string, std::string>> got;
  for (const SubjectScan& s : m.scans) got.push_back({s.subject, s.scan.path.filename().string()});
  const std::vector<std::pair<std::string, std::string>> expected = {{"anna", "anna_1.ply"},
                                                                     {"anna", "anna_10.pcd"},
                                                                     {"ben", "ben.obj"},
                                                                     {"anna_2", "anna_2.ply"}};
  EXPECT_EQ(got, expected);
  std::vector<std::string> left;
  for (const NotCompared& n : m.not_compared) left.push_back(n.where + " / " + n.subject);
  const std::vector<std::string> expected_left = {"scan ben_x.ply / ", "scan carl_1.ply / ",
                                                  "scan anna_.ply / ", "scans folder / dora"};
  EXPECT_EQ(left, expected_left);
}

json Document(const std::vector<std::pair<std::string, double>>& values) {
  json measurements = json::array();
  for (const auto& [name, value] : values) {
    measurements.push_back({{"name", name}, {"value_mm", value}, {"flags", json::array()}});
  }
  return {{"format", "bespoke-measurements"}, {"units", "mm"}, {"measurements", measurements}};
}

ScanMeasurement Measured(const std::string& subject, const std::string& scan, double stature) {
  return {subject, scan, Document({{"stature", stature}}), "", ""};
}

ScanMeasurement Failed(const std::string& subject, const std::string& scan) {
  return {subject, scan, json(), "input_error", "too few points"};
}

TEST(CompareWithReference, MeansOfScansRepeatabilityAndFailures) {
  ReferenceTable table;
  table.subjects = {"a", "b", "c", "d", "e"};
  int line = 2;
  for (const auto& [subject, stature] : std::vector<std::pair<std::string, double>>{
           {"a", 1700}, {"b", 1650}, {"c", 1800}, {"d", 1600}, {"e", 1750}}) {
    table.values.push_back({subject, "stature", stature, "tape", line++});
  }
  table.values.push_back({"a", "waist_girth", 800, "tape", line++});
  const std::vector<ScanMeasurement> scans = {
      Measured("a", "a_1.ply", 1702), Measured("a", "a_2.ply", 1706),  // mean 1704: +4
      Measured("b", "b_1.ply", 1649), Measured("b", "b_2.ply", 1651),  // mean 1650: 0
      Measured("c", "c.ply", 1798),                                    // -2
      Failed("d", "d_1.ply"),         Failed("d", "d_2.ply"),          // d fails
      Measured("e", "e_1.ply", 1751), Failed("e", "e_2.ply")};         // +1
  const AccuracyReport r = CompareWithReference(table, scans, Catalogue::Builtin());
  EXPECT_EQ(r.reference_label, "reference");
  ASSERT_EQ(r.subjects.size(), 4u);

  // Differences 4, 0, -2, 1: mean 0.75, SD sqrt(18.75 / 3) = 2.5, t(3) = 3.182446.
  const MeasurementSummary* stature = nullptr;
  const MeasurementSummary* waist = nullptr;
  for (const MeasurementSummary& m : r.summary.measurements) {
    if (m.name == "stature") stature = &m;
    if (m.name == "waist_girth") waist = &m;
  }
  ASSERT_TRUE(stature && waist);
  EXPECT_EQ(stature->stats.n, 4);
  EXPECT_NEAR(stature->stats.mean_mm, 0.75, 1e-9);
  EXPECT_NEAR(stature->stats.sd_mm, 2.5, 1e-9);
  EXPECT_NEAR(stature->stats.ci_low_mm, 0.75 - 3.182446 * 1.25, 1e-5);
  EXPECT_NEAR(stature->stats.ci_high_mm, 0.75 + 3.182446 * 1.25, 1e-5);
  EXPECT_NEAR(stature->stats.loa_low_mm, 0.75 - 1.959964 * 2.5, 1e-5);
  EXPECT_NEAR(stature->stats.mae_mm, 1.75, 1e-9);
  EXPECT_EQ(stature->verdict, IsoVerdict::kFail);  // 4.73 reaches past the 4 mm limit
  // Bland-Altman x: the mean of each subject's measured and reference values.
  EXPECT_EQ(stature->means_mm, (std::vector<double>{1702, 1650, 1799, 1750.5}));
  EXPECT_EQ(waist->missing, 1);  // no scan measured a's waist
  EXPECT_EQ(waist->stats.n, 0);

  // Repeatability from a (1702, 1706) and b (1649, 1651): pooled variance
  // (8 + 2) / 2 = 5; c and e have one value each.
  ASSERT_EQ(r.repeatability.size(), 1u);
  EXPECT_EQ(r.repeatability[0].name, "stature");
  EXPECT_EQ(r.repeatability[0].stats.subjects, 2);
  EXPECT_EQ(r.repeatability[0].stats.values, 4);
  EXPECT_NEAR(r.repeatability[0].stats.within_sd_mm, std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(r.repeatability[0].stats.coefficient_mm, 2.771808 * std::sqrt(5.0), 1e-5);

  // d: every scan failed; e: one failed scan beside a measured one.
  ASSERT_EQ(r.failures.size(), 1u);
  EXPECT_EQ(r.failures[0].subject, "d");
  EXPECT_EQ(r.failures[0].stage, "input_error");
  EXPECT_NE(r.failures[0].error.find("d_2.ply: too few points"), std::string::npos);
  ASSERT_EQ(r.not_compared.size(), 1u);
  EXPECT_EQ(r.not_compared[0].subject, "e");
  EXPECT_EQ(r.not_compared[0].where, "scan e_2.ply");
}

}  // namespace
}  // namespace bespoke
