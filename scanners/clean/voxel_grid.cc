#include "scanners/clean/voxel_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

struct Cell {
  std::uint64_t key;  // (x, y, z) packed, when the ranges fit 21 bits each
  std::int32_t x, y, z;
  std::int32_t point;
  bool SameCell(const Cell& o) const { return x == o.x && y == o.y && z == o.z; }
  bool operator<(const Cell& o) const {
    if (x != o.x) return x < o.x;
    if (y != o.y) return y < o.y;
    return z < o.z;
  }
};

std::vector<Cell> SortedCells(const Eigen::MatrixX3d& points, double leaf) {
  const double inverse = 1.0 / leaf;
  std::vector<Cell> cells(static_cast<size_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    const Eigen::Vector3d p = points.row(i).transpose() * inverse;
    BESPOKE_CHECK(p.cwiseAbs().maxCoeff() < 2e9, "voxel grid: coordinate out of range");
    cells[static_cast<size_t>(i)] = {0, static_cast<std::int32_t>(std::floor(p.x())),
                                     static_cast<std::int32_t>(std::floor(p.y())),
                                     static_cast<std::int32_t>(std::floor(p.z())),
                                     static_cast<std::int32_t>(i)};
  }
  if (cells.empty()) return cells;
  // Sorting one 64-bit key is ~2x faster than comparing three ints; a scan
  // spanning more than 2^21 leaves (8 km at 4 mm) falls back to the latter.
  std::int64_t low[3] = {cells[0].x, cells[0].y, cells[0].z}, high[3] = {low[0], low[1], low[2]};
  for (const Cell& c : cells) {
    const std::int64_t v[3] = {c.x, c.y, c.z};
    for (int a = 0; a < 3; ++a) low[a] = std::min(low[a], v[a]), high[a] = std::max(high[a], v[a]);
  }
  constexpr std::int64_t kLimit = std::int64_t{1} << 21;
  if (high[0] - low[0] < kLimit && high[1] - low[1] < kLimit && high[2] - low[2] < kLimit) {
    for (Cell& c : cells) {
      c.key = (static_cast<std::uint64_t>(c.x - low[0]) << 42) |
              (static_cast<std::uint64_t>(c.y - low[1]) << 21) |
              static_cast<std::uint64_t>(c.z - low[2]);
    }
    std::sort(cells.begin(), cells.end(),
              [](const Cell& a, const Cell& b) { return a.key < b.key; });
  } else {
    std::sort(cells.begin(), cells.end());
  }
  return cells;
}

}  // namespace

void VoxelGridOptions::Check() const {
  if (!(leaf_mm >= 0.1 && leaf_mm <= 1000.0)) {
    throw InputError("voxel leaf size must be between 0.1 and 1000 mm, got " +
                     std::to_string(leaf_mm));
  }
}

PointCloud VoxelGridDownsample(const VoxelGridOptions& options, const PointCloud& cloud) {
  options.Check();
  cloud.CheckShapes();
  const std::vector<Cell> cells = SortedCells(cloud.points, options.leaf_mm);

  // Runs of equal cells -> one output point each.
  std::vector<size_t> run_start;
  for (size_t c = 0; c < cells.size(); ++c) {
    if (c == 0 || !cells[c].SameCell(cells[c - 1])) run_start.push_back(c);
  }
  run_start.push_back(cells.size());
  const auto m = static_cast<Eigen::Index>(run_start.size() - 1);

  PointCloud out;
  out.points.setZero(m, 3);
  if (cloud.has_normals()) out.normals.setZero(m, 3);
  Eigen::MatrixX3d color_sum;
  if (cloud.has_colors()) color_sum.setZero(m, 3);
  for (const auto& [name, values] : cloud.scalars) {
    if (values.size() == cloud.size()) out.scalars[name].setZero(m);
  }
  for (Eigen::Index v = 0; v < m; ++v) {
    const size_t begin = run_start[static_cast<size_t>(v)];
    const size_t end = run_start[static_cast<size_t>(v) + 1];
    for (size_t c = begin; c < end; ++c) {
      const Eigen::Index i = cells[c].point;
      out.points.row(v) += cloud.points.row(i);
      if (cloud.has_normals()) out.normals.row(v) += cloud.normals.row(i);
      if (cloud.has_colors()) color_sum.row(v) += cloud.colors.row(i).cast<double>();
      for (auto& [name, values] : out.scalars) values[v] += cloud.scalars.at(name)[i];
    }
    const double count = static_cast<double>(end - begin);
    out.points.row(v) /= count;
    if (cloud.has_normals()) {
      const double norm = out.normals.row(v).norm();
      if (norm > 0) out.normals.row(v) /= norm;
    }
    if (cloud.has_colors()) color_sum.row(v) /= count;
    for (auto& [name, values] : out.scalars) values[v] /= count;
  }
  if (cloud.has_colors()) {
    out.colors = color_sum.array().round().min(255.0).max(0.0).cast<std::uint8_t>();
  }
  return out;
}

}  // namespace bespoke
