#include "scanners/clean/outliers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

}  // namespace

void StatisticalOutlierOptions::Check() const {
  if (mean_k < 1 || mean_k > 100) {
    throw InputError("statistical outlier mean_k must be 1..100, got " + std::to_string(mean_k));
  }
  if (!(stddev_mul > 0)) {
    throw InputError("statistical outlier stddev_mul must be > 0, got " +
                     std::to_string(stddev_mul));
  }
}

void RadiusOutlierOptions::Check() const {
  if (!(radius_mm > 0 && std::isfinite(radius_mm))) {
    throw InputError("radius outlier radius must be > 0 mm, got " + std::to_string(radius_mm));
  }
  if (min_neighbors < 1 || min_neighbors > 100) {
    throw InputError("radius outlier min_neighbors must be 1..100, got " +
                     std::to_string(min_neighbors));
  }
}

OutlierTest StatisticalOutliers(const StatisticalOutlierOptions& options,
                                const NeighbourLists& neighbours) {
  options.Check();
  BESPOKE_CHECK(neighbours.k >= options.mean_k, "neighbour lists shorter than mean_k");
  const Eigen::Index n = neighbours.num_points();
  std::vector<double> score(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    double sum = 0.0;
    int count = 0;
    for (int j = 0; j < options.mean_k; ++j) {
      if (neighbours.at(i, j) < 0) break;
      sum += neighbours.distance(i, j);
      ++count;
    }
    // A point with fewer than mean_k neighbours in the whole cloud is isolated.
    score[static_cast<size_t>(i)] =
        count == options.mean_k ? sum / count : std::numeric_limits<double>::infinity();
  }
  std::vector<double> finite;
  finite.reserve(score.size());
  for (double s : score) {
    if (std::isfinite(s)) finite.push_back(s);
  }
  const double median = Median(finite);
  for (double& s : finite) s = std::abs(s - median);
  const double sigma = 1.4826 * Median(finite);

  OutlierTest result;
  result.threshold = median + options.stddev_mul * sigma;
  result.keep.resize(static_cast<size_t>(n));
  for (size_t i = 0; i < score.size(); ++i) result.keep[i] = score[i] <= result.threshold;
  return result;
}

OutlierTest RadiusOutliers(const RadiusOutlierOptions& options, const NeighbourLists& neighbours) {
  options.Check();
  BESPOKE_CHECK(neighbours.k >= options.min_neighbors,
                "neighbour lists shorter than min_neighbors");
  const Eigen::Index n = neighbours.num_points();
  OutlierTest result;
  result.threshold = options.radius_mm;
  result.keep.resize(static_cast<size_t>(n));
  const int j = options.min_neighbors - 1;
  for (Eigen::Index i = 0; i < n; ++i) {
    result.keep[static_cast<size_t>(i)] =
        neighbours.at(i, j) >= 0 && neighbours.distance(i, j) <= options.radius_mm;
  }
  return result;
}

}  // namespace bespoke
