// `bespoke accuracy` as a user runs it: a separate process. Two small
// parametric subjects (coarse meshes, a low-resolution booth, so the exact
// truth and the scans take seconds) plus the posture pair give exit 0 and
// every promised file, with statistics that agree with the per-subject
// table; bad options give exit 1 and write nothing. On real subjects
// (--scans): the same subjects written out as scans with their truth as the
// reference give the oracle report's figures; bad input, repeated scans and
// --resume with the batch's stand-in worker (tests/batch/fake_worker.cc).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "scanners/core/json_io.h"
#include "tests/support/batch_test_util.h"
#include "tests/support/run_command.h"
#include "tests/support/test_support.h"

#ifndef BESPOKE_BINARY
#error "BESPOKE_BINARY (the bespoke executable) must be defined by CMake"
#endif

namespace bespoke {
namespace {

using testing::TempDir;

testing::CommandResult Accuracy(const TempDir& dir, const std::string& args) {
  return testing::RunCommand(std::string("'") + BESPOKE_BINARY + "' -q accuracy " + args,
                             dir.path());
}

// A coarse parametric mesh: exact geodesics in seconds.
const char* kSmallBodies =
    " --param torso_segments=48 --param arm_segments=32 --param ring_spacing_mm=30"
    " --param girth_ring_segments=64 --param max_girth_deficit_mm=2 --resolution 160x120";

std::vector<std::vector<std::string>> ReadCsv(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    std::string cell;
    while (std::getline(s, cell, ',')) cells.push_back(cell);
    if (!line.empty() && line.back() == ',') cells.push_back("");
    rows.push_back(cells);
  }
  return rows;
}

std::map<std::string, std::size_t> Columns(const std::vector<std::string>& header) {
  std::map<std::string, std::size_t> c;
  for (std::size_t i = 0; i < header.size(); ++i) c[header[i]] = i;
  return c;
}

TEST(AccuracyCli, TwoParametricSubjectsAndThePostureTest) {
  TempDir dir;
  const testing::CommandResult r =
      Accuracy(dir, std::string("--subjects 2 --seed 3 --pose both") + kSmallBodies + " -o " +
                        testing::Quote(dir / "report"));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("ISO 20685-1:"), std::string::npos) << r.out;
  const std::filesystem::path report = dir / "report";
  for (const char* f :
       {"index.html", "summary.csv", "measurements.csv", "landmarks.csv", "landmark_errors.csv",
        "posture.csv", "settings.json", "report.json", "plots/errors_large_girth.png",
        "plots/landmarks.png", "plots/posture.png", "plots/hist_waist_girth.png"}) {
    EXPECT_TRUE(std::filesystem::exists(report / f)) << f;
  }
  const nlohmann::json summary = ReadJsonFile(report / "report.json");
  EXPECT_EQ(summary["subjects_compared"].get<int>() + summary["subjects_failed"].get<int>(), 2);
  ASSERT_EQ(summary["subjects_compared"], 2) << summary.dump(2);
  EXPECT_EQ(summary["landmark_frame"], "scanner");
  ASSERT_TRUE(summary.contains("posture"));
  EXPECT_GT(summary["posture"]["judged"].get<int>(), 10);
  EXPECT_EQ(ReadJsonFile(report / "settings.json")["subjects"], 2);

