// One scan's worker, seen from the batch: its command line, and the verdict
// once it has ended.
//
// The worker is `bespoke run SCAN -o FOLDER --scan-id ID [--threads T]
// [--design D] [--units U] [--landmarks L]`, its output going to
// FOLDER/run.log.
// RecordWorkerEnd reads what the worker left and writes FOLDER/done.json:
//   - exit 0 with a valid done.json of status "ok": ok; the worker's record
//     gains a "worker" section (wall/CPU time, peak memory) and is rewritten
//     atomically;
//   - anything else: status "failed" with a kind and a message:
//       timeout        killed by the batch after the time limit
//       crash          ended by a signal (SIGSEGV, SIGABRT, a SIGKILL not
//                      sent by the batch, e.g. the kernel's OOM killer)
//       out_of_memory  exit 2 reporting "out of memory" (the RLIMIT_AS limit)
//       input_error    exit 1: the scan's file or settings are bad
//       internal_error exit 2 or any other exit code, or exit 0 without a
//                      valid done.json
//       not_started    exit 127: the worker program could not be executed
//     The message is the worker's own (its failed done.json, else the last
//     "error:"/"critical:" line of its log), with no pids or times, so the
//     failures table is the same on every run.
#ifndef BESPOKE_PIPELINE_BATCH_SCAN_WORKER_H_
#define BESPOKE_PIPELINE_BATCH_SCAN_WORKER_H_

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "pipeline/batch/done_record.h"
#include "pipeline/batch/scan_list.h"
#include "pipeline/batch/worker_pool.h"

namespace bespoke {

inline constexpr const char* kWorkerLogName = "run.log";

struct WorkerSettings {
  std::filesystem::path executable;  // the program (bespoke itself by default)
  std::string design;                // used when the entry has none
  std::string units;                 // used when the entry has none
  double timeout_s = 600;            // for the failure message
  std::int64_t memory_mb = 0;        // for the failure message
  int threads = 0;                   // --threads of each worker; 0 = all CPUs
};

// argv of the worker for `entry` writing into `folder` (argv[0] = executable).
std::vector<std::string> WorkerArguments(const WorkerSettings& settings, const ScanEntry& entry,
                                         const std::filesystem::path& folder);

// Writes the final done.json of `folder` (see above) and returns it.
DoneRecord RecordWorkerEnd(const WorkerSettings& settings, const ScanEntry& entry,
                           const std::filesystem::path& folder, const WorkerResult& result);

// The last `max_lines` lines of a text file (at most 4 kB), "" when unreadable.
std::string FileTail(const std::filesystem::path& file, int max_lines);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_SCAN_WORKER_H_
