#include "scanners/clean/euclidean_clusters.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>
#include <unordered_map>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int Find(int a) {
    while (parent_[static_cast<size_t>(a)] != a) {
      parent_[static_cast<size_t>(a)] =
          parent_[static_cast<size_t>(parent_[static_cast<size_t>(a)])];
      a = parent_[static_cast<size_t>(a)];
    }
    return a;
  }
  void Join(int a, int b) { parent_[static_cast<size_t>(Find(a))] = Find(b); }

 private:
  std::vector<int> parent_;
};

using CellKey = std::array<std::int32_t, 3>;

std::uint64_t Hash(const CellKey& k) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(k[0])) * 73856093u) ^
         (static_cast<std::uint64_t>(static_cast<std::uint32_t>(k[1])) * 19349663u) ^
         (static_cast<std::uint64_t>(static_cast<std::uint32_t>(k[2])) * 83492791u);
}

struct KeyHash {
  size_t operator()(const CellKey& k) const { return static_cast<size_t>(Hash(k)); }
};

// Neighbour offsets with dx > 0, or dx == 0 && dy > 0, or dx == dy == 0 && dz > 0
// (each unordered cell pair once), sorted so that face neighbours come first.
std::vector<CellKey> HalfOffsets(int reach) {
  std::vector<CellKey> offsets;
  for (int dx = 0; dx <= reach; ++dx) {
    for (int dy = -reach; dy <= reach; ++dy) {
      for (int dz = -reach; dz <= reach; ++dz) {
        if (dx == 0 && (dy < 0 || (dy == 0 && dz <= 0))) continue;
        offsets.push_back({dx, dy, dz});
      }
    }
  }
  std::stable_sort(offsets.begin(), offsets.end(), [](const CellKey& a, const CellKey& b) {
    return a[0] * a[0] + a[1] * a[1] + a[2] * a[2] < b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
  });
  return offsets;
}

}  // namespace

void ClusterOptions::Check() const {
  if (!(tolerance_mm > 0 && tolerance_mm <= 1000)) {
    throw InputError("cluster tolerance must be in (0, 1000] mm, got " +
                     std::to_string(tolerance_mm));
  }
}

Clusters EuclideanClusters(const ClusterOptions& options, const Eigen::MatrixX3d& points) {
  options.Check();
  const double tol = options.tolerance_mm;
  const double tol2 = tol * tol;
  const double cell = tol / std::sqrt(3.0) * (1.0 - 1e-9);  // a cell's diagonal <= tol
  const Eigen::Index n = points.rows();

  // Points grouped by cell.
  std::vector<std::pair<CellKey, int>> keyed(static_cast<size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    CellKey key;
    for (int c = 0; c < 3; ++c) {
      const double v = std::floor(points(i, c) / cell);
      BESPOKE_CHECK(std::abs(v) < 2e9, "clustering: coordinate out of range");
      key[static_cast<size_t>(c)] = static_cast<std::int32_t>(v);
    }
    keyed[static_cast<size_t>(i)] = {key, static_cast<int>(i)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<size_t> start;  // run starts, one per occupied cell
  std::unordered_map<CellKey, int, KeyHash> cell_of;
  for (size_t r = 0; r < keyed.size(); ++r) {
    if (r == 0 || keyed[r].first != keyed[r - 1].first) {
      cell_of.emplace(keyed[r].first, static_cast<int>(start.size()));
      start.push_back(r);
    }
  }
  const size_t cells = start.size();
  start.push_back(keyed.size());

  // Join neighbouring cells that hold a point pair within the tolerance.
  UnionFind sets(cells);
  const std::vector<CellKey> offsets = HalfOffsets(2);  // tol / cell < 2
  for (size_t a = 0; a < cells; ++a) {
    const CellKey& ka = keyed[start[a]].first;
    for (const CellKey& d : offsets) {
      const auto it = cell_of.find({ka[0] + d[0], ka[1] + d[1], ka[2] + d[2]});
      if (it == cell_of.end()) continue;
      const auto b = static_cast<size_t>(it->second);
      if (sets.Find(static_cast<int>(a)) == sets.Find(static_cast<int>(b))) continue;
      bool joined = false;
      for (size_t i = start[a]; i < start[a + 1] && !joined; ++i) {
        const Eigen::RowVector3d p = points.row(keyed[i].second);
        for (size_t j = start[b]; j < start[b + 1]; ++j) {
          if ((points.row(keyed[j].second) - p).squaredNorm() <= tol2) {
            joined = true;
            break;
          }
        }
      }
      if (joined) sets.Join(static_cast<int>(a), static_cast<int>(b));
    }
  }

  // Label clusters by size, largest first.
  std::vector<std::int64_t> root_size(cells, 0);
  for (size_t c = 0; c < cells; ++c) {
    root_size[static_cast<size_t>(sets.Find(static_cast<int>(c)))] +=
        static_cast<std::int64_t>(start[c + 1] - start[c]);
  }
  std::vector<int> roots;
  for (size_t c = 0; c < cells; ++c) {
    if (root_size[c] > 0) roots.push_back(static_cast<int>(c));
  }
  std::stable_sort(roots.begin(), roots.end(), [&](int a, int b) {
    return root_size[static_cast<size_t>(a)] > root_size[static_cast<size_t>(b)];
  });
  std::vector<int> rank(cells, -1);
  Clusters result;
  for (size_t r = 0; r < roots.size(); ++r) {
    rank[static_cast<size_t>(roots[r])] = static_cast<int>(r);
    result.sizes.push_back(root_size[static_cast<size_t>(roots[r])]);
  }
  result.label.assign(static_cast<size_t>(n), -1);
  for (size_t c = 0; c < cells; ++c) {
    const int label = rank[static_cast<size_t>(sets.Find(static_cast<int>(c)))];
    for (size_t i = start[c]; i < start[c + 1]; ++i)
      result.label[static_cast<size_t>(keyed[i].second)] = label;
  }
  return result;
}

}  // namespace bespoke
