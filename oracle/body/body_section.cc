#include "oracle/body/body_section.h"

#include <algorithm>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>

#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// Half of each quadrant's points by arc length, half by curvature (see
// ArcLengthTable): about halves the polygon's length deficit on the
// body's superellipses for the same number of points.
constexpr double kCurvatureShare = 0.5;

// Arc length of the superellipse quarter (|u|/A)^p + (|v|/B)^p = 1 from
// (A, 0) to (0, B). Split at the 45-degree parameter point so that each part
// is a graph with a bounded slope, then integrate sqrt(1 + slope^2).
double SuperellipseQuarterLength(double A, double B, double p) {
  using boost::math::quadrature::gauss_kronrod;
  const double k = std::pow(2.0, -1.0 / p);
  // Part near (A, 0): u(v) = A (1 - (v/B)^p)^(1/p), v in [0, k B].
  auto slope_u = [A, B, p](double v) {
    const double r = std::pow(v / B, p);
    const double du = A * std::pow(1 - r, 1 / p - 1) * std::pow(v / B, p - 1) / B;
    return std::sqrt(1 + du * du);
  };
  // Part near (0, B): v(u) = B (1 - (u/A)^p)^(1/p), u in [0, k A].
  auto slope_v = [A, B, p](double u) {
    const double r = std::pow(u / A, p);
    const double dv = B * std::pow(1 - r, 1 / p - 1) * std::pow(u / A, p - 1) / A;
    return std::sqrt(1 + dv * dv);
  };
  const double tol = 1e-12;
  return gauss_kronrod<double, 31>::integrate(slope_u, 0.0, k * B, 20, tol) +
         gauss_kronrod<double, 31>::integrate(slope_v, 0.0, k * A, 20, tol);
}

// The standard quarter of a half from (a, 0) to (0, b) (local |u|, |v|),
// parameter t in [0, 2]: [0, 1] the superellipse part, [1, 2] the flat part.
Eigen::Vector2d QuarterPoint(double a, const SectionHalf& h, double t) {
  if (t <= 1) {
    const double phi = t * kPi / 2;
    const double c = std::pow(std::max(0.0, std::cos(phi)), 2 / h.p);
    const double s = std::pow(std::max(0.0, std::sin(phi)), 2 / h.p);
    return {h.w + (a - h.w) * c, h.b * s};
  }
  return {h.w * (2 - t), h.b};
}

ArcLengthTable QuarterTable(double a, const SectionHalf& h) {
  const auto curve = [a, &h](double t) { return QuarterPoint(a, h, t); };
  // No flat part: stop at t = 1 (the table would hold a zero-length tail).
  return ArcLengthTable(curve, 0.0, h.w > 0 ? 2.0 : 1.0, 4096, kCurvatureShare);
}

Eigen::Vector2d PlaceInQuadrant(const Section& s, int q, const Eigen::Vector2d& local) {
  switch (q) {
    case 0:
      return {s.cu + local.x(), s.cv + local.y()};
    case 1:
      return {s.cu - local.x(), s.cv + local.y()};
    case 2:
      return {s.cu - local.x(), s.cv - local.y()};
    default:
      return {s.cu + local.x(), s.cv - local.y()};
  }
}

// Is `local` (|u|, |v| about the centre) inside the half's quarter shape?
bool InsideQuarter(double a, const SectionHalf& h, double du, double dv) {
  if (du > a || dv > h.b) return false;
  if (du <= h.w) return true;
  return std::pow((du - h.w) / (a - h.w), h.p) + std::pow(dv / h.b, h.p) <= 1;
}

}  // namespace

void ArcLengthTable::Build(const std::vector<Eigen::Vector2d>& p, double curvature_share) {
  const size_t n = p.size() - 1;
  std::vector<double> chord(n), turn(n, 0.0);
  for (size_t i = 0; i < n; ++i) chord[i] = (p[i + 1] - p[i]).norm();
  // Turning angle at each interior point, shared by its two chords.
  for (size_t i = 1; i < n; ++i) {
    const Eigen::Vector2d a = p[i] - p[i - 1], b = p[i + 1] - p[i];
    if (a.norm() == 0 || b.norm() == 0) continue;
    const double angle = std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b));
    turn[i - 1] += 0.5 * angle;
    turn[i] += 0.5 * angle;
  }
  std::vector<double> bend(n);
  double total_length = 0, total_bend = 0;
  for (size_t i = 0; i < n; ++i) {
    bend[i] = std::cbrt(chord[i] * turn[i] * turn[i]);  // kappa^(2/3) ds
    total_length += chord[i];
    total_bend += bend[i];
  }
  length_ = total_length;
  s_.assign(n + 1, 0.0);
  const double share = total_bend > 0 ? curvature_share : 0.0;
  for (size_t i = 0; i < n; ++i) {
    s_[i + 1] = s_[i] + (1 - share) * chord[i] / std::max(total_length, 1e-300) +
                (share > 0 ? share * bend[i] / total_bend : 0.0);
  }
}

