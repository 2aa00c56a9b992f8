#include "measure/landmarks/body_graph.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>
#include <unordered_map>

#include "scanners/core/constants.h"

namespace bespoke::landmarks {
namespace {

std::int64_t Key(int x, int y, int z) {
  const auto u = [](int v) { return static_cast<std::uint64_t>(v + (1 << 20)) & 0x1fffffu; };
  return static_cast<std::int64_t>((u(x) << 42) | (u(y) << 21) | u(z));
}

// Splits one cell's rows into groups facing the same way: two groups when
// some normals point to the opposite side of others (two skins in one cell).
std::vector<std::vector<int>> SplitByNormal(const Eigen::MatrixX3d* with,
                                            const std::vector<int>& rows) {
  if (with == nullptr || rows.size() < 2) return {rows};
  const Eigen::MatrixX3d& normals = *with;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (int r : rows) mean += normals.row(r).transpose();
  // Seeds: the normal most opposed to the mean, and the one most opposed to it.
  int a = rows.front();
  for (int r : rows)
    if (normals.row(r).dot(mean) < normals.row(a).dot(mean)) a = r;
  int b = a;
  for (int r : rows)
    if (normals.row(r).dot(normals.row(a)) < normals.row(b).dot(normals.row(a))) b = r;
  Eigen::Vector3d na = normals.row(a).transpose(), nb = normals.row(b).transpose();
  if (na.dot(nb) > 0) return {rows};
  std::vector<int> ga, gb;
  for (int pass = 0; pass < 3; ++pass) {
    ga.clear(), gb.clear();
    Eigen::Vector3d sa = Eigen::Vector3d::Zero(), sb = Eigen::Vector3d::Zero();
    for (int r : rows) {
      const Eigen::Vector3d n = normals.row(r).transpose();
      if (n.dot(na) >= n.dot(nb))
        ga.push_back(r), sa += n;
      else
        gb.push_back(r), sb += n;
    }
    if (ga.empty() || gb.empty()) return {rows};
    na = sa.normalized(), nb = sb.normalized();
  }
  if (na.dot(nb) > 0) return {rows};
  return {ga, gb};
}

}  // namespace

BodyGraph::BodyGraph(const BodyGraphOptions& options, const Eigen::MatrixX3d& points,
                     const Eigen::MatrixX3d& normals) {
  const bool with_normals = normals.rows() == points.rows() && points.rows() > 0;
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  cells.reserve(static_cast<size_t>(points.rows() / 8 + 1));
  std::vector<std::array<int, 3>> index(static_cast<size_t>(points.rows()));
  for (Eigen::Index r = 0; r < points.rows(); ++r) {
    auto& c = index[static_cast<size_t>(r)];
    for (int k = 0; k < 3; ++k)
      c[static_cast<size_t>(k)] = static_cast<int>(std::floor(points(r, k) / options.cell_mm));
    cells[Key(c[0], c[1], c[2])].push_back(static_cast<int>(r));
  }
  node_of_.assign(static_cast<size_t>(points.rows()), -1);
  for (const auto& [key, rows] : cells) {
    for (const std::vector<int>& group : SplitByNormal(with_normals ? &normals : nullptr, rows)) {
      const int node = size();
      Eigen::Vector3d sum = Eigen::Vector3d::Zero(), nsum = Eigen::Vector3d::Zero();
      for (int r : group) {
        sum += points.row(r).transpose();
        if (with_normals) nsum += normals.row(r).transpose();
        node_of_[static_cast<size_t>(r)] = node;
      }
      site_.push_back(sum / static_cast<double>(group.size()));
      normal_.push_back(nsum.norm() > 0 ? Eigen::Vector3d(nsum.normalized())
                                        : Eigen::Vector3d::Zero());
      count_.push_back(static_cast<int>(group.size()));
      cell_.push_back(index[static_cast<size_t>(group.front())]);
    }
  }
  Link(options);
  Components();
}

void BodyGraph::Link(const BodyGraphOptions& options) {
  std::unordered_map<std::int64_t, std::vector<int>> by_cell;
  for (int n = 0; n < size(); ++n) {
    const auto& c = cell_[static_cast<size_t>(n)];
    by_cell[Key(c[0], c[1], c[2])].push_back(n);
  }
  const double max_len = options.max_link_cells * options.cell_mm;
  const double min_cos = std::cos(options.max_normal_angle_deg * kPi / 180);
  const double crease_cos = std::cos(options.max_crease_angle_deg * kPi / 180);
  edges_.assign(static_cast<size_t>(size()), {});
  for (int a = 0; a < size(); ++a) {
    const auto& c = cell_[static_cast<size_t>(a)];
    const Eigen::Vector3d& na = normal_[static_cast<size_t>(a)];
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = by_cell.find(Key(c[0] + dx, c[1] + dy, c[2] + dz));
          if (it == by_cell.end()) continue;
          for (int b : it->second) {
            if (b <= a) continue;
            const Eigen::Vector3d d = Site(b) - Site(a);
            const double len = d.norm();
            if (len > max_len) continue;
            if (Site(a).x() * Site(b).x() < 0 &&
                std::max(Site(a).z(), Site(b).z()) < options.midline_apart_below_mm)
              continue;
            const Eigen::Vector3d& nb = normal_[static_cast<size_t>(b)];
            if (na.squaredNorm() > 0 && nb.squaredNorm() > 0) {
              if (na.dot(nb) < min_cos) continue;
              const Eigen::Vector3d u = d / std::max(len, 1e-9);
              if (u.dot(na) > options.max_facing_cosine && -u.dot(nb) > options.max_facing_cosine)
                continue;
              // Concave: the normal turns against the step (a sphere's turns with it).
              if ((nb - na).dot(u) < 0 && na.dot(nb) < crease_cos) continue;
            }
            edges_[static_cast<size_t>(a)].emplace_back(b, len);
            edges_[static_cast<size_t>(b)].emplace_back(a, len);
          }
        }
  }
}

