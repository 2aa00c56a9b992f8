// Runs one measured piece of a benchmark in a forked child process, so that
// its peak resident memory and CPU time are its own: other jobs on the
// machine inflate wall times much more than CPU times, and a child's peak
// memory is not the parent's high-water mark.
#ifndef BESPOKE_EVAL_BENCH_CHILD_RUN_H_
#define BESPOKE_EVAL_BENCH_CHILD_RUN_H_

#include <functional>
#include <vector>

namespace bespoke {

struct ChildUsage {
  bool ok = false;     // the child ran `work` to the end and sent every number
  double peak_mb = 0;  // its peak resident memory, MB
  double cpu_s = 0;    // its user + system CPU time, s
};

// Runs `work` in a child; returns the numbers it returned (through a pipe),
// or an empty vector when it failed (an exception is printed by the child,
// `usage->ok` is false). `usage` must not be null.
std::vector<double> RunInChild(const std::function<std::vector<double>()>& work, ChildUsage* usage);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_BENCH_CHILD_RUN_H_
