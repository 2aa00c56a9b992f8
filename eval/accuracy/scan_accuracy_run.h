// The accuracy run on real subjects behind `bespoke accuracy --scans DIR
// --reference REF.csv -o REPORT`: ISO 20685-1's own protocol, scan-derived
// values against values taken another way, and repeated scans for
// repeatability.
//
// 1. The reference table is read (reference_table.h; other systems' names
//    through name_map.h) and the scans of DIR matched to its subjects
//    (reference_compare.h). Problems of the whole input are an InputError
//    here, before anything is written: an unreadable table, no subject with
//    a scan, REPORT/scans holding an earlier run without `resume`.
// 2. The matched scans are measured by the batch runner (pipeline/batch:
//    each scan is `bespoke run` in its own worker process, `jobs` at once,
//    with time and memory limits) into REPORT/scans/: a folder per scan,
//    the batch's summary.csv (every scan's values), failures and report.
//    `resume` continues an interrupted run there: finished scans are kept
//    (failed ones too, unless `retry_failed`), the others redone.
// 3. The values are compared with the reference (reference_compare.h) into
//    the report, ready for WriteAccuracyReport.
#ifndef BESPOKE_EVAL_ACCURACY_SCAN_ACCURACY_RUN_H_
#define BESPOKE_EVAL_ACCURACY_SCAN_ACCURACY_RUN_H_

#include <cstdint>
#include <filesystem>
#include <string>

#include "eval/accuracy/accuracy_report.h"
#include "scanners/core/progress.h"

namespace bespoke {

struct ScanAccuracyOptions {
  std::filesystem::path scans_dir;   // required: the folder of scans (not searched recursively)
  std::filesystem::path reference;   // required: REF.csv (reference_table.h)
  std::string names;                 // "" (default) = catalogue names only; "valentina",
                                     // "freesewing" or a name map file (name_map.h)
  std::string method;                // rows of this method only; "" (default) = the only one
  std::filesystem::path report_dir;  // required: the report folder; scans measured into scans/
  int jobs = 0;                      // scans measured at once; 0 (default) = the CPUs
  bool resume = false;               // continue the run in report_dir/scans (default no)
  bool retry_failed = false;         // with resume: measure failed scans again (default no)
  std::string units;                 // unit of the scan files: "" (default) = guess; mm cm dm m
  double timeout_s = 600;            // wall-time limit per scan, s; 0 = none (default 600)
  std::int64_t memory_mb = 4096;     // address-space limit per worker, MB; 0 = none (default 4096)
  std::filesystem::path worker;      // program run per scan; "" (default) = this bespoke binary
  void Check() const;                // InputError naming the option
};

struct ScanAccuracyOutcome {
  AccuracyReport report;     // complete unless interrupted
  int scans = 0;             // scans matched to a subject
  bool interrupted = false;  // the batch was interrupted (no report)
  int signal = 0;            // the signal that interrupted it
};

ScanAccuracyOutcome RunScanAccuracy(const ScanAccuracyOptions& options, Progress* progress);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_SCAN_ACCURACY_RUN_H_
