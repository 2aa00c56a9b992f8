// Small 2-D polyline geometry used by patterns, formats and the GA.
//
// Outlines are #V x 2 closed polylines in mm (closing edge implied). Curves
// are sampled into polylines by the helpers at the bottom.
#ifndef BESPOKE_RESIZE_PATTERN_GEOMETRY_H_
#define BESPOKE_RESIZE_PATTERN_GEOMETRY_H_

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "resize/pattern/pattern.h"

namespace bespoke {

// Signed area (mm^2), positive for counter-clockwise outlines.
double SignedArea(const Outline& outline);

// Perimeter of the closed outline (mm).
double Perimeter(const Outline& outline);

// Length walking from vertex `from` to vertex `to` along the outline, forward
// (increasing index, wrapping) or backward (mm). from == to gives 0.
double OutlineDistance(const Outline& outline, int from, int to, bool forward = true);

// A pair of non-adjacent edges of the closed outline that cross or touch
// (edge i runs from vertex i to i+1), or {-1, -1} when the outline is simple.
// O(#V^2); outlines have at most a few hundred vertices.
std::pair<int, int> FindSelfIntersection(const Outline& outline);

// True when segments p0-p1 and q0-q1 intersect (touching counts).
bool SegmentsIntersect(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                       const Eigen::Vector2d& q0, const Eigen::Vector2d& q1);

// Signed turning angle at every vertex (radians, in (-pi, pi]; positive turns
// left). The inner angle of a counter-clockwise outline is pi - turning.
Eigen::VectorXd TurningAngles(const Outline& outline);

// Which vertices of `outline` lie on a curve, where inflections count: not
// marked in `skip` (e.g. on a straight run), turning by less than
// `corner_rad` (0.35 rad: a sharper turn is a corner) and with at least one
// incident edge shorter than `straight_mm` (20 mm: a vertex between two long
// edges is the corner of two straight lines, however slight).
std::vector<bool> CurveVertices(const Outline& outline, const std::vector<bool>& skip,
                                double corner_rad = 0.35, double straight_mm = 20);

// The outline offset outward by `distance_mm` (mitred corners, mitre length
// limited to 3 x distance). Used for cut lines with seam allowance.
Outline OffsetOutline(const Outline& outline, double distance_mm);

// Curve sampling: `samples` points from t = 0 to t = 1 inclusive.
std::vector<Eigen::Vector2d> SampleQuadratic(const Eigen::Vector2d& p0, const Eigen::Vector2d& c,
                                             const Eigen::Vector2d& p1, int samples);
std::vector<Eigen::Vector2d> SampleCubic(const Eigen::Vector2d& p0, const Eigen::Vector2d& c0,
                                         const Eigen::Vector2d& c1, const Eigen::Vector2d& p1,
                                         int samples);
// Centripetal Catmull-Rom spline through `through` (>= 2 points), resampled to
// `samples` points evenly spaced by arc length; the ends are kept exactly.
std::vector<Eigen::Vector2d> SmoothCurve(const std::vector<Eigen::Vector2d>& through, int samples);
// `samples` points evenly spaced by arc length along an open polyline.
std::vector<Eigen::Vector2d> ResamplePolyline(const std::vector<Eigen::Vector2d>& polyline,
                                              int samples);

// Mean and max distance (mm) between corresponding vertices of two outlines
// of the same size after the best rigid alignment (rotation + translation,
// Kabsch) of `b` onto `a`. Throws InputError on a size mismatch.
struct OutlineDistanceStats {
  double mean_mm = 0;
  double max_mm = 0;
};
OutlineDistanceStats CompareOutlines(const Outline& a, const Outline& b);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_PATTERN_GEOMETRY_H_
