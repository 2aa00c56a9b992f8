// Geodesic curvature flow (GCF) of a polyline on a surface that is known only
// through tangent planes: thesis section 3.3-3.4, Eq 3.10-3.17.
//
// A polyline P = [p_0 .. p_{m-1}] (#S x 3, mm) with FIXED end points is moved
// until, at every interior sample, the tangential part of the discrete second
// derivative (Eq 3.10, C'' ~ (p_{i+1}-p_i) + (p_{i-1}-p_i), the matrix K of
// Eq 3.11) vanishes, while every interior sample stays on the tangent plane of
// the surface at its current position (the tangent-space constraint,
// Eq 3.13-3.14). The planes come from a TangentPlaneSource: a point cloud (PCA
// of the d nearest scan points, or a local fit around a grid cell) or a mesh
// (PCA of one-ring face normals). The solver does not care which.
//
// One iteration solves the mu -> infinity limit of the implicit scheme Eq 3.15,
// which is the least-squares form Eq 3.16-3.17 with the end points and the
// tangent-plane rows imposed EXACTLY rather than stacked as weighted rows:
// writing p_i = q_i + T_i u_i (q_i the sample projected onto its plane, T_i a
// 3x2 orthonormal basis of the plane), the conditions
//   T_i^T (p_{i-1} - 2 p_i + p_{i+1}) = 0,   i = 1 .. m-2
// are a symmetric positive definite block-tridiagonal system in the u_i (2x2
// blocks: 2I on the diagonal, -T_i^T T_{i+1} beside it), solved by block
// Cholesky (Thomas) in O(m) time and memory. It is the minimiser of the
// discrete Dirichlet energy sum |p_{i+1} - p_i|^2 over the planes, so samples
// also stay evenly spaced as the curve shortens (no resampling needed).
// The planes are then re-estimated at the moved samples and the step repeats
// until no sample moves more than `tolerance_mm` or `max_iterations` is hit.
// Deviations from the thesis are listed in docs/geodesics.md.
#ifndef BESPOKE_MEASURE_MESH_GEODESIC_CURVATURE_FLOW_H_
#define BESPOKE_MEASURE_MESH_GEODESIC_CURVATURE_FLOW_H_

#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

// A tangent plane of the surface: it passes through `point` (on the surface,
// mm) and has unit normal `normal` (orientation irrelevant).
struct TangentPlane {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

// Where the planes come from. Implemented by the point-cloud grid
// (measure/cloud_geodesic/cloud_grid.h), analytic surfaces in tests, and meshes.
class TangentPlaneSource {
 public:
  virtual ~TangentPlaneSource() = default;
  // The tangent plane of the surface near `position` (mm). `hint` is the
  // sample's locality hint (the grid node, mesh vertex, ... it was last near;
  // -1 when unknown), read and updated by the source so that the next query
  // for the same sample is cheap. Returns false when no surface is near;
  // the flow then holds that sample where it is for the iteration.
  virtual bool PlaneAt(const Eigen::Vector3d& position, int* hint, TangentPlane* plane) const = 0;
};

struct CurvatureFlowOptions {
  // At most this many plane-estimate-and-solve iterations. Default 30.
  int max_iterations = 30;
  // Converged when no sample moved more than this in an iteration (mm).
  // Default 0.001 mm.
  double tolerance_mm = 1e-3;
  // Trust region: in one iteration no sample slides along its plane further
  // than this multiple of the mean segment length (guards against a kinked
  // start leaving the region where its planes are valid). Default 1.
  double max_step_segments = 1.0;
  // A sample's plane is re-estimated only once the sample has slid more than
  // this from the plane's point (mm); 0 (default) = every iteration. With the
  // `planes` cache below, planes also carry over between calls.
  double replan_distance_mm = 0;
  void Check() const;  // InputError when a value is out of range
};

struct CurvatureFlowReport {
  int iterations = 0;             // iterations run
  bool converged = false;         // last move <= tolerance_mm
  double last_move_mm = 0;        // largest sample displacement in the last iteration
  int samples_without_plane = 0;  // sample-iterations held because PlaneAt failed
  double length_mm = 0;           // polyline length after the flow
};

// Flows `samples` (#S x 3, mm, S >= 2, finite; rows 0 and S-1 never move) in
// place. `hints`: null, or #S locality hints passed to the source (in/out; -1
// when unknown). `planes`: null, or #S planes last estimated for the samples
// (in/out; a zero normal means unknown), reused per replan_distance_mm.
// Polylines with S <= 2 are returned unchanged. Throws InputError for bad
// options, fewer than 2 samples, non-finite samples or hints/planes vectors
// of the wrong size.
CurvatureFlowReport FlowPolyline(const CurvatureFlowOptions& options,
                                 const TangentPlaneSource& source, Eigen::MatrixX3d* samples,
                                 std::vector<int>* hints,
                                 std::vector<TangentPlane>* planes = nullptr);

// Sum of segment lengths of a polyline (#S x 3), mm.
double PolylineLength(const Eigen::MatrixX3d& samples);

// The length of the surface curve the polyline samples (#S x 3, mm), given
// each sample's tangent plane (#S; a zero normal = unknown): every chord c is
// replaced by the circular arc through its ends whose normals turn as the
// planes' normals do along the chord, c * asin(s) / s with s = |dn . c^| / 2.
// Exact on spheres and great circles, second order elsewhere; removes the
// chord bias -c^2 k^2 / 24 (k: normal curvature) of coarse polylines. Chords
// with an unknown end normal count as chords.
double SurfaceCurveLength(const Eigen::MatrixX3d& samples, const std::vector<TangentPlane>& planes);

// Asks `source` for the planes still unknown (zero normal) in `planes` (#S,
// resized to #S with zero normals when shorter); `hints` as in FlowPolyline.
void FillMissingPlanes(const TangentPlaneSource& source, const Eigen::MatrixX3d& samples,
                       std::vector<int>* hints, std::vector<TangentPlane>* planes);

// The polyline resampled at uniform arc length with the fewest segments no
// longer than `max_spacing_mm` (> 0); end points kept exactly. New samples lie
// on the old chords (off the surface until a flow moves them). When `hints`
// is not null (#S in, #S' out) each new sample takes the hint of the nearer
// old sample.
Eigen::MatrixX3d ResamplePolyline(const Eigen::MatrixX3d& samples, double max_spacing_mm,
                                  std::vector<int>* hints = nullptr);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MESH_GEODESIC_CURVATURE_FLOW_H_
