#include "resize/ga/ranking.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
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

// Who dominates whom, as one bit row per point: bit j of row i is set when
// point i dominates point j; `count[j]` is how many points dominate j.
// Branch-free over the pairs (the outcome of a comparison is not
// predictable), every pair compared once; `Lt` is the order (plain < when
// no objective is NaN, Less otherwise).
struct DominanceBits {
  size_t words = 0;                 // 64-bit words per row
  std::vector<std::uint64_t> bits;  // n rows of `words`
  std::vector<int> count;
};

template <typename Lt>
void Dominance(const std::vector<ObjectivePoint>& points, Lt lt, DominanceBits* d) {
  const size_t n = points.size();
  d->words = (n + 63) / 64;
  d->bits.assign(n * d->words, 0);
  d->count.assign(n, 0);
  for (size_t i = 0; i < n; ++i) {
    const ObjectivePoint& a = points[i];
    std::uint64_t* row_i = &d->bits[i * d->words];
    for (size_t j = i + 1; j < n; ++j) {
      const ObjectivePoint& b = points[j];
      const bool a_better = lt(a[0], b[0]) | lt(a[1], b[1]) | lt(a[2], b[2]);
      const bool b_better = lt(b[0], a[0]) | lt(b[1], a[1]) | lt(b[2], a[2]);
      const std::uint64_t i_wins = a_better & !b_better, j_wins = b_better & !a_better;
      row_i[j >> 6] |= i_wins << (j & 63);
      d->bits[j * d->words + (i >> 6)] |= j_wins << (i & 63);
      d->count[j] += static_cast<int>(i_wins);
      d->count[i] += static_cast<int>(j_wins);
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
  bool any_nan = false;
  for (const ObjectivePoint& p : points)
    for (double v : p) any_nan = any_nan || std::isnan(v);
  DominanceBits d;
  if (any_nan)
    Dominance(points, Less, &d);
  else
    Dominance(
        points, [](double a, double b) { return a < b; }, &d);
  Fronts f;
  f.rank.assign(n, 0);
  std::vector<int> current;
  for (int i = 0; i < n; ++i)
    if (d.count[i] == 0) current.push_back(i);
  int rank = 0;
  while (!current.empty()) {
    f.fronts.push_back(current);
    std::vector<int> next;
    for (int i : current) {
      f.rank[i] = rank;
      // The points i dominates, ascending (pagmo's order).
      const std::uint64_t* row = &d.bits[static_cast<size_t>(i) * d.words];
      for (size_t w = 0; w < d.words; ++w)
        for (std::uint64_t bits = row[w]; bits != 0; bits &= bits - 1) {
          const int j = static_cast<int>(64 * w + __builtin_ctzll(bits));
          if (--d.count[j] == 0) next.push_back(j);
        }
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
