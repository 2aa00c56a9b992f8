// `bespoke run SCAN -o OUT_DIR [--design shirt|trousers] [--units U]
//  [--landmarks OVERRIDE.json]`: the whole job for one scan (read, clean,
// measure, resize) into one folder, done.json last (pipeline/batch/scan_job.h).
// This is also what each worker of `bespoke batch` runs.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "pipeline/batch/scan_job.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"

namespace bespoke {

CommandRunner SetupRunCommand(CLI::App& app) {
  struct Args {
    std::filesystem::path scan;
    std::filesystem::path out_dir;
    ScanJobOptions job;
  };
  auto args = std::make_shared<Args>();
  app.add_option("SCAN", args->scan, "The scan (.ply .pcd .obj .xyz .csv .txt)")->required();
  app.add_option("-o,--out", args->out_dir, "Output folder (created; done.json is written last)")
      ->required();
  app.add_option("--design", args->job.design,
                 "Also fit a pattern: shirt or trousers (default: none)");
  app.add_option("--units", args->job.units,
                 "The scan file's length unit: mm, cm, dm or m (default: guessed from its size)");
  app.add_option(
      "--landmarks", args->job.landmarks,
      "Landmark override file (JSON name -> [x, y, z]; a measurement or truth document works too)");
  app.add_option("--threads", args->job.threads,
                 "Threads for the parallel stages (default 0 = all CPUs)");
  app.add_option("--scan-id", args->job.scan_id, "Id recorded in done.json (default: file stem)")
      ->group("");  // set by `bespoke batch`
  return [args](const GlobalOptions& global) {
    ProgressBar bar(global.quiet);
    const DoneRecord record = RunScanJob(args->job, args->scan, args->out_dir, &bar);
    for (const auto& step : record.steps) {
      if (step.contains("skipped")) {
        spdlog::info("  {:8} skipped: {}", step.value("name", ""), step.value("skipped", ""));
      } else {
        spdlog::info("  {:8} {:.2f} s", step.value("name", ""), step.value("time_s", 0.0));
      }
    }
    if (!global.quiet) {
      std::cout << "wrote " << record.outputs.size() << " file(s) and done.json to "
                << args->out_dir.string() << " in " << record.time_s << " s\n";
      for (const OutputFile& f : record.outputs) {
        std::cout << "  " << f.file << " (" << f.size_bytes << " bytes)\n";
      }
    }
    return 0;
  };
}

}  // namespace bespoke
