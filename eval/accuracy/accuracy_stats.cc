#include "eval/accuracy/accuracy_stats.h"

#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

constexpr double kZ975 = 1.959963984540054;  // the standard normal's 97.5 % quantile

}  // namespace

double StudentT975(int degrees_of_freedom) {
  if (degrees_of_freedom < 1) {
    throw InputError("Student t quantile needs at least 1 degree of freedom, got " +
                     std::to_string(degrees_of_freedom));
  }
  const boost::math::students_t distribution(static_cast<double>(degrees_of_freedom));
  return boost::math::quantile(distribution, 0.975);
}

double Median(std::vector<double> values) {
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const std::size_t half = values.size() / 2;
  return values.size() % 2 ? values[half] : 0.5 * (values[half - 1] + values[half]);
}

ErrorStats SummarizeErrors(const std::vector<double>& differences_mm) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  ErrorStats stats;
  stats.n = static_cast<int>(differences_mm.size());
  if (stats.n == 0) {
    stats.mean_mm = stats.sd_mm = stats.ci_low_mm = stats.ci_high_mm = kNaN;
    stats.loa_low_mm = stats.loa_high_mm = kNaN;
    stats.mae_mm = stats.max_abs_mm = stats.median_abs_mm = kNaN;
    return stats;
  }
  double sum = 0, sum_abs = 0, max_abs = 0;
  std::vector<double> abs_values;
  abs_values.reserve(differences_mm.size());
  for (std::size_t i = 0; i < differences_mm.size(); ++i) {
    const double d = differences_mm[i];
    if (!std::isfinite(d)) {
      throw InputError("error statistics: difference " + std::to_string(i) + " is not finite");
    }
    sum += d;
    sum_abs += std::abs(d);
    max_abs = std::max(max_abs, std::abs(d));
    abs_values.push_back(std::abs(d));
  }
  stats.mean_mm = sum / stats.n;
  stats.mae_mm = sum_abs / stats.n;
  stats.max_abs_mm = max_abs;
  stats.median_abs_mm = Median(abs_values);
  if (stats.n < 2) {
    stats.sd_mm = stats.ci_low_mm = stats.ci_high_mm = stats.loa_low_mm = stats.loa_high_mm = kNaN;
    return stats;
  }
  double squares = 0;
  for (double d : differences_mm) squares += (d - stats.mean_mm) * (d - stats.mean_mm);
  stats.sd_mm = std::sqrt(squares / (stats.n - 1));
  const double half_width =
      StudentT975(stats.n - 1) * stats.sd_mm / std::sqrt(static_cast<double>(stats.n));
  stats.ci_low_mm = stats.mean_mm - half_width;
  stats.ci_high_mm = stats.mean_mm + half_width;
  stats.loa_low_mm = stats.mean_mm - kZ975 * stats.sd_mm;
  stats.loa_high_mm = stats.mean_mm + kZ975 * stats.sd_mm;
  return stats;
}

RepeatabilityStats SummarizeRepeatability(const std::vector<std::vector<double>>& values_mm) {
  RepeatabilityStats stats;
  double squares = 0;
  int degrees_of_freedom = 0;
  for (std::size_t i = 0; i < values_mm.size(); ++i) {
    const std::vector<double>& values = values_mm[i];
    for (double v : values) {
      if (!std::isfinite(v)) {
        throw InputError("repeatability: a value of subject " + std::to_string(i) +
                         " is not finite");
      }
    }
    if (values.size() < 2) continue;
    double mean = 0;
    for (double v : values) mean += v;
    mean /= static_cast<double>(values.size());
    for (double v : values) squares += (v - mean) * (v - mean);
    degrees_of_freedom += static_cast<int>(values.size()) - 1;
    ++stats.subjects;
    stats.values += static_cast<int>(values.size());
  }
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  stats.within_sd_mm = degrees_of_freedom > 0 ? std::sqrt(squares / degrees_of_freedom) : kNaN;
  stats.coefficient_mm = kZ975 * std::sqrt(2.0) * stats.within_sd_mm;
  return stats;
}

}  // namespace bespoke