  // summary.csv agrees with the per-subject rows of measurements.csv.
  const auto rows = ReadCsv(report / "measurements.csv");
  const auto sums = ReadCsv(report / "summary.csv");
  ASSERT_GT(rows.size(), 2u);
  ASSERT_GT(sums.size(), 10u);
  const auto rc = Columns(rows[0]);
  const auto sc = Columns(sums[0]);
  std::map<std::string, std::vector<double>> differences;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    if (rows[i][rc.at("missing")] == "0") {
      const double truth = std::stod(rows[i][rc.at("truth_mm")]);
      const double measured = std::stod(rows[i][rc.at("measured_mm")]);
      const double difference = std::stod(rows[i][rc.at("difference_mm")]);
      EXPECT_NEAR(difference, measured - truth, 0.011) << rows[i][rc.at("measurement")];
      differences[rows[i][rc.at("measurement")]].push_back(difference);
    }
  }
  int judged = 0;
  for (std::size_t i = 1; i < sums.size(); ++i) {
    const std::string& name = sums[i][sc.at("measurement")];
    const std::vector<double>& d = differences[name];
    ASSERT_EQ(std::stoul(sums[i][sc.at("n")]), d.size()) << name;
    if (d.size() < 2) continue;
    ++judged;
    const double mean = 0.5 * (d[0] + d[1]);
    const double mae = 0.5 * (std::abs(d[0]) + std::abs(d[1]));
    const double sd = std::abs(d[0] - d[1]) / std::sqrt(2.0);
    const double half = 12.7062 * sd / std::sqrt(2.0);  // t(0.975, 1)
    EXPECT_NEAR(std::stod(sums[i][sc.at("bias_mm")]), mean, 0.011) << name;
    EXPECT_NEAR(std::stod(sums[i][sc.at("mae_mm")]), mae, 0.011) << name;
    EXPECT_NEAR(std::stod(sums[i][sc.at("sd_mm")]), sd, 0.011) << name;
    // Each CSV difference is rounded to 0.01 mm (error <= 0.005), so the SD
    // recomputed here may be off by 0.01 / sqrt(2) and the CI half width by
    // t * that / sqrt(2) = 0.064 mm.
    const double ci_slack = 0.07;
    EXPECT_NEAR(std::stod(sums[i][sc.at("ci_high_mm")]), mean + half, ci_slack) << name;
    EXPECT_NEAR(std::stod(sums[i][sc.at("ci_low_mm")]), mean - half, ci_slack) << name;
    const double tolerance = std::stod(sums[i][sc.at("tolerance_mm")]);
    const double margin =
        std::min(std::abs(mean - half + tolerance), std::abs(mean + half - tolerance));
    if (margin < ci_slack) continue;  // too close to the limit to recompute from rounded values
    const bool inside = mean - half >= -tolerance && mean + half <= tolerance;
    EXPECT_EQ(sums[i][sc.at("verdict")], inside ? "pass" : "fail") << name;
  }
  EXPECT_GT(judged, 20);
}

TEST(AccuracyCli, BadOptionsExitOneAndWriteNothing) {
  TempDir dir;
  const std::string out = " -o " + testing::Quote(dir / "report");
  for (const std::string& args :
       {std::string("--subjects 0"), std::string("--subjects 2 --model sphere"),
        std::string("--subjects 2 --pose x"),
        std::string("--subjects 2 --model makehuman --pose t"),
        std::string("--subjects 2 --jobs 0"), std::string("--subjects 2 --noise-mm -1"),
        std::string("--subjects 2 --param no_such_size=3"),
        std::string("--subjects 2 --reuse-set ") + testing::Quote(dir / "none")}) {
    const testing::CommandResult r = Accuracy(dir, args + out);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_FALSE(std::filesystem::exists(dir / "report")) << args;
  }
  EXPECT_EQ(Accuracy(dir, "--subjects 2").exit_code, 1);  // no -o
}

TEST(AccuracyCli, PostureTestNamesWhatItCannotRun) {
  TempDir dir;
  const std::string out = " -o " + testing::Quote(dir / "report");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--subjects 1 --posture-test arms-7", "unknown posture 'arms-7'"},
      {"--subjects 1 --posture-test lean-5", "--posture-test lean-5: the parametric body cannot"},
      {"--subjects 1 --posture-test arms-5", "--posture-test arms-5: the parametric body cannot"},
      {"--subjects 1 --posture-test feet-together", "feet-together: the parametric body cannot"},
      {"--subjects 1 --posture-test arms-30", "is the reference posture itself"},
      {"--subjects 1 --posture-test arms-45,arms-45", "lists arms-45 twice"},
      {"--subjects 1 --posture-test arms-45 --posture arms-30", "drop --posture"},
      {"--subjects 1 --posture-test arms-45 --pose both", "needs --pose a"},
      {"--subjects 1 --posture-test arms-45 --posture-reference sit", "unknown posture 'sit'"}};
  for (const auto& [args, message] : cases) {
    const testing::CommandResult r = Accuracy(dir, args + out);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << args << "\n" << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "report")) << args;
  }
}

