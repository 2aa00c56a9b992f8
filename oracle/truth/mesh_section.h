// The exact section of a triangle mesh by a plane, as loops, and the girth
// of one loop: a tape pulled tight around that body part.
//
// SectionLoops: every triangle crossing the plane contributes one segment;
// segments are chained through the mesh edges they cross, so a closed
// manifold mesh gives closed loops, one per body part the plane cuts (torso,
// each arm, each leg, each hand). Vertices lying exactly on the plane are
// treated as lying on its positive side (symbolic perturbation), so a cut
// through vertices or along edges is still a set of clean loops: the result
// is the limit of sections by planes approaching from the negative side
// (e.g. for a horizontal plane through the armpit apex, the loops just
// below it, where the arm is separate from the trunk).
//
// Units: those of the mesh (mm in the body frame). Plane: a point and a
// normal (any length > 0; normalised inside). Failure: InputError for a
// zero or non-finite normal, or face indices out of range.
#ifndef BESPOKE_ORACLE_TRUTH_MESH_SECTION_H_
#define BESPOKE_ORACLE_TRUTH_MESH_SECTION_H_

#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

struct SectionLoop {
  Eigen::MatrixX3d points;  // #K x 3 on the plane, in order along the loop
  bool closed = true;       // false when the chain ends at a mesh boundary
};

std::vector<SectionLoop> SectionLoops(const TriangleMesh& mesh, const Eigen::Vector3d& plane_point,
                                      const Eigen::Vector3d& plane_normal);

// Distance from `point` to the loop's polyline (closing segment included
// when closed); +infinity for an empty loop.
double DistanceToLoop(const SectionLoop& loop, const Eigen::Vector3d& point);

// Index of the loop nearest to `point` (the loop of the body part whose
// datum point it is), or -1 when there are no loops.
int NearestLoop(const std::vector<SectionLoop>& loops, const Eigen::Vector3d& point);

// Index of the closed loop that encloses `point` (projected along
// `plane_normal`; the innermost when loops nest), or -1 when none does. For
// a trunk girth with several datum points, their centroid lies inside the
// trunk's loop, which picks it even where an arm's loop passes closer.
int EnclosingLoop(const std::vector<SectionLoop>& loops, const Eigen::Vector3d& point,
                  const Eigen::Vector3d& plane_normal);

// Perimeter of the convex hull of the loop's points projected onto the plane
// with normal `plane_normal` (mm): the girth a tape pulled tight would read.
double LoopHullPerimeter(const SectionLoop& loop, const Eigen::Vector3d& plane_normal);

// The loops that make up a trunk girth's section with its main loop
// `loops[main]`: main first, then every other closed loop whose centroid
// lies within the middle 80 % of main's extent along x (body frame) - a
// heavy breast or a fold of the belly that the plane cuts apart from the
// chest wall. A tape round the trunk passes over them; an arm's loop, beside
// the trunk, stays out. Empty when `main` is out of range.
std::vector<int> TrunkLoopIndices(const std::vector<SectionLoop>& loops, int main);

// The points of every loop in `indices`, one loop after another: for hulls
// and extremes, not a polyline. Closed when every one of them is.
SectionLoop MergedLoops(const std::vector<SectionLoop>& loops, const std::vector<int>& indices);

// Length of the loop's own polyline (closing segment included when closed).
double LoopLength(const SectionLoop& loop);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_TRUTH_MESH_SECTION_H_
