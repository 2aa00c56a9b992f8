// Runs worker processes, at most `jobs` at once, each with a wall-time limit,
// and stops cleanly on SIGINT / SIGTERM / SIGHUP.
//
// RunWorkerPool starts the jobs in the given order (SpawnWorker, see
// process.h), calls `on_finish` in the calling thread as each one ends, kills
// (SIGKILL to its process group) any worker that runs longer than timeout_s,
// and returns when all have ended. On a stop signal it kills every running
// worker, reaps them, does not call on_finish for them, starts nothing new and
// returns `interrupted` with the signal: their outputs stay partial (no
// done.json) and a resumed batch redoes them.
//
// The signal handlers are installed for the duration of the call only, and
// restored after. Throws InternalError when a worker cannot be started (after
// killing the ones already running).
#ifndef BESPOKE_PIPELINE_BATCH_WORKER_POOL_H_
#define BESPOKE_PIPELINE_BATCH_WORKER_POOL_H_

#include <functional>
#include <string>
#include <vector>

#include "pipeline/batch/process.h"

namespace bespoke {

struct WorkerJob {
  std::string id;      // the scan id, passed back in WorkerResult
  SpawnOptions spawn;  // what to run
  // Called right before the worker starts (prepare its folder); may throw.
  std::function<void()> prepare;
};

struct WorkerResult {
  std::string id;
  WorkerExit exit;
  bool timed_out = false;  // killed by the pool after timeout_s
  double wall_s = 0;       // from start to reaped
};

struct WorkerPoolOptions {
  int jobs = 1;            // workers at once (>= 1)
  double timeout_s = 600;  // wall-time limit per worker; <= 0 = none
  double poll_s = 0.05;    // how often deadlines are checked (a child's end wakes at once)
};

struct PoolOutcome {
  bool interrupted = false;
  int signal = 0;          // SIGINT / SIGTERM / SIGHUP when interrupted
  int killed_running = 0;  // workers killed because of the interruption
};

PoolOutcome RunWorkerPool(const WorkerPoolOptions& options, const std::vector<WorkerJob>& jobs,
                          const std::function<void(const WorkerResult&)>& on_finish);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_WORKER_POOL_H_
