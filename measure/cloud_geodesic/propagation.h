// Wavefront propagation of geodesics over a CloudGrid: thesis Algorithm 5
// (Algorithm 3's "continuous Dijkstra" without a priority queue, on cells),
// built on the mesh solver's wavefront (measure/mesh_geodesic/wavefront.h),
// parent choice and path reconstruction, with grid nodes for vertices.
//
// From a source point on the surface (mm, scan frame) every reachable grid
// node gets a geodesic: a polyline from the source to the node's site, and its
// length (mm). A new node inherits its parent's path plus its own site (no
// backtracing) and the curvature flow (curvature_flow.h) straightens the last
// `window` samples, the first of them held fixed (Algorithm 3/5), or the whole
// path (`whole_path`, Algorithm 2). Option lengths are in cell sizes.
// A flow may not cut across a gap: if a step between consecutive samples
// leaves the surface (CloudGrid::StepOnSurface: nodes far apart in the graph
// and not on one smooth surface - e.g. straightening round a lip would pass
// through it) the flow is undone and the node keeps the inherited polyline,
// which follows links (counted in stats().undone). Crossing a hole in the
// scan on one smooth surface is allowed.
//
// Memory: each node stores only its window (<= w samples) and where it
// starts in its parent's path, so memory is O(n * w); the full path is
// rebuilt on demand (window_chain.h), O(length). With `whole_path` each node
// stores its whole path: O(n * path length).
//
// The object keeps its state so a query can stop when a target is settled and
// a later query from the same source continues where it stopped.
#ifndef BESPOKE_MEASURE_CLOUD_GEODESIC_PROPAGATION_H_
#define BESPOKE_MEASURE_CLOUD_GEODESIC_PROPAGATION_H_

#include <cstdint>
#include <utility>
#include <vector>

#include "measure/cloud_geodesic/cloud_grid.h"
#include "measure/mesh_geodesic/curvature_flow.h"
#include "measure/mesh_geodesic/wavefront.h"
#include "scanners/core/progress.h"

namespace bespoke {

// The propagation's settings (lengths in cell sizes) and counters.
using PropagationOptions = WavefrontOptions;
using PropagationStats = WavefrontStats;

// The window samples of all settled nodes. A propagation can be handed the
// pool of one that is done with (TakePool), so a run of propagations reuses
// its memory instead of growing and faulting in fresh pages each time.
struct PropagationPool {
  std::vector<Eigen::Vector3d> points;  // mm
  std::vector<int> hints;               // grid node of each sample
  std::vector<TangentPlane> planes;     // its last tangent plane
};

class Propagation {
 public:
  // `source`: a point on the surface (mm) inside node `source_node` of `grid`
  // (see CloudGrid::LocateNode). The grid must outlive this object.
  // `recycled`: storage to reuse (emptied first); its contents do not matter.
  Propagation(const PropagationOptions& options, const CloudGrid& grid,
              const Eigen::Vector3d& source, int source_node, PropagationPool recycled = {});
  // A source in an unscanned region (a hole of the scan, e.g. the crotch):
  // every node in `seeds` (the scanned rim around it, non-empty, the first
  // the nearest) starts with the straight chord source -> its site as its
  // path and the chord's length as its distance - the hole spanned by
  // straight lines - and the wavefront grows from all of them at once. The
  // chords are shortest (triangle inequality), so causality still holds.
  Propagation(const PropagationOptions& options, const CloudGrid& grid,
              const Eigen::Vector3d& source, const std::vector<int>& seeds,
              PropagationPool recycled = {});

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
  // Moves the sample storage out for a next propagation; this object can
  // then only be destroyed.
  PropagationPool TakePool() { return std::move(pool_); }

 private:
  void Init();
  ParentChoice ChooseParent(int node) const;
  void Settle(int node, int parent);
  void Store(int node, const Eigen::MatrixX3d& window, const std::vector<int>& hints,
             const std::vector<TangentPlane>& planes);

  friend class Wavefront;
  template <class View>
  friend ParentChoice ChooseParent(const View&, int, ParentRule, double);
  // The solver interface of Wavefront and ChooseParent (parent_choice.h).
  int num_nodes() const { return grid_.num_nodes(); }
  const int* neighbours_begin(int node) const { return grid_.links_begin(node); }
  const int* neighbours_end(int node) const { return grid_.links_end(node); }
  std::int64_t settled_count() const { return stats_.settled; }
  double distance(int node) const { return distance_[static_cast<size_t>(node)]; }
  const Eigen::Vector3d& position(int node) const { return grid_.site(node); }
  Eigen::Vector3d normal(int node) const { return grid_.surface(node).normal(); }

  PropagationOptions options_;
  CurvatureFlowOptions flow_;  // options_ in mm for this grid
  const CloudGrid& grid_;
  Eigen::Vector3d source_;
  int source_node_;
  std::vector<double> distance_, prefix_;    // per node: length, length before the window
  std::vector<int> parent_, start_, count_;  // window start index in the path, its size
  std::vector<std::int64_t> offset_;         // window position in the pool
  std::vector<Eigen::Vector3d> tangent_;
  PropagationPool pool_;
  Wavefront wavefront_;
  PropagationStats stats_;
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CLOUD_GEODESIC_PROPAGATION_H_
