// Real subjects: scans matched to the subjects of a reference table, and the
// measured values compared with the reference into an accuracy report.
//
// Matching (MatchScans): the scan SUBJECT.<ext> and the scans SUBJECT_<k>.<ext>
// (k digits: repeated scans) belong to SUBJECT; a scan whose whole name is a
// subject belongs to it first (subject "anna_2" takes anna_2.ply). A scan of
// no subject and a subject without a scan are listed as not compared.
//
// Comparison (CompareWithReference): per subject and measurement the
// measured value is the mean over the subjects' scans that gave one (one
// value per subject keeps the subjects independent, as the ISO 20685-1
// confidence interval assumes; with one scan it is that scan's value), with
// the quality flags of every scan. Subjects with two or more values of a
// measurement give its repeatability (accuracy_stats.h). A subject none of
// whose scans could be measured is a failure, with each scan's reason; a
// failed scan of a subject with other, measured scans is listed as not
// compared. Measured documents are those of docs/contracts.md.
#ifndef BESPOKE_EVAL_ACCURACY_REFERENCE_COMPARE_H_
#define BESPOKE_EVAL_ACCURACY_REFERENCE_COMPARE_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "eval/accuracy/accuracy_report.h"
#include "eval/accuracy/reference_table.h"
#include "pipeline/batch/scan_list.h"

namespace bespoke {

struct SubjectScan {
  std::string subject;
  ScanEntry scan;  // id (its results folder) and path
};

struct ScanMatch {
  std::vector<SubjectScan> scans;         // subject order of `subjects`, then file name
  std::vector<NotCompared> not_compared;  // scans of no subject, subjects without a scan
};

// `subjects`: the reference table's subjects; `scans`: DiscoverScans of the folder.
ScanMatch MatchScans(const std::vector<std::string>& subjects, const std::vector<ScanEntry>& scans);

// One scan's result.
struct ScanMeasurement {
  std::string subject;
  std::string scan;             // file name, e.g. "anna_2.ply"
  nlohmann::json measurements;  // its measurement document; null when it failed
  std::string failure_kind;     // e.g. "input_error"; "" when measured
  std::string failure_message;  // why it failed
};

// The report (reference_label "reference"): subjects compared in the
// reference table's subject order, summary, repeatability, failures, and the
// table's rows left out followed by the failed scans of measured subjects.
AccuracyReport CompareWithReference(const ReferenceTable& reference,
                                    const std::vector<ScanMeasurement>& scans,
                                    const Catalogue& catalogue);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_REFERENCE_COMPARE_H_
