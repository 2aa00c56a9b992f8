// Wavefront propagation of geodesics over a CloudGrid: thesis Algorithm 5
// (Algorithm 3's "continuous Dijkstra" without a priority queue, on cells).
//
// From a source point on the surface (mm, scan frame) every reachable grid
// node gets a geodesic: a polyline from the source to the node's site, and its
// length (mm). Wavefronts W (being expanded), W' (settled this pass, expanded
// next) and W_next (nodes with neighbours held back) and the radius limit
// r_max keep causality: a node is settled only when its estimated distance is
// <= r_max; when W and W' run dry, r_max grows and W_next is expanded.
// A new node's parent is chosen among its settled linked neighbours: the one
// whose path continues straightest into it (the thesis's rule), among those
// whose predicted distance is within `tie_cells` cell sizes of the smallest
// (the default rule; `kStraightest` alone is the thesis's). The node inherits
// the parent's path plus its own site (no backtracing) and the curvature flow
// (curvature_flow.h) straightens the last `window` samples, the first of them
// held fixed (Algorithm 3/5), or the whole path (`whole_path`, Algorithm 2).
// A flow may not cut across a gap: if a step between consecutive samples
// leaves the surface (CloudGrid::StepOnSurface: nodes far apart in the graph
// and not on one smooth surface - e.g. straightening round a lip would pass
// through it) the flow is undone and the node keeps the inherited polyline,
// which follows links (counted in stats().rejected). Crossing a hole in the
// scan on one smooth surface is allowed.
//
// Memory: paths share prefixes. Each node stores only its window (<= w
// samples) and where it starts in its parent's path, so memory is O(n * w),
// and the full path is rebuilt on demand by walking parent links, O(length).
// With `whole_path` each node stores its whole path: O(n * path length).
//
// The object keeps its state so a query can stop when a target is settled and
// a later query from the same source continues where it stopped.
#ifndef BESPOKE_MEASURE_CLOUD_GEODESIC_PROPAGATION_H_
#define BESPOKE_MEASURE_CLOUD_GEODESIC_PROPAGATION_H_

#include <cstdint>
#include <vector>

#include "measure/cloud_geodesic/cloud_grid.h"
#include "measure/mesh_geodesic/curvature_flow.h"
#include "scanners/core/progress.h"

namespace bespoke {

enum class ParentRule {
  kStraightest,  // the thesis: the settled neighbour whose path turns least
  kPredicted,    // straightest among those predicting the shortest distance
};

struct PropagationOptions {
  int window = 30;          // w, samples flowed per new node; default 30 (thesis)
  bool whole_path = false;  // flow every node's whole path (Algorithm 2); default off
  double band_cells = 0.5;  // r_max grows by this many cell sizes per round; 0 = the
                            // thesis's r_max = largest held-back estimate. Default 0.5
  ParentRule parent_rule = ParentRule::kPredicted;  // default kPredicted
  double tie_cells = 0.05;  // kPredicted: distance ties within this many cells; default 0.05
  // The flow run for each new node, in units of the grid's cell size so that
  // one setting suits bodies in mm and small objects alike:
  int flow_iterations = 6;              // at most this many iterations; default 6
  double flow_tolerance_cells = 0.005;  // converged below this move; default 0.005 cells
  double replan_cells = 0.1;            // planes re-estimated after a slide of 0.1 cells
  double max_step_segments = 1.0;       // trust region, see CurvatureFlowOptions; default 1
  void Check() const;                   // InputError when out of range
};

struct PropagationStats {
  std::int64_t settled = 0;          // nodes with a geodesic
  std::int64_t flows = 0;            // curvature-flow solves
  std::int64_t flow_iterations = 0;  // their iterations in total
  std::int64_t unconverged = 0;      // solves that hit max_iterations
  std::int64_t rejected = 0;         // flows undone: they cut between unlinked nodes
  std::int64_t rounds = 0;           // times r_max grew
};

class Propagation {
 public:
  // `source`: a point on the surface (mm) inside node `source_node` of `grid`
  // (see CloudGrid::LocateNode). The grid must outlive this object.
  Propagation(const PropagationOptions& options, const CloudGrid& grid,
              const Eigen::Vector3d& source, int source_node);
  // A source in an unscanned region (a hole of the scan, e.g. the crotch):
  // every node in `seeds` (the scanned rim around it, non-empty, the first
  // the nearest) starts with the straight chord source -> its site as its
  // path and the chord's length as its distance - the hole spanned by
  // straight lines - and the wavefront grows from all of them at once. The
  // chords are shortest (triangle inequality), so causality still holds.
  Propagation(const PropagationOptions& options, const CloudGrid& grid,
              const Eigen::Vector3d& source, const std::vector<int>& seeds);

  // Propagates until node `target` is settled, or everything reachable when
  // `target` < 0. Cheap when already done.
  void Run(int target, Progress* progress = nullptr);

  const Eigen::Vector3d& source() const { return source_; }
  int source_node() const { return source_node_; }
  bool settled(int node) const { return count_[static_cast<size_t>(node)] > 0; }
  // Geodesic length from the source to the node's site (mm); +inf if not settled.
  double distance_mm(int node) const { return distance_[static_cast<size_t>(node)]; }
  // The node whose path this node's path continues; -1 for the source node.
  int parent(int node) const { return parent_[static_cast<size_t>(node)]; }
  // Unit direction of the path arriving at the node's site, in its tangent
  // plane (the distance gradient); zero at a source-coincident site.
  const Eigen::Vector3d& tangent(int node) const { return tangent_[static_cast<size_t>(node)]; }
  // The full polyline source -> site (#S x 3, mm) and its samples' hint nodes.
  Eigen::MatrixX3d Path(int node, std::vector<int>* hints = nullptr) const;
  // First-order distance at a point `x` near settled node `node`: the
  // distance from a virtual source behind the node along its tangent,
  // measured in the node's tangent plane (exact on a plane). +inf if unsettled.
  double DistanceNear(int node, const Eigen::Vector3d& x) const;

  const PropagationStats& stats() const { return stats_; }
  std::int64_t memory_bytes() const;

 private:
  struct Choice {
    int parent = -1;
    double estimate = 0;
  };
  void Init();
  Choice ChooseParent(int node) const;
  void Settle(int node, int parent);
  void Store(int node, const Eigen::MatrixX3d& window, const std::vector<int>& hints,
             const std::vector<TangentPlane>& planes);

  PropagationOptions options_;
  CurvatureFlowOptions flow_;  // options_ in mm for this grid
  const CloudGrid& grid_;
  Eigen::Vector3d source_;
  int source_node_;
  std::vector<double> distance_, prefix_;    // per node: length, length before the window
  std::vector<int> parent_, start_, count_;  // window start index in the path, its size
  std::vector<std::int64_t> offset_;         // window position in the pool
  std::vector<Eigen::Vector3d> tangent_;
  std::vector<Eigen::Vector3d> pool_;  // window samples of all settled nodes
  std::vector<int> pool_hints_;
  std::vector<TangentPlane> pool_planes_;  // their last tangent planes
  std::vector<int> front_, next_, stamp_;  // W / W', W_next, dedup of W_next
  double r_max_ = 0, min_held_ = 0, max_held_ = 0;
  bool done_ = false;
  PropagationStats stats_;
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CLOUD_GEODESIC_PROPAGATION_H_
