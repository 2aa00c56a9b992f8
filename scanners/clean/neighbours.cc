#include "scanners/clean/neighbours.h"

#include <algorithm>
#include <cmath>
#include <flann/flann.hpp>
#include <limits>
#include <string>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using FlannIndex = flann::Index<flann::L2_Simple<float>>;

std::vector<float> ToFloat(const Eigen::MatrixX3d& points) {
  std::vector<float> data(static_cast<size_t>(points.rows()) * 3);
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    for (int c = 0; c < 3; ++c)
      data[static_cast<size_t>(i) * 3 + c] = static_cast<float>(points(i, c));
  }
  return data;
}

flann::SearchParams Params(int threads) {
  flann::SearchParams params;
  params.cores = std::max(0, threads);  // FLANN: 0 = all available
  params.sorted = true;
  return params;
}

}  // namespace

int NeighbourLists::count(Eigen::Index i) const {
  int n = 0;
  while (n < k && at(i, n) >= 0) ++n;
  return n;
}

NeighbourLists NeighbourLists::Restrict(const std::vector<Eigen::Index>& kept) const {
  std::vector<int> new_index(static_cast<size_t>(num_points()), -1);
  for (size_t m = 0; m < kept.size(); ++m)
    new_index[static_cast<size_t>(kept[m])] = static_cast<int>(m);
  NeighbourLists out;
  out.k = k;
  out.index.assign(kept.size() * static_cast<size_t>(k), -1);
  out.distance_mm.assign(kept.size() * static_cast<size_t>(k),
                         std::numeric_limits<float>::infinity());
  for (size_t m = 0; m < kept.size(); ++m) {
    int slot = 0;
    for (int j = 0; j < k; ++j) {
      const int old = at(kept[m], j);
      if (old < 0) break;
      const int now = new_index[static_cast<size_t>(old)];
      if (now < 0) continue;
      out.index[m * k + slot] = now;
      out.distance_mm[m * k + slot] = distance(kept[m], j);
      ++slot;
    }
  }
  return out;
}

NeighbourLists FindNearestNeighbours(const Eigen::MatrixX3d& points, int k, int threads) {
  if (k < 1) throw InputError("neighbour count k must be at least 1, got " + std::to_string(k));
  NeighbourLists out;
  out.k = k;
  const auto n = static_cast<size_t>(points.rows());
  out.index.assign(n * k, -1);
  out.distance_mm.assign(n * k, std::numeric_limits<float>::infinity());
  if (n < 2) return out;

  std::vector<float> data = ToFloat(points);
  flann::Matrix<float> dataset(data.data(), n, 3);
  FlannIndex index(dataset, flann::KDTreeSingleIndexParams(10));
  index.buildIndex();
  const int query_k = static_cast<int>(std::min<size_t>(static_cast<size_t>(k) + 1, n));
  std::vector<int> found(n * query_k);
  std::vector<float> found_sq(n * query_k);
  flann::Matrix<int> found_m(found.data(), n, query_k);
  flann::Matrix<float> found_sq_m(found_sq.data(), n, query_k);
  index.knnSearch(dataset, found_m, found_sq_m, query_k, Params(threads));

  for (size_t i = 0; i < n; ++i) {
    // Drop the point itself (normally the first hit; with duplicates it may
    // come later, and then the k+1-th hit is dropped instead).
    int slot = 0;
    for (int j = 0; j < query_k && slot < k; ++j) {
      const int other = found[i * query_k + j];
      if (other == static_cast<int>(i) || other < 0) continue;
      out.index[i * k + slot] = other;
      out.distance_mm[i * k + slot] = std::sqrt(std::max(0.0f, found_sq[i * query_k + j]));
      ++slot;
    }
  }
  return out;
}

std::vector<int> NearestPointIndices(const Eigen::MatrixX3d& points,
                                     const Eigen::MatrixX3d& queries, int threads) {
  const auto nq = static_cast<size_t>(queries.rows());
  std::vector<int> result(nq, -1);
  if (points.rows() == 0 || nq == 0) return result;
  std::vector<float> data = ToFloat(points);
  std::vector<float> query_data = ToFloat(queries);
  flann::Matrix<float> dataset(data.data(), static_cast<size_t>(points.rows()), 3);
  flann::Matrix<float> query_m(query_data.data(), nq, 3);
  FlannIndex index(dataset, flann::KDTreeSingleIndexParams(10));
  index.buildIndex();
  std::vector<float> sq(nq);
  flann::Matrix<int> result_m(result.data(), nq, 1);
  flann::Matrix<float> sq_m(sq.data(), nq, 1);
  index.knnSearch(query_m, result_m, sq_m, 1, Params(threads));
  return result;
}

}  // namespace bespoke
