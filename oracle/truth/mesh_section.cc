#include "oracle/truth/mesh_section.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

#include "measure/tape/convex_hull_2d.h"
#include "scanners/core/cell_key.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

Eigen::Vector3d UnitNormal(const Eigen::Vector3d& normal) {
  const double length = normal.norm();
  if (!(length > 0) || !std::isfinite(length))
    throw InputError("mesh section: the plane normal is zero or not finite");
  return normal / length;
}

// The section as a graph: crossing points (one per crossed mesh edge) and,
// per crossing, the (up to two, more at non-manifold edges) crossings it is
// joined to by a face's segment.
struct SectionGraph {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> neighbours;
};

SectionGraph BuildGraph(const TriangleMesh& mesh, const Eigen::Vector3d& p,
                        const Eigen::Vector3d& n) {
  const Eigen::VectorXd d = (mesh.vertices.rowwise() - p.transpose()) * n;
  SectionGraph g;
  std::unordered_map<std::uint64_t, int> crossing_of_edge;
  auto crossing = [&](int a, int b) {
    const auto [it, added] = crossing_of_edge.emplace(EdgeKey(a, b), 0);
    if (added) {
      if (a > b) std::swap(a, b);  // same point from both faces, bit for bit
      const double t = d[a] / (d[a] - d[b]);
      it->second = static_cast<int>(g.points.size());
      g.points.push_back(mesh.vertices.row(a).transpose() +
                         t * (mesh.vertices.row(b) - mesh.vertices.row(a)).transpose());
      g.neighbours.emplace_back();
    }
    return it->second;
  };
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    int ends[2], count = 0;
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.faces(f, k), b = mesh.faces(f, (k + 1) % 3);
      if ((d[a] >= 0) != (d[b] >= 0) && count < 2) ends[count++] = crossing(a, b);
    }
    if (count == 2) {
      g.neighbours[static_cast<std::size_t>(ends[0])].push_back(ends[1]);
      g.neighbours[static_cast<std::size_t>(ends[1])].push_back(ends[0]);
    }
  }
  return g;
}

// Walks from `start` along unused segments; returns the chain of crossings.
std::vector<int> Walk(const SectionGraph& g, int start, std::vector<std::vector<bool>>* used) {
  std::vector<int> chain = {start};
  int current = start;
  while (true) {
    int next = -1;
    const auto& nb = g.neighbours[static_cast<std::size_t>(current)];
    for (std::size_t i = 0; i < nb.size(); ++i) {
      if ((*used)[static_cast<std::size_t>(current)][i]) continue;
      next = nb[i];
      (*used)[static_cast<std::size_t>(current)][i] = true;
      // Mark the same segment seen from the other end.
      const auto& back = g.neighbours[static_cast<std::size_t>(next)];
      for (std::size_t j = 0; j < back.size(); ++j)
        if (back[j] == current && !(*used)[static_cast<std::size_t>(next)][j]) {
          (*used)[static_cast<std::size_t>(next)][j] = true;
          break;
        }
      break;
    }
    if (next < 0 || next == start) return chain;
    chain.push_back(next);
    current = next;
  }
}

SectionLoop ToLoop(const SectionGraph& g, const std::vector<int>& chain, bool closed) {
  SectionLoop loop;
  loop.closed = closed;
  loop.points.resize(static_cast<Eigen::Index>(chain.size()), 3);
  for (std::size_t i = 0; i < chain.size(); ++i)
    loop.points.row(static_cast<Eigen::Index>(i)) = g.points[static_cast<std::size_t>(chain[i])];
  return loop;
}

}  // namespace

std::vector<SectionLoop> SectionLoops(const TriangleMesh& mesh, const Eigen::Vector3d& plane_point,
                                      const Eigen::Vector3d& plane_normal) {
  mesh.CheckIndices();
  const Eigen::Vector3d n = UnitNormal(plane_normal);
  const SectionGraph g = BuildGraph(mesh, plane_point, n);
  std::vector<std::vector<bool>> used(g.points.size());
  for (std::size_t i = 0; i < g.points.size(); ++i) used[i].assign(g.neighbours[i].size(), false);
  std::vector<SectionLoop> loops;
  // Open chains first: start at crossings with a single segment (boundary).
  for (std::size_t i = 0; i < g.points.size(); ++i) {
    if (g.neighbours[i].size() != 1 || used[i][0]) continue;
    loops.push_back(ToLoop(g, Walk(g, static_cast<int>(i), &used), /*closed=*/false));
  }
  for (std::size_t i = 0; i < g.points.size(); ++i) {
    for (std::size_t k = 0; k < g.neighbours[i].size(); ++k) {
      if (used[i][k]) continue;
      const std::vector<int> chain = Walk(g, static_cast<int>(i), &used);
      if (chain.size() >= 2) loops.push_back(ToLoop(g, chain, /*closed=*/true));
    }
  }
  return loops;
}

