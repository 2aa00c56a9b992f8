#include "pipeline/batch/batch.h"

#include <fcntl.h>
#include <sched.h>
#include <spdlog/spdlog.h>
#include <sys/file.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <set>

#include "pipeline/batch/batch_plan.h"
#include "pipeline/batch/batch_report.h"
#include "pipeline/batch/process.h"
#include "pipeline/batch/scan_worker.h"
#include "scanners/core/atomic_file.h"
#include "scanners/core/errors.h"
#include "scanners/core/units.h"

namespace bespoke {
namespace fs = std::filesystem;
using nlohmann::json;

namespace {

// Holds an exclusive flock on <dir>/.lock for the life of the batch.
class FolderLock {
 public:
  explicit FolderLock(const fs::path& dir) {
    const fs::path file = dir / ".lock";
    fd_ = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw InputError(file, "cannot create the batch lock file");
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd_);
      throw InputError(dir, "another bespoke batch is running on this folder");
    }
  }
  ~FolderLock() { ::close(fd_); }

 private:
  int fd_ = -1;
};

// True when the scan's input still has the bytes its done.json recorded.
bool InputUnchanged(const DoneRecord& record, const ScanEntry& entry) {
  std::error_code ec;
  if (!fs::is_regular_file(entry.path, ec)) return record.input_size_bytes < 0;
  const auto size = fs::file_size(entry.path, ec);
  if (ec || static_cast<std::int64_t>(size) != record.input_size_bytes) return false;
  try {
    return FileSha256(entry.path) == record.input_sha256;
  } catch (const InputError&) {
    return false;
  }
}

// Splits the plan into finished scans and scans to (re)do; clears the latter.
std::vector<ScanEntry> ScansToRun(const BatchOptions& options, const std::vector<ScanEntry>& plan,
                                  int* skipped) {
  std::vector<ScanEntry> todo;
  for (const ScanEntry& entry : plan) {
    const fs::path folder = options.out_dir / entry.id;
    std::error_code ec;
    if (!fs::exists(folder, ec)) {
      todo.push_back(entry);
      continue;
    }
    if (!options.resume) {
      throw InputError(options.out_dir, "already holds results (" + entry.id +
                                            "/); pass --resume to continue that batch, or "
                                            "choose another output folder");
    }
    std::string problem;
    const auto record = ReadValidDoneRecord(folder, /*verify_hashes=*/true, &problem);
    if (record && (record->status == "ok" || !options.retry_failed) &&
        InputUnchanged(*record, entry)) {
      ++*skipped;
      if (const int n = RemoveStrayTempFiles(folder)) {
        spdlog::debug("{}: removed {} stray temporary file(s)", entry.id, n);
      }
      continue;
    }
    spdlog::info(
        "{}: redoing ({})", entry.id,
        record ? (record->status == "failed" ? "failed before" : "input changed") : problem);
    todo.push_back(entry);
  }
  return todo;
}

json SettingsJson(const BatchOptions& o, int jobs) {
  return {{"input", o.input.string()},
          {"out_dir", o.out_dir.string()},
          {"jobs", jobs},
          {"design", o.design},
          {"units", o.units},
          {"resume", o.resume},
          {"retry_failed", o.retry_failed},
          {"recursive", o.recursive},
          {"shard", o.shard.ToString()},
          {"timeout_s", o.timeout_s},
          {"memory_mb", o.memory_mb}};
}

}  // namespace

void BatchOptions::Check() const {
  if (input.empty()) throw InputError("batch: no INPUT_DIR or MANIFEST.csv given");
  if (out_dir.empty()) throw InputError("batch: no output folder (-o OUT_DIR)");
  if (jobs < 0) throw InputError("--jobs must be >= 0 (0 = all CPUs)");
  if (timeout_s < 0) throw InputError("--timeout-s must be >= 0 (0 = no limit)");
  if (memory_mb < 0) throw InputError("--memory-mb must be >= 0 (0 = no limit)");
  if (!design.empty() && design != "shirt" && design != "trousers") {
    throw InputError("--design '" + design + "': expected shirt or trousers");
  }
  if (!units.empty() && !ParseLengthUnit(units)) {
    throw InputError("--units '" + units + "': expected mm, cm, dm or m");
  }
  if (retry_failed && !resume) throw InputError("--retry-failed needs --resume");
}

int BatchOutcome::ExitCode() const { return interrupted ? 128 + signal : counts.ExitCode(); }

int AvailableCpus() {
  if (const char* env = std::getenv("SLURM_CPUS_PER_TASK")) {
    const int n = std::atoi(env);
    if (n > 0) return n;
  }
  cpu_set_t set;
  CPU_ZERO(&set);
  if (::sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0) return CPU_COUNT(&set);
  const long n = ::sysconf(_SC_NPROCESSORS_ONLN);
  return n > 0 ? static_cast<int>(n) : 1;
}

