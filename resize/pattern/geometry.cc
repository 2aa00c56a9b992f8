#include "resize/pattern/geometry.h"

#include <Eigen/LU>
#include <Eigen/SVD>
#include <algorithm>
#include <cmath>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

int Orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double v = Cross(b - a, c - a);
  const double scale = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), 1e-30});
  if (std::abs(v) <= 1e-12 * scale) return 0;
  return v > 0 ? 1 : -1;
}

bool OnSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p) {
  return p.x() <= std::max(a.x(), b.x()) && p.x() >= std::min(a.x(), b.x()) &&
         p.y() <= std::max(a.y(), b.y()) && p.y() >= std::min(a.y(), b.y());
}

}  // namespace

double SignedArea(const Outline& outline) {
  const int n = static_cast<int>(outline.rows());
  double area = 0;
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    area += outline(i, 0) * outline(j, 1) - outline(j, 0) * outline(i, 1);
  }
  return 0.5 * area;
}

double Perimeter(const Outline& outline) {
  const int n = static_cast<int>(outline.rows());
  double length = 0;
  for (int i = 0; i < n; ++i) length += (outline.row((i + 1) % n) - outline.row(i)).norm();
  return length;
}

double OutlineDistance(const Outline& outline, int from, int to, bool forward) {
  const int n = static_cast<int>(outline.rows());
  double length = 0;
  for (int i = from; i != to;) {
    const int next = forward ? (i + 1) % n : (i - 1 + n) % n;
    length += (outline.row(next) - outline.row(i)).norm();
    i = next;
  }
  return length;
}

bool SegmentsIntersect(const Eigen::Vector2d& p0, const Eigen::Vector2d& p1,
                       const Eigen::Vector2d& q0, const Eigen::Vector2d& q1) {
  const int o1 = Orientation(p0, p1, q0), o2 = Orientation(p0, p1, q1);
  const int o3 = Orientation(q0, q1, p0), o4 = Orientation(q0, q1, p1);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && OnSegment(p0, p1, q0)) return true;
  if (o2 == 0 && OnSegment(p0, p1, q1)) return true;
  if (o3 == 0 && OnSegment(q0, q1, p0)) return true;
  if (o4 == 0 && OnSegment(q0, q1, p1)) return true;
  return false;
}

std::pair<int, int> FindSelfIntersection(const Outline& outline) {
  const int n = static_cast<int>(outline.rows());
  if (n < 4) return {-1, -1};
  // Bounding boxes first: most pairs are rejected without orientation tests.
  std::vector<Eigen::Vector4d> box(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = outline.row(i), b = outline.row((i + 1) % n);
    box[i] << std::min(a.x(), b.x()), std::min(a.y(), b.y()), std::max(a.x(), b.x()),
        std::max(a.y(), b.y());
  }
  for (int i = 0; i < n; ++i) {
    for (int j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through the closing edge
      if (box[i][0] > box[j][2] || box[j][0] > box[i][2] || box[i][1] > box[j][3] ||
          box[j][1] > box[i][3])
        continue;
      if (SegmentsIntersect(outline.row(i), outline.row((i + 1) % n), outline.row(j),
                            outline.row((j + 1) % n)))
        return {i, j};
    }
  }
  return {-1, -1};
}

Eigen::VectorXd TurningAngles(const Outline& outline) {
  const int n = static_cast<int>(outline.rows());
  Eigen::VectorXd angles(n);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = outline.row(i) - outline.row((i - 1 + n) % n);
    const Eigen::Vector2d b = outline.row((i + 1) % n) - outline.row(i);
    angles[i] = std::atan2(Cross(a, b), a.dot(b));
  }
  return angles;
}

std::vector<bool> CurveVertices(const Outline& o, const std::vector<bool>& skip, double corner_rad,
                                double straight_mm) {
  const Eigen::VectorXd turning = TurningAngles(o);
  const int n = static_cast<int>(o.rows());
  std::vector<bool> curve(n, false);
  for (int v = 0; v < n; ++v) {
    const double before = (o.row(v) - o.row((v - 1 + n) % n)).norm();
    const double after = (o.row((v + 1) % n) - o.row(v)).norm();
    curve[v] =
        !skip[v] && std::abs(turning[v]) < corner_rad && std::min(before, after) < straight_mm;
  }
  return curve;
}

Outline OffsetOutline(const Outline& outline, double distance_mm) {
  const int n = static_cast<int>(outline.rows());
  const double sign = SignedArea(outline) >= 0 ? 1.0 : -1.0;  // outward = right of CCW travel
  Outline result(n, 2);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d prev = outline.row((i - 1 + n) % n), cur = outline.row(i),
                          next = outline.row((i + 1) % n);
    Eigen::Vector2d d0 = (cur - prev).normalized(), d1 = (next - cur).normalized();
    const Eigen::Vector2d n0(d0.y() * sign, -d0.x() * sign), n1(d1.y() * sign, -d1.x() * sign);
    Eigen::Vector2d bisector = n0 + n1;
    if (bisector.norm() < 1e-9) bisector = n0;
    bisector.normalize();
    const double cos_half = std::max(bisector.dot(n0), 1.0 / 3.0);  // mitre limit 3x
    result.row(i) = cur + bisector * (distance_mm / cos_half);
  }
  return result;
}

