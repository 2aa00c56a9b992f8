// Point clouds sampled from analytic surfaces with known geodesics, for the
// geodesic tests and benchmark (not part of the library). All in mm.
// Sampling is a jittered regular grid in the surface's own parameters, so the
// spacing is about `spacing_mm` everywhere; `noise_mm` adds Gaussian noise
// along the normal (standard deviation); seeds make every cloud reproducible.
#ifndef BESPOKE_TESTS_SUPPORT_SAMPLED_SURFACES_H_
#define BESPOKE_TESTS_SUPPORT_SAMPLED_SURFACES_H_

#include <cstdint>
#include <functional>

#include "scanners/core/types.h"

namespace bespoke::testing {

struct Sampling {
  double spacing_mm = 2.0;
  double noise_mm = 0.0;
  std::uint32_t seed = 1;
};

// The square [-half, half]^2 of the plane z = 0.
Eigen::MatrixX3d SamplePlane(const Sampling& s, double half_mm);
// The sphere of radius r about the origin.
Eigen::MatrixX3d SampleSphere(const Sampling& s, double r_mm);
// The open tube x^2 + y^2 = r^2, 0 <= z <= height.
Eigen::MatrixX3d SampleCylinder(const Sampling& s, double r_mm, double height_mm);
// A folded sheet: the plates z = 0 and z = gap for x >= 0, |y| <= half_width,
// 0 <= x <= length, joined at x < 0 by a half tube of diameter `gap` (axis
// along y through (0, *, gap/2)). Shortest path from (x1, y, 0) to (x2, y, gap)
// is x1 + pi * gap / 2 + x2.
Eigen::MatrixX3d SampleFold(const Sampling& s, double gap_mm, double length_mm,
                            double half_width_mm);
// Removes the points within `radius` of `centre`.
Eigen::MatrixX3d RemoveBall(const Eigen::MatrixX3d& points, const Eigen::Vector3d& centre,
                            double radius_mm);
// Stacks two clouds.
Eigen::MatrixX3d Concatenate(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b);

// Exact geodesic lengths.
double SphereDistance(double r, const Eigen::Vector3d& a, const Eigen::Vector3d& b);
// Points given by (angle rad, z); the shorter way round.
double CylinderDistance(double r, double theta_a, double z_a, double theta_b, double z_b);

// Relative errors of a distance field (#P, mm, +inf unreached) against
// `exact(x)` (mm) over the points at least 10 mm from the source (and with
// exact >= 0: negative means "not counted"); unreached points counted apart.
struct FieldErrors {
  double mean = 0, worst = 0;
  int counted = 0, unreached = 0;
};
FieldErrors CompareField(const Eigen::MatrixX3d& cloud, const Eigen::VectorXd& field,
                         const std::function<double(const Eigen::Vector3d&)>& exact);

}  // namespace bespoke::testing

#endif  // BESPOKE_TESTS_SUPPORT_SAMPLED_SURFACES_H_
