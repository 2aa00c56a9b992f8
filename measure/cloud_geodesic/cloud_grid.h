// The regular grid over a point cloud that geodesics propagate on: thesis
// Algorithm 4, with surface-aware cells and links.
//
// Input: scan points (#P x 3, mm, any frame). The bounding box is cut into
// cubes of side cell_size_mm, addressed directly by Eq 3.19
// (key = ix + nx * (iy + ny * iz)); only non-empty cells are stored (a hash map
// from key to nodes, O(#cells) memory - never the dense nx*ny*nz array).
// A cell's points are split into NODES, one per sheet of surface in the cell:
// points closer than sheet_gap_mm are the same sheet, and so are pieces that
// lie in one plane (a sampling gap); pieces apart along the normal are not. So
// an arm 15 mm from the torso gives two nodes where a cell holds both. Each node has
//   - a local surface fitted to the d = `neighbours` scan points nearest it
//     (FLANN k-d tree), ignoring points off its own sheet;
//   - a site: the mean of its points (the thesis's "destination") moved onto
//     that surface.
// Two nodes in neighbouring cells (26-neighbourhood; farther where the scan is
// sparser than the grid, see LinkSparseNodes) are LINKED only where the
// surface connects them: normals within max_link_angle_deg, each site within
// sheet_gap_mm / 2 of the other's surface, and a scan point near the chord's
// midpoint (within 0.6 sheet_gap_mm or 1.5 local point spacings). Sheets separated
// by an air gap wider than sheet_gap_mm are never linked, so geodesics go
// around, never through the air. Holes smaller than about a cell are bridged.
//
// Oriented normals (optional, #P x 3, consistently outward, e.g. a mesh's
// vertex normals or a scanner's sensor-facing ones): where given, two points
// or nodes whose normals point to opposite sides (dot < 0) are never one
// sheet, and links need the ORIENTED normals to agree. That separates sheets
// closer than the sheet gap that positions alone cannot: the two lips of a
// slit (normals facing each other) and the two sides of thin tissue (normals
// facing away), e.g. a mouth cavity 8 mm behind the skin of a body mesh
// sampled every 3.5 mm.
//
// The grid is also the TangentPlaneSource of the curvature flow: a sample is
// assigned to the nearest site reachable by links from its hint node, and
// gets that node's surface's tangent plane.
//
// Throws InputError for bad options, fewer than 10 points, non-finite points,
// or a grid with more than 2^60 cells (cell far too small for the extent).
#ifndef BESPOKE_MEASURE_CLOUD_GEODESIC_CLOUD_GRID_H_
#define BESPOKE_MEASURE_CLOUD_GEODESIC_CLOUD_GRID_H_

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "measure/cloud_geodesic/local_surface.h"
#include "measure/cloud_geodesic/point_index.h"
#include "scanners/core/progress.h"

namespace bespoke {

struct CloudGridOptions {
  // Grid interval; 0 (default) = the larger of auto_cell_spacings x the median
  // point spacing and the bounding-box diagonal / auto_cells_per_diagonal (so
  // very dense scans do not make needlessly many cells).
  double cell_size_mm = 0;
  double auto_cell_spacings = 3;         // default 3 point spacings
  double auto_cells_per_diagonal = 400;  // default 400 (about 5 mm on an adult)
  // d, scan points per local fit; default 32, raised to (cell / spacing)^2
  // when cells are large compared with the spacing so a fit spans its cell.
  int neighbours = 32;
  double sheet_gap_mm = 0;  // 0 (default) = 2 x the 90th-percentile point spacing
  // A node seeds its surface fit with a plane through its own points when it
  // has at least this many (and 5), else through the points within a cell
  // (or sheet_gap_mm if larger) of it: noise tilts a plane through a handful.
  // Default 16; 5 gives the earlier rule's own-point threshold.
  int min_seed_points = 16;
  double max_link_angle_deg = 60;         // default 60 degrees between linked normals
  SurfaceFit fit = SurfaceFit::kQuadric;  // default quadric (kPlane: the thesis)
  // Tangent planes blend the surfaces of the linked nodes whose sites lie
  // within blend_cells cell sizes (smooth weights), instead of taking the
  // nearest node's alone: no steps between neighbouring fits, which matters
  // on noisy scans. 0 = nearest node only. Default 1.
  double blend_cells = 1.0;
  // Use the oriented normals when the constructor is given them (default
  // true); false ignores them (the thesis's unoriented grid).
  bool use_normals = true;
  void Check() const;  // InputError when out of range
};

// Why candidate links between nodes of neighbouring cells were refused.
struct LinkStats {
  std::int64_t tested = 0, linked = 0;
  std::int64_t angle = 0;       // normals disagree
  std::int64_t offset = 0;      // a site is off the other's surface
  std::int64_t continuity = 0;  // no scan point near the chord's midpoint
  std::int64_t long_links = 0;  // of `linked`, beyond the 26-neighbourhood (sparse nodes)
};

class CloudGrid : public TangentPlaneSource {
 public:
  CloudGrid(const CloudGridOptions& options, const Eigen::MatrixX3d& points,
            Progress* progress = nullptr);
  // `normals`: #P x 3 outward normals of the points (any length; a zero row
  // = side unknown), or 0 x 3 for none. InputError when the row counts differ
  // or a normal is not finite.
  CloudGrid(const CloudGridOptions& options, const Eigen::MatrixX3d& points,
            const Eigen::MatrixX3d& normals, Progress* progress = nullptr);
  ~CloudGrid() override;

