#include "measure/tape/ellipse_fit.h"

#include <Eigen/LU>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "scanners/core/constants.h"

namespace bespoke {

Eigen::Vector2d Ellipse2d::At(double t) const {
  const Eigen::Vector2d v(-axis_u.y(), axis_u.x());
  return centre + semi_axis_u_mm * std::cos(t) * axis_u + semi_axis_v_mm * std::sin(t) * v;
}

double Ellipse2d::ParameterOf(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d d = p - centre, v(-axis_u.y(), axis_u.x());
  return std::atan2(d.dot(v) / semi_axis_v_mm, d.dot(axis_u) / semi_axis_u_mm);
}

double Ellipse2d::RadiusToward(const Eigen::Vector2d& p) const {
  return (At(ParameterOf(p)) - centre).norm();
}

std::optional<Ellipse2d> FitEllipse(const Eigen::MatrixX2d& points) {
  if (points.rows() < 5 || !points.allFinite()) return std::nullopt;
  const Eigen::RowVector2d mean = points.colwise().mean();
  // Points on a line fix no ellipse (OpenCV would still return one).
  const Eigen::MatrixX2d d = points.rowwise() - mean;
  const Eigen::Matrix2d scatter = d.transpose() * d;
  const double trace = scatter.trace(), det = scatter.determinant();
  if (!(det > 1e-8 * trace * trace)) return std::nullopt;
  std::vector<cv::Point2f> centred(static_cast<std::size_t>(points.rows()));
  for (Eigen::Index i = 0; i < points.rows(); ++i)
    centred[static_cast<std::size_t>(i)] = cv::Point2f(static_cast<float>(points(i, 0) - mean.x()),
                                                       static_cast<float>(points(i, 1) - mean.y()));
  cv::RotatedRect rect;
  try {
    rect = cv::fitEllipseDirect(centred);
  } catch (const cv::Exception&) {
    return std::nullopt;  // degenerate input (OpenCV asserts on it)
  }
  Ellipse2d out;
  const double angle_rad = rect.angle * kPi / 180.0;
  out.centre = Eigen::Vector2d(rect.center.x + mean.x(), rect.center.y + mean.y());
  out.axis_u = Eigen::Vector2d(std::cos(angle_rad), std::sin(angle_rad));
  out.semi_axis_u_mm = rect.size.width / 2.0;
  out.semi_axis_v_mm = rect.size.height / 2.0;
  if (!out.centre.allFinite() || !(out.semi_axis_u_mm > 0) || !(out.semi_axis_v_mm > 0) ||
      !std::isfinite(out.semi_axis_u_mm) || !std::isfinite(out.semi_axis_v_mm))
    return std::nullopt;
  return out;
}

}  // namespace bespoke