std::vector<Eigen::Vector2d> SampleQuadratic(const Eigen::Vector2d& p0, const Eigen::Vector2d& c,
                                             const Eigen::Vector2d& p1, int samples) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < samples; ++i) {
    const double t = samples == 1 ? 0.0 : static_cast<double>(i) / (samples - 1);
    points.push_back((1 - t) * (1 - t) * p0 + 2 * (1 - t) * t * c + t * t * p1);
  }
  return points;
}

std::vector<Eigen::Vector2d> SampleCubic(const Eigen::Vector2d& p0, const Eigen::Vector2d& c0,
                                         const Eigen::Vector2d& c1, const Eigen::Vector2d& p1,
                                         int samples) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < samples; ++i) {
    const double t = samples == 1 ? 0.0 : static_cast<double>(i) / (samples - 1);
    const double s = 1 - t;
    points.push_back(s * s * s * p0 + 3 * s * s * t * c0 + 3 * s * t * t * c1 + t * t * t * p1);
  }
  return points;
}

std::vector<Eigen::Vector2d> ResamplePolyline(const std::vector<Eigen::Vector2d>& polyline,
                                              int samples) {
  BESPOKE_CHECK(polyline.size() >= 2 && samples >= 2, "ResamplePolyline needs 2+ points");
  std::vector<double> cumulative(polyline.size(), 0.0);
  for (size_t i = 1; i < polyline.size(); ++i)
    cumulative[i] = cumulative[i - 1] + (polyline[i] - polyline[i - 1]).norm();
  const double total = cumulative.back();
  std::vector<Eigen::Vector2d> points;
  size_t segment = 0;
  for (int k = 0; k < samples; ++k) {
    const double s = total * k / (samples - 1);
    while (segment + 2 < polyline.size() && cumulative[segment + 1] < s) ++segment;
    const double span = cumulative[segment + 1] - cumulative[segment];
    const double t = span > 0 ? std::clamp((s - cumulative[segment]) / span, 0.0, 1.0) : 0.0;
    points.push_back(polyline[segment] + t * (polyline[segment + 1] - polyline[segment]));
  }
  points.front() = polyline.front();
  points.back() = polyline.back();
  return points;
}

std::vector<Eigen::Vector2d> SmoothCurve(const std::vector<Eigen::Vector2d>& through, int samples) {
  BESPOKE_CHECK(through.size() >= 2, "SmoothCurve needs 2+ points");
  if (through.size() == 2) return ResamplePolyline(through, samples);
  // Centripetal Catmull-Rom with reflected end tangents, densely sampled.
  std::vector<Eigen::Vector2d> p;
  p.push_back(2 * through[0] - through[1]);
  p.insert(p.end(), through.begin(), through.end());
  p.push_back(2 * through.back() - through[through.size() - 2]);
  std::vector<Eigen::Vector2d> dense;
  const int per_segment = 32;
  for (size_t i = 1; i + 2 < p.size(); ++i) {
    const Eigen::Vector2d &p0 = p[i - 1], &p1 = p[i], &p2 = p[i + 1], &p3 = p[i + 2];
    const double t0 = 0, t1 = t0 + std::sqrt(std::max((p1 - p0).norm(), 1e-9));
    const double t2 = t1 + std::sqrt(std::max((p2 - p1).norm(), 1e-9));
    const double t3 = t2 + std::sqrt(std::max((p3 - p2).norm(), 1e-9));
    for (int k = (i == 1 ? 0 : 1); k <= per_segment; ++k) {
      const double t = t1 + (t2 - t1) * k / per_segment;
      const Eigen::Vector2d a1 = (t1 - t) / (t1 - t0) * p0 + (t - t0) / (t1 - t0) * p1;
      const Eigen::Vector2d a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2;
      const Eigen::Vector2d a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3;
      const Eigen::Vector2d b1 = (t2 - t) / (t2 - t0) * a1 + (t - t0) / (t2 - t0) * a2;
      const Eigen::Vector2d b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3;
      dense.push_back((t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2);
    }
  }
  return ResamplePolyline(dense, samples);
}

OutlineDistanceStats CompareOutlines(const Outline& a, const Outline& b) {
  if (a.rows() != b.rows() || a.rows() == 0)
    throw InputError("outlines to compare have " + std::to_string(a.rows()) + " and " +
                     std::to_string(b.rows()) + " vertices");
  const Eigen::RowVector2d ca = a.colwise().mean(), cb = b.colwise().mean();
  const Eigen::MatrixX2d a0 = a.rowwise() - ca, b0 = b.rowwise() - cb;
  const Eigen::Matrix2d h = b0.transpose() * a0;
  Eigen::JacobiSVD<Eigen::Matrix2d> svd(h, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix2d r = svd.matrixV() * svd.matrixU().transpose();
  if (r.determinant() < 0) {
    Eigen::Matrix2d d = Eigen::Matrix2d::Identity();
    d(1, 1) = -1;
    r = svd.matrixV() * d * svd.matrixU().transpose();
  }
  OutlineDistanceStats stats;
  for (Eigen::Index i = 0; i < a.rows(); ++i) {
    const double d = (a0.row(i).transpose() - r * b0.row(i).transpose()).norm();
    stats.mean_mm += d;
    stats.max_mm = std::max(stats.max_mm, d);
  }
  stats.mean_mm /= static_cast<double>(a.rows());
  return stats;
}

}  // namespace bespoke