BatchOutcome RunBatch(const BatchOptions& options, Progress* progress) {
  options.Check();
  const auto started = std::chrono::steady_clock::now();
  CreateDirectories(options.out_dir);
  const fs::path out_dir = fs::absolute(options.out_dir).lexically_normal();
  std::vector<ScanEntry> all = ListScans({options.recursive, out_dir}, options.input);
  std::set<std::string> ids;
  for (const ScanEntry& e : all) ids.insert(e.id);
  for (const char* reserved : {"attempts", "shards", "report"}) {
    if (ids.count(reserved))
      throw InputError(options.input, std::string("a scan may not be named '") + reserved +
                                          "' (reserved output folder)");
  }
  Plan plan{options.shard, options.input.string(), SelectShard(all, options.shard),
            static_cast<int>(all.size())};
  BatchOutcome outcome;
  outcome.results_dir = ResultsDir(out_dir, options.shard);
  CreateDirectories(outcome.results_dir);
  FolderLock lock(outcome.results_dir);
  if (!options.resume && fs::exists(outcome.results_dir / kPlanFileName)) {
    throw InputError(options.out_dir,
                     "already holds a batch; pass --resume to continue it, or "
                     "choose another output folder");
  }
  BatchOptions resolved = options;
  resolved.out_dir = out_dir;
  const int jobs = options.jobs > 0 ? options.jobs : AvailableCpus();
  std::vector<ScanEntry> todo = ScansToRun(resolved, plan.scans, &outcome.skipped);
  std::error_code ec;
  fs::remove(outcome.results_dir / kBatchDoneFileName, ec);
  RemoveStrayTempFiles(outcome.results_dir);
  WritePlan(outcome.results_dir, plan);
  Attempt attempt =
      StartAttempt(out_dir, options.shard,
                   options.label.empty() ? AttemptLabelFromEnvironment() : options.label, jobs);
  spdlog::info("batch{}: {} scan(s) planned, {} finished before, {} to run with {} worker(s)",
               options.shard.whole() ? "" : " shard " + options.shard.ToString(), plan.scans.size(),
               outcome.skipped, todo.size(), jobs);

  // Workers share the CPUs: with 2 CPUs and 2 jobs each gets 1 thread, so the
  // parallel stages inside a scan do not oversubscribe the machine.
  const int threads = jobs > 1 ? std::max(1, AvailableCpus() / jobs) : 0;
  WorkerSettings worker{options.worker.empty() ? SelfExecutable() : fs::absolute(options.worker),
                        options.design,
                        options.units,
                        options.timeout_s,
                        options.memory_mb,
                        threads};
  std::vector<WorkerJob> work;
  std::map<std::string, const ScanEntry*> by_id;
  for (const ScanEntry& entry : todo) {
    const fs::path folder = out_dir / entry.id;
    by_id[entry.id] = &entry;
    work.push_back({entry.id,
                    {worker.executable, WorkerArguments(worker, entry, folder),
                     folder / kWorkerLogName, options.memory_mb},
                    [folder] {
                      std::error_code e;
                      fs::remove_all(folder, e);
                      CreateDirectories(folder);
                    }});
  }
  const bool tty = ::isatty(STDERR_FILENO) == 1;
  ProgressBegin(progress, "scans", static_cast<std::int64_t>(work.size()));
  int ok = 0, failed = 0;
  const PoolOutcome pool =
      RunWorkerPool({jobs, options.timeout_s}, work, [&](const WorkerResult& r) {
        const ScanEntry& entry = *by_id.at(r.id);
        const DoneRecord record = RecordWorkerEnd(worker, entry, out_dir / entry.id, r);
        ++outcome.ran;
        (record.status == "ok" ? ok : failed) += 1;
        if (record.status != "ok") {
          if (tty) std::fputs("\r\033[K", stderr);
          spdlog::warn("{} failed ({}): {}", entry.id, record.failure->kind,
                       record.failure->message);
        } else if (!tty) {
          spdlog::info("[{}/{}] {} ok ({:.1f} s)", outcome.ran, work.size(), entry.id, r.wall_s);
        }
        ProgressUpdate(progress, outcome.ran);
        UpdateAttempt(
            &attempt,
            {{"ran", outcome.ran},
             {"ok", ok},
             {"failed", failed},
             {"skipped", outcome.skipped},
             {"wall_s",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()}});
      });
  ProgressEnd(progress);
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  json fields = {{"planned", plan.scans.size()},
                 {"skipped", outcome.skipped},
                 {"ran", outcome.ran},
                 {"ok", ok},
                 {"failed", failed},
                 {"wall_s", wall_s}};
  if (pool.interrupted) {
    outcome.interrupted = true;
    outcome.signal = pool.signal;
    fields["status"] = "interrupted";
    fields["exit_code"] = outcome.ExitCode();
    FinishAttempt(&attempt, fields);
    spdlog::warn(
        "interrupted by {}: {} running worker(s) killed; their folders have no done.json "
        "and will be redone by --resume; no summary written",
        DescribeSignal(pool.signal), pool.killed_running);
    return outcome;
  }
  std::vector<ScanOutcome> outcomes = CollectOutcomes(plan.scans, out_dir, /*verify_hashes=*/true);
  outcome.counts = CountOutcomes(outcomes);
  fields["status"] = "finished";
  fields["exit_code"] = outcome.ExitCode();
  FinishAttempt(&attempt, fields);
  BatchResultsInput results{
      "bespoke batch of " + options.input.string() +
          (options.shard.whole() ? "" : " (shard " + options.shard.ToString() + ")"),
      std::move(outcomes),
      {},
      SettingsJson(options, jobs)};
  for (json& a : ReadAttempts(out_dir)) {  // only this shard's (or whole run's) attempts
    if (a.value("shard", "") == options.shard.ToString()) results.attempts.push_back(std::move(a));
  }
  WriteBatchResults(outcome.results_dir, results);
  spdlog::info("batch done: {} ok, {} failed, {} not processed, {:.1f} scans/min; results in {}",
               outcome.counts.ok, outcome.counts.failed, outcome.counts.not_processed,
               wall_s > 0 ? 60.0 * outcome.ran / wall_s : 0.0, outcome.results_dir.string());
  return outcome;
}

}  // namespace bespoke
