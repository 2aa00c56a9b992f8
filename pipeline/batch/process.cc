#include "pipeline/batch/process.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>

#include "scanners/core/errors.h"

#if defined(__SANITIZE_ADDRESS__)
#define BESPOKE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BESPOKE_ASAN 1
#endif
#endif

namespace bespoke {
namespace {

// Child side of SpawnWorker: only async-signal-safe calls from here to exec.
[[noreturn]] void ExecChild(pid_t parent, int log_fd, int null_fd, std::int64_t memory_limit_mb,
                            const char* executable, char* const* argv) {
  ::setpgid(0, 0);
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(127);  // the batch is already gone
  sigset_t all;
  ::sigemptyset(&all);
  ::sigprocmask(SIG_SETMASK, &all, nullptr);
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  for (int s : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGCHLD}) ::sigaction(s, &dfl, nullptr);
  struct rlimit no_core {
    0, 0
  };
  ::setrlimit(RLIMIT_CORE, &no_core);
  if (memory_limit_mb > 0) {
    const rlim_t bytes = static_cast<rlim_t>(memory_limit_mb) * 1024 * 1024;
    struct rlimit as {
      bytes, bytes
    };
    ::setrlimit(RLIMIT_AS, &as);
  }
  ::dup2(null_fd, STDIN_FILENO);
  ::dup2(log_fd, STDOUT_FILENO);
  ::dup2(log_fd, STDERR_FILENO);
  ::close_range(3, ~0U, 0);
  ::execv(executable, argv);
  const char* what = "bespoke batch: cannot start the worker: exec failed: ";
  ssize_t ignored = ::write(STDERR_FILENO, what, std::strlen(what));
  const char* reason = std::strerror(errno);  // not strictly AS-safe; glibc's is in practice
  ignored = ::write(STDERR_FILENO, reason, std::strlen(reason));
  ignored = ::write(STDERR_FILENO, "\n", 1);
  (void)ignored;
  ::_exit(127);
}

WorkerExit FromStatus(int status, const struct rusage& usage) {
  WorkerExit exit;
  if (WIFSIGNALED(status)) {
    exit.signaled = true;
    exit.signal = WTERMSIG(status);
  } else {
    exit.exit_code = WEXITSTATUS(status);
  }
  exit.user_s = usage.ru_utime.tv_sec + usage.ru_utime.tv_usec * 1e-6;
  exit.system_s = usage.ru_stime.tv_sec + usage.ru_stime.tv_usec * 1e-6;
  exit.max_rss_mb = usage.ru_maxrss / 1024.0;  // ru_maxrss is in KiB on Linux
  return exit;
}

}  // namespace

bool BuiltWithAddressSanitizer() {
#ifdef BESPOKE_ASAN
  return true;
#else
  return false;
#endif
}

std::filesystem::path SelfExecutable() {
  std::error_code ec;
  std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw InternalError("cannot find the bespoke executable: " + ec.message());
  return self;
}

pid_t SpawnWorker(const SpawnOptions& options) {
  BESPOKE_CHECK(!options.argv.empty(), "SpawnWorker without argv");
  // Everything the child needs is prepared before fork.
  std::vector<char*> argv;
  for (const std::string& a : options.argv) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const std::string executable = options.executable.string();
  const int log_fd =
      ::open(options.log_file.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log_fd < 0) {
    throw InternalError("cannot open worker log " + options.log_file.string() + ": " +
                        std::strerror(errno));
  }
  const int null_fd = ::open("/dev/null", O_RDONLY | O_CLOEXEC);
  const std::int64_t memory_mb = BuiltWithAddressSanitizer() ? 0 : options.memory_limit_mb;
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) ExecChild(parent, log_fd, null_fd, memory_mb, executable.c_str(), argv.data());
  const int fork_errno = errno;
  ::close(log_fd);
  if (null_fd >= 0) ::close(null_fd);
  if (pid < 0)
    throw InternalError(std::string("cannot fork a worker: ") + std::strerror(fork_errno));
  ::setpgid(pid, pid);  // also from the parent: no race with SignalWorker
  return pid;
}

std::optional<WorkerExit> TryReapWorker(pid_t pid) {
  int status = 0;
  struct rusage usage {};
  const pid_t r = ::wait4(pid, &status, WNOHANG, &usage);
  if (r == 0) return std::nullopt;
  if (r < 0) {
    if (errno == EINTR) return std::nullopt;
    throw InternalError("waiting for worker " + std::to_string(pid) + ": " + std::strerror(errno));
  }
  return FromStatus(status, usage);
}

WorkerExit ReapWorker(pid_t pid) {
  int status = 0;
  struct rusage usage {};
  pid_t r;
  do {
    r = ::wait4(pid, &status, 0, &usage);
  } while (r < 0 && errno == EINTR);
  if (r < 0)
    throw InternalError("waiting for worker " + std::to_string(pid) + ": " + std::strerror(errno));
  return FromStatus(status, usage);
}

void SignalWorker(pid_t pid, int signal) {
  if (::kill(-pid, signal) != 0) ::kill(pid, signal);
}

std::string DescribeSignal(int signal) {
  const char* abbrev = sigabbrev_np(signal);
  const char* text = sigdescr_np(signal);
  return std::string(abbrev ? std::string("SIG") + abbrev : "signal " + std::to_string(signal)) +
         (text ? std::string(" (") + text + ")" : std::string());
}

}  // namespace bespoke
