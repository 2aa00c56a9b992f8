#include "measure/cloud_geodesic/point_index.h"

#include <algorithm>
#include <cmath>
#include <flann/flann.hpp>

#include "scanners/core/errors.h"

namespace bespoke {

struct PointIndex::Impl {
  std::vector<double> row_major;  // #P x 3, the layout FLANN wants
  std::unique_ptr<flann::KDTreeSingleIndex<flann::L2_Simple<double>>> tree;
};

PointIndex::PointIndex(const Eigen::MatrixX3d& points)
    : points_(points), impl_(std::make_unique<Impl>()) {
  if (points_.rows() == 0) throw InputError("point index: the cloud has no points");
  if (!points_.allFinite()) throw InputError("point index: the cloud has non-finite coordinates");
  const Eigen::Index n = points_.rows();
  impl_->row_major.resize(static_cast<size_t>(n) * 3);
  for (Eigen::Index i = 0; i < n; ++i)
    for (int c = 0; c < 3; ++c) impl_->row_major[static_cast<size_t>(i) * 3 + c] = points_(i, c);
  flann::Matrix<double> data(impl_->row_major.data(), static_cast<size_t>(n), 3);
  impl_->tree = std::make_unique<flann::KDTreeSingleIndex<flann::L2_Simple<double>>>(
      data, flann::KDTreeSingleIndexParams(/*leaf_max_size=*/12));
  impl_->tree->buildIndex();
}

PointIndex::~PointIndex() = default;

int PointIndex::Nearest(const Eigen::Vector3d& query, double* squared_distance) const {
  flann::KNNSimpleResultSet<double> result(1);
  const double q[3] = {query.x(), query.y(), query.z()};
  impl_->tree->findNeighbors(result, q, flann::SearchParams(-1, 0.0f, false));
  size_t index = 0;
  double dist = 0;
  result.copy(&index, &dist, 1);
  if (squared_distance) *squared_distance = dist;
  return static_cast<int>(index);
}

int PointIndex::Knn(const Eigen::Vector3d& query, int k, std::vector<int>* indices,
                    std::vector<double>* squared_distances) const {
  const size_t count =
      static_cast<size_t>(std::max<Eigen::Index>(0, std::min<Eigen::Index>(k, points_.rows())));
  indices->resize(count);
  squared_distances->resize(count);
  if (count == 0) return 0;
  flann::KNNSimpleResultSet<double> result(count);
  const double q[3] = {query.x(), query.y(), query.z()};
  impl_->tree->findNeighbors(result, q, flann::SearchParams(-1, 0.0f, false));
  std::vector<size_t> raw(count);
  result.copy(raw.data(), squared_distances->data(), count);
  for (size_t i = 0; i < count; ++i) (*indices)[i] = static_cast<int>(raw[i]);
  return static_cast<int>(count);
}

double PointIndex::SpacingQuantile(double quantile, int max_samples) const {
  const Eigen::Index n = points_.rows();
  if (n < 2) return 0;
  const Eigen::Index samples = std::min<Eigen::Index>(n, std::max(1, max_samples));
  std::vector<double> spacing;
  spacing.reserve(static_cast<size_t>(samples));
  std::vector<int> idx;
  std::vector<double> d2;
  for (Eigen::Index s = 0; s < samples; ++s) {
    const Eigen::Index i = s * n / samples;
    Knn(point(i), 4, &idx, &d2);
    // The nearest is the point itself, unless it is duplicated; take the
    // first neighbour at a positive distance.
    double d = 0;
    for (size_t j = 0; j < d2.size(); ++j)
      if (idx[j] != i && d2[j] > 0) {
        d = std::sqrt(d2[j]);
        break;
      }
    if (d > 0) spacing.push_back(d);
  }
  if (spacing.empty()) return 0;
  const size_t at = std::min(
      spacing.size() - 1,
      static_cast<size_t>(std::clamp(quantile, 0.0, 1.0) * static_cast<double>(spacing.size())));
  std::nth_element(spacing.begin(), spacing.begin() + static_cast<std::ptrdiff_t>(at),
                   spacing.end());
  return spacing[at];
}

}  // namespace bespoke
