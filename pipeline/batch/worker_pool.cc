#include "pipeline/batch/worker_pool.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <map>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Clock = std::chrono::steady_clock;

volatile std::sig_atomic_t g_stop_signal = 0;
int g_wake_fd = -1;

extern "C" void OnStopSignal(int signal) {
  if (g_stop_signal == 0) g_stop_signal = signal;
  const char byte = 's';
  if (g_wake_fd >= 0) (void)!::write(g_wake_fd, &byte, 1);
}

extern "C" void OnChild(int) {
  const char byte = 'c';
  if (g_wake_fd >= 0) (void)!::write(g_wake_fd, &byte, 1);
}

// Installs the handlers and the self-pipe for one RunWorkerPool call.
class SignalScope {
 public:
  SignalScope() {
    if (::pipe2(pipe_, O_CLOEXEC | O_NONBLOCK) != 0) throw InternalError("cannot create a pipe");
    g_stop_signal = 0;
    g_wake_fd = pipe_[1];
    struct sigaction action {};
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    action.sa_handler = OnStopSignal;
    for (int i = 0; i < 3; ++i) ::sigaction(kStopSignals[i], &action, &previous_[i]);
    action.sa_handler = OnChild;
    action.sa_flags = SA_RESTART | SA_NOCLDSTOP;
    ::sigaction(SIGCHLD, &action, &previous_[3]);
  }
  ~SignalScope() {
    for (int i = 0; i < 3; ++i) ::sigaction(kStopSignals[i], &previous_[i], nullptr);
    ::sigaction(SIGCHLD, &previous_[3], nullptr);
    g_wake_fd = -1;
    ::close(pipe_[0]);
    ::close(pipe_[1]);
  }
  // Sleeps until a signal arrives or `seconds` pass.
  void Wait(double seconds) {
    struct pollfd fd {
      pipe_[0], POLLIN, 0
    };
    ::poll(&fd, 1, static_cast<int>(seconds * 1000));
    char drain[64];
    while (::read(pipe_[0], drain, sizeof drain) > 0) {
    }
  }
  int stop_signal() const { return g_stop_signal; }

 private:
  static constexpr int kStopSignals[3] = {SIGINT, SIGTERM, SIGHUP};
  int pipe_[2] = {-1, -1};
  struct sigaction previous_[4];
};

struct Running {
  std::string id;
  Clock::time_point start;
  bool timed_out = false;
};

void KillAll(std::map<pid_t, Running>* running) {
  for (auto& [pid, r] : *running) SignalWorker(pid, SIGKILL);
  for (auto& [pid, r] : *running) ReapWorker(pid);
  running->clear();
}

}  // namespace

PoolOutcome RunWorkerPool(const WorkerPoolOptions& options, const std::vector<WorkerJob>& jobs,
                          const std::function<void(const WorkerResult&)>& on_finish) {
  BESPOKE_CHECK(options.jobs >= 1, "worker pool needs jobs >= 1");
  SignalScope signals;
  std::map<pid_t, Running> running;
  size_t next = 0;
  PoolOutcome outcome;
  try {
    while (next < jobs.size() || !running.empty()) {
      if (signals.stop_signal() != 0) {
        outcome = {true, signals.stop_signal(), static_cast<int>(running.size())};
        KillAll(&running);
        return outcome;
      }
      while (next < jobs.size() && static_cast<int>(running.size()) < options.jobs) {
        const WorkerJob& job = jobs[next++];
        if (job.prepare) job.prepare();
        const pid_t pid = SpawnWorker(job.spawn);
        running[pid] = {job.id, Clock::now(), false};
      }
      signals.Wait(options.poll_s);
      const Clock::time_point now = Clock::now();
      for (auto it = running.begin(); it != running.end();) {
        const double elapsed = std::chrono::duration<double>(now - it->second.start).count();
        if (std::optional<WorkerExit> exit = TryReapWorker(it->first)) {
          WorkerResult result{it->second.id, *exit, it->second.timed_out, elapsed};
          it = running.erase(it);
          on_finish(result);
          continue;
        }
        if (options.timeout_s > 0 && elapsed > options.timeout_s && !it->second.timed_out) {
          it->second.timed_out = true;
          SignalWorker(it->first, SIGKILL);
        }
        ++it;
      }
    }
  } catch (...) {
    KillAll(&running);
    throw;
  }
  return outcome;  // a signal after the last job ended interrupts nothing
}

}  // namespace bespoke
