// Per-point distance field over the grid's surface graph (not in the thesis).
//
// The thesis's Algorithm 5 gives each grid cell (node) a geodesic; a scan
// point then takes its node's distance carried to first order. Where a
// feature is about a cell thick that is not enough: the sheets of a mouth or
// an eye merge with the skin around them, the underside of a toe takes the
// route over its top, and points where two routes meet inside a cell take
// the longer (docs/geodesics.md has the errors). This field resolves the
// scan's own points:
//
// A Dijkstra sweep over the points in order of distance from the seeds. A
// settled point p offers each of its k nearest points q the edge distance
// d(p) + |q - p| and, with each settled neighbour r of p, the segment
// distance
//     min over s on [p, r] of  d(s) + |q - s|,  d linear along [p, r],
// what a planar wavefront through p and r gives q. The segment offers remove
// most of a graph's zig-zag excess (edge-only Dijkstra overestimates by
// several per cent); both offers are at least the true distance when d(p),
// d(r) are (a point source's distance is convex along a segment), up to the
// chord's shortcut on curved skin.
//
// Each point first gets its own tangent plane and foot: a quadric fitted to
// those of its `fit_points` nearest points that lie on its own sheet, told
// apart by geometry (FitOwnSheet, local_surface.h). A node's surface spans a
// cell and blurs what lies within one (a fold a cell wide; on coarse cells
// the mouth's inside behind the cheek), and a cell can hold two sheets.
//
// Surface, not air: p and q exchange only along a chord within
// `max_chord_angle_deg` of both points' tangent planes (not through thin
// tissue), when one of them lies on the other's fitted surface (within
// `surface_offset_fraction` of the sheet gap plus 3 x the fit's RMS
// residual), and
//   - with oriented normals (CloudGrid built with them): when their normals
//     are within a right angle, so two sheets facing each other across a gap
//     (an arm by the torso, the lips) or back to back across thin tissue are
//     never joined, however close;
//   - without: when the grid says they lie on one piece of surface
//     (CloudGrid::StepOnSurface: nodes within two links, or each on the
//     other's local surface with agreeing normals), so sheets farther apart
//     than the sheet gap are never joined.
// Normals are the given ones, else the points' own fits'. Points the
// seeds cannot reach that way stay +inf (CloudGeodesics then gives them their
// node's distance).
//
// Input: the grid (points #P x 3, mm) and seeds (point, distance in mm).
// Output: #P distances, mm. Throws InputError on bad options or a seed that
// is not a point index with a finite distance >= 0.
#ifndef BESPOKE_MEASURE_CLOUD_GEODESIC_POINT_FIELD_H_
#define BESPOKE_MEASURE_CLOUD_GEODESIC_POINT_FIELD_H_

#include <Eigen/Core>
#include <vector>

#include "measure/cloud_geodesic/cloud_grid.h"

namespace bespoke {

struct PointFieldOptions {
  // Default true. false: each point takes its node's Algorithm 5 distance
  // carried to first order (the thesis's cells only).
  bool enabled = true;
  // k nearest points a point offers its distance to; default 12. Fewer
  // leave a scanner's sparser rows unjoined and the sweep zig-zags; more
  // reach across slits (pressed lips) that no sheet test can see without
  // normals.
  int neighbours = 12;
  double max_chord_angle_deg = 45;  // chord vs both points' tangent planes; default 45
  // Measure chords between the points' feet on their fitted surfaces
  // (fit_points) rather than the raw points: scan noise lengthens raw chords
  // by several per cent. Default true.
  bool project_to_surface = true;
  // Each point's tangent plane and foot come from a quadric fitted to those
  // of its `fit_points` nearest points that lie on its own sheet (within
  // `fit_wedge_deg` of its tangent plane as seen from it; FitOwnSheet in
  // local_surface.h). 0 = its node's surface, fitted over a whole cell (on
  // coarse cells the inside of a mouth is then reached through the cheek).
  // 0 or 10-256; default 24.
  int fit_points = 24;
  // The wedge of FitOwnSheet, degrees; default 30, range [5, 60]. Smaller
  // rejects more of a noisy sheet; larger lets a nearby sheet in
  // (docs/geodesics.md has the sensitivity table).
  double fit_wedge_deg = 30;
  // p and q are joined only when one lies on the other's fitted surface within
  // this fraction of the sheet gap plus 3 x that fit's RMS residual: two sheets
  // closer than the sheet gap (the lips pressed together) are mm off each
  // other's surfaces. Used with fit_points > 0; default 0.1; [0, 1].
  double surface_offset_fraction = 0.1;
  // CloudGeodesics seeds the sweep with the grid's (Algorithm 5) distances of
  // the points within this many cell sizes of the source. Default 3.
  double seed_radius_cells = 3;
  // CloudGeodesics keeps a point's grid (first-order) distance where the
  // sweep's is within this fraction of it, and takes the sweep's elsewhere.
  // Default 0.005; 0 = the sweep's everywhere.
  double agree_fraction = 0.005;
  void Check() const;  // InputError when out of range
};

struct PointSeed {
  int point = 0;           // index into the grid's points
  double distance_mm = 0;  // its distance from the source
};

// See the file comment.
Eigen::VectorXd PointDistanceField(const PointFieldOptions& options, const CloudGrid& grid,
                                   const std::vector<PointSeed>& seeds);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CLOUD_GEODESIC_POINT_FIELD_H_
