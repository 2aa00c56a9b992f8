// `bespoke batch` end to end with a stand-in worker (fake_worker.cc) whose
// scans are directives: crashes, hangs, memory hogs and bad input in one
// batch; kill -9 and Ctrl-C then resume; shards merged. The real worker
// (`bespoke run`) is exercised by batch_e2e_test.cc.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <set>
#include <thread>

#include "pipeline/batch/process.h"
#include "scanners/core/json_io.h"
#include "tests/support/batch_test_util.h"
#include "tests/support/test_support.h"

namespace bespoke::testing {
namespace {
namespace fs = std::filesystem;

std::vector<std::string> BatchArgs(const fs::path& in, const fs::path& out,
                                   std::vector<std::string> extra = {}) {
  std::vector<std::string> args = {"batch",      in.string(), "-o",
                                   out.string(), "--worker",  FakeWorkerBinary().string()};
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

// n scans "s00".."s<n-1>", each "sleep <delay> ok <1500 + 10 i>".
void WriteOkScans(const fs::path& dir, int n, double delay_s) {
  fs::create_directories(dir);
  for (int i = 0; i < n; ++i) {
    char name[16];
    std::snprintf(name, sizeof name, "s%02d.txt", i);
    WriteText(dir / name,
              "sleep " + std::to_string(delay_s) + " ok " + std::to_string(1500 + 10 * i));
  }
}

bool WaitFor(const std::function<bool()>& condition, double seconds) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (condition()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return false;
}

void ExpectSameIdsOnce(const std::string& csv, int n) {
  const std::vector<std::string> rows = CsvRows(csv);
  std::set<std::string> ids;
  for (const std::string& r : rows) EXPECT_TRUE(ids.insert(r.substr(0, r.find(','))).second) << r;
  EXPECT_EQ(static_cast<int>(rows.size()), n);
}

TEST(BatchFake, OneBadScanNeverStopsTheOthers) {
  TempDir dir;
  WriteOkScans(dir / "in", 6, 0);
  WriteText(dir / "in" / "bad_input.txt", "input-error the header is wrong");
  WriteText(dir / "in" / "crash.txt", "crash");
  WriteText(dir / "in" / "abort.txt", "abort");
  WriteText(dir / "in" / "hang.txt", "hang");
  const bool limit = !BuiltWithAddressSanitizer();  // ASan cannot run under RLIMIT_AS
  if (limit) WriteText(dir / "in" / "oom.txt", "oom");
  fs::create_directories(dir / "in" / "folder.txt");  // not a file: fake_worker cannot open it
  const int code = RunBespoke(
      BatchArgs(dir / "in", dir / "out", {"-j", "2", "--timeout-s", "3", "--memory-mb", "256"}),
      dir / "log.txt");
  const std::string log = ReadText(dir / "log.txt");
  EXPECT_EQ(code, 2) << log;  // crashes and time-outs are not bad input
  const std::string summary = ReadText(dir / "out" / "summary.csv");
  ExpectSameIdsOnce(summary, limit ? 12 : 11);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NE(summary.find("s0" + std::to_string(i) + ",ok,,"), std::string::npos) << summary;
  }
  const std::string failures = ReadText(dir / "out" / "failures.csv");
  EXPECT_NE(failures.find("bad_input,"), std::string::npos);
  EXPECT_NE(failures.find(",input_error,1,,"), std::string::npos) << failures;
  EXPECT_NE(failures.find("crash,"), std::string::npos);
  EXPECT_NE(failures.find("SIGSEGV"), std::string::npos) << failures;
  EXPECT_NE(failures.find("SIGABRT"), std::string::npos) << failures;
  EXPECT_NE(failures.find("hang,"), std::string::npos);
  EXPECT_NE(failures.find("timed out after 3 s"), std::string::npos) << failures;
  if (limit) {
    EXPECT_NE(failures.find("oom,"), std::string::npos);
    EXPECT_NE(failures.find("out_of_memory"), std::string::npos) << failures;
  }
  EXPECT_NE(failures.find("folder,"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "out" / "batch.json"));
  const std::string report = ReadText(dir / "out" / "report.html");
  EXPECT_NE(report.find("timed out after 3 s"), std::string::npos);
  EXPECT_NE(report.find("report/hist_stature.png"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "out" / "report" / "hist_stature.png"));
}

TEST(BatchFake, ExitCodeSaysWhatFailed) {
  TempDir dir;
  WriteOkScans(dir / "ok", 3, 0);
  EXPECT_EQ(RunBespoke(BatchArgs(dir / "ok", dir / "out1"), dir / "log1.txt"), 0);
  WriteText(dir / "ok" / "z.txt", "input-error bad");
  EXPECT_EQ(RunBespoke(BatchArgs(dir / "ok", dir / "out2"), dir / "log2.txt"), 1);
  // An existing batch is not overwritten without --resume.
  EXPECT_EQ(RunBespoke(BatchArgs(dir / "ok", dir / "out2"), dir / "log3.txt"), 1);
  EXPECT_NE(ReadText(dir / "log3.txt").find("--resume"), std::string::npos);
  // Resume re-runs nothing; failed scans stay failed unless --retry-failed.
  EXPECT_EQ(RunBespoke(BatchArgs(dir / "ok", dir / "out2", {"--resume"}), dir / "log4.txt"), 1);
  EXPECT_NE(ReadText(dir / "log4.txt").find("4 finished before, 0 to run"), std::string::npos)
      << ReadText(dir / "log4.txt");
  WriteText(dir / "ok" / "z.txt", "ok 1234");  // the input changed: redone
  EXPECT_EQ(RunBespoke(BatchArgs(dir / "ok", dir / "out2", {"--resume"}), dir / "log5.txt"), 0)
      << ReadText(dir / "log5.txt");
}

// kill -9 of the batch mid-run, stray temporary files, a half-written folder
// and a damaged output; --resume must give exactly the uninterrupted summary.
TEST(BatchFake, ResumeAfterKillNineEqualsUninterruptedRun) {
  TempDir dir;
  const int n = 12;
  WriteOkScans(dir / "in", n, 0.3);
  WriteText(dir / "in" / "zz_bad.txt", "input-error cannot parse");
  ASSERT_EQ(RunBespoke(BatchArgs(dir / "in", dir / "reference", {"-j", "2"}), dir / "ref.txt"), 1);

  const pid_t batch =
      StartBespoke(BatchArgs(dir / "in", dir / "out", {"-j", "2"}), dir / "run1.txt");
  ASSERT_TRUE(WaitFor([&] { return CountDone(dir / "out") >= 4; }, 30));
  ::kill(batch, SIGKILL);
  ReapWorker(batch);
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.csv"));
  // Workers die with the batch (PR_SET_PDEATHSIG): no folder changes after.
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  const int done_after_kill = CountDone(dir / "out");
  EXPECT_LT(done_after_kill, n + 1);
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  EXPECT_EQ(CountDone(dir / "out"), done_after_kill);

  // Debris of a power loss: temporary files, a folder without done.json,
  // an output damaged after its done.json was written.
  WriteText(dir / "out" / "s00" / "measurements.json.tmp-99999-0", "{\"half");
  WriteText(dir / "out" / "summary.csv.tmp-99999-1", "scan_id,sta");
  fs::create_directories(dir / "out" / "s11");
  WriteText(dir / "out" / "s11" / "measurements.json", "{\"torn");
  WriteText(dir / "out" / "s01" / "measurements.json", "{}");

  const int code =
      RunBespoke(BatchArgs(dir / "in", dir / "out", {"-j", "2", "--resume"}), dir / "run2.txt");
  ASSERT_EQ(code, 1) << ReadText(dir / "run2.txt");
  EXPECT_NE(ReadText(dir / "run2.txt").find("s01: redoing (measurements.json:"), std::string::npos)
      << ReadText(dir / "run2.txt");
  EXPECT_EQ(ReadText(dir / "out" / "summary.csv"), ReadText(dir / "reference" / "summary.csv"));
  EXPECT_EQ(ReadText(dir / "out" / "failures.csv"), ReadText(dir / "reference" / "failures.csv"));
  ExpectSameIdsOnce(ReadText(dir / "out" / "summary.csv"), n + 1);
  EXPECT_FALSE(fs::exists(dir / "out" / "s00" / "measurements.json.tmp-99999-0"));
  EXPECT_FALSE(fs::exists(dir / "out" / "summary.csv.tmp-99999-1"));
  // Both invocations are in the report; the killed one never finished.
  const std::string report = ReadText(dir / "out" / "report.html");
  EXPECT_NE(report.find("did not finish"), std::string::npos);
  EXPECT_NE(report.find("2 attempt(s)"), std::string::npos);
}

TEST(BatchFake, CtrlCStopsCleanlyAndResumeFinishes) {
  TempDir dir;
  WriteOkScans(dir / "in", 8, 0.4);
  const pid_t batch =
      StartBespoke(BatchArgs(dir / "in", dir / "out", {"-j", "2"}), dir / "run1.txt");
  ASSERT_TRUE(WaitFor([&] { return CountDone(dir / "out") >= 2; }, 30));
  ::kill(batch, SIGINT);
  const WorkerExit exit = ReapWorker(batch);
  EXPECT_EQ(exit.exit_code, 130) << ReadText(dir / "run1.txt");
  EXPECT_NE(ReadText(dir / "run1.txt").find("interrupted by SIGINT"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "out" / "batch.json"));
  EXPECT_LT(CountDone(dir / "out"), 8);
  ASSERT_EQ(RunBespoke(BatchArgs(dir / "in", dir / "out", {"--resume"}), dir / "run2.txt"), 0)
      << ReadText(dir / "run2.txt");
  ExpectSameIdsOnce(ReadText(dir / "out" / "summary.csv"), 8);
  EXPECT_NE(ReadText(dir / "out" / "report.html").find("interrupted"), std::string::npos);
}

TEST(BatchFake, ShardsMergeIntoTheLocalRunsSummary) {
  TempDir dir;
  WriteOkScans(dir / "in", 7, 0);
  WriteText(dir / "in" / "bad.txt", "input-error nope");
  ASSERT_EQ(RunBespoke(BatchArgs(dir / "in", dir / "local"), dir / "local.txt"), 1);
  // Shards 1 and 3 share one folder, shard 2 has its own (another machine).
  for (const std::string shard : {"1/3", "3/3"}) {
    ASSERT_EQ(RunBespoke(BatchArgs(dir / "in", dir / "shared", {"--resume", "--shard", shard}),
                         dir / "s.txt"),
              shard == "1/3" ? 1 : 0)
        << ReadText(dir / "s.txt");
  }
  // Missing shard 2: the merge refuses, or marks it incomplete.
  EXPECT_EQ(RunBespoke({"batch-merge", (dir / "shared").string()}, dir / "m1.txt"), 1);
  EXPECT_NE(ReadText(dir / "m1.txt").find("2/3"), std::string::npos) << ReadText(dir / "m1.txt");
  EXPECT_EQ(RunBespoke({"batch-merge", (dir / "shared").string(), "--allow-incomplete", "-o",
                        (dir / "partial").string()},
                       dir / "m2.txt"),
            2);
  // Sorted ids: bad s00 .. s06; shard 1/3 = bad s02 s05, 2/3 = s00 s03 s06, 3/3 = s01 s04.
  ASSERT_EQ(RunBespoke(BatchArgs(dir / "in", dir / "other", {"--shard", "2/3"}), dir / "s2.txt"),
            0);
  ASSERT_EQ(RunBespoke({"batch-merge", (dir / "shared").string(), (dir / "other").string(), "-o",
                        (dir / "merged").string()},
                       dir / "m3.txt"),
            1)
      << ReadText(dir / "m3.txt");
  EXPECT_EQ(ReadText(dir / "merged" / "summary.csv"), ReadText(dir / "local" / "summary.csv"));
  EXPECT_EQ(ReadText(dir / "merged" / "failures.csv"), ReadText(dir / "local" / "failures.csv"));
  EXPECT_NE(ReadText(dir / "merged" / "report.html").find("3 attempt(s)"), std::string::npos);
}

TEST(BatchFake, ManifestListsScansWithTheirOwnIds) {
  TempDir dir;
  WriteOkScans(dir / "scans", 3, 0);
  WriteText(dir / "m.csv", "id,path\ncustomer-7,scans/s02.txt\ncustomer-1,scans/s00.txt\n");
  ASSERT_EQ(RunBespoke(BatchArgs(dir / "m.csv", dir / "out"), dir / "log.txt"), 0)
      << ReadText(dir / "log.txt");
  const std::vector<std::string> rows = CsvRows(ReadText(dir / "out" / "summary.csv"));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].substr(0, 11), "customer-1,");
  EXPECT_NE(rows[1].find("1520.00"), std::string::npos) << rows[1];
}

}  // namespace
}  // namespace bespoke::testing
