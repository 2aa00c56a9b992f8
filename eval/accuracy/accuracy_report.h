// Writes an accuracy report into a folder: a page for people and tables for
// programs. One writer for both kinds of report: against the oracle's exact
// truth (reference_label "truth") and against measurements taken another way
// on real subjects ("reference": a tape, another scanner). Every file is
// written atomically (scanners/core/atomic_file.h).
//   index.html          summary, targets, ISO 20685-1 table, repeatability,
//                       landmark table, posture table(s), failures, measurements
//                       not compared, names mapped, settings; links the plots
//   summary.csv         per measurement: class, tolerance, n, bias, SD,
//                       95 % CI of the mean, limits of agreement, MAE,
//                       max |error|, verdict
//   measurements.csv    per subject x measurement: truth (or reference),
//                       measured, difference, flags
//   landmarks.csv       per landmark: n, missing, median / mean / max error
//   landmark_errors.csv per subject x landmark: error and both points
//   posture.csv         the posture test: per pair x measurement both
//                       postures' values, difference, limit, verdict, truths;
//                       else the A/T pair: per measurement both poses
//   repeatability.csv   (with repeated scans) per measurement: within-subject
//                       SD and repeatability coefficient
//   not_compared.csv    (when any) reference rows, subjects and scans left out, with the reason
//   report.json         settings, headline figures, verdicts, failures,
//                       repeatability, what was not compared
//   plots/*.png         error distributions per ISO class (strip charts with the
//                       95 % CI and tolerance), per measurement a histogram and a
//                       Bland-Altman plot (difference against the mean of both
//                       values, bias and limits of agreement), landmark errors,
//                       the posture differences
// Numbers in mm with 0.01 mm precision in CSV; empty cells for missing values.
// Failure: InputError when `dir` cannot be created; InternalError on a failed write.
#ifndef BESPOKE_EVAL_ACCURACY_ACCURACY_REPORT_H_
#define BESPOKE_EVAL_ACCURACY_ACCURACY_REPORT_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "eval/accuracy/accuracy_stats.h"
#include "eval/accuracy/accuracy_summary.h"
#include "eval/accuracy/compare.h"
#include "eval/accuracy/posture.h"

namespace bespoke {

struct SubjectFailure {
  std::string subject;
  std::string stage;  // e.g. "body", "truth", "scan", "clean", "landmarks", "measure", "compare"
  std::string error;  // the error's message
};

// The project's targets, shown beside the measured figures (never used to tune anything).
struct AccuracyTargets {
  double large_girth_mae_mm = 5;        // MAE of large girths <= 5 mm
  double median_landmark_error_mm = 8;  // median landmark error <= 8 mm
};

// Something of the input that was left out of the comparison, and why.
struct NotCompared {
  std::string subject;      // "" when not about one subject
  std::string measurement;  // as written in the input; "" when not about one measurement
  std::string where;        // e.g. "REF.csv line 12", "scan anna_3.ply"
  std::string reason;       // e.g. "value 'abc' is not a number"
};

// A name of another system read through the name map.
struct MappedName {
  std::string their_name;   // as in the name map
  std::string measurement;  // catalogue name
  std::string note;         // how the definitions differ; "" when they agree
  int rows = 0;             // reference rows that used it
};

// Repeated measurements of the same subjects (several scans each).
struct RepeatabilityRow {
  std::string name;  // catalogue measurement
  RepeatabilityStats stats;
};

struct AccuracyReport {
  std::string title = "Bespoke accuracy report";
  std::string created_utc;  // ISO 8601 UTC time the report was made
  // What the measured values are compared with: "truth" (the oracle's exact
  // values) or "reference" (measured another way on real subjects).
  std::string reference_label = "truth";
  nlohmann::json settings;  // how the report was made (command line options, versions)
  std::vector<SubjectComparison> subjects;  // compared subjects
  std::vector<SubjectFailure> failures;     // subjects (or scans) that could not be measured
  AccuracySummary summary;
  AccuracyTargets targets;
  std::optional<PostureComparison> posture;      // the parametric A/T pair
  std::vector<PostureComparison> posture_pairs;  // the posture test: subject x posture
  std::vector<RepeatabilityRow> repeatability;   // measurements with repeated scans
  std::vector<NotCompared> not_compared;         // input left out, with the reason
  std::vector<MappedName> mapped_names;          // other systems' names that were used
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