double ArcLengthTable::ParameterAt(double f) const {
  const double target = std::clamp(f, 0.0, 1.0) * s_.back();
  const auto it = std::lower_bound(s_.begin(), s_.end(), target);
  if (it == s_.begin()) return t_.front();
  if (it == s_.end()) return t_.back();
  const size_t i = static_cast<size_t>(it - s_.begin());
  const double span = s_[i] - s_[i - 1];
  const double u = span > 0 ? (target - s_[i - 1]) / span : 0;
  return t_[i - 1] + u * (t_[i] - t_[i - 1]);
}

void Section::CheckValid() const {
  const auto check_half = [this](const SectionHalf& h, const char* which) {
    BESPOKE_CHECK(std::isfinite(h.b) && h.b > 0, std::string("section ") + which + " depth <= 0");
    BESPOKE_CHECK(std::isfinite(h.p) && h.p >= 1.5,
                  std::string("section ") + which + " exponent < 1.5");
    BESPOKE_CHECK(std::isfinite(h.w) && h.w >= 0 && h.w < a,
                  std::string("section ") + which + " flat part outside [0, a)");
  };
  BESPOKE_CHECK(std::isfinite(a) && a > 0, "section half-width <= 0");
  BESPOKE_CHECK(std::isfinite(cu) && std::isfinite(cv), "section centre not finite");
  check_half(front, "front");
  check_half(back, "back");
}

double Section::Perimeter() const {
  CheckValid();
  const auto half = [this](const SectionHalf& h) {
    return 2 * (h.w + SuperellipseQuarterLength(a - h.w, h.b, h.p));
  };
  return half(front) + half(back);
}

Section Section::Scaled(double s) const {
  Section out = *this;
  out.a *= s;
  for (SectionHalf* h : {&out.front, &out.back}) {
    h->b *= s;
    h->w *= s;
  }
  return out;
}

std::vector<Eigen::Vector2d> Section::Sample(int quarter) const {
  CheckValid();
  BESPOKE_CHECK(quarter >= 1, "Section::Sample needs at least one point per quadrant");
  const ArcLengthTable front_table = QuarterTable(a, front);
  const ArcLengthTable back_table = QuarterTable(a, back);
  const Eigen::Vector2d extremes[4] = {
      {cu + a, cv}, {cu, cv + front.b}, {cu - a, cv}, {cu, cv - back.b}};
  std::vector<Eigen::Vector2d> points;
  points.reserve(static_cast<size_t>(4 * quarter));
  for (int q = 0; q < 4; ++q) {
    const SectionHalf& h = (q < 2) ? front : back;
    const ArcLengthTable& table = (q < 2) ? front_table : back_table;
    points.push_back(extremes[q]);
    for (int k = 1; k < quarter; ++k) {
      const double f = static_cast<double>(k) / quarter;
      // Quadrants 1 and 3 run from the centre line outwards: reverse.
      const double g = (q % 2 == 1) ? 1 - f : f;
      points.push_back(PlaceInQuadrant(*this, q, QuarterPoint(a, h, table.ParameterAt(g))));
    }
  }
  return points;
}

Eigen::Vector2d Section::PointInQuadrant(int q, double f) const {
  CheckValid();
  const SectionHalf& h = (q < 2) ? front : back;
  const ArcLengthTable table = QuarterTable(a, h);
  const double g = (q == 1 || q == 3) ? 1 - f : f;
  return PlaceInQuadrant(*this, q, QuarterPoint(a, h, table.ParameterAt(g)));
}

double Section::Gauge(const Eigen::Vector2d& uv) const {
  const double du = std::abs(uv.x() - cu);
  const double dv_signed = uv.y() - cv;
  const SectionHalf& h = dv_signed >= 0 ? front : back;
  const double dv = std::abs(dv_signed);
  if (du == 0 && dv == 0) return 0;
  // Smallest lambda with (du, dv) / lambda inside: bisection (the shape is
  // convex and contains the centre, so "inside" is monotone in lambda).
  double lo = 0, hi = 1;
  while (!InsideQuarter(a, h, du / hi, dv / hi)) hi *= 2;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (InsideQuarter(a, h, du / mid, dv / mid) ? hi : lo) = mid;
  }
  return hi;
}

Section Lerp(const Section& x, const Section& y, double t) {
  const auto mix = [t](double p, double q) { return (1 - t) * p + t * q; };
  const auto mix_half = [&mix](const SectionHalf& p, const SectionHalf& q) {
    return SectionHalf{mix(p.b, q.b), mix(p.p, q.p), mix(p.w, q.w)};
  };
  Section s;
  s.cu = mix(x.cu, y.cu);
  s.cv = mix(x.cv, y.cv);
  s.a = mix(x.a, y.a);
  s.front = mix_half(x.front, y.front);
  s.back = mix_half(x.back, y.back);
  return s;
}

double PolygonPerimeter(const std::vector<Eigen::Vector2d>& points) {
  double sum = 0;
  for (size_t i = 0; i < points.size(); ++i)
    sum += (points[(i + 1) % points.size()] - points[i]).norm();
  return sum;
}

}  // namespace bespoke
