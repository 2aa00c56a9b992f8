#include "tests/support/sampled_surfaces.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace bespoke::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Jittered grid over [0, lu] x [0, lv] with about `spacing` between samples;
// `emit(u, v, noise)` adds a point.
template <typename Emit>
void JitteredGrid(const Sampling& s, double lu, double lv, Emit emit) {
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  std::normal_distribution<double> noise(0.0, 1.0);
  const int nu = std::max(1, static_cast<int>(std::round(lu / s.spacing_mm)));
  const int nv = std::max(1, static_cast<int>(std::round(lv / s.spacing_mm)));
  for (int i = 0; i <= nu; ++i)
    for (int j = 0; j <= nv; ++j) {
      const double u = std::clamp((i + jitter(rng)) * lu / nu, 0.0, lu);
      const double v = std::clamp((j + jitter(rng)) * lv / nv, 0.0, lv);
      emit(u, v, s.noise_mm > 0 ? s.noise_mm * noise(rng) : 0.0);
    }
}

Eigen::MatrixX3d ToMatrix(const std::vector<Eigen::Vector3d>& v) {
  Eigen::MatrixX3d m(static_cast<Eigen::Index>(v.size()), 3);
  for (size_t i = 0; i < v.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = v[i].transpose();
  return m;
}

}  // namespace

Eigen::MatrixX3d SamplePlane(const Sampling& s, double half_mm) {
  std::vector<Eigen::Vector3d> out;
  JitteredGrid(s, 2 * half_mm, 2 * half_mm, [&](double u, double v, double n) {
    out.emplace_back(u - half_mm, v - half_mm, n);
  });
  return ToMatrix(out);
}

Eigen::MatrixX3d SampleSphere(const Sampling& s, double r_mm) {
  // Latitude bands with longitude counts proportional to the circumference.
  std::mt19937 rng(s.seed);
  std::uniform_real_distribution<double> jitter(-0.35, 0.35);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<Eigen::Vector3d> out;
  const int bands = std::max(2, static_cast<int>(std::round(kPi * r_mm / s.spacing_mm)));
  for (int b = 0; b <= bands; ++b) {
    const double lat = -kPi / 2 + kPi * (b + (b == 0 || b == bands ? 0 : jitter(rng))) / bands;
    const int count =
        std::max(1, static_cast<int>(std::round(2 * kPi * r_mm * std::cos(lat) / s.spacing_mm)));
    const double offset = jitter(rng);
    for (int k = 0; k < count; ++k) {
      const double lon = 2 * kPi * (k + offset + 0.5 * jitter(rng)) / count;
      const Eigen::Vector3d n(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                              std::sin(lat));
      out.push_back((r_mm + (s.noise_mm > 0 ? s.noise_mm * noise(rng) : 0.0)) * n);
    }
  }
  return ToMatrix(out);
}

Eigen::MatrixX3d SampleCylinder(const Sampling& s, double r_mm, double height_mm) {
  std::vector<Eigen::Vector3d> out;
  const double circumference = 2 * kPi * r_mm;
  JitteredGrid(s, circumference, height_mm, [&](double u, double v, double n) {
    if (u >= circumference) return;  // the seam is sampled once
    const double a = u / r_mm;
    out.emplace_back((r_mm + n) * std::cos(a), (r_mm + n) * std::sin(a), v);
  });
  return ToMatrix(out);
}

Eigen::MatrixX3d SampleFold(const Sampling& s, double gap_mm, double length_mm,
                            double half_width_mm) {
  std::vector<Eigen::Vector3d> out;
  const double r = gap_mm / 2, arc = kPi * r;
  // Unrolled: u in [0, length] bottom plate (x = length - u), then the half
  // tube, then the top plate.
  JitteredGrid(s, 2 * length_mm + arc, 2 * half_width_mm, [&](double u, double v, double n) {
    const double y = v - half_width_mm;
    if (u <= length_mm) {
      out.emplace_back(length_mm - u, y, -n);
    } else if (u <= length_mm + arc) {
      const double a = (u - length_mm) / r;  // 0 at the bottom, pi at the top
      out.emplace_back(-(r + n) * std::sin(a), y, r - (r + n) * std::cos(a));
    } else {
      out.emplace_back(u - length_mm - arc, y, gap_mm + n);
    }
  });
  return ToMatrix(out);
}

Eigen::MatrixX3d RemoveBall(const Eigen::MatrixX3d& points, const Eigen::Vector3d& centre,
                            double radius_mm) {
  std::vector<Eigen::Vector3d> out;
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    if ((points.row(i).transpose() - centre).norm() > radius_mm)
      out.push_back(points.row(i).transpose());
  return ToMatrix(out);
}

Eigen::MatrixX3d Concatenate(const Eigen::MatrixX3d& a, const Eigen::MatrixX3d& b) {
  Eigen::MatrixX3d m(a.rows() + b.rows(), 3);
  m << a, b;
  return m;
}

double SphereDistance(double r, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return r * std::atan2(a.cross(b).norm(), a.dot(b));
}

double CylinderDistance(double r, double theta_a, double z_a, double theta_b, double z_b) {
  double d = std::fmod(std::abs(theta_a - theta_b), 2 * kPi);
  if (d > kPi) d = 2 * kPi - d;
  return std::hypot(r * d, z_b - z_a);
}

FieldErrors CompareField(const Eigen::MatrixX3d& cloud, const Eigen::VectorXd& field,
                         const std::function<double(const Eigen::Vector3d&)>& exact) {
  FieldErrors e;
  for (Eigen::Index i = 0; i < cloud.rows(); ++i) {
    if (!std::isfinite(field[i])) {
      ++e.unreached;
      continue;
    }
    const double truth = exact(cloud.row(i).transpose());
    if (truth < 10) continue;
    const double relative = std::abs(field[i] - truth) / truth;
    e.mean += relative;
    e.worst = std::max(e.worst, relative);
    ++e.counted;
  }
  if (e.counted > 0) e.mean /= e.counted;
  return e;
}

}  // namespace bespoke::testing
