#include "resize/ga/ranking.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <pagmo/utils/multi_objective.hpp>

#include "scanners/core/constants.h"

namespace bespoke {
namespace {

// a < b with NaN above infinity, as pagmo orders it.
bool Less(double a, double b) {
  if (std::isnan(a)) return false;
  if (std::isnan(b)) return true;
  return a < b;
}

// 1 when a dominates b, -1 when b dominates a, 0 otherwise; `Lt` is the
// order (plain < when no objective is NaN, Less otherwise).
template <typename Lt>
int Dominance(const ObjectivePoint& a, const ObjectivePoint& b, Lt lt) {
  bool a_better = false, b_better = false;
  for (int k = 0; k < 3; ++k) {
    if (lt(a[k], b[k])) a_better = true;
    if (lt(b[k], a[k])) b_better = true;
  }
  if (a_better == b_better) return 0;
  return a_better ? 1 : -1;
}

template <typename Lt>
void DominanceLists(const std::vector<ObjectivePoint>& points, Lt lt,
                    std::vector<std::vector<int>>* dominated, std::vector<int>* count) {
  const int n = static_cast<int>(points.size());
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      const int d = Dominance(points[i], points[j], lt);
      if (d > 0) {
        (*dominated)[i].push_back(j);
        ++(*count)[j];
      } else if (d < 0) {
        (*dominated)[j].push_back(i);
        ++(*count)[i];
      }
    }
}

// a > b with NaN above infinity (a crowding distance is NaN when an
// objective is equal over the front).
bool Greater(double a, double b) {
  if (std::isnan(a)) return !std::isnan(b);
  if (std::isnan(b)) return false;
  return a > b;
}

}  // namespace

Fronts SortFronts(const std::vector<ObjectivePoint>& points) {
  const int n = static_cast<int>(points.size());
  std::vector<std::vector<int>> dominated(n);  // the points each point dominates, ascending
  std::vector<int> count(n, 0);                // how many points dominate each point
  bool any_nan = false;
  for (const ObjectivePoint& p : points)
    for (double v : p) any_nan = any_nan || std::isnan(v);
  if (any_nan)
    DominanceLists(points, Less, &dominated, &count);
  else
    DominanceLists(
        points, [](double a, double b) { return a < b; }, &dominated, &count);
  // dominated[j] got its entries i < j before those k > j: ascending.
  Fronts f;
  f.rank.assign(n, 0);
  std::vector<int> current;
  for (int i = 0; i < n; ++i)
    if (count[i] == 0) current.push_back(i);
  int rank = 0;
  while (!current.empty()) {
    f.fronts.push_back(current);
    std::vector<int> next;
    for (int i : current) {
      f.rank[i] = rank;
      for (int j : dominated[i])
        if (--count[j] == 0) next.push_back(j);
    }
    current = std::move(next);
    ++rank;
  }
  return f;
}

std::vector<double> CrowdingDistance(const std::vector<ObjectivePoint>& front) {
  if (front.size() < 3) return std::vector<double>(front.size(), kInf);
  std::vector<pagmo::vector_double> points;
  for (const ObjectivePoint& p : front) points.push_back({p[0], p[1], p[2]});
  return pagmo::crowding_distance(points);
}

std::vector<int> SelectBest(const std::vector<ObjectivePoint>& points, int n,
                            std::vector<int>* rank) {
  std::vector<int> chosen;
  const Fronts fronts = SortFronts(points);
  for (const std::vector<int>& front : fronts.fronts) {
    const int room = n - static_cast<int>(chosen.size());
    if (static_cast<int>(front.size()) <= room) {
      chosen.insert(chosen.end(), front.begin(), front.end());
      if (static_cast<int>(chosen.size()) == n) break;
      continue;
    }
    std::vector<ObjectivePoint> members;
    for (int i : front) members.push_back(points[i]);
    const std::vector<double> crowding = CrowdingDistance(members);
    std::vector<size_t> order(front.size());
    std::iota(order.begin(), order.end(), size_t(0));
    std::sort(order.begin(), order.end(),
              [&](size_t a, size_t b) { return Greater(crowding[a], crowding[b]); });
    for (int k = 0; k < room; ++k) chosen.push_back(front[order[k]]);
    break;
  }
  if (rank) {
    rank->clear();
    for (int i : chosen) rank->push_back(fronts.rank[i]);
  }
  return chosen;
}

}  // namespace bespoke