void BodyGraph::Components() {
  component_.assign(static_cast<size_t>(size()), -1);
  std::vector<int> sizes;
  for (int s = 0; s < size(); ++s) {
    if (component_[static_cast<size_t>(s)] >= 0) continue;
    const int id = static_cast<int>(sizes.size());
    int count = 0;
    std::vector<int> stack{s};
    component_[static_cast<size_t>(s)] = id;
    while (!stack.empty()) {
      const int n = stack.back();
      stack.pop_back();
      count += count_[static_cast<size_t>(n)];
      for (const auto& [m, len] : edges_[static_cast<size_t>(n)]) {
        if (component_[static_cast<size_t>(m)] >= 0) continue;
        component_[static_cast<size_t>(m)] = id;
        stack.push_back(m);
      }
    }
    sizes.push_back(count);
  }
  // Renumber by size, largest first.
  std::vector<int> order(sizes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
    return sizes[static_cast<size_t>(x)] > sizes[static_cast<size_t>(y)];
  });
  std::vector<int> rank(sizes.size());
  for (size_t i = 0; i < order.size(); ++i)
    rank[static_cast<size_t>(order[i])] = static_cast<int>(i);
  for (int& c : component_) c = rank[static_cast<size_t>(c)];
}

int BodyGraph::Nearest(const Eigen::Vector3d& x) const {
  int best = -1;
  double best_d = kInf;
  for (int n = 0; n < size(); ++n) {
    if (component_[static_cast<size_t>(n)] != 0) continue;
    const double d = (Site(n) - x).squaredNorm();
    if (d < best_d) best_d = d, best = n;
  }
  return best;
}

std::vector<double> BodyGraph::Distances(const std::vector<int>& sources, std::vector<int>* parent,
                                         double max_mm) const {
  std::vector<double> dist(static_cast<size_t>(size()), kInf);
  if (parent) parent->assign(static_cast<size_t>(size()), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int s : sources) {
    if (s < 0 || s >= size()) continue;
    dist[static_cast<size_t>(s)] = 0;
    queue.emplace(0.0, s);
  }
  while (!queue.empty()) {
    const auto [d, n] = queue.top();
    queue.pop();
    if (d > dist[static_cast<size_t>(n)]) continue;
    for (const auto& [m, len] : edges_[static_cast<size_t>(n)]) {
      const double dm = d + len;
      if (dm <= max_mm && dm < dist[static_cast<size_t>(m)]) {
        dist[static_cast<size_t>(m)] = dm;
        if (parent) (*parent)[static_cast<size_t>(m)] = n;
        queue.emplace(dm, m);
      }
    }
  }
  return dist;
}

std::vector<int> BodyGraph::PathTo(const std::vector<int>& parent, int node) {
  std::vector<int> path;
  for (int n = node; n >= 0; n = parent[static_cast<size_t>(n)]) path.push_back(n);
  return path;
}

}  // namespace bespoke::landmarks
