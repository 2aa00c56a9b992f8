// The real worker: `bespoke run` on one scan, and `bespoke batch` over
// generated scans mixed with malformed and hostile files (corpus.h). The
// small, ctest-sized version of the 100-scan reliability run
// (scripts/batch-reliability.sh, docs/batch.md).
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "pipeline/batch/done_record.h"
#include "scanners/core/json_io.h"
#include "tests/support/batch_test_util.h"
#include "tests/support/corpus.h"
#include "tests/support/test_support.h"

namespace bespoke::testing {
namespace {
namespace fs = std::filesystem;

TEST(BatchE2E, RunWritesEverythingAndDoneJsonLast) {
  TempDir dir;
  WriteSyntheticBodyScan({60000, 1700, 1.0, 1.0, 30, 7}, dir / "person.ply");
  ASSERT_EQ(RunBespoke({"run", (dir / "person.ply").string(), "-o", (dir / "out").string()},
                       dir / "log.txt"),
            0)
      << ReadText(dir / "log.txt");
  std::string problem;
  const auto record = ReadValidDoneRecord(dir / "out", /*verify_hashes=*/true, &problem);
  ASSERT_TRUE(record) << problem;
  EXPECT_EQ(record->status, "ok");
  EXPECT_EQ(record->scan_id, "person");
  EXPECT_EQ(record->input_sha256, FileSha256(dir / "person.ply"));
  EXPECT_EQ(record->results.value("file_unit", ""), "m");
  EXPECT_FALSE(record->outputs.empty());
  // The measure step ran: the document, its exports and the render.
  for (const char* f : {"measurements.json", "measurements.csv", "measurements.vit",
                        "freesewing.json", "render.png"})
    EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  const nlohmann::json doc = ReadJsonFile(dir / "out" / "measurements.json");
  EXPECT_EQ(doc["format"], "bespoke-measurements");
  EXPECT_GE(doc["measurements"].size(), 40u) << doc["skipped"].dump();
  EXPECT_GE(record->results.value("measurements", 0), 40);
  EXPECT_EQ(record->steps.front().value("name", ""), "read");
  // done.json is the newest file of the folder.
  const auto done_time = fs::last_write_time(dir / "out" / "done.json");
  for (const OutputFile& f : record->outputs) {
    EXPECT_LE(fs::last_write_time(dir / "out" / f.file), done_time) << f.file;
  }
  // A failing scan leaves a done.json that says so, and exit code 1.
  WriteText(dir / "bad.ply", "ply\nformat ascii 1.0\nelement vertex 9\nend_header\n");
  EXPECT_EQ(RunBespoke({"run", (dir / "bad.ply").string(), "-o", (dir / "out").string()},
                       dir / "log2.txt"),
            1);
  const auto failed = ReadValidDoneRecord(dir / "out", true, &problem);
  ASSERT_TRUE(failed) << problem;
  EXPECT_EQ(failed->status, "failed");
  EXPECT_EQ(failed->failure->kind, "input_error");
  EXPECT_NE(failed->failure->message.find("bad.ply"), std::string::npos);
}

TEST(BatchE2E, GoodScansMeasuredHostileFilesListedWithReasons) {
  TempDir dir;
  const int good = 8;
  fs::create_directories(dir / "in");
  for (int k = 0; k < good; ++k) {
    WriteSyntheticBodyScan(
        {60000, 1600.0 + 25 * k, 0.9 + 0.03 * k, 1.0, 40.0 * k, static_cast<std::uint32_t>(k + 1)},
        dir / "in" / ("good_" + std::to_string(k) + ".ply"));
  }
  const std::vector<std::string> hostile = WriteHostileFiles(dir / "in", 3);
  const int code = RunBespoke({"batch", (dir / "in").string(), "-o", (dir / "out").string(), "-j",
                               "2", "--timeout-s", "120"},
                              dir / "log.txt");
  EXPECT_EQ(code, 1) << ReadText(dir / "log.txt");  // bad input only: no crash, no time-out
  const std::vector<std::string> rows = CsvRows(ReadText(dir / "out" / "summary.csv"));
  EXPECT_EQ(rows.size(), good + hostile.size());
  int ok = 0;
  for (const std::string& r : rows) ok += r.find(",ok,") != std::string::npos ? 1 : 0;
  EXPECT_EQ(ok, good) << ReadText(dir / "out" / "summary.csv");
  // summary.csv carries the measurements' columns.
  const std::string header = ReadText(dir / "out" / "summary.csv")
                                 .substr(0, ReadText(dir / "out" / "summary.csv").find('\n'));
  for (const char* column : {"stature_mm", "waist_girth_mm", "hip_girth_mm", "flagged"})
    EXPECT_NE(header.find(column), std::string::npos) << header;
  const std::vector<std::string> failures = CsvRows(ReadText(dir / "out" / "failures.csv"));
  EXPECT_EQ(failures.size(), hostile.size());
  for (const std::string& f : failures) {
    EXPECT_NE(f.find(",input_error,1,,"), std::string::npos) << f;
    const std::string id = f.substr(0, f.find(','));
    EXPECT_NE(f.find("/" + id + "."), std::string::npos) << "message names the file: " << f;
  }
  // A resume has nothing left to do and reproduces the same tables.
  const std::string summary = ReadText(dir / "out" / "summary.csv");
  EXPECT_EQ(RunBespoke({"batch", (dir / "in").string(), "-o", (dir / "out").string(), "--resume"},
                       dir / "log2.txt"),
            1);
  EXPECT_NE(ReadText(dir / "log2.txt").find("0 to run"), std::string::npos)
      << ReadText(dir / "log2.txt");
  EXPECT_EQ(ReadText(dir / "out" / "summary.csv"), summary);
}

TEST(BatchE2E, DesignFitsAPatternToEveryScan) {
  // `--design shirt`: each scan folder gets the fitted pattern (JSON, SVG,
  // DXF) and its report, and done.json records how well it fits. 100k-point
  // scans: at 60k points the landmark detector loses an arm or a back
  // armpit fold on these two bodies (docs/landmarks.md, failure modes), and
  // the shirt needs both.
  TempDir dir;
  fs::create_directories(dir / "in");
  WriteSyntheticBodyScan({100000, 1620, 0.92, 1.0, 0, 11}, dir / "in" / "small.ply");
  WriteSyntheticBodyScan({100000, 1840, 1.10, 1.0, 120, 12}, dir / "in" / "large.ply");
  ASSERT_EQ(RunBespoke({"batch", (dir / "in").string(), "-o", (dir / "out").string(), "-j", "2",
                        "--design", "shirt", "--timeout-s", "300"},
                       dir / "log.txt"),
            0)
      << ReadText(dir / "log.txt");
  std::map<std::string, double> achieved_sum_mm;
  for (const char* id : {"small", "large"}) {
    const fs::path folder = dir / "out" / id;
    std::string problem;
    const auto record = ReadValidDoneRecord(folder, /*verify_hashes=*/true, &problem);
    ASSERT_TRUE(record) << id << ": " << problem;
    EXPECT_EQ(record->status, "ok") << id;
    for (const char* f : {"fitted.json", "fitted.svg", "fitted.dxf", "resize_report.json"})
      EXPECT_TRUE(fs::exists(folder / f)) << id << ": " << f;
    // Every bound measurement met within 1 mm (the resize evidence's bound).
    EXPECT_LE(record->results.value("fit_max_measurement_error_mm", 1e9), 1.0) << id;
    EXPECT_LE(record->results.value("fit_max_seam_mismatch_mm", 1e9), 1.0) << id;
    // The fit's targets are this scan's own measurements (+ the design's ease).
    const nlohmann::json report = ReadJsonFile(folder / "resize_report.json");
    const nlohmann::json doc = ReadJsonFile(folder / "measurements.json");
    EXPECT_EQ(report["settings"].value("design", ""), "shirt");
    ASSERT_FALSE(report["measurements"].empty()) << id;
    for (const nlohmann::json& b : report["measurements"]) {
      const std::string name = b.value("measurement", "");
      double scan_mm = -1;
      for (const nlohmann::json& m : doc["measurements"])
        if (m.value("name", "") == name) scan_mm = m.value("value_mm", -1.0);
      EXPECT_NEAR(b.value("body_mm", 0.0), scan_mm, 1e-6) << id << ": " << name;
      EXPECT_NEAR(b.value("achieved_mm", 0.0), b.value("target_mm", 0.0), 1.0)
          << id << ": " << name;
      achieved_sum_mm[id] += b.value("achieved_mm", 0.0);
    }
  }
  EXPECT_GT(achieved_sum_mm["large"], achieved_sum_mm["small"] + 100)
      << "the larger body's shirt is not larger";
}

}  // namespace
}  // namespace bespoke::testing
