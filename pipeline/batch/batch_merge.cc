#include "pipeline/batch/batch_merge.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <map>
#include <set>

#include "pipeline/batch/batch_plan.h"
#include "pipeline/batch/batch_report.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

void MergeOptions::Check() const {
  if (out_dirs.empty()) throw InputError("batch-merge: give at least one OUT_DIR");
  std::error_code ec;
  for (const fs::path& d : out_dirs) {
    if (!fs::is_directory(d, ec)) throw InputError(d, "is not a batch output folder");
  }
}

int MergeOutcome::ExitCode() const { return missing_shards > 0 ? 2 : counts.ExitCode(); }

MergeOutcome MergeBatches(const MergeOptions& options) {
  options.Check();
  std::vector<FoundPlan> plans;
  for (const fs::path& dir : options.out_dirs) {
    std::vector<FoundPlan> found = FindPlans(fs::absolute(dir).lexically_normal());
    const bool sharded = std::any_of(found.begin(), found.end(),
                                     [](const FoundPlan& p) { return !p.plan.shard.whole(); });
    for (FoundPlan& p : found) {
      if (!sharded || !p.plan.shard.whole()) plans.push_back(std::move(p));
    }
  }
  if (plans.empty()) throw InputError(options.out_dirs.front(), "holds no batch plan (plan.json)");
  const int count = plans.front().plan.shard.count;
  std::map<int, const FoundPlan*> by_index;
  std::set<std::string> inputs;
  for (const FoundPlan& p : plans) {
    if (p.plan.shard.count != count) {
      throw InputError(p.file, "is shard " + p.plan.shard.ToString() + " but " +
                                   plans.front().file.string() + " is of " + std::to_string(count));
    }
    if (by_index.count(p.plan.shard.index)) {
      throw InputError(p.file, "shard " + p.plan.shard.ToString() + " also in " +
                                   by_index[p.plan.shard.index]->file.string());
    }
    by_index[p.plan.shard.index] = &p;
    inputs.insert(p.plan.input);
  }
  MergeOutcome outcome;
  outcome.shards = static_cast<int>(plans.size());
  std::string missing;
  for (int i = 1; i <= count; ++i) {
    if (!by_index.count(i)) {
      ++outcome.missing_shards;
      missing += (missing.empty() ? "" : ", ") + Shard{i, count}.ToString();
    }
  }
  if (!missing.empty()) {
    if (!options.allow_incomplete) {
      throw InputError(options.out_dirs.front(), "shard(s) " + missing +
                                                     " have no plan: did their tasks run? "
                                                     "(--allow-incomplete merges the rest)");
    }
    spdlog::warn("merging without shard(s) {}", missing);
  }
  if (inputs.size() > 1) spdlog::warn("the shards were planned from different inputs");

  std::vector<ScanOutcome> outcomes;
  std::set<std::string> ids;
  for (const auto& [index, p] : by_index) {
    for (const ScanEntry& e : p->plan.scans) {
      if (!ids.insert(e.id).second)
        throw InputError(p->file, "scan id '" + e.id + "' is in two shards");
    }
    std::vector<ScanOutcome> part =
        CollectOutcomes(p->plan.scans, p->out_dir, /*verify_hashes=*/true);
    std::move(part.begin(), part.end(), std::back_inserter(outcomes));
  }
  std::sort(outcomes.begin(), outcomes.end(),
            [](const ScanOutcome& a, const ScanOutcome& b) { return a.entry.id < b.entry.id; });

  BatchResultsInput input;
  input.title = "bespoke batch of " + *inputs.begin() + " (merged from " +
                std::to_string(plans.size()) + " of " + std::to_string(count) + " shard(s))";
  input.outcomes = std::move(outcomes);
  std::set<fs::path> dirs;
  for (const FoundPlan& p : plans) dirs.insert(p.out_dir);
  for (const fs::path& d : dirs) {
    for (json& a : ReadAttempts(d)) input.attempts.push_back(std::move(a));
  }
  std::stable_sort(input.attempts.begin(), input.attempts.end(), [](const json& a, const json& b) {
    return a.value("started_utc", "") < b.value("started_utc", "");
  });
  json shards = json::array();
  for (const FoundPlan& p : plans) shards.push_back(p.file.string());
  input.settings = {{"merged_plans", shards}, {"missing_shards", missing}};
  outcome.results_dir = options.results_dir.empty() ? fs::absolute(options.out_dirs.front())
                                                    : fs::absolute(options.results_dir);
  outcome.counts = WriteBatchResults(outcome.results_dir, input);
  return outcome;
}

}  // namespace bespoke
