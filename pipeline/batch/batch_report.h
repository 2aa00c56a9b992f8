// The batch's end products in a results folder (OUT_DIR, or a shard's folder):
// summary.csv, failures.csv, timings.csv (batch_summary.h), report.html with
// its PNG plots in report/, and batch.json LAST (counts, exit code, files),
// which marks the results as complete.
//
// report.html: counts by status and failure kind, throughput (scans per
// minute over the attempts' wall time; per-scan time median/mean/max; peak
// memory), the attempts (every invocation, so Slurm retries and interrupted
// runs show), failures with reasons and a link to each worker log,
// distribution plots of the main measurements and of per-scan time
// (scanners/render/plot.h), and a table of every scan with links to its
// folder. The page is self-contained apart from the PNGs beside it.
#ifndef BESPOKE_PIPELINE_BATCH_BATCH_REPORT_H_
#define BESPOKE_PIPELINE_BATCH_BATCH_REPORT_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pipeline/batch/batch_summary.h"

namespace bespoke {

struct BatchResultsInput {
  std::string title;                                   // e.g. "batch of /data/scans"
  std::vector<ScanOutcome> outcomes;                   // sorted by id
  std::vector<nlohmann::json> attempts;                // ReadAttempts() of every output folder
  nlohmann::json settings = nlohmann::json::object();  // shown in the report and batch.json
};

// Writes everything listed above into `results_dir` (atomic files) and
// returns the counts. batch.json is removed first and written last.
BatchCounts WriteBatchResults(const std::filesystem::path& results_dir,
                              const BatchResultsInput& input);

// The HTML page alone; writes its PNGs into results_dir/report/. Exposed for tests.
std::string BatchReportHtml(const std::filesystem::path& results_dir,
                            const BatchResultsInput& input, const BatchCounts& counts);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_BATCH_REPORT_H_
