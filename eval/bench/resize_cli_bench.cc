// Benchmark of `bespoke resize` end to end, as a user runs it: the command
// is started as a process (read the pattern and measurements, fit, write
// fitted.json/.svg/.dxf, report.json/.txt, pareto_front.csv and the two
// pictures) and timed from start to exit, wall and CPU (user + system of
// the process and all its threads). Each case runs with all CPUs and,
// as the reference in the same run, with `--threads 1`; each is the best
// wall time of --repeats runs (the machine is shared: the CPU time is the
// steadier figure). The load average is printed before and after.
//
//   resize_cli_bench [--bespoke build/bespoke] [--shared ../shared]
//                    [--population 400] [--generations 200] [--repeats 3]
//                    [--compare OTHER/bespoke]
//
// --compare adds, in the same run, another build's `bespoke` (e.g. the
// previous commit's) with all CPUs on the same cases.
//
// Cases: Valentina's men's shirt (the standard-size DXF with
// eval/resize/data/maleshirt.sidecar.json, fitted to MaleShirt_big.vit;
// skipped with a message when ../shared is absent) and the built-in shirt
// and trousers fitted to body A of resize/designs/body_variants.h.
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "eval/bench/bench_main.h"
#include "resize/designs/body_variants.h"
#include "resize/pattern/measurements.h"
#include "scanners/core/errors.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;

struct Timing {
  double wall_s = 0;
  double cpu_s = 0;
};

// Runs `args` (args[0] the program) to its end: wall and CPU time.
// InternalError when it cannot start or exits non-zero.
Timing RunProcess(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  if (posix_spawn(&pid, argv[0], nullptr, nullptr, argv.data(), environ) != 0)
    throw bespoke::InternalError("cannot start " + args[0]);
  int status = 0;
  rusage usage{};
  if (wait4(pid, &status, 0, &usage) != pid)
    throw bespoke::InternalError("lost the child " + args[0]);
  Timing t;
  t.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  auto seconds = [](const timeval& tv) { return tv.tv_sec + 1e-6 * tv.tv_usec; };
  t.cpu_s = seconds(usage.ru_utime) + seconds(usage.ru_stime);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string line;
    for (const std::string& a : args) line += " " + a;
    throw bespoke::InternalError("failed (status " + std::to_string(status) + "):" + line);
  }
  return t;
}

// The best (least wall) of `repeats` runs.
Timing Best(const std::vector<std::string>& args, int repeats) {
  Timing best;
  for (int r = 0; r < repeats; ++r) {
    const Timing t = RunProcess(args);
    if (r == 0 || t.wall_s < best.wall_s) best = t;
  }
  return best;
}

std::string Fixed(double v) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", v);
  return text;
}

struct Case {
  std::string name;
  std::vector<std::string> input;  // the pattern and measurement arguments
};

std::vector<Case> Cases(const fs::path& shared, const fs::path& scratch) {
  std::vector<Case> cases;
  const fs::path v = shared / "data/patterns/valentina";
  const fs::path sidecar = fs::path(BESPOKE_SOURCE_DIR) / "eval/resize/data/maleshirt.sidecar.json";
  if (fs::exists(v / "maleshirt_std_AAMA_R12.dxf")) {
    cases.push_back({"Valentina men's shirt (17 pieces)",
                     {"--pattern", (v / "maleshirt_std_AAMA_R12.dxf").string(), "--sidecar",
                      sidecar.string(), "--measurements", (v / "MaleShirt_big.vit").string()}});
  } else {
    std::printf("skipped: Valentina men's shirt (%s not found; give --shared)\n",
                (v / "maleshirt_std_AAMA_R12.dxf").string().c_str());
  }
  for (const std::string design : {"shirt", "trousers"}) {
    const fs::path body = scratch / (design + "_A.json");
    std::ofstream(body)
        << bespoke::MeasurementsToJson(bespoke::VariedMeasurements(design, 1)).dump(1);
    cases.push_back(
        {"built-in " + design + ", body A", {"--design", design, "--measurements", body.string()}});
  }
  return cases;
}

int Main(int argc, char** argv) {
  std::string bespoke = BESPOKE_BINARY, shared = BESPOKE_DEFAULT_SHARED_DIR, compare;
  std::string population = "400", generations = "200";
  int repeats = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i], value = argv[i + 1];
    if (key == "--bespoke")
      bespoke = value;
    else if (key == "--shared")
      shared = value;
    else if (key == "--population")
      population = value;
    else if (key == "--generations")
      generations = value;
    else if (key == "--repeats")
      repeats = std::stoi(value);
    else if (key == "--compare")
      compare = value;
    else
      throw bespoke::InputError("unknown option " + key);
  }
  if (repeats < 1) throw bespoke::InputError("--repeats must be >= 1");
  const fs::path scratch =
      fs::temp_directory_path() / ("resize_cli_bench." + std::to_string(getpid()));
  fs::create_directories(scratch);
  bespoke::PrintLoadAverage("at start");
  std::printf("%s resize, population %s, generations %s, best of %d run(s)\n\n", bespoke.c_str(),
              population.c_str(), generations.c_str(), repeats);
  if (!compare.empty()) std::printf("compared with %s (all CPUs)\n", compare.c_str());
  std::printf(
      "| case | wall s | CPU s | 1-thread wall s | 1-thread CPU s | speed-up (wall) | "
      "<= 3 s | compared wall s | compared CPU s |\n|---|---|---|---|---|---|---|---|---|\n");
  for (const Case& c : Cases(shared, scratch)) {
    std::vector<std::string> args = {bespoke, "--quiet", "resize"};
    args.insert(args.end(), c.input.begin(), c.input.end());
    for (const std::string& a :
         {std::string("--population"), population, std::string("--generations"), generations,
          std::string("-o"), (scratch / "out").string()})
      args.push_back(a);
    std::string other = "- | -";
    if (!compare.empty()) {
      std::vector<std::string> other_args = args;
      other_args[0] = compare;
      const Timing t = Best(other_args, repeats);
      other = Fixed(t.wall_s) + " | " + Fixed(t.cpu_s);
    }
    const Timing all = Best(args, repeats);
    args.insert(args.end(), {"--threads", "1"});
    const Timing one = Best(args, repeats);
    std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.2f | %s | %s |\n", c.name.c_str(), all.wall_s,
                all.cpu_s, one.wall_s, one.cpu_s, one.wall_s / all.wall_s,
                all.wall_s <= 3.0 ? "yes" : "no", other.c_str());
    std::fflush(stdout);
  }
  std::printf("\n");
  bespoke::PrintLoadAverage("at end");
  fs::remove_all(scratch);
  return 0;
}

}  // namespace

// Errors end the run with a message and an exit code (1 bad input, 2 other).
int main(int argc, char** argv) {
  return bespoke::RunBenchMain("resize_cli_bench", Main, argc, argv);
}
