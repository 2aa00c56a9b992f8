#include "measure/landmarks/profile_extreme.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "scanners/core/errors.h"

namespace bespoke::landmarks {

double ProfileExtreme(const ProfileExtremeOptions& options, const std::vector<double>& at,
                      const std::vector<double>& value, size_t best) {
  if (at.size() != value.size() || best >= at.size())
    throw InternalError("ProfileExtreme: sample index out of range or sizes differ");
  const size_t lo = best >= static_cast<size_t>(options.half_window)
                        ? best - static_cast<size_t>(options.half_window)
                        : 0;
  const size_t hi = std::min(at.size() - 1, best + static_cast<size_t>(options.half_window));
  // Normal equations of the fit in u = at - at[best] (well conditioned).
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  int n = 0;
  const double sign = options.minimum ? 1.0 : -1.0;
  for (size_t k = lo; k <= hi; ++k) {
    if (!std::isfinite(value[k])) continue;
    const double u = at[k] - at[best];
    const Eigen::Vector3d row(u * u, u, 1.0);
    ata += row * row.transpose();
    atb += row * (sign * value[k]);
    ++n;
  }
  if (n < std::max(3, options.min_samples)) return at[best];
  const Eigen::Vector3d coef = ata.ldlt().solve(atb);
  if (!coef.allFinite() || coef(0) <= 0) return at[best];
  const double left = best > 0 ? at[best - 1] : at[best];
  const double right = best + 1 < at.size() ? at[best + 1] : at[best];
  return std::clamp(at[best] - coef(1) / (2 * coef(0)), left, right);
}

double TopCentre(const ProfileExtremeOptions& options, const std::vector<double>& at,
                 const std::vector<double>& value, double depth) {
  if (at.size() != value.size() || !(depth > 0))
    throw InternalError("TopCentre: sizes differ or depth <= 0");
  const size_t best = BestSample(options, value, std::vector<bool>(value.size(), true));
  if (best == value.size()) return std::numeric_limits<double>::quiet_NaN();
  const double sign = options.minimum ? -1.0 : 1.0;
  const double line = sign * value[best] - depth;
  double sum = 0, weight = 0;
  for (size_t k = 0; k < value.size(); ++k) {
    const double w = std::isfinite(value[k]) ? sign * value[k] - line : 0.0;
    if (w > 0) sum += w * at[k], weight += w;
  }
  return sum / weight;
}

std::vector<double> WindowMean(const std::vector<double>& value, size_t half, int min_count) {
  std::vector<double> out(value.size(), std::numeric_limits<double>::quiet_NaN());
  for (size_t k = half; k + half < value.size(); ++k) {
    double sum = 0;
    int n = 0;
    for (size_t j = k - half; j <= k + half; ++j)
      if (std::isfinite(value[j])) sum += value[j], ++n;
    if (n >= min_count) out[k] = sum / n;
  }
  return out;
}

size_t BestSample(const ProfileExtremeOptions& options, const std::vector<double>& value,
                  const std::vector<bool>& eligible) {
  if (value.size() != eligible.size()) throw InternalError("BestSample: sizes differ");
  size_t best = value.size();
  for (size_t k = 0; k < value.size(); ++k) {
    if (!eligible[k] || !std::isfinite(value[k])) continue;
    if (best == value.size() || (options.minimum ? value[k] < value[best] : value[k] > value[best]))
      best = k;
  }
  return best;
}

}  // namespace bespoke::landmarks
