#include "resize/ga/ranking.h"

#include <gtest/gtest.h>

#include <cmath>
#include <pagmo/utils/multi_objective.hpp>
#include <random>

namespace bespoke {
namespace {

// Random points on a coarse lattice, so ties and duplicates are common;
// for odd seeds a few objectives are NaN.
std::vector<ObjectivePoint> RandomPoints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> level(0, 6);
  std::vector<ObjectivePoint> points(n);
  for (ObjectivePoint& p : points) p = {0.5 * level(rng), 0.25 * level(rng), 1.0 * level(rng)};
  if (seed % 2 == 1)
    for (int k = 0; k < n; k += 17) points[k][k % 3] = std::nan("");
  return points;
}

std::vector<pagmo::vector_double> ToPagmo(const std::vector<ObjectivePoint>& points) {
  std::vector<pagmo::vector_double> out;
  for (const ObjectivePoint& p : points) out.push_back({p[0], p[1], p[2]});
  return out;
}

TEST(Ranking, FrontsMatchPagmo) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const std::vector<ObjectivePoint> points = RandomPoints(120, seed);
    const auto expected = pagmo::fast_non_dominated_sorting(ToPagmo(points));
    const Fronts got = SortFronts(points);
    const auto& fronts = std::get<0>(expected);
    ASSERT_EQ(got.fronts.size(), fronts.size()) << seed;
    for (size_t f = 0; f < fronts.size(); ++f) {
      ASSERT_EQ(got.fronts[f].size(), fronts[f].size()) << seed;
      for (size_t k = 0; k < fronts[f].size(); ++k)
        EXPECT_EQ(got.fronts[f][k], static_cast<int>(fronts[f][k])) << seed;
    }
    const auto& ranks = std::get<3>(expected);
    for (size_t i = 0; i < points.size(); ++i)
      EXPECT_EQ(got.rank[i], static_cast<int>(ranks[i])) << seed;
  }
}

TEST(Ranking, SelectionMatchesPagmo) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const std::vector<ObjectivePoint> points = RandomPoints(200, seed);
    for (int n : {1, 37, 100, 199}) {
      const auto expected = pagmo::select_best_N_mo(ToPagmo(points), n);
      const std::vector<int> got = SelectBest(points, n);
      ASSERT_EQ(got.size(), expected.size());
      for (size_t k = 0; k < got.size(); ++k)
        EXPECT_EQ(got[k], static_cast<int>(expected[k])) << seed << " " << n;
    }
  }
}

// The ranks SelectBest gives are the chosen points' fronts among themselves.
TEST(Ranking, SelectionRanksAreTheFrontsOfTheChosen) {
  for (unsigned seed = 1; seed <= 20; ++seed) {
    const std::vector<ObjectivePoint> points = RandomPoints(200, seed);
    for (int n : {1, 37, 100, 199}) {
      std::vector<int> rank;
      const std::vector<int> chosen = SelectBest(points, n, &rank);
      std::vector<ObjectivePoint> kept;
      for (int i : chosen) kept.push_back(points[i]);
      EXPECT_EQ(rank, SortFronts(kept).rank) << seed << " " << n;
    }
  }
}

TEST(Ranking, ADominatedPointIsInALaterFront) {
  const Fronts f = SortFronts({{1, 1, 1}, {2, 2, 2}, {0, 3, 1}, {1, 1, 1}});
  EXPECT_EQ(f.rank, (std::vector<int>{0, 1, 0, 0}));
}

}  // namespace
}  // namespace bespoke
