// Statistics against hand-computed values, ISO 20685-1 classes and verdicts,
// the comparison of documents built here (frames mapped), the summary, the
// posture table and the report files.
#include <gtest/gtest.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "eval/accuracy/accuracy_report.h"
#include "eval/accuracy/accuracy_stats.h"
#include "eval/accuracy/accuracy_summary.h"
#include "eval/accuracy/compare.h"
#include "eval/accuracy/iso_20685.h"
#include "eval/accuracy/posture.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

TEST(AccuracyStats, StudentQuantilesMatchTables) {
  EXPECT_NEAR(StudentT975(1), 12.7062, 1e-4);
  EXPECT_NEAR(StudentT975(4), 2.7764, 1e-4);
  EXPECT_NEAR(StudentT975(29), 2.0452, 1e-4);
  EXPECT_THROW(StudentT975(0), InputError);
}

TEST(AccuracyStats, HandComputedValues) {
  // 1..5 mm: mean 3, SD sqrt(2.5), CI 3 -/+ 2.776445 * sqrt(2.5 / 5).
  ErrorStats s = SummarizeErrors({1, 2, 3, 4, 5});
  EXPECT_EQ(s.n, 5);
  EXPECT_DOUBLE_EQ(s.mean_mm, 3);
  EXPECT_NEAR(s.sd_mm, 1.581139, 1e-6);
  EXPECT_NEAR(s.ci_low_mm, 1.036757, 1e-5);
  EXPECT_NEAR(s.ci_high_mm, 4.963243, 1e-5);
  EXPECT_DOUBLE_EQ(s.mae_mm, 3);
  EXPECT_DOUBLE_EQ(s.max_abs_mm, 5);
  EXPECT_DOUBLE_EQ(s.median_abs_mm, 3);
  // Limits of agreement 3 -/+ 1.959964 * 1.581139.
  EXPECT_NEAR(s.loa_low_mm, -0.098975, 1e-5);
  EXPECT_NEAR(s.loa_high_mm, 6.098975, 1e-5);
  // -2, 0, 2, 4: mean 1, |e| = 2, 0, 2, 4 (MAE 2, median 2), SD sqrt(20/3), t(3) = 3.182446.
  s = SummarizeErrors({-2, 0, 2, 4});
  EXPECT_DOUBLE_EQ(s.mean_mm, 1);
  EXPECT_NEAR(s.sd_mm, 2.581989, 1e-6);
  EXPECT_NEAR(s.ci_low_mm, -3.108521, 1e-5);
  EXPECT_NEAR(s.ci_high_mm, 5.108521, 1e-5);
  EXPECT_DOUBLE_EQ(s.mae_mm, 2);
  EXPECT_DOUBLE_EQ(s.max_abs_mm, 4);
  EXPECT_DOUBLE_EQ(s.median_abs_mm, 2);
}

TEST(AccuracyStats, SmallSamplesAndBadValues) {
  ErrorStats one = SummarizeErrors({-3});
  EXPECT_EQ(one.n, 1);
  EXPECT_DOUBLE_EQ(one.mean_mm, -3);
  EXPECT_DOUBLE_EQ(one.mae_mm, 3);
  EXPECT_TRUE(std::isnan(one.sd_mm));
  EXPECT_TRUE(std::isnan(one.ci_low_mm));
  EXPECT_TRUE(std::isnan(SummarizeErrors({}).mean_mm));
  EXPECT_THROW(SummarizeErrors({1, NAN}), InputError);
  EXPECT_DOUBLE_EQ(Median({4, 1, 3, 2}), 2.5);
}

