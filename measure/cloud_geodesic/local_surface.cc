#include "measure/cloud_geodesic/local_surface.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

LocalSurface PcaPlane(const Eigen::MatrixX3d& points, double* planarity, double* breadth) {
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
  if (breadth) *breadth = values[2] > 0 ? std::max(0.0, values[1]) / values[2] : 0.0;
  return s;
}

LocalSurface FitLocalSurface(SurfaceFit fit, const Eigen::MatrixX3d& points,
                             const LocalSurface& seed, double inlier_offset_mm) {
  BESPOKE_CHECK(inlier_offset_mm > 0, "inlier offset must be positive");
  std::vector<Eigen::Index> inliers;
  inliers.reserve(static_cast<size_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if (std::abs(seed.Offset(points.row(i).transpose())) <= inlier_offset_mm) inliers.push_back(i);
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
  Eigen::Matrix<double, 6, 6> normal = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs = Eigen::Matrix<double, 6, 1>::Zero();
  for (Eigen::Index i = 0; i < kept.rows(); ++i) {  // fixed-size sums, no GEMM on tiny sizes
    const double u = local(i, 0) / scale, v = local(i, 1) / scale;
    const Eigen::Matrix<double, 6, 1> row(u * u, u * v, v * v, u, v, 1.0);
    normal.selfadjointView<Eigen::Lower>().rankUpdate(row);
    rhs += row * local(i, 2);
  }
  normal.triangularView<Eigen::StrictlyUpper>() = normal.transpose();
  // Degenerate (points on a line, or too few distinct in the plane): the
  // normal matrix's smallest eigenvalue below 1e-6 of its largest. The
  // eigenvalues are computed only where the LDLT's reciprocal condition
  // estimate is not clearly above that (they cost more than the fit).
  const Eigen::LDLT<Eigen::Matrix<double, 6, 6>> ldlt(normal);
  if (!(ldlt.info() == Eigen::Success && ldlt.rcond() > 1e-3)) {
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> spread(normal,
                                                                      Eigen::EigenvaluesOnly);
    if (!(spread.eigenvalues()[0] > 1e-6 * spread.eigenvalues()[5])) return s;
  }
  const Eigen::Matrix<double, 6, 1> c = ldlt.solve(rhs);
  if (!c.allFinite()) return s;
  const double s2 = scale * scale;
  s.coefficients << c[0] / s2, c[1] / s2, c[2] / s2, c[3] / scale, c[4] / scale, c[5];
  return s;
}

namespace {

// Unit normal of the plane through points[0] and two of points[1 .. 7] that
// minimises sum_j min(e_j^2, tan2) (see FitOwnSheet); zero if none is proper.
Eigen::Vector3d MsacNormal(const Eigen::MatrixX3d& points, double tan2) {
  const Eigen::RowVector3d x = points.row(0);
  Eigen::MatrixX3d unit =
      points.bottomRows(points.rows() - 1).rowwise() - x;  // to each other point
  for (Eigen::Index j = 0; j < unit.rows(); ++j)  // e_j = |unit_j . n|; a duplicate of x costs 0
    if (const double length = unit.row(j).norm(); length > 0) unit.row(j) /= length;
  const Eigen::Index first = std::min<Eigen::Index>(8, points.rows());
  Eigen::Vector3d best_normal = Eigen::Vector3d::Zero();
  double best = std::numeric_limits<double>::infinity();
  for (Eigen::Index a = 1; a < first; ++a)
    for (Eigen::Index b = a + 1; b < first; ++b) {
      const Eigen::Vector3d u = (points.row(a) - x).transpose(),
                            v = (points.row(b) - x).transpose();
      Eigen::Vector3d n = u.cross(v);
      if (n.norm() < 0.3 * u.norm() * v.norm()) continue;  // nearly collinear: a poor plane
      n.normalize();
      const double cost = (unit * n).array().square().min(tan2).sum();
      if (cost < best) best = cost, best_normal = n;
    }
  return best_normal;
}

// Rows of `points` within the wedge: |n.(y - through)| <= tan |y - x|, x = row 0 (always kept).
Eigen::MatrixX3d InWedge(const Eigen::MatrixX3d& points, const Eigen::Vector3d& n,
                         const Eigen::Vector3d& through, double tan2) {
  const Eigen::Vector3d x = points.row(0).transpose();
  Eigen::MatrixX3d kept(points.rows(), 3);
  Eigen::Index m = 0;
  for (Eigen::Index j = 0; j < points.rows(); ++j) {
    const double h = n.dot(points.row(j).transpose() - through);
    if (j == 0 || h * h <= tan2 * (points.row(j).transpose() - x).squaredNorm())
      kept.row(m++) = points.row(j);
  }
  return kept.topRows(m);
}

}  // namespace

bool FitOwnSheet(const Eigen::MatrixX3d& points, double wedge_deg, double inlier_offset_mm,
                 const Eigen::Vector3d& orient, LocalSurface* surface, double* rms_mm) {
  if (points.rows() < 10) return false;
  const double tan2 = std::pow(std::tan(wedge_deg * M_PI / 180), 2);
  Eigen::MatrixX3d kept = points;
  LocalSurface seed;
  bool seeded = false;  // seed = PcaPlane(kept) already
  Eigen::Vector3d n = MsacNormal(points, tan2), through = points.row(0).transpose();
  for (int round = 0; round < 2 && n.squaredNorm() > 0; ++round) {
    Eigen::MatrixX3d in = InWedge(points, n, through, tan2);
    if (in.rows() < 10) break;  // too few on the sheet: all the points, as before
    seed = PcaPlane(in);
    n = seed.normal(), through = seed.origin;
    if (round == 1) kept = std::move(in), seeded = true;
  }
  if (!seeded) seed = PcaPlane(kept);
  if (seed.normal().dot(orient) < 0) seed.frame.col(1) *= -1, seed.frame.col(2) *= -1;
  *surface = FitLocalSurface(SurfaceFit::kQuadric, kept, seed, inlier_offset_mm);
  double sum = 0;
  int counted = 0;
  for (Eigen::Index j = 0; j < kept.rows(); ++j) {
    const double offset = surface->Offset(kept.row(j).transpose());
    if (std::abs(offset) <= inlier_offset_mm) sum += offset * offset, ++counted;
  }
  *rms_mm = counted > 0 ? std::sqrt(sum / counted) : 0;
  return true;
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
