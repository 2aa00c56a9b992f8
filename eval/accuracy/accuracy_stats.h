// Statistics of measurement errors (measured - reference, mm) over subjects,
// as an accuracy report needs them: bias (mean difference), sample SD, the
// 95 % confidence interval of the mean (Student t with n - 1 degrees of
// freedom), the Bland-Altman 95 % limits of agreement (bias -/+ 1.96 SD),
// mean absolute error, largest absolute error and median absolute error.
// And the repeatability of repeated measurements of the same subjects
// (Bland & Altman, BMJ 1996;313:744): the within-subject SD and the
// repeatability coefficient.
//
// Input: values in mm (non-finite values are an InputError: a missing
// measurement is counted by the caller, never averaged in).
// Output: with n = 0 every value is NaN, with n = 1 the SD, the interval and
// the limits are NaN (one subject says nothing about the spread).
#ifndef BESPOKE_EVAL_ACCURACY_ACCURACY_STATS_H_
#define BESPOKE_EVAL_ACCURACY_ACCURACY_STATS_H_

#include <vector>

namespace bespoke {

struct ErrorStats {
  int n = 0;           // differences summarised
  double mean_mm = 0;  // bias: mean of measured - reference
  double sd_mm = 0;    // sample standard deviation (n - 1)
  double ci_low_mm =
      0;  // 95 % confidence interval of the mean: mean -/+ t(0.975, n-1) SD / sqrt(n)
  double ci_high_mm = 0;
  double loa_low_mm = 0;  // Bland-Altman limits of agreement: mean -/+ 1.96 SD
  double loa_high_mm = 0;
  double mae_mm = 0;         // mean of |difference|
  double max_abs_mm = 0;     // largest |difference|
  double median_abs_mm = 0;  // median of |difference|
};

// The two-sided 95 % Student t quantile t(0.975, dof); InputError for dof < 1.
double StudentT975(int degrees_of_freedom);

// Median of `values` (mean of the two middle ones for an even count); NaN when empty.
double Median(std::vector<double> values);

// Summarises `differences_mm`; InputError naming the index of a non-finite value.
ErrorStats SummarizeErrors(const std::vector<double>& differences_mm);

struct RepeatabilityStats {
  int subjects = 0;  // subjects with at least two values (the others say nothing here)
  int values = 0;    // values of those subjects
  // Within-subject SD: sqrt(sum_i sum_j (x_ij - mean_i)^2 / sum_i (n_i - 1)),
  // the pooled SD of one subject's repeated values; NaN without such a subject.
  double within_sd_mm = 0;
  // Repeatability coefficient 1.96 * sqrt(2) * within_sd_mm: two measurements
  // of one subject differ by less than this for 95 % of pairs; NaN as above.
  double coefficient_mm = 0;
};

// Repeatability of `values_mm`: one list per subject of its repeated values
// (lists with fewer than two values are skipped). InputError naming the
// subject index for a non-finite value.
RepeatabilityStats SummarizeRepeatability(const std::vector<std::vector<double>>& values_mm);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_ACCURACY_STATS_H_