TEST(AccuracyStats, RepeatabilityByHand) {
  // 100, 102 (mean 101, squares 2, 1 dof); 200, 203, 206 (mean 203, squares
  // 18, 2 dof); 300 alone says nothing. Pooled variance 20 / 3.
  const RepeatabilityStats r = SummarizeRepeatability({{100, 102}, {200, 203, 206}, {300}});
  EXPECT_EQ(r.subjects, 2);
  EXPECT_EQ(r.values, 5);
  EXPECT_NEAR(r.within_sd_mm, 2.581989, 1e-6);
  EXPECT_NEAR(r.coefficient_mm, 2.771808 * 2.581989, 1e-5);  // 1.959964 * sqrt(2) * SD
  const RepeatabilityStats none = SummarizeRepeatability({{1}, {}});
  EXPECT_EQ(none.subjects, 0);
  EXPECT_TRUE(std::isnan(none.within_sd_mm));
  EXPECT_TRUE(std::isnan(none.coefficient_mm));
  EXPECT_THROW(SummarizeRepeatability({{1, std::nan("")}}), InputError);
}

TEST(Iso20685, CataloguesClassesAndLimits) {
  const Catalogue& c = Catalogue::Builtin();
  for (const char* name : {"bust_girth", "chest_girth", "under_bust_girth", "waist_girth",
                           "middle_hip_girth", "hip_girth"}) {
    EXPECT_EQ(IsoClassOf(c.Measurement(name)), IsoClass::kLargeGirth) << name;
  }
  for (const char* name : {"neck_girth", "upper_arm_girth", "wrist_girth", "thigh_girth",
                           "calf_girth", "ankle_girth"}) {
    EXPECT_EQ(IsoClassOf(c.Measurement(name)), IsoClass::kSmallGirth) << name;
  }
  EXPECT_EQ(IsoClassOf(c.Measurement("back_length")), IsoClass::kSegmentLength);
  EXPECT_EQ(IsoClassOf(c.Measurement("inside_leg")), IsoClass::kSegmentLength);
  EXPECT_EQ(IsoClassOf(c.Measurement("shoulder_width")), IsoClass::kBreadth);
  EXPECT_EQ(IsoClassOf(c.Measurement("stature")), IsoClass::kHeight);
  EXPECT_EQ(IsoToleranceMm(IsoClass::kHeight), 4);
  EXPECT_EQ(IsoToleranceMm(IsoClass::kSmallGirth), 4);
  EXPECT_EQ(IsoToleranceMm(IsoClass::kSegmentLength), 5);
  EXPECT_EQ(IsoToleranceMm(IsoClass::kLargeGirth), 9);
}

TEST(Iso20685, VerdictUsesTheWholeInterval) {
  ErrorStats s;
  s.n = 10;
  s.ci_low_mm = -3.9, s.ci_high_mm = 3.9;
  EXPECT_EQ(JudgeIso20685(s, 4), IsoVerdict::kPass);
  s.ci_low_mm = -4.1, s.ci_high_mm = 1;  // the mean may be fine, the interval is not
  EXPECT_EQ(JudgeIso20685(s, 4), IsoVerdict::kFail);
  s.ci_low_mm = 8, s.ci_high_mm = 9.5;
  EXPECT_EQ(JudgeIso20685(s, 9), IsoVerdict::kFail);
  EXPECT_EQ(JudgeIso20685(SummarizeErrors({1}), 4), IsoVerdict::kNotJudged);
}

json Measurement(const std::string& name, const std::string& kind, double value,
                 std::vector<std::string> flags = {}) {
  return {{"name", name}, {"kind", kind}, {"value_mm", value}, {"flags", flags}};
}