TEST(AccuracyCli, PostureTestPairsASubjectWithItself) {
  TempDir dir;
  const testing::CommandResult r =
      Accuracy(dir, std::string("--subjects 1 --seed 3 --posture-test arms-45") + kSmallBodies +
                        " -o " + testing::Quote(dir / "report"));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("posture: "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" of 1 subject x posture pairs hold; "), std::string::npos) << r.out;
  const nlohmann::json summary = ReadJsonFile(dir / "report" / "report.json");
  EXPECT_FALSE(summary.contains("posture")) << "no A/T pair with --posture-test";
  ASSERT_TRUE(summary.contains("posture_test"));
  const nlohmann::json& test = summary["posture_test"];
  EXPECT_EQ(test["reference_posture"], "arms-30");
  EXPECT_EQ(test["pairs"], 1);
  ASSERT_EQ(test["postures"].size(), 1u);
  EXPECT_EQ(test["postures"][0]["posture"], "arms-45");
  // Every judged value is a line of posture.csv with a verdict; the judged
  // lengths and girths add up to the values judged.
  const auto rows = ReadCsv(dir / "report" / "posture.csv");
  ASSERT_GT(rows.size(), 40u);
  const auto c = Columns(rows[0]);
  int judged = 0, passed = 0;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    EXPECT_EQ(rows[i][c.at("subject")], "subject_000");
    EXPECT_EQ(rows[i][c.at("posture")], "arms-45");
    const std::string& verdict = rows[i][c.at("pass")];
    judged += !verdict.empty();
    passed += verdict == "pass";
    const std::string& kind = rows[i][c.at("kind")];
    if (kind == "height" || kind == "girth") {
      EXPECT_EQ(verdict.empty(), kind == "height") << rows[i][c.at("measurement")];
    }
  }
  EXPECT_EQ(test["values_judged"], judged);
  EXPECT_EQ(test["values_passed"], passed);
  const nlohmann::json& p = test["postures"][0];
  EXPECT_EQ(p["lengths"]["judged"].get<int>() + p["girths"]["judged"].get<int>(), judged);
  EXPECT_EQ(ReadJsonFile(dir / "report" / "settings.json")["posture_test"], "arms-45");
}

// Column `name` of every data row, keyed by the rows' first cell(s).
std::map<std::string, std::string> Column(const std::vector<std::vector<std::string>>& rows,
                                          const std::string& name, std::size_t key_cells = 1) {
  const auto c = Columns(rows.at(0));
  std::map<std::string, std::string> out;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    std::string key;
    for (std::size_t k = 0; k < key_cells; ++k) key += rows[i][k] + "/";
    out[key] = rows[i].at(c.at(name));
  }
  return out;
}

TEST(AccuracyCli, ScansWithTheTruthAsReferenceGiveTheOracleFigures) {
  TempDir dir;
  // Two subjects written out as scans (mm, so the scan files hold the same
  // numbers the oracle scans in memory) with their exact truth.
  const testing::CommandResult set = testing::RunCommand(
      std::string("'") + BESPOKE_BINARY + "' -q synth-set --count 2 --seed 3 --units mm" +
          kSmallBodies + " -o " + testing::Quote(dir / "set"),
      dir.path());
  ASSERT_EQ(set.exit_code, 0) << set.err;
  std::filesystem::create_directories(dir / "scans");
  std::ofstream ref(dir / "REF.csv");
  ref << "subject,measurement,value_mm,method\n";
  for (const char* subject : {"subject_000", "subject_001"}) {
    std::filesystem::copy_file(dir / "set" / subject / "scan.ply",
                               dir / "scans" / (std::string(subject) + ".ply"));
    const nlohmann::json truth = ReadJsonFile(dir / "set" / subject / "truth.json");
    for (const nlohmann::json& m : truth.at("measurements")) {
      if (!m.contains("value_mm") || !m["value_mm"].is_number()) continue;
      char value[40];
      std::snprintf(value, sizeof(value), "%.17g", m["value_mm"].get<double>());
      ref << subject << ',' << m["name"].get<std::string>() << ',' << value << ",oracle truth\n";
    }
  }
  ref.close();
  const testing::CommandResult oracle = Accuracy(
      dir, std::string("--subjects 2 --seed 3 --pose a --jobs 2") + kSmallBodies + " --reuse-set " +
               testing::Quote(dir / "set") + " -o " + testing::Quote(dir / "oracle"));
  ASSERT_EQ(oracle.exit_code, 0) << oracle.err;
  const testing::CommandResult real = Accuracy(
      dir, "--scans " + testing::Quote(dir / "scans") + " --reference " +
               testing::Quote(dir / "REF.csv") + " --jobs 2 -o " + testing::Quote(dir / "real"));
  ASSERT_EQ(real.exit_code, 0) << real.err;

  const auto oracle_summary = ReadCsv(dir / "oracle" / "summary.csv");
  const auto real_summary = ReadCsv(dir / "real" / "summary.csv");
  ASSERT_EQ(oracle_summary.size(), real_summary.size());
  for (const char* column :
       {"n", "missing", "flagged", "bias_mm", "sd_mm", "ci_low_mm", "ci_high_mm", "loa_low_mm",
        "loa_high_mm", "mae_mm", "max_abs_mm", "verdict"}) {
    EXPECT_EQ(Column(real_summary, column), Column(oracle_summary, column)) << column;
  }
  const auto oracle_rows = ReadCsv(dir / "oracle" / "measurements.csv");
  const auto real_rows = ReadCsv(dir / "real" / "measurements.csv");
  EXPECT_EQ(Column(real_rows, "measured_mm", 2), Column(oracle_rows, "measured_mm", 2));
  EXPECT_EQ(Column(real_rows, "reference_mm", 2), Column(oracle_rows, "truth_mm", 2));
  // The real report has no datum points to judge, and says what it compared with.
  EXPECT_FALSE(std::filesystem::exists(dir / "real" / "landmarks.csv"));
  EXPECT_TRUE(std::filesystem::exists(dir / "real" / "plots" / "bland_altman_waist_girth.png"));
  EXPECT_TRUE(std::filesystem::exists(dir / "real" / "scans" / "summary.csv"));
  const nlohmann::json report = ReadJsonFile(dir / "real" / "report.json");
  EXPECT_EQ(report["reference"], "reference");
  EXPECT_EQ(report["settings"]["method"], "oracle truth");
  EXPECT_EQ(report["subjects_compared"], 2);
}

