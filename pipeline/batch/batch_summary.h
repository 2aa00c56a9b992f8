// The tables a batch ends with, built from the scans' folders alone, so that
// a local run, a resumed run and a merge of shards produce the same bytes.
//
//   summary.csv   one row per planned scan, sorted by id: scan_id, status,
//                 failure_kind, the scan job's `results` (sorted by name),
//                 then one column per measurement "<name>_mm" (order of first
//                 appearance, scans taken in id order) and `flagged` (the
//                 measurements carrying quality flags, ';'-separated).
//                 Values only, no times: it is what resume/merge compare.
//   failures.csv  scan_id, input, kind, exit_code, signal, message.
//   timings.csv   scan_id, status, time_s, worker_wall_s, user_s, system_s,
//                 max_rss_mb, then "<step>_s" per step: everything that varies
//                 from run to run lives here, never in summary.csv.
// Numbers are printed with fixed precision (lengths 0.01 mm, times 0.001 s).
#ifndef BESPOKE_PIPELINE_BATCH_BATCH_SUMMARY_H_
#define BESPOKE_PIPELINE_BATCH_BATCH_SUMMARY_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pipeline/batch/done_record.h"
#include "pipeline/batch/scan_list.h"

namespace bespoke {

// The measurements document a scan job writes (docs/contracts.md schema).
inline constexpr const char* kMeasurementsFileName = "measurements.json";

// One planned scan and what its folder holds.
struct ScanOutcome {
  ScanEntry entry;
  std::filesystem::path folder;      // the scan's output folder
  std::optional<DoneRecord> record;  // nullopt: not processed (no valid done.json)
  std::string problem;               // why record is nullopt
  nlohmann::json measurements;       // measurements.json of an ok scan, else null

  bool ok() const { return record && record->status == "ok"; }
  // "" when ok; the failure kind, or "not_processed".
  std::string failure_kind() const;
  std::string failure_message() const;
};

// Reads every scan's folder (`out_dir`/<id>) for the `plan` (sorted by id).
std::vector<ScanOutcome> CollectOutcomes(const std::vector<ScanEntry>& plan,
                                         const std::filesystem::path& out_dir, bool verify_hashes);

std::string SummaryCsv(const std::vector<ScanOutcome>& outcomes);
std::string FailuresCsv(const std::vector<ScanOutcome>& outcomes);
std::string TimingsCsv(const std::vector<ScanOutcome>& outcomes);

struct BatchCounts {
  int planned = 0, ok = 0, failed = 0, not_processed = 0;
  int input_errors = 0;  // failures of kind input_error
  // 0 all ok; 1 every failure is bad input; 2 any other failure (crash,
  // time-out, out of memory, internal error) or a scan not processed.
  int ExitCode() const;
};
BatchCounts CountOutcomes(const std::vector<ScanOutcome>& outcomes);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_BATCH_SUMMARY_H_