// A scanner truth (scanner frame = body turned 90 deg about z and moved) and
// a measured document in an estimated body frame 3 mm and 1 deg off the true
// one; the crown is found 2 mm too high, the back neck 5 mm too far back.
struct Documents {
  json truth, measured;
};
Documents MakeDocuments(double bust_error_mm) {
  const Eigen::Vector3d crown(0, 10, 1700), back_neck(0, -60, 1400), hip(150, 0, 900);
  Eigen::Affine3d scanner_from_body = Eigen::Affine3d::Identity();
  scanner_from_body.rotate(Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()));
  scanner_from_body.pretranslate(Eigen::Vector3d(500, -200, 30));
  Eigen::Affine3d estimated_body_from_true_body = Eigen::Affine3d::Identity();
  estimated_body_from_true_body.rotate(Eigen::AngleAxisd(M_PI / 180, Eigen::Vector3d::UnitZ()));
  estimated_body_from_true_body.pretranslate(Eigen::Vector3d(3, 0, 0));
  const Eigen::Affine3d body_from_scanner =
      estimated_body_from_true_body * scanner_from_body.inverse();
  Documents d;
  d.truth = {
      {"format", "bespoke-measurements"},
      {"version", 1},
      {"units", "mm"},
      {"frame", "scanner"},
      {"landmarks",
       {{"crown", ToJson(Eigen::Vector3d(scanner_from_body * crown))},
        {"back_neck", ToJson(Eigen::Vector3d(scanner_from_body * back_neck))},
        {"hip_right", ToJson(Eigen::Vector3d(scanner_from_body * hip))}}},
      {"landmarks_body",
       {{"crown", ToJson(crown)}, {"back_neck", ToJson(back_neck)}, {"hip_right", ToJson(hip)}}},
      {"scanner_from_body", ToJson(scanner_from_body)},
      {"measurements",
       {Measurement("bust_girth", "girth", 930), Measurement("stature", "height", 1700),
        Measurement("back_length", "length", 400, {"datum_off_section"})}}};
  const auto found = [&](const Eigen::Vector3d& p) {
    return ToJson(Eigen::Vector3d(estimated_body_from_true_body * p));
  };
  d.measured = {{"format", "bespoke-measurements"},
                {"version", 1},
                {"units", "mm"},
                {"frame", "body"},
                {"body_from_scanner", ToJson(body_from_scanner)},
                {"landmarks",
                 {{"crown", found(crown + Eigen::Vector3d(0, 0, 2))},
                  {"back_neck", found(back_neck + Eigen::Vector3d(0, -5, 0))}}},
                {"measurements",
                 {Measurement("bust_girth", "girth", 930 + bust_error_mm, {"section_open"}),
                  Measurement("stature", "height", 1701.5)}}};
  return d;
}

TEST(CompareDocuments, DifferencesMissingAndFlags) {
  const Documents d = MakeDocuments(-6);
  const SubjectComparison c = CompareDocuments(d.measured, d.truth, "s1");
  ASSERT_EQ(c.measurements.size(), 3u);
  EXPECT_EQ(c.measurements[0].name, "bust_girth");
  EXPECT_NEAR(c.measurements[0].difference_mm, -6, 1e-9);
  EXPECT_EQ(c.measurements[0].flags, std::vector<std::string>{"section_open"});
  EXPECT_NEAR(c.measurements[1].difference_mm, 1.5, 1e-9);
  EXPECT_TRUE(c.measurements[2].missing);
  EXPECT_EQ(c.measurements[2].truth_flags, std::vector<std::string>{"datum_off_section"});
}

TEST(CompareDocuments, LandmarksInTheScannerFrameIgnoreTheFramesError) {
  const Documents d = MakeDocuments(0);
  const SubjectComparison c = CompareDocuments(d.measured, d.truth, "s1");
  EXPECT_EQ(c.landmark_frame, "scanner");
  ASSERT_EQ(c.landmarks.size(), 3u);  // by name: back_neck, crown, hip_right
  EXPECT_EQ(c.landmarks[0].name, "back_neck");
  EXPECT_NEAR(c.landmarks[0].error_mm, 5, 1e-9);
  EXPECT_NEAR(c.landmarks[1].error_mm, 2, 1e-9);
  EXPECT_TRUE(c.landmarks[2].missing);
  // Without body_from_scanner the body frames are compared directly: the
  // estimated frame's 3 mm and 1 deg now add to the error.
  json measured = d.measured;
  measured.erase("body_from_scanner");
  const SubjectComparison body = CompareDocuments(measured, d.truth, "s1");
  EXPECT_EQ(body.landmark_frame, "body");
  EXPECT_GT(body.landmarks[1].error_mm, 3);
}

