// The shared wavefront pieces on small graphs built in code: the parent
// choice's two rules, the window chain of a path, and the scheduler's
// causality on a path graph.
#include "measure/mesh_geodesic/wavefront.h"

#include <gtest/gtest.h>

#include <vector>

#include "measure/mesh_geodesic/window_chain.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// Nodes on the plane z = 0 with given neighbours; settled ones carry a
// distance and an arrival tangent.
struct PlaneGraph {
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::vector<int>> links;
  std::vector<double> distances;  // +inf = unsettled
  std::vector<Eigen::Vector3d> tangents;

  const int* neighbours_begin(int u) const { return links[size_t(u)].data(); }
  const int* neighbours_end(int u) const {
    return links[size_t(u)].data() + links[size_t(u)].size();
  }
  bool settled(int u) const { return std::isfinite(distances[size_t(u)]); }
  double distance(int u) const { return distances[size_t(u)]; }
  const Eigen::Vector3d& tangent(int u) const { return tangents[size_t(u)]; }
  Eigen::Vector3d position(int u) const { return positions[size_t(u)]; }
  Eigen::Vector3d normal(int) const { return Eigen::Vector3d::UnitZ(); }
};

// Node 0 unsettled at the origin; neighbours 1 (behind on the x axis, its
// path arriving along +x: straight on), 2 (off to the side, nearer the
// source) and 3 (unsettled).
PlaneGraph ThreeNeighbours() {
  const double inf = std::numeric_limits<double>::infinity();
  PlaneGraph g;
  g.positions = {{0, 0, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}};
  g.links = {{1, 2, 3}, {0}, {0}, {0}};
  g.distances = {inf, 10.0, 9.5, inf};
  g.tangents = {Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitX(),
                Eigen::Vector3d::Zero()};
  return g;
}

TEST(ParentChoice, PredictedRuleTakesTheShortestPredictionUnlessTied) {
  const PlaneGraph g = ThreeNeighbours();
  // Through 1: 10 + 1 = 11 straight on. Through 2: a virtual source 9.5
  // behind 2 along +x, 1 mm to the side: hypot(9.5, 1) = 9.552.
  const ParentChoice tight = ChooseParent(g, 0, ParentRule::kPredicted, 0.1);
  EXPECT_EQ(tight.parent, 2);
  EXPECT_NEAR(tight.estimate, std::hypot(9.5, 1.0), 1e-12);
  // With a wide tie both qualify and the straighter continuation (1) wins.
  const ParentChoice tied = ChooseParent(g, 0, ParentRule::kPredicted, 2.0);
  EXPECT_EQ(tied.parent, 1);
  EXPECT_NEAR(tied.estimate, 11.0, 1e-12);
}

TEST(ParentChoice, StraightestRuleIgnoresThePredictionAndEstimatesAlongTheEdge) {
  const ParentChoice choice = ChooseParent(ThreeNeighbours(), 0, ParentRule::kStraightest, 0);
  EXPECT_EQ(choice.parent, 1);
  EXPECT_NEAR(choice.estimate, 11.0, 1e-12);
}

TEST(ParentChoice, NoSettledNeighbourGivesNoParent) {
  PlaneGraph g = ThreeNeighbours();
  g.distances[1] = g.distances[2] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(ChooseParent(g, 0, ParentRule::kPredicted, 0.1).parent, -1);
}

TEST(WindowChain, WalksParentsToTheSourceAndTakesEachWindowsPrefix) {
  // Path 0 -> 1 -> 2: node 0's window is the path's samples 0-2, node 1's
  // starts at sample 1 (4 samples: 1-4), node 2's at sample 3 (3 samples).
  const std::vector<int> parent = {-1, 0, 1}, start = {0, 1, 3}, size = {3, 4, 3};
  const auto chain = WindowChain(2, parent, start, [&](int u) { return size[size_t(u)]; });
  const std::vector<std::pair<int, int>> expected = {{0, 1}, {1, 2}, {2, 3}};
  EXPECT_EQ(chain, expected);
  const Eigen::MatrixX3d path = ChainPolyline(
      chain,
      [&](int u, int i) {
        static Eigen::Vector3d point;
        point = Eigen::Vector3d(start[size_t(u)] + i, 0, 0);
        return std::pair<const Eigen::Vector3d&, int>(point, u);
      },
      nullptr);
  ASSERT_EQ(path.rows(), 6);
  for (Eigen::Index i = 0; i < 6; ++i) EXPECT_EQ(path(i, 0), static_cast<double>(i));
}

TEST(WindowChain, ABrokenChainIsAnInternalError) {
  const std::vector<int> parent = {-1, -1}, start = {0, 2}, size = {3, 3};
  EXPECT_THROW(WindowChain(1, parent, start, [&](int u) { return size[size_t(u)]; }),
               InternalError);
}

// A path graph 0 - 1 - ... - n-1 with unit edges, settled from node 0: each
// node's distance is its parent's + 1; the order of settling is recorded.
struct LineSolver {
  explicit LineSolver(int n) : distances(size_t(n), -1) {
    for (int i = 0; i < n; ++i) {
      links.push_back({});
      if (i > 0) links.back().push_back(i - 1);
      if (i + 1 < n) links.back().push_back(i + 1);
    }
    distances[0] = 0;
  }
  int num_nodes() const { return static_cast<int>(links.size()); }
  const int* neighbours_begin(int u) const { return links[size_t(u)].data(); }
  const int* neighbours_end(int u) const {
    return links[size_t(u)].data() + links[size_t(u)].size();
  }
  bool settled(int u) const { return distances[size_t(u)] >= 0; }
  std::int64_t settled_count() const { return 1 + static_cast<std::int64_t>(order.size()); }
  ParentChoice ChooseParent(int u) const {
    for (const int v : links[size_t(u)])
      if (settled(v)) return {v, distances[size_t(v)] + 1};
    return {};
  }
  void Settle(int u, int parent) {
    distances[size_t(u)] = distances[size_t(parent)] + 1;
    order.push_back(u);
  }
  std::vector<std::vector<int>> links;
  std::vector<double> distances;
  std::vector<int> order;
};

TEST(Wavefront, SettlesInOrderOfDistanceAndStopsAtTheTarget) {
  LineSolver solver(20);
  Wavefront wavefront(solver.num_nodes(), 0.5);
  wavefront.Seed(0);
  wavefront.set_r_max(0.5);
  wavefront.Run(solver, 7, "test", 1000, nullptr);
  EXPECT_TRUE(solver.settled(7));
  EXPECT_FALSE(solver.settled(9));  // held back by r_max
  EXPECT_FALSE(wavefront.done());
  wavefront.Run(solver, -1, "test", 1000, nullptr);  // continues where it stopped
  EXPECT_TRUE(wavefront.done());
  ASSERT_EQ(solver.order.size(), 19u);
  for (size_t i = 0; i < solver.order.size(); ++i) EXPECT_EQ(solver.order[i], int(i) + 1);
  EXPECT_GE(wavefront.rounds(), 18);  // r_max grew by half an edge at a time
}

TEST(WavefrontOptions, CheckRejectsOutOfRangeValues) {
  WavefrontOptions options;
  EXPECT_NO_THROW(options.Check());
  options.window = 2;
  EXPECT_THROW(options.Check(), InputError);
  options = WavefrontOptions();
  options.band_spacings = -1;
  EXPECT_THROW(options.Check(), InputError);
  options = WavefrontOptions();
  options.flow_tolerance_spacings = 0;
  EXPECT_THROW(options.Check(), InputError);
}

}  // namespace
}  // namespace bespoke
