// Geodesics over a scanned surface, computed directly on the point cloud (no
// mesh): the entry point for measurements, `bespoke geodesic` and benchmarks.
//
// Holds the grid (cloud_grid.h: cells, sheet-aware nodes and links, FLANN
// index, local surfaces) so that many queries on one scan are cheap, and the
// propagation of the last source, so point-to-point queries sharing a start
// point reuse it. Not thread-safe (that cache); one object per thread.
//
//   DistancesFrom(source): single source to all destinations: a distance per
//     grid node (Algorithm 5) and per scan point (point_field.h: a sweep over
//     the points along the grid's surface connections, which resolves
//     features about a cell thick; or, with point_field.enabled = false, the
//     node's distance carried to the point to first order along its path).
//   Between(from, to): point to point. Propagates only until the target's
//     node is settled, then flows the whole inherited path (resampled to
//     polish_spacing_mm) with its true end points: the windowed propagation
//     finds the route, the final flow makes it locally shortest. Where that
//     flow cuts across a gap, the path is split there and its parts flowed
//     apart (polish_splits).
//
// Coordinates are in the scan's frame and units (mm). A query point that is
// not finite, or farther than max_snap_distance_mm from every scan point,
// throws InputError saying so; so does a pair with no surface path between
// them (different pieces of the cloud).
#ifndef BESPOKE_MEASURE_CLOUD_GEODESIC_CLOUD_GEODESICS_H_
#define BESPOKE_MEASURE_CLOUD_GEODESIC_CLOUD_GEODESICS_H_

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "measure/cloud_geodesic/cloud_geodesics_options.h"
#include "measure/cloud_geodesic/cloud_grid.h"
#include "measure/cloud_geodesic/propagation.h"

namespace bespoke {

struct CloudDistanceField {
  Eigen::VectorXd node_distance_mm;                  // #nodes, +inf where unreachable
  Eigen::VectorXd point_distance_mm;                 // #P, +inf where unreachable
  Eigen::Vector3d source = Eigen::Vector3d::Zero();  // snapped onto the surface, mm
  PropagationStats stats;
};

struct CloudGeodesicPath {
  double length_mm = 0;             // geodesic length
  Eigen::MatrixX3d points;          // #S x 3 polyline, from the snapped `from` to `to`, mm
  double propagated_length_mm = 0;  // the wavefront's estimate, before the final flow
  bool polish_converged = true;
  int polish_iterations = 0;
  bool polish_rejected = false;    // some part of the final flow cut across a gap and was undone
  std::int64_t nodes_settled = 0;  // size of the propagation behind the answer
  // How far each query point was moved onto the scanned surface (mm), and
  // whether it lay in an unscanned region (farther than max_snap_distance_mm):
  // then the length runs from the nearest scanned skin, not from the point,
  // and a measurement built on it should say so.
  double from_snap_mm = 0, to_snap_mm = 0;
  bool from_unscanned = false, to_unscanned = false;
};

class CloudGeodesics {
 public:
  // Builds the grid over `points` (#P x 3, mm). Throws InputError as
  // CloudGrid does.
  CloudGeodesics(const CloudGeodesicsOptions& options, const Eigen::MatrixX3d& points,
                 Progress* progress = nullptr);
  // With the points' outward normals (#P x 3, or 0 x 3 for none): sheets
  // closer than the point spacing are told apart by which way they face
  // (see CloudGrid). They must face outwards consistently: a patch turned
  // the wrong way cuts the surface (docs/geodesics.md). The measuring passes
  // none (measured: no gain).
  CloudGeodesics(const CloudGeodesicsOptions& options, const Eigen::MatrixX3d& points,
                 const Eigen::MatrixX3d& normals, Progress* progress = nullptr);
  ~CloudGeodesics();

  // Another solver on this one's grid (shared, read-only: its queries are
  // thread-safe) with a cache of its own, for another thread; the grid is
  // not built again.
  std::unique_ptr<CloudGeodesics> Fork() const;

  const CloudGrid& grid() const { return grid_; }
  const CloudGeodesicsOptions& options() const { return options_; }

