// `bespoke accuracy` as a user runs it: a separate process. Two small
// parametric subjects (coarse meshes, a low-resolution booth, so the exact
// truth and the scans take seconds) plus the posture pair give exit 0 and
// every promised file, with statistics that agree with the per-subject
// table; bad options give exit 1 and write nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "scanners/core/json_io.h"
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

}  // namespace
}  // namespace bespoke
