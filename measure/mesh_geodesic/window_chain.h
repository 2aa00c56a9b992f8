// Path reconstruction shared by the mesh and point-cloud geodesics: paths
// share prefixes, so each settled node keeps only the last samples of its
// path (its window) and the full path is rebuilt by walking parent links,
// in O(path length).
#ifndef BESPOKE_MEASURE_MESH_GEODESIC_WINDOW_CHAIN_H_
#define BESPOKE_MEASURE_MESH_GEODESIC_WINDOW_CHAIN_H_

#include <Eigen/Core>
#include <algorithm>
#include <utility>
#include <vector>

#include "scanners/core/errors.h"

namespace bespoke {

// A node's window starts at index start[node] of its path and continues its
// parent's path. The windows that make up the path to `node`, from the
// source's end: (node, samples taken from the start of its window). `parent`, `start`: per node
// (#nodes); `window_size(u)`: the samples in u's window. InternalError on a
// broken chain.
template <class WindowSize>
std::vector<std::pair<int, int>> WindowChain(int node, const std::vector<int>& parent,
                                             const std::vector<int>& start,
                                             WindowSize window_size) {
  std::vector<std::pair<int, int>> chunks;
  chunks.emplace_back(node, window_size(node));
  int need = start[static_cast<size_t>(node)];
  for (int cur = parent[static_cast<size_t>(node)]; need > 0;
       cur = parent[static_cast<size_t>(cur)]) {
    BESPOKE_CHECK(cur >= 0, "broken parent chain");
    const int take = need - start[static_cast<size_t>(cur)];
    BESPOKE_CHECK(take >= 0 && take <= window_size(cur), "inconsistent window chain");
    chunks.emplace_back(cur, take);
    need = start[static_cast<size_t>(cur)];
  }
  std::reverse(chunks.begin(), chunks.end());
  return chunks;
}

// The polyline (#S x 3) of a chain, with its samples' hints when `hints` is
// not null: `sample(u, i)` returns sample i of node u's window as a pair
// (position, hint).
template <class Sample>
Eigen::MatrixX3d ChainPolyline(const std::vector<std::pair<int, int>>& chain, Sample sample,
                               std::vector<int>* hints) {
  Eigen::Index total = 0;
  for (const auto& link : chain) total += link.second;
  Eigen::MatrixX3d out(total, 3);
  if (hints) hints->resize(static_cast<size_t>(total));
  Eigen::Index row = 0;
  for (const auto& [u, take] : chain)
    for (int i = 0; i < take; ++i, ++row) {
      const auto [point, hint] = sample(u, i);
      out.row(row) = point.transpose();
      if (hints) (*hints)[static_cast<size_t>(row)] = hint;
    }
  return out;
}

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MESH_GEODESIC_WINDOW_CHAIN_H_
