// The `main` of the benchmark and evidence tools under eval/bench: runs
// `run(argc, argv)` and turns errors into a message on stderr naming the tool
// and an exit code, never an abort: InputError (bad options or input files)
// -> 1, any other exception -> 2 ("internal error"). Otherwise run's result.
#ifndef BESPOKE_EVAL_BENCH_BENCH_MAIN_H_
#define BESPOKE_EVAL_BENCH_BENCH_MAIN_H_

#include <cstdio>
#include <cstdlib>
#include <exception>

#include "scanners/core/errors.h"

namespace bespoke {

inline int RunBenchMain(const char* tool, int (*run)(int, char**), int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s: %s\n", tool, e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", tool, e.what());
    return 2;
  }
}

// Prints the machine's load average ("load average WHEN: 1-, 5- and
// 15-minute figures"), which every timing table is read against on a
// shared machine; nothing when the system does not give it.
inline void PrintLoadAverage(const char* when) {
  double load[3] = {0, 0, 0};
  if (getloadavg(load, 3) == 3)
    std::printf("load average %s: %.2f (1 min), %.2f (5 min), %.2f (15 min)\n", when, load[0],
                load[1], load[2]);
}

}  // namespace bespoke

#endif  // BESPOKE_EVAL_BENCH_BENCH_MAIN_H_
