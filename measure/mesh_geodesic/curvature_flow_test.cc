#include "measure/mesh_geodesic/curvature_flow.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Exact tangent planes of analytic surfaces (the solver's contract only).
class PlaneZ0 : public TangentPlaneSource {
 public:
  bool PlaneAt(const Eigen::Vector3d& x, int* hint, TangentPlane* plane) const override {
    ++*hint;  // counts queries per sample, to test that hints travel
    plane->point = Eigen::Vector3d(x.x(), x.y(), 0);
    plane->normal = Eigen::Vector3d::UnitZ();
    return true;
  }
};

class Sphere : public TangentPlaneSource {
 public:
  explicit Sphere(double radius) : r_(radius) {}
  bool PlaneAt(const Eigen::Vector3d& x, int*, TangentPlane* plane) const override {
    plane->normal = x.normalized();
    plane->point = r_ * plane->normal;
    return true;
  }

 private:
  double r_;
};

class CylinderZ : public TangentPlaneSource {
 public:
  explicit CylinderZ(double radius) : r_(radius) {}
  bool PlaneAt(const Eigen::Vector3d& x, int*, TangentPlane* plane) const override {
    const Eigen::Vector3d radial = Eigen::Vector3d(x.x(), x.y(), 0).normalized();
    plane->normal = radial;
    plane->point = r_ * radial + Eigen::Vector3d(0, 0, x.z());
    return true;
  }

 private:
  double r_;
};

Eigen::Vector3d OnSphere(double r, double lon, double lat) {
  return r * Eigen::Vector3d(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                             std::sin(lat));
}

TEST(CurvatureFlow, PlaneZigzagBecomesEvenlySpacedStraightLine) {
  const int m = 21;
  Eigen::MatrixX3d p(m, 3);
  for (int i = 0; i < m; ++i) p.row(i) << 5.0 * i, (i % 2 ? 10.0 : -7.0), (i % 3 ? 3.0 : -2.0);
  p.row(0) << 0, 0, 0;
  p.row(m - 1) << 100, 0, 0;
  std::vector<int> hints(m, 0);
  const CurvatureFlowReport report = FlowPolyline({}, PlaneZ0(), &p, &hints);
  EXPECT_TRUE(report.converged);
  EXPECT_NEAR(report.length_mm, 100.0, 1e-6);
  for (int i = 0; i < m; ++i) {
    EXPECT_NEAR(p(i, 0), 5.0 * i, 1e-6) << i;  // equal spacing, exact on a plane
    EXPECT_NEAR(p(i, 1), 0.0, 1e-6) << i;
    EXPECT_NEAR(p(i, 2), 0.0, 1e-6) << i;
  }
  EXPECT_EQ(hints[0], 0);                  // end points are never queried
  EXPECT_EQ(hints[5], report.iterations);  // one query per iteration
}

TEST(CurvatureFlow, SphereConvergesToTheInscribedGreatCircleArc) {
  const double r = 100;
  const int m = 41;
  const Eigen::Vector3d a = OnSphere(r, 0.0, 0.0), b = OnSphere(r, 1.6, 0.3);
  // Start on a detour through a point well off the great circle.
  const Eigen::Vector3d detour = OnSphere(r, 0.7, 0.9);
  Eigen::MatrixX3d p(m, 3);
  for (int i = 0; i < m; ++i) {
    const double t = static_cast<double>(i) / (m - 1);
    const Eigen::Vector3d x =
        t < 0.5 ? (1 - 2 * t) * a + 2 * t * detour : (2 - 2 * t) * detour + (2 * t - 1) * b;
    p.row(i) = (r * x.normalized()).transpose();
  }
  p.row(0) = a.transpose();
  p.row(m - 1) = b.transpose();
  const CurvatureFlowReport report = FlowPolyline({}, Sphere(r), &p, nullptr);
  ASSERT_TRUE(report.converged) << report.last_move_mm;
  const double angle = std::acos(a.normalized().dot(b.normalized()));
  const double inscribed = 2 * r * (m - 1) * std::sin(angle / (2 * (m - 1)));
  EXPECT_NEAR(report.length_mm, inscribed, 1e-3);
  EXPECT_NEAR(report.length_mm / (r * angle), 1.0, 1e-3);  // the arc itself
  const Eigen::Vector3d great = a.cross(b).normalized();
  for (int i = 0; i < m; ++i) {
    EXPECT_NEAR(p.row(i).dot(great), 0.0, 1e-3) << i;  // in the great-circle plane
    EXPECT_NEAR(p.row(i).norm(), r, 1e-3) << i;        // on the sphere
  }
  EXPECT_EQ(p.row(0).transpose(), a);
  EXPECT_EQ(p.row(m - 1).transpose(), b);
}

