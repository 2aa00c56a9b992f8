// The posture comparison: one body measured in two postures, the second's
// measurements judged against the first's. Two rules:
//  - kLengths (the parametric A/T test: arm abduction 30 and 90 deg):
//    lengths measured along the surface should not depend on the pose (the
//    thesis's Fig 3.1 argument for geodesic lengths), so every measurement of
//    kind "length" of pose B must lie within `tolerance_mm` of pose A's;
//  - kLengthsAndGirths (the posture target): every length along the surface
//    (ISO 20685-1 class segment_length) within `tolerance_mm`, every girth
//    within its ISO 20685-1 class limit (eval/accuracy/iso_20685.h: 4 mm
//    small, 9 mm large); heights and the straight breadths (shoulder width,
//    sleeve top) are shown, not judged, as are names the catalogue lacks.
// A judged value that one posture lacks fails.
//
// Input: the measurement documents of both postures (docs/contracts.md) and,
// optionally (null json = none), both truth documents, shown beside so the
// reader sees how much the body itself changed between the postures.
// Output: one row per measurement of the truth A (when given) and of either
// measured document. Failure: InputError for a document without a
// "measurements" array or a tolerance that is not positive.
//
// SummarizePostures folds many such pairs (subjects x postures, each against
// the same subject's reference posture) into per-posture and per-measurement
// tables.
#ifndef BESPOKE_EVAL_ACCURACY_POSTURE_H_
#define BESPOKE_EVAL_ACCURACY_POSTURE_H_

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace bespoke {

enum class PostureRule { kLengths, kLengthsAndGirths };

struct PostureRow {
  std::string name;
  std::string kind;
  std::string iso_class;                        // ISO 20685-1 class; "" when not in the catalogue
  double measured_a_mm = 0, measured_b_mm = 0;  // NaN when that pose lacks a value
  double truth_a_mm = 0, truth_b_mm = 0;        // NaN when not given
  double difference_mm = 0;  // measured_b - measured_a; NaN when either is missing
  double limit_mm = 0;       // |difference| allowed when judged; NaN when not judged
  bool judged = false;       // the rule judges this row
  bool pass = false;         // judged and |difference| <= limit
};

struct PostureComparison {
  std::string subject;                               // whose body (reporting only)
  std::string pose_a = "A-pose", pose_b = "T-pose";  // labels (posture names for the target)
  double arm_a_deg = 0, arm_b_deg = 0;               // arm abduction of each pose (reporting only)
  double tolerance_mm = 5;                           // default 5 mm: |B - A| allowed per length
  PostureRule rule = PostureRule::kLengths;
  std::vector<PostureRow> rows;
  int judged = 0, passed = 0;                  // rows judged / within their limit
  int lengths_judged = 0, lengths_passed = 0;  // of them, kind "length"
  int girths_judged = 0, girths_passed = 0;    // of them, kind "girth"
  double max_abs_difference_mm = 0;            // over judged rows with values; NaN if none
  int worst = -1;     // index in rows of the judged row furthest over its limit; -1 if none
  std::string error;  // set by the caller when a pose failed to run
  bool pass() const { return error.empty() && judged > 0 && passed == judged; }
};

PostureComparison ComparePostures(const nlohmann::json& measured_a,
                                  const nlohmann::json& measured_b, const nlohmann::json& truth_a,
                                  const nlohmann::json& truth_b, double tolerance_mm,
                                  PostureRule rule = PostureRule::kLengths);

// One posture over every subject compared in it.
struct PostureSetRow {
  std::string posture;  // pose_b of its pairs
  int pairs = 0, held = 0, did_not_run = 0;
  int lengths_judged = 0, lengths_passed = 0, girths_judged = 0, girths_passed = 0;
  std::string worst_subject, worst_measurement;        // furthest over its limit; "" if none
  double worst_difference_mm = 0, worst_limit_mm = 0;  // NaN difference: a missing value
};

// One measurement over every pair that ran.
struct PostureMeasurementRow {
  std::string name, kind, iso_class;
  double limit_mm = 0;                     // NaN when not judged
  int pairs = 0;                           // pairs with the row (judged or shown)
  int judged = 0;                          // of them, judged
  int within = 0;                          // judged pairs within the limit
  int missing = 0;                         // pairs where one of the two values is missing
  double max_abs_difference_mm = 0;        // largest |measured B - A|; NaN if none
  std::string max_subject, max_posture;    // the pair it came from
  double max_abs_truth_difference_mm = 0;  // largest |truth B - A| (the body itself); NaN if none
  int truth_beyond = 0;  // judged pairs whose truth itself moved more than the limit
};

struct PostureSetSummary {
  std::string reference;                // pose_a of the pairs
  std::vector<PostureSetRow> postures;  // in the pairs' order
  std::vector<PostureMeasurementRow> measurements;
  int pairs = 0, held = 0, values_judged = 0, values_passed = 0;
  // "posture: P of N subject x posture pairs hold; L of M values within limit"
  std::string Headline() const;
};

PostureSetSummary SummarizePostures(const std::vector<PostureComparison>& pairs);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_POSTURE_H_
