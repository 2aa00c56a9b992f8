#include "measure/measurements/section_holes.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <vector>

#include "measure/tape/ellipse_fit.h"
#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// RMS of the points' radial distance to the ellipse over their mean radius.
double ResidualShare(const Ellipse2d& e, const Eigen::MatrixX2d& loop) {
  double sum2 = 0, radius = 0;
  for (Eigen::Index i = 0; i < loop.rows(); ++i) {
    const Eigen::Vector2d p = loop.row(i).transpose();
    const double r = (p - e.centre).norm(), off = r - e.RadiusToward(p);
    sum2 += off * off;
    radius += r;
  }
  const double n = static_cast<double>(loop.rows());
  return std::sqrt(sum2 / n) / std::max(1e-9, radius / n);
}

// The points over the hole from a (parameter ta) forward to b, `dt` radians
// of the ellipse; appends them to `out` and returns the polyline's length.
double Bridge(const SkinOverHolesOptions& options, const Ellipse2d& e, const Eigen::Vector2d& a,
              double ta, const Eigen::Vector2d& b, double dt, std::vector<Eigen::Vector2d>* out) {
  const Eigen::Vector2d off_a = a - e.At(ta), off_b = b - e.At(ta + dt);
  const double longest = std::max(e.semi_axis_u_mm, e.semi_axis_v_mm);
  const int n = std::max(2, static_cast<int>(std::ceil(dt * longest / options.step_mm)));
  double length = 0;
  Eigen::Vector2d last = a;
  for (int k = 1; k <= n; ++k) {
    const double s = static_cast<double>(k) / n;
    const Eigen::Vector2d q = e.At(ta + s * dt) + (1 - s) * off_a + s * off_b;
    length += (q - last).norm();
    last = q;
    if (k < n) out->push_back(q);
  }
  return length;
}

}  // namespace

void SkinOverHolesOptions::Check() const {
  if (!(open_gap_mm > 0)) throw InputError("section holes: open_gap_mm must be > 0");
  if (!(step_mm > 0)) throw InputError("section holes: step_mm must be > 0");
  if (!(max_hole_deg > 0 && max_hole_deg < 360))
    throw InputError("section holes: max_hole_deg must be in (0, 360)");
  if (!(max_residual_share > 0)) throw InputError("section holes: max_residual_share must be > 0");
  if (min_points < 5) throw InputError("section holes: min_points must be >= 5");
}

SkinOverHoles FillSectionHoles(const SkinOverHolesOptions& options, const Eigen::MatrixX2d& loop) {
  options.Check();
  SkinOverHoles out;
  if (loop.rows() < options.min_points) return out;
  const std::optional<Ellipse2d> e = FitEllipse(loop);
  if (!e || ResidualShare(*e, loop) > options.max_residual_share) return out;
  std::vector<std::pair<double, Eigen::Index>> order;
  for (Eigen::Index i = 0; i < loop.rows(); ++i)
    order.emplace_back(e->ParameterOf(loop.row(i).transpose()), i);
  std::sort(order.begin(), order.end());
  std::vector<Eigen::Vector2d> fill;
  const double max_dt = options.max_hole_deg * (2 * kPi) / 360;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const auto& [ta, ia] = order[k];
    const auto& [tb, ib] = order[(k + 1) % order.size()];
    const Eigen::Vector2d a = loop.row(ia).transpose(), b = loop.row(ib).transpose();
    if ((b - a).norm() <= options.open_gap_mm) continue;
    const double dt = k + 1 < order.size() ? tb - ta : tb + (2 * kPi) - ta;
    if (!(dt > 0) || dt > max_dt) continue;
    out.bridged_mm += Bridge(options, *e, a, ta, b, dt, &fill);
    ++out.holes;
  }
  out.points.resize(static_cast<Eigen::Index>(fill.size()), 2);
  for (std::size_t i = 0; i < fill.size(); ++i)
    out.points.row(static_cast<Eigen::Index>(i)) = fill[i].transpose();
  return out;
}

}  // namespace bespoke
