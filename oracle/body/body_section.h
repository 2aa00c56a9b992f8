// The convex cross-section shape of the parametric body (a helper of
// parametric_body.cc, public so that tests and the oracle can use the same
// analytic shapes).
//
// In its own plane with coordinates (u, v) about the centre (cu, cv), a
// Section is two halves glued at v = cv: the front half (v >= cv) and the
// back half (v <= cv). Each half, in |u| <= a, is
//   v - cv = +-b                                  for |u| <= w  (flat middle)
//   ((|u| - w) / (a - w))^p + (|v - cv| / b)^p = 1  for w <= |u| <= a
// with its own depth b > 0, exponent p >= 1.5 and flat half-width 0 <= w < a.
// Both halves meet at (cu +- a, cv) with a vertical tangent, so the curve is
// convex and C1 (C2 where p > 2). p = 2, w = 0 gives half-ellipses.
// Units: millimetres.
#ifndef BESPOKE_ORACLE_BODY_BODY_SECTION_H_
#define BESPOKE_ORACLE_BODY_BODY_SECTION_H_

#include <Eigen/Core>
#include <vector>

namespace bespoke {

struct SectionHalf {
  double b = 1;  // depth from the centre line (mm, > 0)
  double p = 2;  // superellipse exponent (>= 1.5)
  double w = 0;  // half-width of the flat middle part (mm, 0 <= w < a)
};

struct Section {
  double cu = 0, cv = 0;  // centre (mm)
  double a = 1;           // half-width along u (mm)
  SectionHalf front;      // v >= cv
  SectionHalf back;       // v <= cv

  // Arc length of the closed curve (mm): adaptive Gauss-Kronrod quadrature,
  // relative error below 1e-10.
  double Perimeter() const;
  // The same shape scaled about its centre by `s` (perimeter times s).
  Section Scaled(double s) const;
  // 4 * quarter points, counter-clockwise in (u, v) starting at (cu + a, cv):
  // point k * quarter is the k-th extreme (+u side, front centre, -u side,
  // back centre), points in between are spread evenly in arc length within
  // each quadrant. Every point lies exactly on the curve.
  std::vector<Eigen::Vector2d> Sample(int quarter) const;
  // The point of the quadrant starting at extreme `q` (0..3) at fraction
  // `f` in [0, 1] of that quadrant's arc length (exact point on the curve).
  Eigen::Vector2d PointInQuadrant(int q, double f) const;
  // Gauge function: < 1 inside, 1 on the curve, > 1 outside.
  double Gauge(const Eigen::Vector2d& uv) const;
  // Throws InternalError when a field is out of its range.
  void CheckValid() const;
};

// Field-wise linear blend (1 - t) x + t y; the result is a valid Section.
Section Lerp(const Section& x, const Section& y, double t);

// Perimeter of the closed polygon through `points` (#P, in order).
double PolygonPerimeter(const std::vector<Eigen::Vector2d>& points);

// Sampling of any smooth plane curve c(t), t in [t0, t1], by a measure
// that mixes arc length and curvature: a dense table of chords, inverted by
// interpolation. With curvature_share = 0 the points are spread evenly in arc
// length; with a share > 0, part of them is spread by the integral of
// kappa^(2/3) ds, the density that minimises the length lost by an inscribed
// polygon (local loss ~ kappa^2 h^3 / 24).
class ArcLengthTable {
 public:
  template <typename Curve>
  ArcLengthTable(const Curve& curve, double t0, double t1, int samples = 4096,
                 double curvature_share = 0) {
    std::vector<Eigen::Vector2d> p(static_cast<size_t>(samples) + 1);
    t_.resize(p.size());
    for (int i = 0; i <= samples; ++i) {
      t_[static_cast<size_t>(i)] = t0 + (t1 - t0) * i / samples;
      p[static_cast<size_t>(i)] = curve(t_[static_cast<size_t>(i)]);
    }
    Build(p, curvature_share);
  }
  double length() const { return length_; }
  // The parameter t at fraction f in [0, 1] of the measure.
  double ParameterAt(double f) const;

 private:
  void Build(const std::vector<Eigen::Vector2d>& points, double curvature_share);
  std::vector<double> t_, s_;
  double length_ = 0;
};

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_BODY_BODY_SECTION_H_
