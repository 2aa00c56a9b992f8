#include "eval/bench/child_run.h"

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <exception>

namespace bespoke {

namespace {

// The child's side: runs `work` and writes the count, then the numbers.
[[noreturn]] void ChildMain(const std::function<std::vector<double>()>& work, int fd) {
  std::vector<double> out;
  try {
    out = work();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "  run failed: %s\n", e.what());
    _exit(1);
  }
  const size_t n = out.size();
  if (write(fd, &n, sizeof n) != sizeof n) _exit(2);
  const char* p = reinterpret_cast<const char*>(out.data());
  for (size_t left = n * sizeof(double); left > 0;) {
    const ssize_t w = write(fd, p, left);
    if (w <= 0) _exit(2);
    p += w;
    left -= static_cast<size_t>(w);
  }
  _exit(0);
}

// The parent's side: reads what ChildMain wrote; empty on a short read.
std::vector<double> ReadNumbers(int fd) {
  size_t n = 0;
  std::vector<double> out;
  if (read(fd, &n, sizeof n) != sizeof n) return out;
  out.resize(n);
  char* p = reinterpret_cast<char*>(out.data());
  for (size_t left = n * sizeof(double); left > 0;) {
    const ssize_t r = read(fd, p, left);
    if (r <= 0) return {};
    p += r;
    left -= static_cast<size_t>(r);
  }
  return out;
}

}  // namespace

std::vector<double> RunInChild(const std::function<std::vector<double>()>& work,
                               ChildUsage* usage) {
  *usage = ChildUsage();
  int fds[2];
  if (pipe(fds) != 0) return {};
  std::fflush(stdout);  // the child must not print the parent's buffered output again
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    return {};
  }
  if (pid == 0) {
    close(fds[0]);
    ChildMain(work, fds[1]);
  }
  close(fds[1]);
  std::vector<double> out = ReadNumbers(fds[0]);
  close(fds[0]);
  int status = 0;
  struct rusage resources {};
  wait4(pid, &status, 0, &resources);
  usage->peak_mb = static_cast<double>(resources.ru_maxrss) / 1024.0;
  usage->cpu_s =
      static_cast<double>(resources.ru_utime.tv_sec + resources.ru_stime.tv_sec) +
      1e-6 * static_cast<double>(resources.ru_utime.tv_usec + resources.ru_stime.tv_usec);
  usage->ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (!usage->ok) out.clear();
  return out;
}

}  // namespace bespoke
