// Writes an accuracy report into a folder: a page for people and tables for
// programs. Every file is written atomically (scanners/core/atomic_file.h).
//   index.html          summary, targets, ISO 20685-1 table, landmark table,
//                       posture table, failures, settings; links the plots
//   summary.csv         per measurement: class, tolerance, n, bias, SD,
//                       95 % CI of the mean, MAE, max |error|, verdict
//   measurements.csv    per subject x measurement: truth, measured, difference, flags
//   landmarks.csv       per landmark: n, missing, median / mean / max error
//   landmark_errors.csv per subject x landmark: error and both points
//   posture.csv         (with a posture comparison) per measurement: both poses
//   report.json         settings, headline figures, verdicts, failures
//   plots/*.png         error distributions per ISO class (strip charts with the
//                       95 % CI and tolerance), a histogram per measurement,
//                       landmark errors, the posture differences
// Numbers in mm with 0.01 mm precision in CSV; empty cells for missing values.
// Failure: InputError when `dir` cannot be created; InternalError on a failed write.
#ifndef BESPOKE_EVAL_ACCURACY_ACCURACY_REPORT_H_
#define BESPOKE_EVAL_ACCURACY_ACCURACY_REPORT_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "eval/accuracy/accuracy_summary.h"
#include "eval/accuracy/compare.h"
#include "eval/accuracy/posture.h"

namespace bespoke {

struct SubjectFailure {
  std::string subject;
  std::string stage;  // e.g. "body", "truth", "scan", "clean", "landmarks", "measure", "compare"
  std::string error;  // the error's message
};

// The targets, shown beside the measured figures (never used to tune anything).
struct AccuracyTargets {
  double large_girth_mae_mm = 5;         // MAE of large girths <= 5 mm
  double median_landmark_error_mm = 10;  // median landmark error <= 10 mm
};

struct AccuracyReport {
  std::string title = "Bespoke accuracy report";
  std::string created_utc;  // e.g. "2026-11-22T08:00:00Z"
  nlohmann::json settings;  // how the report was made (command line options, versions)
  std::vector<SubjectComparison> subjects;  // compared subjects
  std::vector<SubjectFailure> failures;     // subjects that could not be compared
  AccuracySummary summary;
  AccuracyTargets targets;
  std::optional<PostureComparison> posture;
};

void WriteAccuracyReport(const AccuracyReport& report, const std::filesystem::path& dir);

// The plots of the report into dir/plots; returns the file names written,
// relative to `dir` ("plots/errors_large_girth.png", ...). Used by
// WriteAccuracyReport; exposed for tests.
std::vector<std::string> WriteAccuracyPlots(const AccuracyReport& report,
                                            const std::filesystem::path& dir);

// The page (index.html) for `plots` as returned by WriteAccuracyPlots.
std::string AccuracyHtml(const AccuracyReport& report, const std::vector<std::string>& plots);

// "12.35", or "" for NaN/inf (CSV cells); `digits` after the point.
std::string FormatNumber(double value, int digits = 2);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_ACCURACY_REPORT_H_