// A point defined by a level (the calf: the level of the largest calf
// girth) counts its height's error only, along the body's up axis, which a
// y-up scanner frame turns onto its y; other points count the 3-D distance.
TEST(CompareDocuments, ALevelsPointCountsItsHeightOnly) {
  Eigen::Affine3d scanner_from_body = Eigen::Affine3d::Identity();
  scanner_from_body.rotate(Eigen::AngleAxisd(-M_PI / 2, Eigen::Vector3d::UnitX()));
  scanner_from_body.pretranslate(Eigen::Vector3d(20, 900, -100));
  const Eigen::Vector3d calf(100, -40, 350), knee(100, 60, 480), off(0, -20, -5);
  const auto in_scanner = [&](const Eigen::Vector3d& p) {
    return ToJson(Eigen::Vector3d(scanner_from_body * p));
  };
  const json truth = {
      {"format", "bespoke-measurements"},
      {"units", "mm"},
      {"frame", "scanner"},
      {"landmarks", {{"calf_right", in_scanner(calf)}, {"knee_right", in_scanner(knee)}}},
      {"measurements", json::array()}};
  const json measured = {
      {"format", "bespoke-measurements"},
      {"units", "mm"},
      {"frame", "body"},
      {"body_from_scanner", ToJson(Eigen::Affine3d(scanner_from_body.inverse()))},
      {"landmarks",
       {{"calf_right", ToJson(Eigen::Vector3d(calf + off))},
        {"knee_right", ToJson(Eigen::Vector3d(knee + off))}}},
      {"measurements", json::array()}};
  const SubjectComparison c = CompareDocuments(measured, truth, "s1");
  ASSERT_EQ(c.landmarks.size(), 2u);  // calf_right, knee_right
  EXPECT_TRUE(c.landmarks[0].height_only);
  EXPECT_NEAR(c.landmarks[0].error_mm, 5, 1e-9);
  EXPECT_FALSE(c.landmarks[1].height_only);
  EXPECT_NEAR(c.landmarks[1].error_mm, off.norm(), 1e-9);
}

TEST(CompareDocuments, RejectsOtherDocuments) {
  const Documents d = MakeDocuments(0);
  EXPECT_THROW(
      CompareDocuments(json{{"format", "x"}, {"measurements", json::array()}}, d.truth, "s"),
      InputError);
  EXPECT_THROW(CompareDocuments(d.measured, json::object(), "s"), InputError);
  json bad = d.measured;
  bad["landmarks"]["crown"] = {1, 2};
  EXPECT_THROW(CompareDocuments(bad, d.truth, "s"), InputError);
}

TEST(SummarizeAccuracy, PerMeasurementAndHeadline) {
  std::vector<SubjectComparison> subjects;
  for (double e : {-6.0, -2.0, 2.0}) {
    const Documents d = MakeDocuments(e);
    subjects.push_back(CompareDocuments(d.measured, d.truth, "s"));
  }
  const AccuracySummary s = SummarizeAccuracy(subjects, Catalogue::Builtin());
  EXPECT_EQ(s.subjects, 3);
  ASSERT_EQ(s.measurements.size(), 3u);  // catalogue order: bust_girth, back_length, stature
  const MeasurementSummary& bust = s.measurements[0];
  EXPECT_EQ(bust.name, "bust_girth");
  EXPECT_EQ(bust.iso_class, IsoClass::kLargeGirth);
  EXPECT_EQ(bust.stats.n, 3);
  EXPECT_NEAR(bust.stats.mean_mm, -2, 1e-9);
  EXPECT_EQ(bust.flagged, 3);
  EXPECT_EQ(bust.verdict, IsoVerdict::kFail);  // SD 4, CI -2 -/+ 4.303 * 4 / sqrt(3) = [-11.9, 7.9]
  EXPECT_EQ(s.measurements[1].name, "back_length");
  EXPECT_EQ(s.measurements[1].missing, 3);
  EXPECT_EQ(s.measurements[1].verdict, IsoVerdict::kNotJudged);
  EXPECT_EQ(s.measurements[2].name, "stature");
  EXPECT_EQ(s.measurements[2].stats.sd_mm, 0);
  EXPECT_EQ(s.measurements[2].verdict, IsoVerdict::kPass);  // always 1.5 mm: CI [1.5, 1.5]
  EXPECT_EQ(s.passed, 1);
  EXPECT_EQ(s.failed, 1);
  EXPECT_EQ(s.not_judged, 1);
  EXPECT_NEAR(s.large_girth_mae_mm, 10.0 / 3, 1e-9);
  EXPECT_NEAR(s.median_landmark_error_mm, 3.5, 1e-9);  // 2, 2, 2, 5, 5, 5
  EXPECT_EQ(s.landmark_frame, "scanner");
  ASSERT_GE(s.landmarks.size(), 3u);
  EXPECT_EQ(s.landmarks[0].name, "crown");  // catalogue order
  EXPECT_NEAR(s.landmarks[0].median_mm, 2, 1e-9);
}