// A folder of stand-in scans: each file is the fake worker's directive.
void WriteScans(const std::filesystem::path& dir,
                const std::vector<std::pair<std::string, std::string>>& scans) {
  std::filesystem::create_directories(dir);
  for (const auto& [file, directive] : scans) testing::WriteText(dir / file, directive + "\n");
}

std::string RealArgs(const TempDir& dir, const std::string& ref, const std::string& report) {
  return "--scans " + testing::Quote(dir / "scans") + " --reference " + testing::Quote(dir / ref) +
         " --worker " + testing::Quote(testing::FakeWorkerBinary()) + " --jobs 2 -o " +
         testing::Quote(dir / report);
}

TEST(AccuracyCli, RealSubjectsBadInputRepeatabilityAndResume) {
  TempDir dir;
  // The fake worker measures stature V and waist_girth V / 2 from "ok V".
  WriteScans(dir / "scans", {{"a_1.ply", "ok 1702"},
                             {"a_2.ply", "ok 1706"},
                             {"b_1.ply", "ok 1649"},
                             {"b_2.ply", "ok 1651"},
                             {"c.ply", "ok 1798"},
                             {"d.ply", "input-error no points"},
                             {"e.ply", "ok 1750"}});
  testing::WriteText(dir / "REF.csv",
                     "subject,measurement,value_mm,unit\n"
                     "a,stature,1700,mm\n"
                     "a,waist_girth,851,mm\n"
                     "a,stature,1700,mm\n"  // duplicate
                     "b,stature,1650,mm\n"
                     "b,shoe_size,42,mm\n"  // unknown name
                     "c,stature,1800,mm\n"
                     "c,hip_girth,abc,mm\n"   // not a number
                     "c,neck_girth,35,cm\n"   // not mm
                     "d,stature,1600,mm\n"    // its scan fails
                     "f,stature,1700,mm\n");  // no scan; e.ply has no rows
  const testing::CommandResult r = Accuracy(dir, RealArgs(dir, "REF.csv", "report"));
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const std::filesystem::path report = dir / "report";
  // Each left-out input on its own line of not_compared.csv, with its reason.
  std::istringstream not_compared(testing::ReadText(report / "not_compared.csv"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(not_compared, line);) lines.push_back(line);
  for (const auto& [where, reason] : std::vector<std::pair<std::string, std::string>>{
           {"a,stature,REF.csv line 4,", "duplicate of line 2"},
           {"b,shoe_size,REF.csv line 6,", "unknown measurement"},
           {"c,hip_girth,REF.csv line 8,", "value 'abc' is not a number"},
           {"c,neck_girth,REF.csv line 9,", "unit 'cm'"},
           {"f,,scans folder,", "no scan f.<ext>"},
           {",,scan e.ply,", "no subject of the reference table is called 'e'"}}) {
    const auto line = std::find_if(lines.begin(), lines.end(),
                                   [&](const std::string& l) { return l.rfind(where, 0) == 0; });
    ASSERT_NE(line, lines.end()) << where;
    EXPECT_NE(line->find(reason), std::string::npos) << *line;
  }
  EXPECT_EQ(lines.size(), 7u);  // the header and the six above
  const nlohmann::json summary_json = ReadJsonFile(report / "report.json");
  EXPECT_EQ(summary_json["subjects_compared"], 3);
  ASSERT_EQ(summary_json["failures"].size(), 1u);
  EXPECT_EQ(summary_json["failures"][0]["subject"], "d");
  EXPECT_NE(summary_json["failures"][0]["error"].get<std::string>().find("no points"),
            std::string::npos);
  const std::string html = testing::ReadText(report / "index.html");
  for (const char* expected :
       {"Not compared", "Subjects that failed", "Repeatability", "shoe_size"})
    EXPECT_NE(html.find(expected), std::string::npos) << expected;

  // Repeatability by hand. Stature: a 1702, 1706 and b 1649, 1651, pooled
  // variance (8 + 2) / 2 = 5. Waist: a 851, 853 (b has no waist reference).
  const auto rows = ReadCsv(report / "repeatability.csv");
  const auto sd = Column(rows, "within_subject_sd_mm");
  const auto coefficient = Column(rows, "repeatability_coefficient_mm");
  const auto subjects = Column(rows, "subjects");
  EXPECT_EQ(sd.at("stature/"), "2.236");
  EXPECT_EQ(coefficient.at("stature/"), "6.198");  // 1.959964 * sqrt(2) * sqrt(5)
  EXPECT_EQ(subjects.at("stature/"), "2");
  EXPECT_EQ(sd.at("waist_girth/"), "1.414");
  EXPECT_EQ(subjects.at("waist_girth/"), "1");
  // Differences: stature a +4 (mean of both scans), b 0, c -2; waist a +1.
  const auto bias = Column(ReadCsv(report / "summary.csv"), "bias_mm");
  EXPECT_EQ(bias.at("stature/"), "0.667");
  EXPECT_EQ(bias.at("waist_girth/"), "1.000");

  // An earlier run is refused without --resume (nothing touched), continued with it.
  const std::string summary = testing::ReadText(report / "summary.csv");
  EXPECT_EQ(Accuracy(dir, RealArgs(dir, "REF.csv", "report")).exit_code, 1);
  const testing::CommandResult resumed =
      Accuracy(dir, RealArgs(dir, "REF.csv", "report") + " --resume");
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(testing::ReadText(report / "summary.csv"), summary);
}

TEST(AccuracyCli, RealSubjectsBadFilesExitOneAndWriteNothing) {
  TempDir dir;
  WriteScans(dir / "scans", {{"a.ply", "ok 1700"}});
  testing::WriteText(dir / "cm.csv", "subject,measurement,value_cm\na,stature,170\n");
  testing::WriteText(dir / "nobody.csv", "subject,measurement,value_mm\nzed,stature,1700\n");
  testing::WriteText(dir / "ok.csv", "subject,measurement,value_mm\na,stature,1700\n");
  for (const std::string& args :
       {RealArgs(dir, "cm.csv", "report"), RealArgs(dir, "nobody.csv", "report"),
        RealArgs(dir, "missing.csv", "report"),
        RealArgs(dir, "ok.csv", "report") + " --names seamly",
        RealArgs(dir, "ok.csv", "report") + " --method tape",
        RealArgs(dir, "ok.csv", "report") + " --subjects 2",
        std::string("--scans ") + testing::Quote(dir / "scans") + " -o " +
            testing::Quote(dir / "report"),
        std::string("--reference ") + testing::Quote(dir / "ok.csv") + " -o " +
            testing::Quote(dir / "report")}) {
    const testing::CommandResult r = Accuracy(dir, args);
    EXPECT_EQ(r.exit_code, 1) << args << "\n" << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    EXPECT_FALSE(std::filesystem::exists(dir / "report")) << args;
  }
}

}  // namespace
}  // namespace bespoke
