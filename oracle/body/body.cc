#include "oracle/body/body.h"

#include <limits>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// Closest point on triangle (a, b, c) to p, as barycentric weights
// (Ericson, Real-Time Collision Detection, 5.1.5).
Eigen::Vector3d ClosestBarycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                   const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return {1, 0, 0};
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return {0, 1, 0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {1 - v, v, 0};
  }
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return {0, 0, 1};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {1 - w, 0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0, 1 - w, w};
  }
  const double denom = 1.0 / (va + vb + vc);
  const double v = vb * denom, w = vc * denom;
  return {1 - v - w, v, w};
}

}  // namespace

Eigen::Vector3d PositionOf(const TriangleMesh& mesh, const SurfacePoint& point) {
  BESPOKE_CHECK(point.face >= 0 && point.face < mesh.num_faces(),
                "surface point face out of range");
  const auto f = mesh.faces.row(point.face);
  return point.barycentric[0] * mesh.vertices.row(f[0]).transpose() +
         point.barycentric[1] * mesh.vertices.row(f[1]).transpose() +
         point.barycentric[2] * mesh.vertices.row(f[2]).transpose();
}

SurfacePoint ClosestSurfacePoint(const TriangleMesh& mesh, const Eigen::Vector3d& position) {
  BESPOKE_CHECK(mesh.num_faces() > 0, "ClosestSurfacePoint on a mesh without faces");
  SurfacePoint best;
  double best_d2 = std::numeric_limits<double>::infinity();
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0));
    const Eigen::Vector3d b = mesh.vertices.row(mesh.faces(f, 1));
    const Eigen::Vector3d c = mesh.vertices.row(mesh.faces(f, 2));
    const Eigen::Vector3d w = ClosestBarycentric(position, a, b, c);
    const double d2 = (w[0] * a + w[1] * b + w[2] * c - position).squaredNorm();
    if (d2 < best_d2) {
      best_d2 = d2;
      best.face = static_cast<int>(f);
      best.barycentric = w;
    }
  }
  return best;
}

}  // namespace bespoke