TEST(ComparePostures, JudgesLengthsOnly) {
  const json a = {
      {"measurements",
       {Measurement("back_length", "length", 400), Measurement("arm_length", "length", 560),
        Measurement("upper_arm_girth", "girth", 290)}}};
  const json b = {
      {"measurements",
       {Measurement("back_length", "length", 403), Measurement("arm_length", "length", 552),
        Measurement("upper_arm_girth", "girth", 300)}}};
  const PostureComparison p = ComparePostures(a, b, nullptr, nullptr, 5);
  ASSERT_EQ(p.rows.size(), 3u);
  EXPECT_TRUE(p.rows[0].pass);
  EXPECT_FALSE(p.rows[1].pass);
  EXPECT_FALSE(p.rows[2].judged);
  EXPECT_EQ(p.judged, 2);
  EXPECT_EQ(p.passed, 1);
  EXPECT_NEAR(p.max_abs_difference_mm, 8, 1e-9);
  EXPECT_FALSE(p.pass());
  EXPECT_TRUE(std::isnan(p.rows[0].truth_a_mm));
  // A length the truth has but one pose lacks is a failed row, not a gap.
  const json truth = {{"measurements", {Measurement("inside_leg", "length", 760)}}};
  const PostureComparison q = ComparePostures(a, b, truth, truth, 5);
  ASSERT_EQ(q.rows.size(), 4u);
  EXPECT_EQ(q.rows[0].name, "inside_leg");
  EXPECT_TRUE(q.rows[0].judged);
  EXPECT_FALSE(q.rows[0].pass);
  EXPECT_EQ(q.judged, 3);
}

// A reference and a posture document: waist (large girth) and neck (small
// girth) both 8 mm off, a length 4 mm off, a height and a breadth far off,
// the hip girth missing in the posture.
struct PosturePair {
  json reference = {
      {"measurements",
       {Measurement("waist_girth", "girth", 800), Measurement("neck_girth", "girth", 380),
        Measurement("back_length", "length", 400), Measurement("stature", "height", 1700),
        Measurement("shoulder_width", "length", 420), Measurement("hip_girth", "girth", 1000)}}};
  json posture = {
      {"measurements",
       {Measurement("waist_girth", "girth", 808), Measurement("neck_girth", "girth", 388),
        Measurement("back_length", "length", 404), Measurement("stature", "height", 1650),
        Measurement("shoulder_width", "length", 380)}}};
};

