#include "measure/cloud_geodesic/cell_sheets.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <unordered_map>

#include "measure/cloud_geodesic/local_surface.h"

namespace bespoke {
namespace {

int Find(std::vector<int>* parent, int i) {
  while ((*parent)[i] != i) i = (*parent)[i] = (*parent)[(*parent)[i]];
  return i;
}

}  // namespace

// Splits the points `run` (indices into `points`, all in one cell) into
// groups connected by steps shorter than `gap` (and, with unit `normals`,
// between points whose normals point to the same side). Brute force for the
// usual handful of points, k-NN for crowded cells.
std::vector<std::vector<int>> SplitSheets(const Eigen::MatrixX3d& points,
                                          const Eigen::MatrixX3d* normals, const int* run,
                                          int count, double gap, const PointIndex& index,
                                          const std::vector<std::int64_t>& keys) {
  std::vector<int> parent(static_cast<size_t>(count));
  std::iota(parent.begin(), parent.end(), 0);
  const double gap2 = gap * gap;
  auto same_side = [&](int p, int q) {
    return !normals || normals->row(p).dot(normals->row(q)) >= 0;
  };
  if (count <= 96) {
    for (int i = 0; i < count; ++i)
      for (int j = i + 1; j < count; ++j)
        if ((points.row(run[i]) - points.row(run[j])).squaredNorm() <= gap2 &&
            same_side(run[i], run[j]))
          parent[Find(&parent, i)] = Find(&parent, j);
  } else {
    std::unordered_map<int, int> local;
    for (int i = 0; i < count; ++i) local[run[i]] = i;
    std::vector<int> near;
    std::vector<double> d2;
    for (int i = 0; i < count; ++i) {
      index.Knn(points.row(run[i]).transpose(), 12, &near, &d2);
      for (size_t k = 0; k < near.size(); ++k) {
        if (d2[k] > gap2 || keys[near[k]] != keys[run[i]] || !same_side(run[i], near[k])) continue;
        parent[Find(&parent, i)] = Find(&parent, local.at(near[k]));
      }
    }
  }
  std::unordered_map<int, int> group_of_root;
  std::vector<std::vector<int>> groups;
  for (int i = 0; i < count; ++i) {
    const int root = Find(&parent, i);
    auto [it, inserted] = group_of_root.emplace(root, static_cast<int>(groups.size()));
    if (inserted) groups.emplace_back();
    groups[it->second].push_back(run[i]);
  }
  return groups;
}

// Pieces of one cell that lie in one plane are one sheet with a sampling gap
// between them (scan lines, grazing angles); pieces apart ALONG the normal are
// different sheets, and so are pieces whose unit `normals` (when given) point
// to opposite sides. Merges the former, largest pieces first.
std::vector<std::vector<int>> MergeCoplanar(const Eigen::MatrixX3d& points,
                                            const Eigen::MatrixX3d* normals,
                                            std::vector<std::vector<int>> groups, double gap) {
  if (groups.size() <= 1) return groups;
  std::stable_sort(groups.begin(), groups.end(),
                   [](const auto& a, const auto& b) { return a.size() > b.size(); });
  auto rows = [&](const std::vector<int>& g) {
    Eigen::MatrixX3d m(static_cast<Eigen::Index>(g.size()), 3);
    for (size_t i = 0; i < g.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = points.row(g[i]);
    return m;
  };
  auto facing = [&](const std::vector<int>& g) {  // sum of the unit normals
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    if (normals)
      for (const int p : g) sum += normals->row(p).transpose();
    return sum;
  };
  std::vector<std::vector<int>> merged;
  std::vector<LocalSurface> planes;
  std::vector<bool> planar;
  std::vector<Eigen::Vector3d> sides;
  for (auto& g : groups) {
    const Eigen::MatrixX3d pts = rows(g);
    const Eigen::Vector3d centre = pts.colwise().mean().transpose();
    const Eigen::Vector3d side = facing(g);
    double flatness = 1;
    if (g.size() >= 3) PcaPlane(pts, &flatness);
    size_t target = merged.size();
    for (size_t m = 0; m < merged.size() && target == merged.size(); ++m)
      if (planar[m] && std::abs(planes[m].Offset(centre)) < 0.5 * gap && sides[m].dot(side) >= 0)
        target = m;
    // A piece too small or too crooked for a plane of its own, in a cell where
    // no piece has a plane either, shows no sign of being another sheet: it
    // joins the nearest piece. (Off a planar piece's plane it stays apart.)
    const bool any_planar = std::find(planar.begin(), planar.end(), true) != planar.end();
    if (target == merged.size() && !merged.empty() && !(flatness < 0.3) && !any_planar) {
      double best = std::numeric_limits<double>::infinity();
      for (size_t m = 0; m < merged.size(); ++m) {
        const double d = (rows(merged[m]).colwise().mean().transpose() - centre).squaredNorm();
        if (d < best && sides[m].dot(side) >= 0) best = d, target = m;
      }
    }
    if (target == merged.size()) {
      merged.emplace_back();
      planes.emplace_back();
      planar.push_back(false);
      sides.push_back(Eigen::Vector3d::Zero());
    }
    sides[target] += side;
    merged[target].insert(merged[target].end(), g.begin(), g.end());
    if (merged[target].size() >= 3) {
      double flatness = 1;
      planes[target] = PcaPlane(rows(merged[target]), &flatness);
      planar[target] = flatness < 0.3;
    }
  }
  return merged;
}

}  // namespace bespoke
