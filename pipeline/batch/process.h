// Starting and ending worker processes for the batch.
//
// SpawnWorker fork()s and exec()s a program (normally the running `bespoke`
// binary itself) with:
//   - its own process group, so a Ctrl-C on the terminal reaches only the
//     batch, which then ends its workers itself, and a time-out kills the
//     worker and anything it started;
//   - an address-space limit (setrlimit RLIMIT_AS) when memory_limit_mb > 0,
//     so a runaway allocation fails inside the worker (std::bad_alloc -> exit
//     2, "out of memory") instead of taking the machine down; core dumps off;
//   - PR_SET_PDEATHSIG = SIGKILL: if the batch dies (kill -9), its workers die
//     with it rather than writing into folders a resumed batch is redoing;
//   - stdin from /dev/null, stdout and stderr appended to `log_file`.
// Between fork and exec the child only makes async-signal-safe system calls,
// so it is safe even if the parent has threads. Fork-without-exec is never
// used: TBB/OpenMP thread pools do not survive fork.
//
// Not available under AddressSanitizer: ASan reserves terabytes of address
// space, so RLIMIT_AS is skipped there (the memory limit is then not enforced;
// see docs/batch.md).
#ifndef BESPOKE_PIPELINE_BATCH_PROCESS_H_
#define BESPOKE_PIPELINE_BATCH_PROCESS_H_

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bespoke {

struct SpawnOptions {
  std::filesystem::path executable;  // program to exec (absolute path)
  std::vector<std::string> argv;     // argv[0] first
  std::filesystem::path log_file;    // stdout + stderr (appended; created if needed)
  std::int64_t memory_limit_mb = 0;  // RLIMIT_AS in MB; 0 = unlimited (default)
};

// Starts the process; returns its pid (also its process group id). Throws
// InternalError when fork or opening the log fails. When exec fails the
// child exits with code 127 after writing the reason to the log.
pid_t SpawnWorker(const SpawnOptions& options);

struct WorkerExit {
  bool signaled = false;  // ended by a signal
  int exit_code = -1;     // when !signaled
  int signal = 0;         // when signaled
  double user_s = 0;      // CPU time in user mode
  double system_s = 0;    // CPU time in the kernel
  double max_rss_mb = 0;  // peak resident memory
};

// Non-blocking wait for `pid` (wait4 with WNOHANG); nullopt while it runs.
std::optional<WorkerExit> TryReapWorker(pid_t pid);

// Blocking wait.
WorkerExit ReapWorker(pid_t pid);

// Sends `signal` to the worker's whole process group.
void SignalWorker(pid_t pid, int signal);

// "SIGSEGV (Segmentation fault)".
std::string DescribeSignal(int signal);

// True when built with AddressSanitizer (memory limits are then skipped).
bool BuiltWithAddressSanitizer();

// The running program's own executable (/proc/self/exe resolved).
std::filesystem::path SelfExecutable();

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_PROCESS_H_