TEST(ComparePostures, JudgesGirthsByTheirIsoClass) {
  const PosturePair d;
  const PostureComparison p =
      ComparePostures(d.reference, d.posture, nullptr, nullptr, 5, PostureRule::kLengthsAndGirths);
  ASSERT_EQ(p.rows.size(), 6u);
  const auto row = [&](const std::string& name) {
    for (const PostureRow& r : p.rows) {
      if (r.name == name) return r;
    }
    ADD_FAILURE() << name;
    return PostureRow();
  };
  EXPECT_TRUE(row("waist_girth").pass);  // 8 mm, large girth: 9 mm allowed
  EXPECT_DOUBLE_EQ(row("waist_girth").limit_mm, 9);
  EXPECT_EQ(row("waist_girth").iso_class, "large_girth");
  EXPECT_TRUE(row("neck_girth").judged);
  EXPECT_FALSE(row("neck_girth").pass);  // 8 mm, small girth: 4 mm allowed
  EXPECT_DOUBLE_EQ(row("neck_girth").limit_mm, 4);
  EXPECT_TRUE(row("back_length").pass);
  EXPECT_DOUBLE_EQ(row("back_length").limit_mm, 5);
  EXPECT_FALSE(row("stature").judged);  // heights and breadths: shown only
  EXPECT_FALSE(row("shoulder_width").judged);
  EXPECT_NEAR(row("shoulder_width").difference_mm, -40, 1e-9);
  EXPECT_TRUE(row("hip_girth").judged);  // missing in the posture: fails
  EXPECT_FALSE(row("hip_girth").pass);
  EXPECT_EQ(p.judged, 4);
  EXPECT_EQ(p.passed, 2);
  EXPECT_EQ(p.lengths_judged, 1);
  EXPECT_EQ(p.lengths_passed, 1);
  EXPECT_EQ(p.girths_judged, 3);
  EXPECT_EQ(p.girths_passed, 1);
  ASSERT_GE(p.worst, 0);
  EXPECT_EQ(p.rows[p.worst].name, "hip_girth");  // a missing value is the worst
  EXPECT_NEAR(p.max_abs_difference_mm, 8, 1e-9);
  EXPECT_FALSE(p.pass());
  // The A/T rule on the same documents: every length (the breadth too), no girth.
  const PostureComparison q = ComparePostures(d.reference, d.posture, nullptr, nullptr, 5);
  EXPECT_EQ(q.judged, 2);
  EXPECT_EQ(q.passed, 1);
  EXPECT_EQ(q.girths_judged, 0);
  EXPECT_EQ(q.rows[q.worst].name, "shoulder_width");
}

TEST(SummarizePostures, CountsPairsValuesAndTheWorst) {
  const PosturePair d;
  const auto pair = [&](const std::string& subject, const std::string& posture, const json& b) {
    PostureComparison p =
        ComparePostures(d.reference, b, d.reference, b, 5, PostureRule::kLengthsAndGirths);
    p.subject = subject;
    p.pose_a = "arms-30";
    p.pose_b = posture;
    return p;
  };
  PostureComparison failed;
  failed.subject = "s2";
  failed.pose_a = "arms-30";
  failed.pose_b = "lean-5";
  failed.error = "lean-5 (scan): no points";
  const std::vector<PostureComparison> pairs = {pair("s1", "lean-5", d.reference),
                                                pair("s1", "twist-5", d.posture), failed,
                                                pair("s2", "twist-5", d.reference)};
  const PostureSetSummary s = SummarizePostures(pairs);
  EXPECT_EQ(s.reference, "arms-30");
  EXPECT_EQ(s.pairs, 4);
  EXPECT_EQ(s.held, 2);            // the reference against itself; the failed run does not hold
  EXPECT_EQ(s.values_judged, 12);  // 3 girths and 1 length in each of the 3 pairs that ran
  EXPECT_EQ(s.values_passed, 10);
  EXPECT_EQ(s.Headline(),
            "posture: 2 of 4 subject x posture pairs hold; 10 of 12 values within limit");
  ASSERT_EQ(s.postures.size(), 2u);
  EXPECT_EQ(s.postures[0].posture, "lean-5");
  EXPECT_EQ(s.postures[0].pairs, 2);
  EXPECT_EQ(s.postures[0].held, 1);
  EXPECT_EQ(s.postures[0].did_not_run, 1);
  EXPECT_EQ(s.postures[1].worst_subject, "s1");
  EXPECT_EQ(s.postures[1].worst_measurement, "hip_girth");
  EXPECT_TRUE(std::isnan(s.postures[1].worst_difference_mm));
  const auto m =
      std::find_if(s.measurements.begin(), s.measurements.end(),
                   [](const PostureMeasurementRow& r) { return r.name == "neck_girth"; });
  ASSERT_NE(m, s.measurements.end());
  EXPECT_EQ(m->judged, 3);
  EXPECT_EQ(m->within, 2);
  EXPECT_NEAR(m->max_abs_difference_mm, 8, 1e-9);
  EXPECT_EQ(m->max_posture, "twist-5");
  EXPECT_NEAR(m->max_abs_truth_difference_mm, 8, 1e-9);  // the truths given are the documents
  EXPECT_EQ(m->truth_beyond, 1);                         // 8 mm > 4 mm in s1 twist-5
}

