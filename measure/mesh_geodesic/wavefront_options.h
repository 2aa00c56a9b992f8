// Settings and counters of the wavefront propagation (wavefront.h), shared
// by the mesh geodesics (mesh_geodesics.h) and the point-cloud geodesics
// (measure/cloud_geodesic/propagation.h).
//
// Lengths are counted in spacings s of the surface: the mean edge length of
// a mesh, the cell size of a point-cloud grid, so that one setting suits
// bodies in mm and small objects alike.
#ifndef BESPOKE_MEASURE_MESH_GEODESIC_WAVEFRONT_OPTIONS_H_
#define BESPOKE_MEASURE_MESH_GEODESIC_WAVEFRONT_OPTIONS_H_

#include <cstdint>

#include "measure/mesh_geodesic/curvature_flow.h"

namespace bespoke {

enum class ParentRule {
  kStraightest,  // the thesis: the settled neighbour whose path turns least
  kPredicted,    // straightest among those predicting the shortest distance
};

struct WavefrontOptions {
  int window = 30;          // w, samples flowed per new node (Algorithm 3); default 30
  bool whole_path = false;  // flow every node's whole path (Algorithm 2); default off
  // r_max grows by this many s per round; 0 = the thesis's r_max = the
  // largest held-back estimate. Default 0.5.
  double band_spacings = 0.5;
  ParentRule parent_rule = ParentRule::kPredicted;  // default kPredicted
  double tie_spacings = 0.05;  // kPredicted: distance ties within this many s; default 0.05
  // The curvature flow run for each new node:
  int flow_iterations = 6;                 // at most this many iterations; default 6
  double flow_tolerance_spacings = 0.005;  // converged below this move (s); default 0.005
  double replan_spacings = 0.1;            // planes re-estimated after a slide of 0.1 s (default)
  double max_step_segments = 1.0;          // trust region, see CurvatureFlowOptions; default 1
  void Check() const;                      // InputError when out of range
};

// The curvature-flow settings of `options` for a surface of spacing `spacing`
// (surface units, > 0).
CurvatureFlowOptions FlowOptionsFor(const WavefrontOptions& options, double spacing);

struct WavefrontStats {
  std::int64_t settled = 0;          // nodes with a geodesic
  std::int64_t flows = 0;            // curvature-flow solves
  std::int64_t flow_iterations = 0;  // their iterations in total
  std::int64_t unconverged = 0;      // solves that hit flow_iterations
  std::int64_t undone = 0;           // flows undone: they left the surface or cut a gap
  std::int64_t rounds = 0;           // times r_max grew
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MESH_GEODESIC_WAVEFRONT_OPTIONS_H_
