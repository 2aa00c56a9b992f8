#include "measure/tape/convex_hull_2d.h"

#include <CGAL/Convex_hull_traits_adapter_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>
#include <CGAL/property_map.h>

#include <algorithm>
#include <limits>
#include <numeric>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;

}  // namespace

std::vector<int> ConvexHullIndices(const Eigen::MatrixX2d& points) {
  if (!points.allFinite()) throw InputError("convex hull: a point has a non-finite coordinate");
  std::vector<Point2> cgal_points;
  cgal_points.reserve(static_cast<std::size_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    cgal_points.emplace_back(points(i, 0), points(i, 1));
  std::vector<std::size_t> order(cgal_points.size());
  std::iota(order.begin(), order.end(), 0);
  std::vector<std::size_t> hull;
  // Hull of the indices, comparing the points they refer to.
  CGAL::convex_hull_2(
      order.begin(), order.end(), std::back_inserter(hull),
      CGAL::Convex_hull_traits_adapter_2<Kernel, CGAL::Pointer_property_map<Point2>::type>(
          CGAL::make_property_map(cgal_points)));
  return std::vector<int>(hull.begin(), hull.end());
}

double ConvexHullPerimeter(const Eigen::MatrixX2d& points) {
  const std::vector<int> hull = ConvexHullIndices(points);
  if (hull.size() < 2) return 0;
  double perimeter = 0;
  for (std::size_t i = 0; i < hull.size(); ++i)
    perimeter += (points.row(hull[(i + 1) % hull.size()]) - points.row(hull[i])).norm();
  return perimeter;
}

double DepthInsideHull(const Eigen::MatrixX2d& points, const std::vector<int>& hull,
                       const Eigen::Vector2d& q) {
  double depth = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < hull.size(); ++k) {
    const Eigen::Vector2d a = points.row(hull[k]), b = points.row(hull[(k + 1) % hull.size()]);
    const double t =
        std::clamp((q - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-12), 0.0, 1.0);
    depth = std::min(depth, (a + t * (b - a) - q).norm());
  }
  return depth;
}

}  // namespace bespoke