std::string ReadText(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(WriteAccuracyReport, WritesEveryFile) {
  AccuracyReport report;
  for (double e : {-6.0, -2.0, 2.0}) {
    const Documents d = MakeDocuments(e);
    report.subjects.push_back(CompareDocuments(d.measured, d.truth, "s"));
  }
  report.summary = SummarizeAccuracy(report.subjects, Catalogue::Builtin());
  report.failures.push_back({"s4", "scan", "too few points"});
  report.settings = {{"subjects", 4}};
  const Documents d = MakeDocuments(0);
  report.posture = ComparePostures(d.measured, d.measured, nullptr, nullptr, 5);
  const fs::path dir =
      fs::temp_directory_path() / ("accuracy_report_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  WriteAccuracyReport(report, dir);
  for (const char* file :
       {"index.html", "summary.csv", "measurements.csv", "landmarks.csv", "landmark_errors.csv",
        "posture.csv", "settings.json", "report.json", "plots/errors_large_girth.png",
        "plots/hist_bust_girth.png", "plots/bland_altman_bust_girth.png", "plots/landmarks.png"}) {
    EXPECT_TRUE(fs::exists(dir / file)) << file;
  }
  // Nothing the report does not have: no repeated scans, nothing left out.
  EXPECT_FALSE(fs::exists(dir / "repeatability.csv"));
  EXPECT_FALSE(fs::exists(dir / "not_compared.csv"));
  const std::string summary = ReadText(dir / "summary.csv");
  EXPECT_NE(summary.find("bust_girth,girth,large_girth,9,3,0,3,0,-2.000,4.000,"), std::string::npos)
      << summary;
  const std::string html = ReadText(dir / "index.html");
  EXPECT_NE(html.find("too few points"), std::string::npos);
  EXPECT_NE(html.find("plots/errors_large_girth.png"), std::string::npos);
  EXPECT_NE(html.find("plots/bland_altman_bust_girth.png"), std::string::npos);
  EXPECT_NE(html.find("measured &minus; truth"), std::string::npos);
  const json r = ReadJsonFile(dir / "report.json");
  EXPECT_EQ(r["subjects_failed"], 1);
  EXPECT_EQ(r["verdicts"]["stature"], "pass");
  fs::remove_all(dir);
}

TEST(WriteAccuracyReport, WritesThePostureTest) {
  AccuracyReport report;
  const PosturePair d;
  report.posture_pairs.push_back(
      ComparePostures(d.reference, d.posture, nullptr, nullptr, 5, PostureRule::kLengthsAndGirths));
  report.posture_pairs[0].subject = "subject_000";
  report.posture_pairs[0].pose_a = "arms-30";
  report.posture_pairs[0].pose_b = "lean-5";
  const fs::path dir =
      fs::temp_directory_path() / ("accuracy_posture_test_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  WriteAccuracyReport(report, dir);
  const std::string csv = ReadText(dir / "posture.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "subject,reference_posture,posture,measurement,kind,iso_class,reference_mm,posture_mm,"
            "difference_mm,limit_mm,pass,truth_reference_mm,truth_posture_mm");
  EXPECT_NE(csv.find("subject_000,arms-30,lean-5,neck_girth,girth,small_girth,380.00,388.00,8.00,4,"
                     "fail,,\n"),
            std::string::npos)
      << csv;
  EXPECT_NE(csv.find("subject_000,arms-30,lean-5,stature,height,height,1700.00,1650.00,-50.00,,,"),
            std::string::npos)
      << csv;
  const json r = ReadJsonFile(dir / "report.json");
  EXPECT_EQ(r["posture_test"]["headline"],
            "posture: 0 of 1 subject x posture pairs hold; 2 of 4 values within limit");
  EXPECT_NE(ReadText(dir / "index.html").find("Posture test"), std::string::npos);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace bespoke
