#include "pipeline/batch/batch_plan.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>

#include "pipeline/batch/done_record.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

fs::path ResultsDir(const fs::path& out_dir, const Shard& shard) {
  return shard.whole() ? out_dir : out_dir / "shards" / shard.DirName();
}

void WritePlan(const fs::path& results_dir, const Plan& plan) {
  json scans = json::array();
  for (const ScanEntry& s : plan.scans) {
    scans.push_back({{"id", s.id},
                     {"path", s.path.string()},
                     {"design", s.design},
                     {"units", s.units},
                     {"landmarks", s.landmarks.string()}});
  }
  CreateDirectories(results_dir);
  WriteJsonFile(results_dir / kPlanFileName, {{"format", "bespoke-batch-plan"},
                                              {"version", 1},
                                              {"shard", plan.shard.ToString()},
                                              {"input", plan.input},
                                              {"total_scans", plan.total_scans},
                                              {"scans", scans}});
}

Plan ReadPlan(const fs::path& file) {
  const json j = ReadJsonFile(file);
  try {
    if (j.value("format", "") != "bespoke-batch-plan") throw InputError(file, "not a batch plan");
    Plan plan;
    plan.shard = ParseShard(j.at("shard").get<std::string>());
    plan.input = j.value("input", "");
    plan.total_scans = j.value("total_scans", 0);
    for (const json& s : j.at("scans")) {
      plan.scans.push_back({s.at("id").get<std::string>(), s.at("path").get<std::string>(),
                            s.value("design", ""), s.value("units", ""), s.value("landmarks", "")});
    }
    return plan;
  } catch (const json::exception& e) {
    throw InputError(file, std::string("malformed batch plan: ") + e.what());
  }
}

std::vector<FoundPlan> FindPlans(const fs::path& out_dir) {
  std::vector<FoundPlan> found;
  std::error_code ec;
  if (fs::is_regular_file(out_dir / kPlanFileName, ec)) {
    found.push_back({ReadPlan(out_dir / kPlanFileName), out_dir, out_dir / kPlanFileName});
  }
  std::vector<fs::path> shard_dirs;
  if (fs::is_directory(out_dir / "shards", ec)) {
    for (const auto& e : fs::directory_iterator(out_dir / "shards", ec))
      shard_dirs.push_back(e.path());
  }
  std::sort(shard_dirs.begin(), shard_dirs.end());
  for (const fs::path& d : shard_dirs) {
    if (fs::is_regular_file(d / kPlanFileName, ec)) {
      found.push_back({ReadPlan(d / kPlanFileName), out_dir, d / kPlanFileName});
    }
  }
  return found;
}

std::string AttemptLabelFromEnvironment() {
  auto env = [](const char* name) {
    const char* v = std::getenv(name);
    return std::string(v ? v : "");
  };
  std::string label;
  if (!env("SLURM_ARRAY_JOB_ID").empty()) {
    label = "slurm job " + env("SLURM_ARRAY_JOB_ID") + " task " + env("SLURM_ARRAY_TASK_ID");
  } else if (!env("SLURM_JOB_ID").empty()) {
    label = "slurm job " + env("SLURM_JOB_ID");
  }
  if (!env("SLURM_RESTART_COUNT").empty()) label += " requeue " + env("SLURM_RESTART_COUNT");
  if (!env("BESPOKE_TRY").empty())
    label += (label.empty() ? "" : " ") + std::string("try ") + env("BESPOKE_TRY");
  return label;
}

Attempt StartAttempt(const fs::path& out_dir, const Shard& shard, const std::string& label,
                     int jobs) {
  char host[256] = {0};
  ::gethostname(host, sizeof host - 1);
  const std::string started = UtcNow();
  std::string stamp = started;
  stamp.erase(std::remove(stamp.begin(), stamp.end(), ':'), stamp.end());
  const fs::path dir = out_dir / "attempts";
  CreateDirectories(dir);
  Attempt a;
  a.file = dir / ((shard.whole() ? std::string("whole") : shard.DirName()) + "-" + stamp + "-" +
                  host + "-" + std::to_string(::getpid()) + ".json");
  a.record = {{"format", "bespoke-batch-attempt"},
              {"shard", shard.ToString()},
              {"label", label},
              {"host", host},
              {"pid", ::getpid()},
              {"jobs", jobs},
              {"started_utc", started},
              {"status", "running"}};
  WriteJsonFile(a.file, a.record);
  return a;
}

namespace {
double SteadySeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
}  // namespace

void UpdateAttempt(Attempt* attempt, const json& fields, double min_interval_s) {
  attempt->record.update(fields);
  const double now = SteadySeconds();
  if (now - attempt->last_write_s < min_interval_s) return;
  attempt->last_write_s = now;
  attempt->record["updated_utc"] = UtcNow();
  WriteJsonFile(attempt->file, attempt->record);
}

void FinishAttempt(Attempt* attempt, const json& fields) {
  attempt->record.update(fields);
  attempt->record["finished_utc"] = UtcNow();
  WriteJsonFile(attempt->file, attempt->record);
}

std::vector<json> ReadAttempts(const fs::path& out_dir) {
  std::vector<std::pair<std::string, json>> found;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(out_dir / "attempts", ec)) {
    if (e.path().extension() != ".json") continue;
    try {
      json j = ReadJsonFile(e.path());
      if (j.value("format", "") != "bespoke-batch-attempt") continue;
      found.push_back({j.value("started_utc", "") + e.path().filename().string(), std::move(j)});
    } catch (const InputError&) {
      // a torn record cannot exist (atomic writes); skip anything foreign
    }
  }
  std::sort(found.begin(), found.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<json> attempts;
  for (auto& f : found) attempts.push_back(std::move(f.second));
  return attempts;
}

int RemoveStrayTempFiles(const fs::path& dir) {
  int removed = 0;
  std::error_code ec;
  std::vector<fs::path> stray;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    if (e.path().filename().string().find(".tmp-") != std::string::npos) stray.push_back(e.path());
  }
  for (const fs::path& p : stray) removed += fs::remove(p, ec) ? 1 : 0;
  return removed;
}

}  // namespace bespoke
