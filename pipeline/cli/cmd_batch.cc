// `bespoke batch INPUT_DIR|MANIFEST.csv -o OUT_DIR [--jobs N] [--design D]
//  [--resume] [--shard I/N] [--timeout-s 600] [--memory-mb 4096]`: every scan
// through `bespoke run` in its own worker process (pipeline/batch/batch.h).
// Exit code: 0 all scans ok, 1 some failed on bad input, 2 some failed
// otherwise (crash, time-out, memory, internal) or the batch itself failed,
// 128 + signal when interrupted (130 for Ctrl-C).
#include <CLI/CLI.hpp>
#include <memory>

#include "pipeline/batch/batch.h"
#include "pipeline/cli/commands.h"
#include "pipeline/cli/progress_bar.h"

namespace bespoke {

CommandRunner SetupBatchCommand(CLI::App& app) {
  struct Args {
    BatchOptions batch;
    std::string shard = "1/1";
  };
  auto args = std::make_shared<Args>();
  BatchOptions& b = args->batch;
  app.add_option("INPUT", b.input,
                 "A folder of scans (.ply .pcd .obj .xyz .csv .txt), or a manifest CSV with the "
                 "columns id,path[,design,units,landmarks]")
      ->required();
  app.add_option("-o,--out", b.out_dir, "Output folder: one sub-folder per scan, summary, report")
      ->required();
  app.add_option("-j,--jobs", b.jobs, "Scans at once (default 0 = all CPUs)");
  app.add_option("--design", b.design, "Fit this pattern to every scan: shirt or trousers");
  app.add_option("--units", b.units,
                 "Length unit of the scan files: mm, cm, dm, m (default: guess)");
  app.add_flag("--resume", b.resume,
               "Continue a batch in OUT_DIR: skip finished scans, redo partial ones");
  app.add_flag("--retry-failed", b.retry_failed, "With --resume: also redo scans that failed");
  app.add_flag("--recursive", b.recursive, "Also look for scans in sub-folders of INPUT");
  app.add_option("--shard", args->shard,
                 "Run only shard I of N of the sorted scan list (e.g. 2/4)");
  app.add_option("--timeout-s", b.timeout_s, "Wall-time limit per scan in seconds (0 = none)")
      ->capture_default_str();
  app.add_option("--memory-mb", b.memory_mb, "Address-space limit per worker in MB (0 = none)")
      ->capture_default_str();
  app.add_option("--worker", b.worker, "Program run per scan instead of bespoke (tests)")
      ->group("");
  app.add_option("--label", b.label, "Label of this attempt in the report")->group("");
  return [args](const GlobalOptions& global) {
    args->batch.shard = ParseShard(args->shard);
    ProgressBar bar(global.quiet);
    return RunBatch(args->batch, &bar).ExitCode();
  };
}

}  // namespace bespoke
