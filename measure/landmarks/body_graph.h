// A coarse surface graph over a body scan, for the detector's structure
// (body_structure.h; internal to measure/landmarks): geodesic distances
// between body parts at a resolution of a few centimetres, cheap enough to
// compute many fields per scan.
//
// Nodes: the scan's points binned into cubic cells of `cell_mm`; within a
// cell, points whose outward normals point to opposite sides (the two faces
// of a hand, an arm against the trunk, thighs that touch) form separate
// nodes. Edges: between nodes of neighbouring cells (26-neighbourhood) whose
// sites are close, whose normals are not opposed (angle below
// max_normal_angle_deg), which do not face each other across a gap (the
// link would leave both surfaces along their normals) and which do not
// span a sharp concave fold (max_crease_angle_deg). So two skins that touch
// stay apart: the graph follows the surface, not the space or the contact
// between them.
// Without normals every pair of close sites is linked.
//
// Frame and units: the cloud's (body frame, mm). Distances in mm, +inf where
// unreachable.
#ifndef BESPOKE_MEASURE_LANDMARKS_BODY_GRAPH_H_
#define BESPOKE_MEASURE_LANDMARKS_BODY_GRAPH_H_

#include <Eigen/Core>
#include <array>
#include <limits>
#include <utility>
#include <vector>

namespace bespoke::landmarks {

struct BodyGraphOptions {
  double cell_mm = 12;                // default 12 mm: cell size of the nodes
  double max_normal_angle_deg = 110;  // default 110 deg: linked nodes' normals differ less
  double max_facing_cosine = 0.75;    // default 0.75: a link leaving both surfaces along their
                                      // normals more steeply than this is refused
  double max_link_cells = 1.8;        // default 1.8: linked sites are closer than this many cells
  // A concave link (the normal turns against the step) whose normals differ
  // by more than this is a fold where two skins meet (thighs or an arm
  // against the trunk), not a surface to walk over (default 80).
  double max_crease_angle_deg = 80;
  // Below this height (mm) no link crosses x = 0, the body's mid-sagittal
  // plane: two legs, or feet set together, touch there but never share
  // skin, and where they touch toe to toe the fronts of both face forward,
  // so the normal tests above would link them (default 0: none).
  double midline_apart_below_mm = 0;
};

class BodyGraph {
 public:
  // `points` #P x 3 (mm); `normals` #P x 3 unit outward normals, or 0 x 3.
  BodyGraph(const BodyGraphOptions& options, const Eigen::MatrixX3d& points,
            const Eigen::MatrixX3d& normals);

  int size() const { return static_cast<int>(site_.size()); }
  const Eigen::Vector3d& Site(int node) const { return site_[static_cast<size_t>(node)]; }
  const Eigen::Vector3d& Normal(int node) const { return normal_[static_cast<size_t>(node)]; }
  int Weight(int node) const { return count_[static_cast<size_t>(node)]; }
  // Node of cloud row `row` (#P entries).
  int NodeOf(int row) const { return node_of_[static_cast<size_t>(row)]; }
  // Connected component of each node (0 = the largest).
  int Component(int node) const { return component_[static_cast<size_t>(node)]; }
  // The node of the largest component whose site is nearest `x`; -1 if none.
  int Nearest(const Eigen::Vector3d& x) const;

  // Dijkstra from `sources` (distance 0 each): #nodes distances (mm), and
  // with `parent` the predecessor of each node on its shortest path (-1 at
  // sources and unreachable nodes). Nodes farther than `max_mm` stay +inf.
  std::vector<double> Distances(const std::vector<int>& sources, std::vector<int>* parent = nullptr,
                                double max_mm = std::numeric_limits<double>::infinity()) const;
  // Neighbours of `node` and the link lengths (mm).
  const std::vector<std::pair<int, double>>& Edges(int node) const {
    return edges_[static_cast<size_t>(node)];
  }
  // The nodes from `node` back to its source along `parent`.
  static std::vector<int> PathTo(const std::vector<int>& parent, int node);

 private:
  void Link(const BodyGraphOptions& options);
  void Components();

  std::vector<Eigen::Vector3d> site_, normal_;
  std::vector<int> count_, node_of_, component_;
  std::vector<std::vector<std::pair<int, double>>> edges_;  // neighbour, length (mm)
  std::vector<std::array<int, 3>> cell_;                    // cell indices of each node
};

}  // namespace bespoke::landmarks

#endif  // BESPOKE_MEASURE_LANDMARKS_BODY_GRAPH_H_
