// Unit tests of the batch's parts: scan discovery and ids, manifests, shards,
// done records, summary tables, worker processes.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <csignal>
#include <set>

#include "pipeline/batch/batch_summary.h"
#include "pipeline/batch/done_record.h"
#include "pipeline/batch/process.h"
#include "pipeline/batch/scan_list.h"
#include "pipeline/batch/scan_worker.h"
#include "scanners/core/errors.h"
#include "tests/support/batch_test_util.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {
namespace fs = std::filesystem;
using testing::TempDir;
using testing::WriteText;

TEST(ScanList, DiscoversScanNamedEntriesWithStableCollisionFreeIds) {
  TempDir dir;
  for (const char* name : {"b.ply", "a.ply", "a.PCD", "c d.xyz", "notes.md", ".hidden.ply",
                           "x.ply.tmp-12-0", "z.txt"}) {
    WriteText(dir / name, "x");
  }
  fs::create_directories(dir / "folder.ply");  // kept: the batch must report it
  fs::create_directories(dir / "sub");
  WriteText(dir / "sub" / "deep.ply", "x");
  ::mkfifo((dir / "pipe.obj").c_str(), 0644);
  std::vector<ScanEntry> scans = DiscoverScans({}, dir.path());
  std::vector<std::string> ids;
  for (const ScanEntry& s : scans) ids.push_back(s.id);
  EXPECT_EQ(ids, (std::vector<std::string>{"a_pcd", "a_ply", "b", "c_d", "folder", "pipe", "z"}));
  for (const ScanEntry& s : scans) EXPECT_TRUE(s.path.is_absolute()) << s.path;

  scans = DiscoverScans({true, {}}, dir.path());
  ids.clear();
  for (const ScanEntry& s : scans) ids.push_back(s.id);
  EXPECT_NE(std::find(ids.begin(), ids.end(), "sub__deep"), ids.end());
  EXPECT_THROW(DiscoverScans({}, dir / "missing"), InputError);
}

