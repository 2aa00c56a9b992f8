// A local model of a scanned surface from nearby scan points, giving the
// tangent planes the geodesic curvature flow needs (thesis 3.5: "the normal
// vector of the tangent plane is calculated by performing PCA to the d
// scattered points").
//
// Two fits (all in the points' units, mm):
//   kPlane   - the thesis: the PCA plane through the centroid of the points.
//              On a curved surface the centroid lies inside the surface by
//              about r^2 * curvature / 4 (r: radius of the neighbourhood), so
//              geodesics on convex parts come out slightly short.
//   kQuadric - a height field w = h(u, v) = c0 u^2 + c1 uv + c2 v^2 + c3 u +
//              c4 v + c5 over the PCA plane, fitted by least squares: second
//              order, so the curvature bias above vanishes. Falls back to the
//              plane with fewer than 10 points or a degenerate spread.
// A point x is mapped to the surface point above/below it along the frame's
// normal (the "foot") and the tangent plane there.
#ifndef BESPOKE_MEASURE_CLOUD_GEODESIC_LOCAL_SURFACE_H_
#define BESPOKE_MEASURE_CLOUD_GEODESIC_LOCAL_SURFACE_H_

#include <vector>

#include "measure/cloud_geodesic/point_index.h"
#include "measure/mesh_geodesic/curvature_flow.h"

namespace bespoke {

enum class SurfaceFit { kPlane, kQuadric };

struct LocalSurface {
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();     // centroid of the fitted points, mm
  Eigen::Matrix3d frame = Eigen::Matrix3d::Identity();  // columns: tangent u, tangent v, normal
  Eigen::Matrix<double, 6, 1> coefficients = Eigen::Matrix<double, 6, 1>::Zero();  // of h

  Eigen::Vector3d normal() const { return frame.col(2); }
  // The tangent plane at the foot of `x` (point on the surface, unit normal).
  TangentPlane PlaneAt(const Eigen::Vector3d& x) const;
  // Signed height of `x` above the surface along the frame normal, mm.
  double Offset(const Eigen::Vector3d& x) const;
};

// The PCA frame of `points` (#K x 3, K >= 1): origin = centroid, columns of
// the frame ordered by decreasing variance (column 2 = normal). `planarity`
// (optional) gets lambda_min / lambda_mid (0 for a perfect plane, 1 isotropic);
// `breadth` (optional) lambda_mid / lambda_max (0 for points on a line, whose
// normal is any direction across it).
LocalSurface PcaPlane(const Eigen::MatrixX3d& points, double* planarity = nullptr,
                      double* breadth = nullptr);

// Fits `fit` to `points` (#K x 3, K >= 3, mm). Rows whose distance from the
// plane `seed` exceeds `inlier_offset_mm` (> 0) are ignored: they belong to
// another sheet (e.g. the torso behind an arm). Returns the seed when fewer
// than 3 rows remain.
LocalSurface FitLocalSurface(SurfaceFit fit, const Eigen::MatrixX3d& points,
                             const LocalSurface& seed, double inlier_offset_mm);

// A surface through scan point x's neighbourhood that keeps to x's own sheet
// when another lies among its nearest points at an angle (the two faces of a
// lip a few mm apart). A parallel sheet closer than the wedge's reach (at 30
// degrees, points of a sheet 3 mm away count from 5.2 mm on) still gets in:
// positions cannot part those (docs/geodesics.md). Not in the thesis, whose
// PCA plane of the d nearest points tilts halfway between two such sheets. A point belongs to x's
// sheet when it lies within `wedge_deg` of x's tangent plane as seen from x:
//   1. the plane through x and two of its 7 nearest points that minimises
//      sum over the others of min(e^2, tan^2 wedge), e = |n.(y - x)| / |y - x|
//      (MSAC; the other sheet's points cost the capped amount);
//   2. twice: the points within the wedge (measured from the previous plane,
//      which after the first round passes through its points' centroid, so
//      x's own noise does not decide), and their PCA plane;
//   3. a quadric (FitLocalSurface) through the points kept.
// `points`: #K x 3 (mm), x's nearest with x itself in row 0. `surface`: the
// fit, oriented like `orient` (a normal, any length). `rms_mm`: RMS offset of
// the points kept from it. Falls back to all the points when the wedge keeps
// fewer than 10; false (nothing written) when there are fewer than 10.
bool FitOwnSheet(const Eigen::MatrixX3d& points, double wedge_deg, double inlier_offset_mm,
                 const Eigen::Vector3d& orient, LocalSurface* surface, double* rms_mm);

// The thesis's per-sample planes: PCA of the `neighbours` scan points nearest
// the sample, through their centroid. Slow (a k-NN query per sample and
// iteration) and blind to near-touching sheets; kept to compare against.
class KnnPlaneSource : public TangentPlaneSource {
 public:
  KnnPlaneSource(const PointIndex& index, int neighbours) : index_(index), k_(neighbours) {}
  bool PlaneAt(const Eigen::Vector3d& position, int* hint, TangentPlane* plane) const override;

 private:
  const PointIndex& index_;
  int k_;
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CLOUD_GEODESIC_LOCAL_SURFACE_H_
