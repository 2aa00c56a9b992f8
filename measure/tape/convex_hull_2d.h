// The convex hull of 2-D points and its perimeter: the length of a tape
// measure pulled tight around a body section (thesis 3.7; ISO 8559-1 girths
// are taken with the tape touching the skin without compressing it, which on
// a concave section such as the bust or the small of the back bridges the
// hollows exactly like the hull does).
//
// Input: #P x 2 points in any length unit (results in the same unit). Robust
// predicates (CGAL's exact-predicates kernel) decide orientation, so
// duplicated, collinear and nearly collinear points are handled.
// Failure: InputError when a coordinate is not finite.
#ifndef BESPOKE_MEASURE_TAPE_CONVEX_HULL_2D_H_
#define BESPOKE_MEASURE_TAPE_CONVEX_HULL_2D_H_

#include <Eigen/Core>
#include <vector>

namespace bespoke {

// Row indices of the hull's vertices, counter-clockwise, without collinear
// points on its edges; empty for no points, one index for coincident points,
// two for collinear points.
std::vector<int> ConvexHullIndices(const Eigen::MatrixX2d& points);

// Perimeter of the convex hull: 0 for fewer than two distinct points, twice
// the segment's length for collinear points (a tape around a flat band).
double ConvexHullPerimeter(const Eigen::MatrixX2d& points);

// How far `q` lies inside the convex polygon `hull` (ConvexHullIndices of
// `points`): its distance to the nearest edge, in the points' unit. A
// section's pockets (the armpit folds) are its points deepest inside its
// hull.
double DepthInsideHull(const Eigen::MatrixX2d& points, const std::vector<int>& hull,
                       const Eigen::Vector2d& q);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_TAPE_CONVEX_HULL_2D_H_
