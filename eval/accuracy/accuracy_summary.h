// The accuracy of many subjects at once: per measurement the error
// statistics over the subjects (accuracy_stats.h) and the ISO 20685-1
// verdict (iso_20685.h); per landmark the error statistics (compare.h); and the
// headline figures the report sets targets for (every measurement passes,
// MAE of the large girths, median landmark error).
//
// Input: the per-subject comparisons (compare.h) of the subjects that ran,
// and the catalogue (for kinds and ISO classes). A measurement unknown to
// the catalogue is classed by its kind alone (girth -> small girth, length ->
// segment length). Missing values are counted, not averaged in; measured
// values carrying quality flags are included and counted.
#ifndef BESPOKE_EVAL_ACCURACY_ACCURACY_SUMMARY_H_
#define BESPOKE_EVAL_ACCURACY_ACCURACY_SUMMARY_H_

#include <string>
#include <vector>

#include "eval/accuracy/accuracy_stats.h"
#include "eval/accuracy/compare.h"
#include "eval/accuracy/iso_20685.h"
#include "measure/catalogue/catalogue.h"

namespace bespoke {

struct MeasurementSummary {
  std::string name;
  std::string kind;  // "girth", "length", "height"
  IsoClass iso_class = IsoClass::kSegmentLength;
  double tolerance_mm = 0;  // ISO 20685-1 maximum allowable error of the class
  ErrorStats stats;         // over the subjects with a value
  int missing = 0;          // subjects whose measurement had no value
  int flagged = 0;          // subjects whose measured value carried quality flags
  int truth_flagged = 0;    // subjects whose truth value carried flags
  IsoVerdict verdict = IsoVerdict::kNotJudged;
  std::vector<double> differences_mm;  // the values summarised, subject order
  std::vector<double> means_mm;  // (measured + reference) / 2 of the same subjects (Bland-Altman x)
};

struct LandmarkSummary {
  std::string name;
  int n = 0, missing = 0;
  double median_mm = 0, mean_mm = 0, max_mm = 0;  // of the error (compare.h); NaN when n = 0
};

struct AccuracySummary {
  int subjects = 0;                              // compared
  std::vector<MeasurementSummary> measurements;  // catalogue order, then unknown names
  std::vector<LandmarkSummary> landmarks;        // catalogue order, then unknown names
  int passed = 0, failed = 0, not_judged = 0;    // ISO 20685-1 verdicts
  double large_girth_mae_mm = 0;  // mean |difference| over every large-girth value; NaN if none
  double median_landmark_error_mm =
      0;                       // median over every landmark error of every subject; NaN if none
  std::string landmark_frame;  // "scanner", "body" or "mixed"
};

AccuracySummary SummarizeAccuracy(const std::vector<SubjectComparison>& subjects,
                                  const Catalogue& catalogue);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_ACCURACY_SUMMARY_H_