  CloudDistanceField DistancesFrom(const Eigen::Vector3d& source, Progress* progress = nullptr);
  CloudGeodesicPath Between(const Eigen::Vector3d& from, const Eigen::Vector3d& to);
  // Of the scan points `targets` (#T row indices into the scan), the one
  // with the least first-order geodesic distance from `from` plus its
  // `extra_mm` (#T, mm; e.g. a bridge on from it): its position in
  // `targets`, -1 when none is reachable; `cost_mm` gets that sum. The
  // propagation goes only as far as the targets that can still win (a
  // target's straight distance bounds its cost from below), and
  // Between(from, its point) then reuses it.
  int NearestOf(const Eigen::Vector3d& from, const std::vector<int>& targets,
                const std::vector<double>& extra_mm, double* cost_mm);
  // Distances from the last DistancesFrom source to other points near the
  // surface (#Q x 3, mm; e.g. a mesh's vertices): each point takes the
  // distance of its nearest scan point on the source's piece of the scan plus
  // the change of that point's node's first-order field between the two (a
  // scan point gets exactly its DistancesFrom value).
  // +inf where unreachable. InputError before any DistancesFrom call.
  Eigen::VectorXd DistancesAt(const Eigen::MatrixX3d& points);

  // `x` moved onto the surface and its node; InputError (naming `what`, e.g.
  // "--from") when not finite or too far from the scan (see
  // max_snap_distance_mm and max_hole_snap_distance_mm). The node is taken in
  // connected component `component` when one is near enough; with -1, in the
  // nearest point's component unless that is a small island (under 5 % of
  // the largest component's points, e.g. a stray patch in the crotch) and the
  // largest is near enough. `snap_mm`: distance from `x` to the returned
  // point; `unscanned`: whether `x` was accepted as lying in an unscanned region.
  std::pair<Eigen::Vector3d, int> Snap(const Eigen::Vector3d& x, const std::string& what,
                                       int component = -1, double* snap_mm = nullptr,
                                       bool* unscanned = nullptr) const;

 private:
  // The cached propagation's storage for the next one (the cache is emptied).
  PropagationPool TakeCachedPool();
  Propagation& PropagationFrom(const Eigen::Vector3d& source, int node);
  Propagation& HolePropagationFrom(const Eigen::Vector3d& source, double distance, int node);
  std::vector<int> RimNodes(const Eigen::Vector3d& x, double distance, int node) const;
  CloudGeodesicPath BetweenAcrossHoles(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                                       int node_a, int node_b, double snap_a, double snap_b,
                                       bool hole_a, bool hole_b);
  bool InUnscannedRegion(const Eigen::Vector3d& x, double distance, int node) const;
  // From `start` (on the surface, in `node`) to the best rim node round `x`
  // (in a hole, `distance` mm off, nearest point in `x_node`) by propagated
  // distance plus chord, flowed (Polished), then the chord; +inf if none.
  CloudGeodesicPath FromScannedEnd(const Eigen::Vector3d& start, int node, const Eigen::Vector3d& x,
                                   double distance, int x_node);
  // Flows `path` (#S x 3, mm; `hints` its #S grid nodes) into a locally
  // shortest path, ends held, when options_.polish (`result`'s polish fields
  // say how); returns its length over the surface (mm).
  double Polished(Eigen::MatrixX3d* path, std::vector<int>* hints, CloudGeodesicPath* result) const;
  void SweepPoints(const Eigen::Vector3d& point, const std::vector<int>& rim_nodes);
  static std::string FormatPoint(const Eigen::Vector3d& x);  // "(x, y, z)", mm

  CloudGeodesics(const CloudGeodesicsOptions& options, std::shared_ptr<const CloudGrid> grid);

  CloudGeodesicsOptions options_;
  std::shared_ptr<const CloudGrid> shared_grid_;  // shared with forks
  const CloudGrid& grid_;
  std::unique_ptr<Propagation> cached_;
  std::optional<Eigen::Vector3d> field_source_;  // source of the last DistancesFrom
  Eigen::VectorXd field_distance_;               // and its per-point distances, mm
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CLOUD_GEODESIC_CLOUD_GEODESICS_H_
