#include "measure/landmarks/body_structure.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <utility>

#include "measure/landmarks/landmark_slices.h"
#include "scanners/core/constants.h"

namespace bespoke::landmarks {
namespace {

// The trunk's ring at 60 % of stature: the nodes of the slab 59-61 % whose
// points lie in the piece spanning x = 0 (linked within 15 mm in x, y);
// distances from the whole ring treat front and back alike.
std::vector<int> SeedRing(const BodyGraph& g, const Eigen::MatrixX3d& points, double h) {
  std::vector<int> rows;
  for (Eigen::Index r = 0; r < points.rows(); ++r)
    if (std::abs(points(r, 2) - 0.6 * h) < 0.01 * h) rows.push_back(static_cast<int>(r));
  std::vector<int> seeds;
  for (const Piece& piece : SplitPieces(points, rows, 15)) {
    if (!(piece.lo.x() < 0 && piece.hi.x() > 0)) continue;
    for (int r : piece.rows)
      if (g.Component(g.NodeOf(r)) == 0) seeds.push_back(g.NodeOf(r));
  }
  std::sort(seeds.begin(), seeds.end());
  seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
  return seeds;
}

// The ends of the body: maxima of d0 whose superlevel component lives for
// at least `persistence` before it merges into an older one (the merge tree
// of d0, swept from the farthest node down). A toe beside the heel, a thumb
// or the nose merge within a few centimetres and do not count.
std::vector<int> Extremities(const BodyGraph& g, const std::vector<double>& d0,
                             double persistence) {
  std::vector<int> order;
  for (int n = 0; n < g.size(); ++n)
    if (g.Component(n) == 0 && std::isfinite(d0[static_cast<size_t>(n)])) order.push_back(n);
  std::sort(order.begin(), order.end(),
            [&](int a, int b) { return d0[static_cast<size_t>(a)] > d0[static_cast<size_t>(b)]; });
  std::vector<int> root(static_cast<size_t>(g.size()), -1), peak(static_cast<size_t>(g.size()), -1);
  auto find = [&](int n) {
    while (root[static_cast<size_t>(n)] != n) {
      root[static_cast<size_t>(n)] = root[static_cast<size_t>(root[static_cast<size_t>(n)])];
      n = root[static_cast<size_t>(n)];
    }
    return n;
  };
  std::vector<int> ends;
  for (int n : order) {
    root[static_cast<size_t>(n)] = n, peak[static_cast<size_t>(n)] = n;
    for (const auto& [m, len] : g.Edges(n)) {
      if (root[static_cast<size_t>(m)] < 0) continue;
      const int a = find(n), b = find(m);
      if (a == b) continue;
      // The younger component (lower peak) dies here.
      int old = a, young = b;
      if (d0[static_cast<size_t>(peak[static_cast<size_t>(a)])] <
          d0[static_cast<size_t>(peak[static_cast<size_t>(b)])])
        std::swap(old, young);
      const int p = peak[static_cast<size_t>(young)];
      if (d0[static_cast<size_t>(p)] - d0[static_cast<size_t>(n)] >= persistence) ends.push_back(p);
      root[static_cast<size_t>(young)] = old;
    }
  }
  if (!order.empty()) ends.push_back(peak[static_cast<size_t>(find(order.front()))]);
  return ends;
}

// The node of `path` farthest from the straight line through its ends.
int Corner(const BodyGraph& g, const std::vector<int>& path) {
  if (path.size() < 3) return -1;
  const Eigen::Vector3d a = g.Site(path.front()), b = g.Site(path.back());
  const Eigen::Vector3d u = (b - a).normalized();
  int best = -1;
  double best_d = -1;
  for (int n : path) {
    const Eigen::Vector3d v = g.Site(n) - a;
    const double d = (v - v.dot(u) * u).norm();
    if (d > best_d) best_d = d, best = n;
  }
  return best;
}

// Limb labels of the main component's nodes; the other components' nodes
// take the label of the nearest main node within three cells, else kNone.
void LabelNodes(const BodyGraph& g, double cell_mm, std::vector<Part>* label) {
  std::vector<int> main;
  for (int n = 0; n < g.size(); ++n)
    if (g.Component(n) == 0) main.push_back(n);
  for (int n = 0; n < g.size(); ++n) {
    if (g.Component(n) == 0) continue;
    (*label)[static_cast<size_t>(n)] = Part::kNone;
    double best = 9 * cell_mm * cell_mm;
    for (int m : main) {
      const double d = (g.Site(m) - g.Site(n)).squaredNorm();
      if (d < best) best = d, (*label)[static_cast<size_t>(n)] = (*label)[static_cast<size_t>(m)];
    }
  }
}

// The arm's nodes: those nearer the hand than the armpit corner is, and,
// lateral of the corner, those whose distance grows less from the corner
// going out from the hand than going out from the trunk's ring (`d0`): the
// outside of the upper arm, which a threshold on the hand's distance alone
// leaves to the trunk (its contour tilts down the outside of the arm, so an
// arm resting on a heavy trunk would join the trunk's girths at the bust).
void LabelArm(const BodyGraph& g, const std::vector<double>& d0,
              const std::vector<double>& from_hand, int corner, int side, double cell_mm,
              std::vector<Part>* label) {
  const size_t k = static_cast<size_t>(corner);
  const double sign = side == 0 ? 1 : -1, corner_x = sign * g.Site(corner).x();
  const Part arm = side == 0 ? Part::kArmRight : Part::kArmLeft;
  for (int n = 0; n < g.size(); ++n) {
    const size_t i = static_cast<size_t>(n);
    if (!std::isfinite(from_hand[i])) continue;
    const bool near_hand = from_hand[i] < from_hand[k] - cell_mm;
    const bool outside =
        sign * g.Site(n).x() > corner_x + cell_mm && from_hand[i] - from_hand[k] < d0[i] - d0[k];
    if (near_hand || outside) (*label)[i] = arm;
  }
}

}  // namespace

BodyStructure FindBodyStructure(const BodyStructureOptions& o, const Eigen::MatrixX3d& points,
                                const Eigen::MatrixX3d& normals, double h) {
  BodyStructure s;
  BodyGraphOptions graph = o.graph;
  graph.midline_apart_below_mm = std::max(graph.midline_apart_below_mm, o.legs_apart_share * h);
  const BodyGraph g(graph, points, normals);
  const std::vector<int> ring = SeedRing(g, points, h);
  if (ring.empty()) {
    s.why = "no trunk section at 60 % of stature";
    return s;
  }
  const std::vector<double> d0 = g.Distances(ring);
  std::vector<int> ends = Extremities(g, d0, o.persistence * h);
  // Feet: the lowest extremity, and the lowest on the other side of x = 0.
  std::sort(ends.begin(), ends.end(), [&](int a, int b) { return g.Site(a).z() < g.Site(b).z(); });
  int foot[2] = {-1, -1};
  for (int n : ends) {
    if (g.Site(n).z() > 0.2 * h) break;
    const int side = g.Site(n).x() > 0 ? 0 : 1;
    if (foot[side] < 0) foot[side] = n;
  }
  if (foot[0] < 0 || foot[1] < 0) {
    s.why = "two feet were not found at the ends of the body";
    return s;
  }
  std::vector<int> upper;
  for (int n : ends)
    if (n != foot[0] && n != foot[1] && g.Site(n).z() > 0.2 * h) upper.push_back(n);
  // Head: the highest of the rest; hands: the farthest on each side.
  int head = -1, hand[2] = {-1, -1};
  for (int n : upper)
    if (head < 0 || g.Site(n).z() > g.Site(head).z()) head = n;
  for (int n : upper) {
    if (n == head) continue;
    const int side = g.Site(n).x() > 0 ? 0 : 1;
    if (hand[side] < 0 || d0[static_cast<size_t>(n)] > d0[static_cast<size_t>(hand[side])])
      hand[side] = n;
  }
  s.ok = true;
  s.head = head >= 0 ? g.Site(head) : Eigen::Vector3d(0, 0, h);
  std::vector<Part> label(static_cast<size_t>(g.size()), Part::kTrunk);
  // Legs and the crotch.
  std::vector<double> from_foot[2];
  std::vector<int> parent;
  for (int side : {0, 1}) {
    s.foot[side] = g.Site(foot[side]);
    from_foot[side] = g.Distances({foot[side]}, side == 0 ? &parent : nullptr);
  }
  const std::vector<int> between = BodyGraph::PathTo(parent, foot[1]);
  int crotch = between.front();
  for (int n : between)
    if (g.Site(n).z() > g.Site(crotch).z()) crotch = n;
  s.crotch = g.Site(crotch);
  for (int side : {0, 1}) {
    const double limit = from_foot[side][static_cast<size_t>(crotch)] - o.graph.cell_mm;
    for (int n = 0; n < g.size(); ++n)
      if (from_foot[side][static_cast<size_t>(n)] < limit)
        label[static_cast<size_t>(n)] = side == 0 ? Part::kLegRight : Part::kLegLeft;
  }
  // Arms and the armpits.
  std::vector<double> from_hand_node[2];
  for (int side : {0, 1}) {
    if (hand[side] < 0) continue;
    s.has_hand[side] = true;
    s.hand[side] = g.Site(hand[side]);
    from_hand_node[side] = g.Distances({hand[side]}, &parent);
    const int corner = Corner(g, BodyGraph::PathTo(parent, foot[side]));
    if (corner < 0 || !std::isfinite(from_hand_node[side][static_cast<size_t>(corner)])) continue;
    s.has_armpit[side] = true;
    s.armpit[side] = g.Site(corner);
    LabelArm(g, d0, from_hand_node[side], corner, side, o.graph.cell_mm, &label);
  }
  LabelNodes(g, o.graph.cell_mm, &label);
  s.part.resize(static_cast<size_t>(points.rows()));
  for (int side : {0, 1})
    if (!from_hand_node[side].empty()) s.from_hand[side].resize(static_cast<size_t>(points.rows()));
  for (Eigen::Index r = 0; r < points.rows(); ++r) {
    const int n = g.NodeOf(static_cast<int>(r));
    s.part[static_cast<size_t>(r)] = label[static_cast<size_t>(n)];
    for (int side : {0, 1})
      if (!from_hand_node[side].empty())
        s.from_hand[side][static_cast<size_t>(r)] = from_hand_node[side][static_cast<size_t>(n)];
  }
  return s;
}

void ReturnFilletToTrunk(const Eigen::MatrixX3d& points, int side, const Eigen::Vector3d& armpit,
                         int armpit_row, BodyStructure* s) {
  const std::vector<double>& d = s->from_hand[side];
  if (d.size() != static_cast<size_t>(points.rows()) || armpit_row < 0 ||
      armpit_row >= points.rows())
    return;
  const double limit = d[static_cast<size_t>(armpit_row)], sign = side == 0 ? 1 : -1;
  const Part arm = side == 0 ? Part::kArmRight : Part::kArmLeft;
  if (!std::isfinite(limit)) return;
  for (Eigen::Index r = 0; r < points.rows(); ++r) {
    const size_t i = static_cast<size_t>(r);
    if (s->part[i] != arm || !(d[i] > limit)) continue;
    if (points(r, 2) < armpit.z() && sign * points(r, 0) < sign * armpit.x())
      s->part[i] = Part::kTrunk;
  }
}

}  // namespace bespoke::landmarks
