// `bespoke batch-merge OUT_DIR... [-o RESULTS_DIR] [--allow-incomplete]`:
// the summary, failures and report of a sharded batch (e.g. a Slurm job
// array), identical to an unsharded run's (pipeline/batch/batch_merge.h).
// Exit code as `bespoke batch`.
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "pipeline/batch/batch_merge.h"
#include "pipeline/cli/commands.h"

namespace bespoke {

CommandRunner SetupBatchMergeCommand(CLI::App& app) {
  auto options = std::make_shared<MergeOptions>();
  app.add_option("OUT_DIR", options->out_dirs,
                 "Output folders of the shards (or one shared folder)")
      ->required();
  app.add_option("-o,--out", options->results_dir,
                 "Where the merged summary and report go (default: the first OUT_DIR)");
  app.add_flag("--allow-incomplete", options->allow_incomplete,
               "Merge even when some shards have not run (exit code 2)");
  return [options](const GlobalOptions&) {
    const MergeOutcome outcome = MergeBatches(*options);
    spdlog::info("merged {} shard(s): {} ok, {} failed, {} not processed; results in {}",
                 outcome.shards, outcome.counts.ok, outcome.counts.failed,
                 outcome.counts.not_processed, outcome.results_dir.string());
    return outcome.ExitCode();
  };
}

}  // namespace bespoke
