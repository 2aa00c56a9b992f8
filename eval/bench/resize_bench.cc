// Benchmark of `bespoke resize` at the thesis budget (population 400, 200
// generations) on the built-in designs, reported as thesis Table 4.2 does:
// the objective values of the final answer (and of the GA's pick before the
// polish) and the running time. The same run with one thread is the
// reference the parallel run is compared with (ratio).
//
//   build-resize/eval/bench/resize_bench [--population 400] [--generations 200]
//                                           [--bodies 4] [--seed 1]
// Bodies: far-from-standard measurement sets (resize/designs/body_variants.h),
// like the thesis's four characters A-D.
#include <tbb/global_control.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

#include "eval/bench/bench_main.h"
#include "resize/designs/body_variants.h"
#include "resize/designs/designs.h"
#include "resize/ga/resize.h"
#include "scanners/core/errors.h"

namespace {

struct Run {
  bespoke::ResizeResult result;
  double wall_s = 0;
  double cpu_s = 0;  // process CPU time (all threads)
};

Run Time(const bespoke::ResizeOptions& o, const bespoke::Pattern& p,
         const bespoke::MeasurementSet& body) {
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  Run run{bespoke::ResizePattern(o, p, body, nullptr), 0, 0};
  run.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  run.cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  return run;
}

}  // namespace

namespace {
int Main(int argc, char** argv) {
  bespoke::ResizeOptions options;
  int bodies = 4;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--population"))
      options.population = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--generations"))
      options.generations = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--bodies"))
      bodies = std::stoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--seed"))
      options.seed = std::stoull(argv[i + 1]);
  }
  bespoke::PrintLoadAverage("at start");
  std::printf("population %d, generations %d, hardware threads %d\n\n", options.population,
              options.generations,
              static_cast<int>(
                  tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism)));
  std::printf(
      "| design | body | measurement (Eq 4.5, mm) | seam (Eq 4.8) | shape (deg) | "
      "GA pick: meas / seam / shape | GA s | polish s | wall s | CPU s | 1-thread wall s | "
      "speed-up |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& design : bespoke::DesignNames()) {
    const bespoke::Pattern base = bespoke::DraftDesign(design, bespoke::BaseMeasurements(design));
    for (int b = 1; b <= bodies; ++b) {
      const bespoke::MeasurementSet body = bespoke::VariedMeasurements(design, b);
      const Run parallel = Time(options, base, body);
      Run serial;
      {
        tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
        serial = Time(options, base, body);
      }
      const auto& f = parallel.result.objectives;
      const auto& g = parallel.result.ga_objectives;
      std::printf(
          "| %s | %c | %.4f | %.3f | %.3f | %.2f / %.2f / %.2f | %.2f | %.2f | %.2f | %.2f | %.2f "
          "| %.2f |\n",
          design.c_str(), 'A' + b - 1, f.measurement_mm, f.seam, f.shape_deg, g.measurement_mm,
          g.seam, g.shape_deg, parallel.result.ga_time_s, parallel.result.polish_time_s,
          parallel.wall_s, parallel.cpu_s, serial.wall_s, serial.wall_s / parallel.wall_s);
      std::fflush(stdout);
    }
  }
  return 0;
}
}  // namespace

// Errors end the run with a message and an exit code (1 bad input, 2 other).
int main(int argc, char** argv) { return bespoke::RunBenchMain("resize_bench", Main, argc, argv); }
