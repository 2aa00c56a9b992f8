// Options of CloudGeodesics (cloud_geodesics.h): the grid, the propagation,
// how far a query point may lie off the scan, the final flow of a path and
// the per-point distance fields. Each with its default.
#ifndef BESPOKE_MEASURE_CLOUD_GEODESIC_CLOUD_GEODESICS_OPTIONS_H_
#define BESPOKE_MEASURE_CLOUD_GEODESIC_CLOUD_GEODESICS_OPTIONS_H_

#include "measure/cloud_geodesic/cloud_grid.h"
#include "measure/cloud_geodesic/point_field.h"
#include "measure/cloud_geodesic/propagation.h"
#include "measure/mesh_geodesic/curvature_flow.h"

namespace bespoke {

struct CloudGeodesicsOptions {
  CloudGridOptions grid;
  PropagationOptions propagation;
  // Query points farther than this from the nearest scan point are rejected;
  // 0 (default) = the larger of 3 cell sizes and 10 mm...
  double max_snap_distance_mm = 0;
  // ...unless they lie in an unscanned region: a point up to this far from
  // the scan that lies ALONG the surface from the nearest scanned skin
  // (within 20 degrees of its tangent plane) or that the scan surrounds, as
  // in the crotch or an armpit no sensor saw - not along the normal, as a
  // point in the air off the skin or inside the body - is snapped to the
  // nearest scanned skin and flagged (CloudGeodesicPath::from_unscanned).
  // Default 60 mm; 0 = never.
  double max_hole_snap_distance_mm = 60;
  // Point to point: flow the whole path at the end (default true).
  bool polish = true;
  // Sample spacing of that final flow; 0 (default) = half a cell.
  double polish_spacing_mm = 0;
  CurvatureFlowOptions polish_flow = {100, 0.001, 1.0};  // 100 iterations, 0.001 mm
  // A final flow that cuts across a gap (round an armpit, between touching
  // thighs) is undone and the path split at that step, the sample held where
  // the propagation put it, each part flowed on its own: at most this many
  // splits deep (default 3, up to 8 parts; 0 = the whole path or nothing).
  int polish_splits = 3;
  // Distance fields: the scan points' distances (point_field.h); default on.
  PointFieldOptions point_field;
  void Check() const;  // InputError when out of range
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CLOUD_GEODESIC_CLOUD_GEODESICS_OPTIONS_H_