TEST(ScanList, ReadsManifestsAndRejectsBadOnesWithTheLine) {
  TempDir dir;
  WriteText(dir / "m.csv",
            "# comment\nid,path,design,units,extra\n"
            "s2,scans/two.ply,shirt,m,whatever\n"
            "\"s1\",\"/abs/one, with comma.ply\",,,\n");
  const std::vector<ScanEntry> scans = ReadManifest(dir / "m.csv");
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_EQ(scans[0].id, "s1");
  EXPECT_EQ(scans[0].path, fs::path("/abs/one, with comma.ply"));
  EXPECT_EQ(scans[1].path, dir.path() / "scans/two.ply");
  EXPECT_EQ(scans[1].design, "shirt");
  EXPECT_EQ(scans[1].units, "m");

  auto message = [&](const std::string& text) {
    WriteText(dir / "bad.csv", text);
    try {
      ReadManifest(dir / "bad.csv");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("name,file\na,b\n").find("'id' and 'path'"), std::string::npos);
  EXPECT_NE(message("id,path\na,x.ply\na,y.ply\n").find("line 3: id 'a' repeats line 2"),
            std::string::npos);
  EXPECT_NE(message("id,path\n../up,x.ply\n").find("may use only"), std::string::npos);
  EXPECT_NE(message("id,path\n.x,x.ply\n").find("may use only"), std::string::npos);
  EXPECT_NE(message("id,path\na,\"x.ply\n").find("unterminated"), std::string::npos);
  EXPECT_NE(message("").find("empty manifest"), std::string::npos);
}

TEST(ScanList, ShardsPartitionTheSortedListEvenly) {
  std::vector<ScanEntry> all;
  for (int i = 0; i < 23; ++i) all.push_back({"s" + std::to_string(100 + i), "/x", "", "", {}});
  for (int n : {1, 2, 3, 4, 7, 23, 30}) {
    std::set<std::string> seen;
    size_t smallest = all.size(), largest = 0;
    for (int i = 1; i <= n; ++i) {
      const std::vector<ScanEntry> part =
          SelectShard(all, ParseShard(std::to_string(i) + "/" + std::to_string(n)));
      smallest = std::min(smallest, part.size());
      largest = std::max(largest, part.size());
      for (const ScanEntry& e : part) EXPECT_TRUE(seen.insert(e.id).second) << e.id << " twice";
    }
    EXPECT_EQ(seen.size(), all.size()) << n << " shards";
    EXPECT_LE(largest - smallest, 1u) << n << " shards";
  }
  for (const char* bad : {"0/4", "5/4", "1/0", "a/b", "1", "1/2/3", "-1/2", "2/4x"}) {
    EXPECT_THROW(ParseShard(bad), InputError) << bad;
  }
  EXPECT_EQ(ParseShard("2/4").DirName(), "shard-2-of-4");
}

TEST(DoneRecord, DetectsMissingResizedAndAlteredOutputs) {
  TempDir dir;
  WriteText(dir / "a.json", "{\"v\": 1}\n");
  DoneRecord record;
  record.status = "ok";
  record.scan_id = "s";
  record.input = "/in/s.ply";
  record.outputs.push_back(DescribeOutput(dir.path(), "a.json"));
  EXPECT_EQ(record.outputs[0].size_bytes, 9);
  EXPECT_EQ(record.outputs[0].sha256.size(), 64u);
  WriteDoneRecord(dir.path(), record);
  std::string problem;
  ASSERT_TRUE(ReadValidDoneRecord(dir.path(), true, &problem)) << problem;

  WriteText(dir / "a.json", "{\"v\": 2}\n");  // same size, other bytes
  EXPECT_TRUE(ReadValidDoneRecord(dir.path(), false));
  EXPECT_FALSE(ReadValidDoneRecord(dir.path(), true, &problem));
  EXPECT_NE(problem.find("SHA-256"), std::string::npos) << problem;
  WriteText(dir / "a.json", "{}\n");
  EXPECT_FALSE(ReadValidDoneRecord(dir.path(), false, &problem));
  EXPECT_NE(problem.find("bytes, recorded 9"), std::string::npos) << problem;
  fs::remove(dir / "a.json");
  EXPECT_FALSE(ReadValidDoneRecord(dir.path(), false, &problem));
  WriteText(dir / "done.json", "{\"format\": \"bespoke-scan-done\", \"status\": \"ok\"");  // torn
  EXPECT_FALSE(ReadValidDoneRecord(dir.path(), false, &problem));
}

ScanOutcome Outcome(const std::string& id, const std::string& status, double stature) {
  ScanOutcome o;
  o.entry = {id, "/in/" + id + ".ply", "", "", {}};
  o.folder = "/out/" + id;
  o.record = DoneRecord();
  o.record->status = status;
  o.record->time_s = stature / 1000;  // varies: must not reach summary.csv
  if (status == "ok") {
    o.record->results = {{"points_cleaned", 1000}, {"file_unit", "m"}};
    o.measurements = {
        {"measurements",
         {{{"name", "stature"}, {"value_mm", stature}, {"flags", nlohmann::json::array()}},
          {{"name", "waist_girth"}, {"value_mm", 801.234}, {"flags", {"open"}}}}}};
  } else {
    o.record->failure = ScanFailure{"input_error", "bad, \"really\"", 1, 0, ""};
  }
  return o;
}

TEST(BatchSummary, RowsColumnsAndQuotingAreFixed) {
  std::vector<ScanOutcome> outcomes = {Outcome("a", "ok", 1750.0), Outcome("b", "failed", 0),
                                       Outcome("c", "ok", 1600.5)};
  outcomes.push_back(
      ScanOutcome{{"d", "/in/d.ply", "", "", {}}, "/out/d", std::nullopt, "no done.json", {}});
  EXPECT_EQ(
      SummaryCsv(outcomes),
      "scan_id,status,failure_kind,file_unit,points_cleaned,stature_mm,waist_girth_mm,flagged\n"
      "a,ok,,m,1000,1750.00,801.23,waist_girth\n"
      "b,failed,input_error,,,,,\n"
      "c,ok,,m,1000,1600.50,801.23,waist_girth\n"
      "d,failed,not_processed,,,,,\n");
  EXPECT_EQ(FailuresCsv(outcomes),
            "scan_id,input,kind,exit_code,signal,message\n"
            "b,/in/b.ply,input_error,1,,\"bad, \"\"really\"\"\"\n"
            "d,/in/d.ply,not_processed,,,not processed: no done.json\n");
  const BatchCounts counts = CountOutcomes(outcomes);
  EXPECT_EQ(counts.ok, 2);
  EXPECT_EQ(counts.failed, 1);
  EXPECT_EQ(counts.not_processed, 1);
  EXPECT_EQ(counts.ExitCode(), 2);  // a scan not processed is not a bad input
  outcomes.pop_back();
  EXPECT_EQ(CountOutcomes(outcomes).ExitCode(), 1);
}

TEST(Process, ReportsExitCodesSignalsAndStartFailures) {
  TempDir dir;
  auto run = [&](const std::string& script) {
    return ReapWorker(SpawnWorker({"/bin/sh", {"sh", "-c", script}, dir / "log.txt", 0}));
  };
  WorkerExit e = run("echo hello; exit 3");
  EXPECT_FALSE(e.signaled);
  EXPECT_EQ(e.exit_code, 3);
  EXPECT_NE(testing::ReadText(dir / "log.txt").find("hello"), std::string::npos);
  e = run("kill -SEGV $$");
  EXPECT_TRUE(e.signaled);
  EXPECT_EQ(e.signal, SIGSEGV);
  EXPECT_EQ(DescribeSignal(SIGSEGV), "SIGSEGV (Segmentation fault)");
  e = ReapWorker(SpawnWorker({"/nonexistent/program", {"x"}, dir / "log2.txt", 0}));
  EXPECT_EQ(e.exit_code, 127);
  EXPECT_NE(testing::ReadText(dir / "log2.txt").find("exec failed"), std::string::npos);
  // The child sees the address-space limit.
  const pid_t pid = SpawnWorker({"/bin/sh", {"sh", "-c", "ulimit -v"}, dir / "limit.txt", 256});
  ReapWorker(pid);
  if (!BuiltWithAddressSanitizer()) {
    EXPECT_EQ(testing::ReadText(dir / "limit.txt"), std::to_string(256 * 1024) + "\n");
  }
}

TEST(ScanWorker, FailureMessagesCarryNoTimesOrPids) {
  TempDir dir;
  WorkerSettings settings{"/bin/true", "", "", 30, 512};
  ScanEntry entry{"s", "/in/s.ply", "", "", {}};
  fs::create_directories(dir / "s");
  WriteText(dir / "s" / "run.log", "info: reading\nerror: /in/s.ply: truncated\n");
  WorkerResult r{"s", {}, false, 1.0};
  r.exit.exit_code = 1;
  DoneRecord d = RecordWorkerEnd(settings, entry, dir / "s", r);
  EXPECT_EQ(d.status, "failed");
  EXPECT_EQ(d.failure->kind, "input_error");
  EXPECT_EQ(d.failure->message, "/in/s.ply: truncated");
  r.timed_out = true;
  r.exit.signaled = true;
  r.exit.signal = SIGKILL;
  d = RecordWorkerEnd(settings, entry, dir / "s", r);
  EXPECT_EQ(d.failure->kind, "timeout");
  EXPECT_EQ(d.failure->message, "timed out after 30 s; the worker was killed");
  r.timed_out = false;
  r.exit.signal = SIGABRT;
  d = RecordWorkerEnd(settings, entry, dir / "s", r);
  EXPECT_EQ(d.failure->kind, "crash");
  EXPECT_NE(d.failure->message.find("SIGABRT"), std::string::npos);
  WriteText(dir / "s" / "run.log", "critical: internal error: out of memory\n");
  fs::remove(dir / "s" / "done.json");
  r.exit = {};
  r.exit.exit_code = 2;
  d = RecordWorkerEnd(settings, entry, dir / "s", r);
  EXPECT_EQ(d.failure->kind, "out_of_memory");
  EXPECT_EQ(d.failure->message, "out of memory (limit 512 MB): out of memory");
  fs::remove(dir / "s" / "done.json");
  r.exit.exit_code = 0;  // exit 0 without a done.json is not success
  d = RecordWorkerEnd(settings, entry, dir / "s", r);
  EXPECT_EQ(d.failure->kind, "internal_error");
}

}  // namespace
}  // namespace bespoke