double DistanceToLoop(const SectionLoop& loop, const Eigen::Vector3d& point) {
  const Eigen::Index k = loop.points.rows();
  if (k == 0) return std::numeric_limits<double>::infinity();
  double best = (loop.points.row(0).transpose() - point).norm();
  const Eigen::Index segments = loop.closed ? k : k - 1;
  for (Eigen::Index i = 0; i < segments; ++i) {
    const Eigen::Vector3d a = loop.points.row(i), b = loop.points.row((i + 1) % k);
    const Eigen::Vector3d ab = b - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0 ? std::clamp((point - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * ab - point).norm());
  }
  return best;
}

int NearestLoop(const std::vector<SectionLoop>& loops, const Eigen::Vector3d& point) {
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const double d = DistanceToLoop(loops[i], point);
    if (d < best_distance) best_distance = d, best = static_cast<int>(i);
  }
  return best;
}

namespace {

// An orthonormal basis (u, v) of the plane with unit normal n.
std::pair<Eigen::Vector3d, Eigen::Vector3d> PlaneBasis(const Eigen::Vector3d& n) {
  const Eigen::Vector3d helper =
      std::abs(n.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d u = n.cross(helper).normalized();
  return {u, n.cross(u)};
}

}  // namespace

int EnclosingLoop(const std::vector<SectionLoop>& loops, const Eigen::Vector3d& point,
                  const Eigen::Vector3d& plane_normal) {
  const auto [u, v] = PlaneBasis(UnitNormal(plane_normal));
  const double px = point.dot(u), py = point.dot(v);
  int best = -1;
  double best_area = std::numeric_limits<double>::infinity();
  for (std::size_t l = 0; l < loops.size(); ++l) {
    if (!loops[l].closed) continue;
    const Eigen::VectorXd x = loops[l].points * u, y = loops[l].points * v;
    const Eigen::Index k = x.size();
    bool inside = false;
    double area = 0;
    for (Eigen::Index i = 0, j = k - 1; i < k; j = i++) {
      if ((y[i] > py) != (y[j] > py) && px < (x[j] - x[i]) * (py - y[i]) / (y[j] - y[i]) + x[i])
        inside = !inside;
      area += x[j] * y[i] - x[i] * y[j];
    }
    if (inside && std::abs(area) < best_area)
      best_area = std::abs(area), best = static_cast<int>(l);
  }
  return best;
}

double LoopHullPerimeter(const SectionLoop& loop, const Eigen::Vector3d& plane_normal) {
  const auto [u, v] = PlaneBasis(UnitNormal(plane_normal));
  Eigen::MatrixX2d projected(loop.points.rows(), 2);
  projected.col(0) = loop.points * u;
  projected.col(1) = loop.points * v;
  return ConvexHullPerimeter(projected);
}

std::vector<int> TrunkLoopIndices(const std::vector<SectionLoop>& loops, int main) {
  if (main < 0 || main >= static_cast<int>(loops.size())) return {};
  const Eigen::MatrixX3d& trunk = loops[static_cast<std::size_t>(main)].points;
  std::vector<int> out{main};
  if (trunk.rows() == 0) return out;
  const double lo = trunk.col(0).minCoeff(), hi = trunk.col(0).maxCoeff();
  const double margin = 0.1 * (hi - lo);
  for (int i = 0; i < static_cast<int>(loops.size()); ++i) {
    const SectionLoop& loop = loops[static_cast<std::size_t>(i)];
    if (i == main || !loop.closed || loop.points.rows() < 3) continue;
    const double x = loop.points.col(0).mean();
    if (x > lo + margin && x < hi - margin) out.push_back(i);
  }
  return out;
}

SectionLoop MergedLoops(const std::vector<SectionLoop>& loops, const std::vector<int>& indices) {
  SectionLoop all;
  Eigen::Index rows = 0;
  for (int i : indices) rows += loops.at(static_cast<std::size_t>(i)).points.rows();
  all.points.resize(rows, 3);
  rows = 0;
  for (int i : indices) {
    const SectionLoop& loop = loops[static_cast<std::size_t>(i)];
    all.points.middleRows(rows, loop.points.rows()) = loop.points;
    rows += loop.points.rows();
    all.closed = all.closed && loop.closed;
  }
  return all;
}

double LoopLength(const SectionLoop& loop) {
  const Eigen::Index k = loop.points.rows();
  double length = 0;
  for (Eigen::Index i = 0; i + 1 < k; ++i)
    length += (loop.points.row(i + 1) - loop.points.row(i)).norm();
  if (loop.closed && k > 2) length += (loop.points.row(0) - loop.points.row(k - 1)).norm();
  return length;
}

}  // namespace bespoke
