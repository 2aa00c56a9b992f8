// What a batch folder holds besides the scans' folders: the plan (which scans
// a run or shard covers) and the attempt records (every invocation, so
// retries and interruptions show in the report).
//
// Layout of OUT_DIR (docs/batch.md):
//   <scan-id>/...                   one folder per scan, done.json last
//   plan.json, summary.csv, failures.csv, timings.csv, report.html,
//   report/*.png, batch.json        results of a whole (unsharded) run
//   shards/shard-I-of-N/...         the same per shard of a sharded run
//   attempts/<shard>-<utc>-<host>-<pid>.json   one per invocation
// batch.json is written last: a results folder without it is incomplete.
#ifndef BESPOKE_PIPELINE_BATCH_BATCH_PLAN_H_
#define BESPOKE_PIPELINE_BATCH_BATCH_PLAN_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pipeline/batch/scan_list.h"

namespace bespoke {

inline constexpr const char* kPlanFileName = "plan.json";
inline constexpr const char* kBatchDoneFileName = "batch.json";

// Where a run's results go: OUT_DIR for a whole run, OUT_DIR/shards/<dir> for a shard.
std::filesystem::path ResultsDir(const std::filesystem::path& out_dir, const Shard& shard);

struct Plan {
  Shard shard;
  std::string input;             // the batch's INPUT_DIR or manifest
  std::vector<ScanEntry> scans;  // this shard's scans, sorted by id
  int total_scans = 0;           // scans in the whole (unsharded) list
};

void WritePlan(const std::filesystem::path& results_dir, const Plan& plan);
// InputError for a missing or malformed plan.
Plan ReadPlan(const std::filesystem::path& file);

// Every plan under `out_dir` (plan.json and shards/*/plan.json), with the
// folder it was found in.
struct FoundPlan {
  Plan plan;
  std::filesystem::path out_dir;
  std::filesystem::path file;
};
std::vector<FoundPlan> FindPlans(const std::filesystem::path& out_dir);

// One invocation of `bespoke batch`. Written when it starts (status
// "running") and again when it ends ("finished" or "interrupted"); a record
// still "running" after the fact means the process was killed or lost.
struct Attempt {
  std::filesystem::path file;
  double last_write_s = 0;  // steady-clock seconds of the last write
  nlohmann::json record;    // shard, label, host, pid, started_utc, finished_utc,
                            // status, exit_code, planned, skipped, ran, ok, failed, wall_s, jobs
};
Attempt StartAttempt(const std::filesystem::path& out_dir, const Shard& shard,
                     const std::string& label, int jobs);
void FinishAttempt(Attempt* attempt, const nlohmann::json& fields);
// Records progress (ran, ok, failed, wall_s) while running, so a killed
// attempt still shows what it did; writes at most every `min_interval_s`.
void UpdateAttempt(Attempt* attempt, const nlohmann::json& fields, double min_interval_s = 2.0);
// All attempt records of `out_dir`, ordered by start time then file name.
std::vector<nlohmann::json> ReadAttempts(const std::filesystem::path& out_dir);

// A label for this attempt from the environment: "slurm job 123 task 2 try 1"
// under Slurm (SLURM_ARRAY_JOB_ID, SLURM_ARRAY_TASK_ID, SLURM_RESTART_COUNT,
// BESPOKE_TRY), else "".
std::string AttemptLabelFromEnvironment();

// Removes Bespoke's temporary files ("*.tmp-<pid>-<n>") left in `dir` (not
// recursive) by a killed writer; returns how many.
int RemoveStrayTempFiles(const std::filesystem::path& dir);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_BATCH_PLAN_H_
