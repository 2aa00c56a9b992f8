// An ellipse fitted to 2-D points: the shape a limb's section continues with
// across a scan hole (see section_girth.h, step 5). A tape round an arm or a
// thigh whose inner side the booth did not see passes over skin that bulges
// past the hole's chord; the ellipse through the scanned arcs says by how
// much.
//
// Method: OpenCV's direct least-squares ellipse fit (Fitzgibbon, Pilu and
// Fisher 1999, `cv::fitEllipseDirect`), which always returns an ellipse, on
// the points centred on their mean (single precision inside OpenCV).
// Input: #P x 2 points (mm), P >= 5. Output: the ellipse, or nothing when
// the points fix none (fewer than 5, all on a line, not finite).
#ifndef BESPOKE_MEASURE_TAPE_ELLIPSE_FIT_H_
#define BESPOKE_MEASURE_TAPE_ELLIPSE_FIT_H_

#include <Eigen/Core>
#include <optional>

namespace bespoke {

struct Ellipse2d {
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();   // mm
  double semi_axis_u_mm = 0;                          // semi-axis along `axis_u`
  double semi_axis_v_mm = 0;                          // semi-axis along `axis_u` turned +90 deg
  Eigen::Vector2d axis_u = Eigen::Vector2d::UnitX();  // unit direction of the first axis

  // The point at parameter t (radians): centre + a cos t u + b sin t v.
  Eigen::Vector2d At(double t) const;
  // The parameter of the ellipse point on the ray from the centre through
  // `p` (its eccentric angle), in (-pi, pi].
  double ParameterOf(const Eigen::Vector2d& p) const;
  // The ellipse's radius along the ray from the centre through `p` (mm).
  double RadiusToward(const Eigen::Vector2d& p) const;
};

std::optional<Ellipse2d> FitEllipse(const Eigen::MatrixX2d& points);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_TAPE_ELLIPSE_FIT_H_
