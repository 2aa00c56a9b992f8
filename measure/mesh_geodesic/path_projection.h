// Thesis Algorithm 1: projecting a "floating" geodesic (a polyline whose
// samples lie on tangent planes, slightly off the mesh) back onto the mesh's
// faces by cutting them with the curve's osculating plane.
//
// Every sample s_i is first put on the mesh (its closest point, found from
// its hint vertex). Consecutive feet f_{i-1}, f_i are then joined by the trace
// of a cutting plane on the faces between them: the walk starts in f_{i-1}'s
// face, leaves each face through the edge the plane crosses (Eq 3.18: the
// direction N1 x N2 of the plane and the face) and stops in f_i's face.
// The cutting plane is the osculating plane of the floating curve at s_i (the
// plane of s_{i-1}, s_i, s_{i+1}; the last segment uses the previous triple),
// turned about the feet's chord so that it passes through both feet (the
// thesis does not say how it reaches f_i's face when the plane misses it).
// Where the curve is straight to 1e-4 rad the osculating plane is undefined;
// the plane through the chord and the surface normal is used (for a geodesic
// the two coincide). Across two faces the trace is the straight unfolding.
// A walk that hits the mesh boundary or needs more than `max_faces` faces
// falls back to the straight chord between the feet (counted). A piece more
// than 1.5 times longer or shorter than its floating segment (a foot on the
// wrong side of a thin part: an ear, a finger) counts as the floating
// segment (counted).
//
// Units: the mesh's. Cost: O(faces crossed) per segment.
#ifndef BESPOKE_MEASURE_MESH_GEODESIC_PATH_PROJECTION_H_
#define BESPOKE_MEASURE_MESH_GEODESIC_PATH_PROJECTION_H_

#include <cstdint>
#include <vector>

#include "measure/mesh_geodesic/mesh_surface.h"

namespace bespoke {

struct ProjectedPath {
  // Cumulative length of the projected path at each sample's foot (#S; [0] = 0).
  std::vector<double> cumulative;
  double length = 0;  // cumulative.back()
  // The projected polyline (#K x 3, on the faces), only when asked for.
  Eigen::MatrixX3d points;
  std::int64_t fallbacks = 0;  // segments measured as chords (walk failed or too long)
};

// Projects `samples` (#S x 3, S >= 1) with locality hints `hints` (#S mesh
// vertices, updated to the vertex nearest each sample). `before`: the sample
// preceding samples[0] on the full curve (for the first osculating plane),
// or null. `keep_points`: fill ProjectedPath::points. `max_faces`: walk limit
// per segment (default 64). Throws InputError when the sizes differ.
ProjectedPath ProjectPolyline(const MeshSurface& surface, const Eigen::MatrixX3d& samples,
                              std::vector<int>* hints, const Eigen::Vector3d* before,
                              bool keep_points, int max_faces = 64);

// One cut: the trace of the plane through `from` and `to` with normal
// `plane_normal` (its component along the chord is removed) on the faces
// from from.face to to.face. Appends the crossing points (not `from`, but
// `to`) to `points` when not null. Returns the trace's length, or the chord's
// with *fell_back = true when the walk fails.
double CutBetween(const MeshSurface& surface, const MeshFoot& from, const MeshFoot& to,
                  const Eigen::Vector3d& plane_normal, int max_faces,
                  std::vector<Eigen::Vector3d>* points, bool* fell_back);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MESH_GEODESIC_PATH_PROJECTION_H_