TEST(CurvatureFlow, CylinderConvergesToTheHelix) {
  const double r = 50, theta = 2.0, dz = 80;
  const int m = 31;
  Eigen::MatrixX3d p(m, 3);
  for (int i = 0; i < m; ++i) {  // start: turn first, then climb
    const double t = static_cast<double>(i) / (m - 1);
    const double th = theta * std::min(1.0, 2 * t), z = dz * std::max(0.0, 2 * t - 1);
    p.row(i) << r * std::cos(th), r * std::sin(th), z;
  }
  const CurvatureFlowReport report = FlowPolyline({}, CylinderZ(r), &p, nullptr);
  ASSERT_TRUE(report.converged) << report.last_move_mm;
  const double step = theta / (m - 1);
  const double chord = std::hypot(2 * r * std::sin(step / 2), dz / (m - 1));
  EXPECT_NEAR(report.length_mm, (m - 1) * chord, 1e-3);
  EXPECT_NEAR(report.length_mm / std::hypot(r * theta, dz), 1.0, 2e-4);
  for (int i = 0; i < m; ++i) {  // z grows linearly with the angle
    const double th = std::atan2(p(i, 1), p(i, 0));
    EXPECT_NEAR(p(i, 2), dz * th / theta, 1e-2) << i;
  }
}

TEST(CurvatureFlow, HeldSampleStaysAndTwoSamplesAreUntouched) {
  class Holes : public TangentPlaneSource {
   public:
    bool PlaneAt(const Eigen::Vector3d& x, int*, TangentPlane* plane) const override {
      if (std::abs(x.x() - 50) < 1e-9) return false;  // no surface at x = 50
      plane->point = Eigen::Vector3d(x.x(), x.y(), 0);
      return true;
    }
  };
  Eigen::MatrixX3d p(11, 3);
  for (int i = 0; i < 11; ++i) p.row(i) << 10.0 * i, (i == 5 ? 4.0 : 1.0), 0;
  p.row(0).setZero();
  p.row(10) << 100, 0, 0;
  const CurvatureFlowReport report = FlowPolyline({}, Holes(), &p, nullptr);
  EXPECT_GT(report.samples_without_plane, 0);
  EXPECT_DOUBLE_EQ(p(5, 1), 4.0);           // held where it was
  EXPECT_NEAR(p(2, 1), 4.0 * 2 / 5, 1e-3);  // straight from (0,0) to the held sample

  Eigen::MatrixX3d two(2, 3);
  two << 0, 0, 0, 3, 4, 0;
  const Eigen::MatrixX3d before = two;
  EXPECT_NEAR(FlowPolyline({}, PlaneZ0(), &two, nullptr).length_mm, 5.0, 1e-12);
  EXPECT_EQ(two, before);
}

TEST(CurvatureFlow, LongPolylinesSolveInLinearMemory) {
  // 200k samples: a dense 600k x 600k solve would need terabytes.
  const int m = 200001;
  Eigen::MatrixX3d p(m, 3);
  for (int i = 0; i < m; ++i) p.row(i) << 0.01 * i, std::sin(0.001 * i), 0;
  p.row(m - 1) << 0.01 * (m - 1), 0, 0;
  p.row(0).setZero();
  std::vector<int> hints(m, 0);
  CurvatureFlowOptions options;
  options.max_step_segments = 1e9;  // a plane needs no trust region
  const CurvatureFlowReport report = FlowPolyline(options, PlaneZ0(), &p, &hints);
  EXPECT_TRUE(report.converged);
  EXPECT_NEAR(report.length_mm, 0.01 * (m - 1), 1e-6);
}

TEST(CurvatureFlow, BadInputIsRejected) {
  Eigen::MatrixX3d one(1, 3);
  one.setZero();
  EXPECT_THROW(FlowPolyline({}, PlaneZ0(), &one, nullptr), InputError);
  Eigen::MatrixX3d nan(3, 3);
  nan.setZero();
  nan(1, 1) = std::nan("");
  EXPECT_THROW(FlowPolyline({}, PlaneZ0(), &nan, nullptr), InputError);
  Eigen::MatrixX3d ok = Eigen::MatrixX3d::Zero(3, 3);
  std::vector<int> wrong(2, 0);
  EXPECT_THROW(FlowPolyline({}, PlaneZ0(), &ok, &wrong), InputError);
  CurvatureFlowOptions bad;
  bad.tolerance_mm = 0;
  EXPECT_THROW(FlowPolyline(bad, PlaneZ0(), &ok, nullptr), InputError);
  EXPECT_THROW(ResamplePolyline(ok, -1), InputError);
}

TEST(CurvatureFlow, ResampleKeepsEndsAndBoundsSpacing) {
  Eigen::MatrixX3d p(3, 3);
  p << 0, 0, 0, 10, 0, 0, 10, 25, 0;
  std::vector<int> hints = {7, 8, 9};
  const Eigen::MatrixX3d out = ResamplePolyline(p, 4.0, &hints);
  EXPECT_EQ(out.rows(), 10);  // 35 mm in ceil(35/4) = 9 segments
  EXPECT_EQ(out.row(0), p.row(0));
  EXPECT_EQ(out.row(9), p.row(2));
  for (int i = 1; i < out.rows(); ++i) EXPECT_LE((out.row(i) - out.row(i - 1)).norm(), 4.0);
  EXPECT_LT(PolylineLength(out), 35.0);  // the corner is cut by one chord
  EXPECT_GT(PolylineLength(out), 33.5);
  ASSERT_EQ(hints.size(), 10u);
  EXPECT_EQ(hints.front(), 7);
  EXPECT_EQ(hints.back(), 9);
  EXPECT_EQ(hints[3], 8);  // 11.7 mm along: nearer the corner sample
}

}  // namespace
}  // namespace bespoke