  const PointIndex& index() const { return *index_; }
  double spacing_mm() const { return spacing_; }  // median point spacing
  double cell_size_mm() const { return cell_; }
  double blend_radius_mm() const { return blend_; }
  int neighbours() const { return neighbours_; }  // d actually used
  double sheet_gap_mm() const { return gap_; }
  bool oriented() const { return !node_normal_.empty(); }  // built with normals
  int num_cells() const { return static_cast<int>(cells_.size()); }
  int num_nodes() const { return static_cast<int>(sites_.size()); }
  std::int64_t num_links() const { return static_cast<std::int64_t>(link_targets_.size()) / 2; }

  const Eigen::Vector3d& site(int node) const { return sites_[static_cast<size_t>(node)]; }
  const LocalSurface& surface(int node) const { return surfaces_[static_cast<size_t>(node)]; }
  const int* links_begin(int node) const { return link_targets_.data() + link_offsets_[node]; }
  const int* links_end(int node) const { return link_targets_.data() + link_offsets_[node + 1]; }
  int node_of_point(Eigen::Index point) const { return point_node_[static_cast<size_t>(point)]; }
  // The given oriented normals, unit (zero rows: side unknown); 0 x 3 when
  // built without them.
  const Eigen::MatrixX3d& point_normals() const { return point_normals_; }
  const LinkStats& link_stats() const { return link_stats_; }
  // Approximate bytes held by the grid (sites, surfaces, links, maps, index).
  std::int64_t memory_bytes() const;

  // The node of the scan point nearest `x`; the distance to that point in
  // `*distance_mm` when not null. With `component` >= 0, the nearest of the
  // 1024 nearest points lying in that component, if any (unscanned regions such
  // as the crotch leave small islands of points that a query should skip).
  int LocateNode(const Eigen::Vector3d& x, double* distance_mm = nullptr, int component = -1) const;
  // The same, returning the scan point's index instead of its node.
  int LocatePoint(const Eigen::Vector3d& x, double* distance_mm = nullptr,
                  int component = -1) const;
  // True when `a` and `b` are at most `hops` links apart (0: the same node).
  // Consecutive samples of a path on the surface are within a few hops; a
  // path cut across a gap joins nodes that are far apart in the graph.
  bool WithinHops(int a, int b, int hops = 4) const;
  // Whether a path may step from `pa` (a sample near node `a`) to `pb` (near
  // `b`): the nodes are within two links, or the step stays on one smooth
  // surface - each point within sheet_gap_mm / 2 of the other's local surface
  // and their normals within max_link_angle_deg - as when crossing a hole in
  // the scan. A step across an air gap between sheets is neither.
  bool StepOnSurface(int a, const Eigen::Vector3d& pa, int b, const Eigen::Vector3d& pb) const;
  // Connected component of each node (0 = the one with the most scan points,
  // 1 the next, ...), and the number of scan points per component.
  int component(int node) const { return component_[static_cast<size_t>(node)]; }
  const std::vector<Eigen::Index>& component_points() const { return component_points_; }
  // From `start`, follows links to the node whose site is nearest `x`.
  int WalkToNearest(const Eigen::Vector3d& x, int start) const;

  bool PlaneAt(const Eigen::Vector3d& position, int* hint, TangentPlane* plane) const override;

 private:
  void BuildCells(const Eigen::MatrixX3d& points, const Eigen::MatrixX3d* normals);
  // Dot product of the two nodes' surface normals at `pa`, `pb`: signed when
  // both nodes are oriented, absolute otherwise.
  double NormalAgreement(int a, const Eigen::Vector3d& pa, int b, const Eigen::Vector3d& pb) const;
  void FitNodes(const CloudGridOptions& options, const Eigen::MatrixX3d& points,
                const Eigen::MatrixX3d* normals);
  void LinkNodes(const CloudGridOptions& options);
  void LinkSparseNodes(double cos_max, std::vector<std::pair<int, int>>* pairs);
  void FindComponents();
  bool Connected(int a, int b, double cos_max);
  std::int64_t KeyOf(const Eigen::Vector3d& x) const;

  std::unique_ptr<PointIndex> index_;
  double spacing_ = 0, cell_ = 0, gap_ = 0, blend_ = 0;
  int neighbours_ = 0;
  double cos_max_angle_ = 0;
  Eigen::Vector3d min_ = Eigen::Vector3d::Zero();
  std::int64_t dims_[3] = {0, 0, 0};
  // cell key -> (first node, node count); nodes of a cell are contiguous.
  std::unordered_map<std::int64_t, std::pair<int, int>> cells_;
  std::vector<std::int64_t> node_cell_;  // key per node
  std::vector<int> node_point_offsets_;  // CSR into node_points_
  std::vector<int> node_points_;         // point indices grouped by node
  std::vector<int> point_node_;          // #P
  std::vector<Eigen::Vector3d> sites_;
  std::vector<LocalSurface> surfaces_;
  std::vector<double> local_spacing_;  // per node, mm
  // Per node: the mean of its points' unit normals (length <= 1; < 0.5 = its
  // points disagree, treated as unoriented). Empty without normals.
  std::vector<Eigen::Vector3d> node_normal_;
  Eigen::MatrixX3d point_normals_;                // #P x 3 unit, or 0 x 3
  std::vector<int> link_offsets_, link_targets_;  // CSR adjacency
  LinkStats link_stats_;
  std::vector<int> component_;                  // per node
  std::vector<Eigen::Index> component_points_;  // per component, descending
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CLOUD_GEODESIC_CLOUD_GRID_H_
