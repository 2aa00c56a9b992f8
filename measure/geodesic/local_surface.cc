#include "measure/geodesic/local_surface.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

double Height(const Eigen::Matrix<double, 6, 1>& c, double u, double v) {
  return c[0] * u * u + c[1] * u * v + c[2] * v * v + c[3] * u + c[4] * v + c[5];
}

}  // namespace

TangentPlane LocalSurface::PlaneAt(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d local = frame.transpose() * (x - origin);
  const double u = local.x(), v = local.y();
  const auto& c = coefficients;
  const double hu = 2 * c[0] * u + c[1] * v + c[3];
  const double hv = c[1] * u + 2 * c[2] * v + c[4];
  TangentPlane plane;
  plane.point = origin + frame * Eigen::Vector3d(u, v, Height(c, u, v));
  plane.normal = (frame * Eigen::Vector3d(-hu, -hv, 1.0)).normalized();
  return plane;
}

double LocalSurface::Offset(const Eigen::Vector3d& x) const {
  const Eigen::Vector3d local = frame.transpose() * (x - origin);
  return local.z() - Height(coefficients, local.x(), local.y());
}

LocalSurface PcaPlane(const Eigen::MatrixX3d& points, double* planarity) {
  BESPOKE_CHECK(points.rows() >= 1, "PCA of no points");
  LocalSurface s;
  s.origin = points.colwise().mean().transpose();
  const Eigen::MatrixX3d centred = points.rowwise() - s.origin.transpose();
  const Eigen::Matrix3d covariance = centred.transpose() * centred;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance);
  const Eigen::Vector3d values = eigen.eigenvalues();  // ascending
  s.frame.col(0) = eigen.eigenvectors().col(2);
  s.frame.col(1) = eigen.eigenvectors().col(1);
  s.frame.col(2) = s.frame.col(0).cross(s.frame.col(1)).normalized();
  if (planarity) *planarity = values[1] > 0 ? std::max(0.0, values[0]) / values[1] : 1.0;
  return s;
}

LocalSurface FitLocalSurface(SurfaceFit fit, const Eigen::MatrixX3d& points,
                             const LocalSurface& seed, double inlier_offset_mm) {
  BESPOKE_CHECK(inlier_offset_mm > 0, "inlier offset must be positive");
  std::vector<Eigen::Index> inliers;
  inliers.reserve(static_cast<size_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (std::abs(seed.Offset(points.row(i).transpose())) <= inlier_offset_mm)
      inliers.push_back(i);
  if (inliers.size() < 3) return seed;
  Eigen::MatrixX3d kept(static_cast<Eigen::Index>(inliers.size()), 3);
  for (size_t i = 0; i < inliers.size(); ++i) kept.row(i) = points.row(inliers[i]);
  LocalSurface s = PcaPlane(kept);
  // Keep the seed's normal orientation (callers may have oriented it).
  if (s.normal().dot(seed.normal()) < 0) {
    s.frame.col(1) = -s.frame.col(1);
    s.frame.col(2) = -s.frame.col(2);
  }
  if (fit == SurfaceFit::kPlane || kept.rows() < 10) return s;
  // Least-squares quadric in the PCA frame, coordinates scaled to ~1.
  const Eigen::MatrixX3d local = (kept.rowwise() - s.origin.transpose()) * s.frame;
  const double scale = std::max(1e-12, local.leftCols<2>().rowwise().norm().maxCoeff());
  Eigen::MatrixXd a(kept.rows(), 6);
  for (Eigen::Index i = 0; i < kept.rows(); ++i) {
    const double u = local(i, 0) / scale, v = local(i, 1) / scale;
    a.row(i) << u * u, u * v, v * v, u, v, 1.0;
  }
  const Eigen::Matrix<double, 6, 6> normal = a.transpose() * a;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> spread(normal,
                                                                   Eigen::EigenvaluesOnly);
  if (!(spread.eigenvalues()[0] > 1e-6 * spread.eigenvalues()[5])) return s;  // degenerate
  const Eigen::Matrix<double, 6, 1> c = normal.ldlt().solve(a.transpose() * local.col(2));
  if (!c.allFinite()) return s;
  const double s2 = scale * scale;
  s.coefficients << c[0] / s2, c[1] / s2, c[2] / s2, c[3] / scale, c[4] / scale, c[5];
  return s;
}

bool KnnPlaneSource::PlaneAt(const Eigen::Vector3d& position, int* /*hint*/,
                             TangentPlane* plane) const {
  thread_local std::vector<int> indices;
  thread_local std::vector<double> distances;
  if (index_.Knn(position, k_, &indices, &distances) < 3) return false;
  Eigen::MatrixX3d near(static_cast<Eigen::Index>(indices.size()), 3);
  for (size_t i = 0; i < indices.size(); ++i) near.row(i) = index_.points().row(indices[i]);
  const LocalSurface s = PcaPlane(near);
  plane->point = s.origin;
  plane->normal = s.normal();
  return true;
}

}  // namespace bespoke
