// Statistics of measurement errors (measured - truth, mm) over subjects, as
// an accuracy report needs them: bias (mean difference), sample SD, the 95 %
// confidence interval of the mean (Student t with n - 1 degrees of freedom),
// mean absolute error, largest absolute error and median absolute error.
//
// Input: differences in mm (non-finite values are an InputError: a missing
// measurement is counted by the caller, never averaged in).
// Output: ErrorStats; with n = 0 every value is NaN, with n = 1 the SD and
// the interval are NaN (one subject says nothing about the spread).
#ifndef BESPOKE_EVAL_ACCURACY_ACCURACY_STATS_H_
#define BESPOKE_EVAL_ACCURACY_ACCURACY_STATS_H_

#include <vector>

namespace bespoke {

struct ErrorStats {
  int n = 0;           // differences summarised
  double mean_mm = 0;  // bias: mean of measured - truth
  double sd_mm = 0;    // sample standard deviation (n - 1)
  double ci_low_mm =
      0;  // 95 % confidence interval of the mean: mean -/+ t(0.975, n-1) SD / sqrt(n)
  double ci_high_mm = 0;
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

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_ACCURACY_STATS_H_
