#include "measure/landmarks/landmark_slices.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "measure/tape/convex_hull_2d.h"
#include "scanners/core/cell_key.h"

namespace bespoke::landmarks {
namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int Find(int i) {
    while (parent[static_cast<size_t>(i)] != i) {
      parent[static_cast<size_t>(i)] = parent[static_cast<size_t>(parent[static_cast<size_t>(i)])];
      i = parent[static_cast<size_t>(i)];
    }
    return i;
  }
  void Join(int a, int b) { parent[static_cast<size_t>(Find(a))] = Find(b); }
};

}  // namespace

std::vector<Piece> SplitPieces(const Eigen::MatrixX3d& points, const std::vector<int>& rows,
                               double link_mm) {
  const int n = static_cast<int>(rows.size());
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  cells.reserve(static_cast<size_t>(n));
  auto cell_of = [&](int i, std::int64_t* ix, std::int64_t* iy) {
    *ix = static_cast<std::int64_t>(std::floor(points(rows[static_cast<size_t>(i)], 0) / link_mm));
    *iy = static_cast<std::int64_t>(std::floor(points(rows[static_cast<size_t>(i)], 1) / link_mm));
  };
  for (int i = 0; i < n; ++i) {
    std::int64_t ix, iy;
    cell_of(i, &ix, &iy);
    cells[CellKey2(ix, iy)].push_back(i);
  }
  UnionFind uf(n);
  const double link2 = link_mm * link_mm;
  for (int i = 0; i < n; ++i) {
    std::int64_t ix, iy;
    cell_of(i, &ix, &iy);
    const Eigen::Vector2d p = points.row(rows[static_cast<size_t>(i)]).head<2>();
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      for (std::int64_t dy = -1; dy <= 1; ++dy) {
        auto it = cells.find(CellKey2(ix + dx, iy + dy));
        if (it == cells.end()) continue;
        for (int j : it->second) {
          if (j <= i || uf.Find(i) == uf.Find(j)) continue;
          const Eigen::Vector2d q = points.row(rows[static_cast<size_t>(j)]).head<2>();
          if ((p - q).squaredNorm() < link2) uf.Join(i, j);
        }
      }
    }
  }
  std::unordered_map<int, int> piece_of_root;
  std::vector<Piece> pieces;
  for (int i = 0; i < n; ++i) {
    const int root = uf.Find(i);
    auto [it, added] = piece_of_root.emplace(root, static_cast<int>(pieces.size()));
    if (added) pieces.emplace_back();
    pieces[static_cast<size_t>(it->second)].rows.push_back(rows[static_cast<size_t>(i)]);
  }
  for (Piece& piece : pieces) {
    piece.lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
    piece.hi = -piece.lo;
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (int r : piece.rows) {
      const Eigen::Vector2d p = points.row(r).head<2>();
      piece.lo = piece.lo.cwiseMin(p);
      piece.hi = piece.hi.cwiseMax(p);
      sum += p;
    }
    piece.centroid = sum / static_cast<double>(piece.rows.size());
  }
  return pieces;
}

std::vector<Slice> SliceCloud(const SliceOptions& options, const Eigen::MatrixX3d& points) {
  std::vector<int> order(static_cast<size_t>(points.rows()));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) { return points(a, 2) < points(b, 2); });
  std::vector<Slice> slices;
  if (order.empty()) return slices;
  const double z0 = points(order.front(), 2), z1 = points(order.back(), 2);
  const int count = static_cast<int>(std::floor((z1 - z0) / options.step_mm)) + 1;
  slices.resize(static_cast<size_t>(count));
  size_t begin = 0;
  for (int s = 0; s < count; ++s) {
    Slice& slice = slices[static_cast<size_t>(s)];
    slice.z = z0 + s * options.step_mm;
    while (begin < order.size() && points(order[begin], 2) < slice.z - options.half_thickness_mm)
      ++begin;
    for (size_t k = begin;
         k < order.size() && points(order[k], 2) <= slice.z + options.half_thickness_mm; ++k) {
      slice.rows.push_back(order[k]);
    }
  }
  // Pieces per slice: independent, so in parallel.
#pragma omp parallel for schedule(dynamic, 8)
  for (int s = 0; s < count; ++s) {
    Slice& slice = slices[static_cast<size_t>(s)];
    slice.pieces = SplitPieces(points, slice.rows, options.link_mm);
  }
  return slices;
}

int SliceAt(const std::vector<Slice>& slices, double z) {
  if (slices.empty()) return -1;
  const double step = slices.size() > 1 ? slices[1].z - slices[0].z : 1.0;
  const int i = static_cast<int>(std::lround((z - slices.front().z) / step));
  return std::clamp(i, 0, static_cast<int>(slices.size()) - 1);
}

double PieceGap(const Eigen::MatrixX3d& points, const Piece& a, const Piece& b) {
  double best = std::numeric_limits<double>::infinity();
  for (int i : a.rows) {
    const Eigen::Vector2d p = points.row(i).head<2>();
    for (int j : b.rows)
      best = std::min(best, (points.row(j).head<2>().transpose() - p).squaredNorm());
  }
  return std::sqrt(best);
}

double HullPerimeter(const Eigen::MatrixX3d& points, const std::vector<int>& rows) {
  Eigen::MatrixX2d xy(static_cast<Eigen::Index>(rows.size()), 2);
  for (size_t k = 0; k < rows.size(); ++k)
    xy.row(static_cast<Eigen::Index>(k)) = points.row(rows[k]).head<2>();
  return ConvexHullPerimeter(xy);
}

}  // namespace bespoke::landmarks
