// `bespoke batch`: every scan of a folder or manifest through the single-scan
// job (`bespoke run`), each in its own worker process.
//
// For each scan of the plan (scan_list.h; one shard of it with --shard) the
// batch starts `bespoke run SCAN -o OUT_DIR/<id> ...` as a separate process
// (process.h) with a wall-time and an address-space limit, at most `jobs` at
// once. A crash, hang, out-of-memory or bad file in one scan ends only that
// worker; the batch writes the scan's done.json with status "failed" and the
// reason, and goes on. At the end it writes the summary, failures and timing
// tables and the HTML report (batch_report.h); batch.json last.
//
// Resume: with `resume`, scans whose folder holds a valid done.json (every
// output present with its size and SHA-256, same input bytes) are skipped;
// other folders are removed and redone; stray temporary files are removed.
// Failed scans count as finished unless `retry_failed`. Without `resume`, a
// folder that already holds results for this plan is refused (InputError).
//
// Interruption (SIGINT/SIGTERM/SIGHUP): running workers are killed, their
// folders stay without done.json (so a resume redoes them), no results
// tables are written, and the outcome says `interrupted`.
// Concurrency: one batch per results folder at a time (an flock on
// <results>/.lock); a second one gets an InputError.
#ifndef BESPOKE_PIPELINE_BATCH_BATCH_H_
#define BESPOKE_PIPELINE_BATCH_BATCH_H_

#include <cstdint>
#include <filesystem>
#include <string>

#include "pipeline/batch/batch_summary.h"
#include "pipeline/batch/scan_list.h"
#include "scanners/core/progress.h"

namespace bespoke {

struct BatchOptions {
  std::filesystem::path input;    // INPUT_DIR or MANIFEST.csv
  std::filesystem::path out_dir;  // OUT_DIR (created)
  int jobs = 0;                   // workers at once; 0 (default) = the CPUs this process may use
  std::string design;             // default design for every scan: "" (none), "shirt", "trousers"
  std::string units;              // default file unit: "" (guess), "mm", "cm", "dm", "m"
  bool resume = false;            // continue an earlier run in out_dir (default no)
  bool retry_failed = false;      // with resume: redo scans that failed (default no)
  bool recursive = false;         // look into sub-folders of INPUT_DIR (default no)
  Shard shard;                    // default 1/1 (everything)
  double timeout_s = 600;         // wall-time limit per scan, s; 0 = none (default 600)
  std::int64_t memory_mb = 4096;  // address-space limit per worker, MB; 0 = none (default 4096)
  std::filesystem::path worker;   // program run per scan; "" (default) = this bespoke binary
  std::string label;              // attempt label in the report; "" = from SLURM_* variables
  // Throws InputError for a bad value.
  void Check() const;
};

struct BatchOutcome {
  BatchCounts counts;  // over the whole plan (when not interrupted)
  int skipped = 0;     // finished before (resume)
  int ran = 0;         // scans run by this invocation
  bool interrupted = false;
  int signal = 0;
  std::filesystem::path results_dir;
  // 0 all ok, 1 some scans failed on bad input, 2 other failures (crash,
  // time-out, memory, internal), 128 + signal when interrupted.
  int ExitCode() const;
};

BatchOutcome RunBatch(const BatchOptions& options, Progress* progress);

// The CPUs this process may run on (SLURM_CPUS_PER_TASK when set, else the
// affinity mask), at least 1.
int AvailableCpus();

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_BATCH_H_
