// `bespoke batch-merge`: one summary, failures table and report from the
// shards of a batch (run on several machines, e.g. as a Slurm job array).
//
// Reads the plans under each OUT_DIR (batch_plan.h): a sharded batch leaves
// shards/shard-I-of-N/plan.json; an unsharded one plan.json. When a folder
// has shard plans, those are used. Every shard 1..N must be present exactly
// once over all folders (else InputError naming the missing ones, unless
// allow_incomplete), scan ids must not repeat, and each scan's results are
// read from the folder its plan was found in. The merged results are written
// by the same code as an unsharded run's (batch_report.h), so summary.csv
// and failures.csv are byte-identical to those of `bespoke batch` over the
// same scans; the report lists every attempt of every shard (retries show).
#ifndef BESPOKE_PIPELINE_BATCH_BATCH_MERGE_H_
#define BESPOKE_PIPELINE_BATCH_BATCH_MERGE_H_

#include <filesystem>
#include <vector>

#include "pipeline/batch/batch_summary.h"

namespace bespoke {

struct MergeOptions {
  std::vector<std::filesystem::path> out_dirs;  // the batches' OUT_DIRs (>= 1)
  std::filesystem::path results_dir;            // "" (default) = the first OUT_DIR
  bool allow_incomplete = false;                // merge even with shards missing (default no)
  // Throws InputError when no folder is given or one does not exist.
  void Check() const;
};

struct MergeOutcome {
  BatchCounts counts;
  int shards = 0;          // plans merged
  int missing_shards = 0;  // with allow_incomplete
  std::filesystem::path results_dir;
  // As `bespoke batch`: 0 all ok, 1 only bad-input failures, 2 otherwise
  // (including missing shards).
  int ExitCode() const;
};

MergeOutcome MergeBatches(const MergeOptions& options);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_BATCH_MERGE_H_
