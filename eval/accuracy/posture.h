// The posture test: one body measured in two poses (the parametric body's
// arm abduction, e.g. an A-pose at 30 deg and a T-pose at 90 deg). Lengths
// measured along the surface should not depend on the pose (the thesis's
// Fig 3.1 argument for geodesic lengths): every length of pose B must lie
// within `tolerance_mm` of pose A's.
//
// Input: the measurement documents of both poses (docs/contracts.md) and,
// optionally (null json = none), both truth documents, shown beside so the
// reader sees how much the body itself changed between the poses.
// Output: one row per measurement of the truth A (when given) and of either
// measured document; rows of kind "length" are judged (a length one pose
// lacks fails), the others are shown only. Failure: InputError for a
// document without a "measurements" array.
#ifndef BESPOKE_EVAL_ACCURACY_POSTURE_H_
#define BESPOKE_EVAL_ACCURACY_POSTURE_H_

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace bespoke {

struct PostureRow {
  std::string name;
  std::string kind;
  double measured_a_mm = 0, measured_b_mm = 0;  // NaN when that pose lacks a value
  double truth_a_mm = 0, truth_b_mm = 0;        // NaN when not given
  double difference_mm = 0;  // measured_b - measured_a; NaN when either is missing
  bool judged = false;       // kind "length"
  bool pass = false;         // judged and |difference| <= tolerance
};

struct PostureComparison {
  std::string pose_a = "A-pose", pose_b = "T-pose";  // labels
  double arm_a_deg = 0, arm_b_deg = 0;               // arm abduction of each pose (reporting only)
  double tolerance_mm = 5;                           // default 5 mm: |B - A| allowed per length
  std::vector<PostureRow> rows;
  int judged = 0, passed = 0;        // lengths judged / within tolerance
  double max_abs_difference_mm = 0;  // over judged lengths with values; NaN if none
  std::string error;                 // set by the caller when a pose failed to run
  bool pass() const { return error.empty() && judged > 0 && passed == judged; }
};

PostureComparison ComparePostures(const nlohmann::json& measured_a,
                                  const nlohmann::json& measured_b, const nlohmann::json& truth_a,
                                  const nlohmann::json& truth_b, double tolerance_mm);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_POSTURE_H_
