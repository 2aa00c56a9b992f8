#include "scanners/clean/body_frame.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

double Quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1) + 0.5);
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[static_cast<size_t>(k)];
}

// Centre of the robust extent (2nd to 98th percentile): insensitive to
// where the scanner happened to sample densely.
double ExtentCentre(const std::vector<double>& values) {
  return 0.5 * (Quantile(values, 0.02) + Quantile(values, 0.98));
}

double Cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Area of the convex hull (Andrew's monotone chain).
double HullArea(std::vector<Eigen::Vector2d> p) {
  if (p.size() < 3) return 0.0;
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  std::vector<Eigen::Vector2d> hull(2 * p.size());
  size_t k = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && Cross(hull[k - 2], hull[k - 1], p[i]) <= 0) --k;
    hull[k++] = p[i];
  }
  for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && Cross(hull[k - 2], hull[k - 1], p[i - 1]) <= 0) --k;
    hull[k++] = p[i - 1];
  }
  double area = 0.0;
  for (size_t i = 0; i + 1 < k; ++i)
    area += hull[i].x() * hull[i + 1].y() - hull[i + 1].x() * hull[i].y();
  return 0.5 * std::abs(area);
}

// Points in "body coordinates so far": height z along `up`, and the two
// horizontal coordinates along e1, e2.
struct Projected {
  std::vector<double> z, a, b;
};

Projected Project(const Eigen::MatrixX3d& points, const Eigen::Vector3d& up, double offset,
                  const Eigen::Vector3d& e1, const Eigen::Vector3d& e2) {
  Projected p;
  const auto n = static_cast<size_t>(points.rows());
  p.z.resize(n);
  p.a.resize(n);
  p.b.resize(n);
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d x = points.row(static_cast<Eigen::Index>(i)).transpose();
    p.z[i] = up.dot(x) + offset;
    p.a[i] = e1.dot(x);
    p.b[i] = e2.dot(x);
  }
  return p;
}

void HorizontalBasis(const Eigen::Vector3d& up, Eigen::Vector3d* e1, Eigen::Vector3d* e2) {
  *e1 = up.unitOrthogonal();
  *e2 = up.cross(*e1);
}

double HullAreaOfBand(const Projected& p, double z_from, double z_to) {
  std::vector<Eigen::Vector2d> band;
  for (size_t i = 0; i < p.z.size(); ++i) {
    if (p.z[i] >= z_from && p.z[i] <= z_to) band.emplace_back(p.a[i], p.b[i]);
  }
  return HullArea(std::move(band));
}

// Up from the principal axis, signed so the wide end (feet) is at the bottom.
void PrincipalUp(const BodyFrameOptions& options, const Eigen::MatrixX3d& points,
                 Eigen::Vector3d* up, double* ratio) {
  const Eigen::RowVector3d mean = points.colwise().mean();
  const Eigen::MatrixX3d centred = points.rowwise() - mean;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(centred.transpose() * centred);
  *up = solver.eigenvectors().col(2).normalized();
  Eigen::Vector3d e1, e2;
  HorizontalBasis(*up, &e1, &e2);
  const Projected p = Project(points, *up, 0.0, e1, e2);
  const double low = Quantile(p.z, 0.0005), high = Quantile(p.z, 0.9995);
  const double band = options.end_fraction * (high - low);
  const double bottom = HullAreaOfBand(p, low, low + band);
  const double top = HullAreaOfBand(p, high - band, high);
  *ratio = top > 0 ? bottom / top : 0.0;
  if (bottom < top) {
    *up = -*up;
    *ratio = bottom > 0 ? top / bottom : 0.0;
  }
}

// Per side of the body (lateral coordinate below / above `split`): footprint
// centre minus ankle centre along `forward`.
struct FeetCue {
  int sides = 0;
  double offset[2] = {0, 0};
  bool found[2] = {false, false};
};

bool InAnkleBand(const BodyFrameOptions& options, double z, double height) {
  return z >= options.ankle_low_fraction * height && z <= options.ankle_high_fraction * height;
}

FeetCue MeasureFeet(const BodyFrameOptions& options, const Projected& p, double height,
                    const std::vector<double>& lateral, const std::vector<double>& forward,
                    double split) {
  FeetCue cue;
  for (int side = 0; side < 2; ++side) {
    std::vector<double> foot, ankle;
    for (size_t i = 0; i < p.z.size(); ++i) {
      if ((lateral[i] > split) != (side == 1)) continue;
      if (p.z[i] <= options.foot_fraction * height) foot.push_back(forward[i]);
      if (InAnkleBand(options, p.z[i], height)) ankle.push_back(forward[i]);
    }
    if (foot.size() < 20 || ankle.size() < 20) continue;
    cue.found[side] = true;
    cue.offset[side] = ExtentCentre(foot) - ExtentCentre(ankle);
    ++cue.sides;
  }
  return cue;
}

// Head section centre (mouth to eyes) minus neck centre, along `forward`;
// Width across (lateral) of the points within `depth` of the extreme of
// `forward` in direction `sign` (+1 front tip, -1 back tip).
double TipWidth(const std::vector<double>& across, const std::vector<double>& along, double sign,
                double depth) {
  double extreme = -1e300;
  for (double f : along) extreme = std::max(extreme, sign * f);
  double low = 1e300, high = -1e300;
  for (size_t i = 0; i < along.size(); ++i) {
    if (sign * along[i] < extreme - depth) continue;
    low = std::min(low, across[i]);
    high = std::max(high, across[i]);
  }
  return high - low;
}

// The nose: between the chin and the eyes, each horizontal section of the
// head ends in a narrow tip at the front (the nose, ~30 mm wide 10 mm from
// its tip) and a round one at the back (the occiput, ~75 mm). Returns the
// narrowest back tip minus the narrowest front tip over those sections
// (positive: +forward is the front), 0 when the head is not found.
double MeasureNose(const Projected& p, double height, const std::vector<double>& lateral,
                   const std::vector<double>& forward) {
  std::vector<double> upper;
  for (size_t i = 0; i < p.z.size(); ++i) {
    if (p.z[i] >= 0.75 * height && p.z[i] <= 0.95 * height) upper.push_back(lateral[i]);
  }
  if (upper.size() < 50) return 0.0;
  const double centre = ExtentCentre(upper);
  const double slab = 10.0;
  // The neck: the narrowest section (arms excluded) between 75 and 92 %.
  double best_width = 1e300, neck_z = -1;
  for (double z = 0.75 * height; z <= 0.92 * height; z += slab) {
    std::vector<double> across;
    for (size_t i = 0; i < p.z.size(); ++i) {
      if (p.z[i] >= z && p.z[i] < z + slab && std::abs(lateral[i] - centre) <= 0.1 * height) {
        across.push_back(lateral[i]);
      }
    }
    if (across.size() < 15) continue;
    const double width = Quantile(across, 0.98) - Quantile(across, 0.02);
    if (width < best_width) best_width = width, neck_z = z + slab / 2;
  }
  if (neck_z < 0) return 0.0;
  double front = 1e300, back = 1e300;
  for (double z = neck_z + 0.02 * height; z <= neck_z + 0.09 * height; z += slab) {
    std::vector<double> across, along;
    for (size_t i = 0; i < p.z.size(); ++i) {
      if (p.z[i] >= z && p.z[i] < z + slab && std::abs(lateral[i] - centre) <= 0.1 * height) {
        across.push_back(lateral[i]);
        along.push_back(forward[i]);
      }
    }
    if (across.size() < 30) continue;
    front = std::min(front, TipWidth(across, along, +1, 10.0));
    back = std::min(back, TipWidth(across, along, -1, 10.0));
  }
  return front < 1e299 ? back - front : 0.0;
}

}  // namespace

void BodyFrameOptions::Check() const {
  auto require = [](bool ok, const std::string& what) {
    if (!ok) throw InputError("body frame option out of range: " + what);
  };
  require(end_fraction > 0 && end_fraction < 0.5, "end_fraction must be in (0, 0.5)");
  require(min_end_area_ratio >= 1, "min_end_area_ratio must be >= 1");
  require(foot_fraction > 0 && foot_fraction <= ankle_low_fraction,
          "foot_fraction must be in (0, ankle_low_fraction]");
  require(ankle_low_fraction < ankle_high_fraction && ankle_high_fraction < 0.5,
          "need ankle_low_fraction < ankle_high_fraction < 0.5");
  require(min_foot_offset_mm >= 0 && min_nose_cue_mm >= 0, "minimum offsets must be >= 0");
}

BodyFrame EstimateBodyFrame(const BodyFrameOptions& options, const Eigen::MatrixX3d& points,
                            const std::optional<FloorPlane>& floor) {
  options.Check();
  if (points.rows() < 100) {
    throw InputError("only " + std::to_string(points.rows()) +
                     " points left after cleaning; too few to be a body");
  }
  BodyFrame frame;
  Eigen::Vector3d up;
  if (floor) {
    up = floor->up.normalized();
    frame.up_source = "floor";
  } else {
    PrincipalUp(options, points, &up, &frame.end_area_ratio);
    frame.up_source = "principal_axis";
    if (frame.end_area_ratio < options.min_end_area_ratio) frame.flags.push_back("up_uncertain");
  }
  Eigen::Vector3d e1, e2;
  HorizontalBasis(up, &e1, &e2);
  Projected p = Project(points, up, 0.0, e1, e2);
  const double offset = floor ? floor->offset_mm : -Quantile(p.z, 0.0005);
  for (double& z : p.z) z += offset;
  const double height = Quantile(p.z, 0.9995);
  frame.height_mm = height;
  if (height < 300) {
    throw InputError("the cleaned points reach only " + std::to_string(static_cast<int>(height)) +
                     " mm above the feet; too short to be a standing person");
  }
  if (floor) {
    const double band = options.end_fraction * height;
    const double top = HullAreaOfBand(p, height - band, height);
    frame.end_area_ratio = top > 0 ? HullAreaOfBand(p, 0, band) / top : 0.0;
  }

  // Lateral axis: horizontal PCA of the hips-to-chest band.
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  double count = 0;
  for (size_t i = 0; i < p.z.size(); ++i) {
    if (p.z[i] < 0.35 * height || p.z[i] > 0.8 * height) continue;
    const Eigen::Vector2d q(p.a[i], p.b[i]);
    sum += q;
    cov += q * q.transpose();
    ++count;
  }
  if (count < 10)
    throw InputError("too few points at torso height to find the body's left and right");
  const Eigen::Vector2d mean = sum / count;
  cov = cov / count - mean * mean.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(cov);
  const Eigen::Vector2d major = solver.eigenvectors().col(1);
  frame.lateral_ratio =
      solver.eigenvalues()(0) > 0 ? solver.eigenvalues()(1) / solver.eigenvalues()(0) : 1e9;
  if (frame.lateral_ratio < 1.15) frame.flags.push_back("lateral_axis_uncertain");
  const Eigen::Vector3d lateral = (major.x() * e1 + major.y() * e2).normalized();
  const Eigen::Vector3d forward0 = up.cross(lateral).normalized();

  std::vector<double> lat(p.z.size()), fwd(p.z.size());
  std::vector<double> low_lateral;
  for (size_t i = 0; i < p.z.size(); ++i) {
    const Eigen::Vector3d x = points.row(static_cast<Eigen::Index>(i)).transpose();
    lat[i] = lateral.dot(x);
    fwd[i] = forward0.dot(x);
    if (p.z[i] <= options.ankle_high_fraction * height) low_lateral.push_back(lat[i]);
  }
  // Not the median: with two legs the median falls at the inner edge of
  // whichever leg has a few more points.
  const double split = ExtentCentre(low_lateral);

  // Which way is front.
  const FeetCue feet = MeasureFeet(options, p, height, lat, fwd, split);
  frame.feet_found = feet.sides;
  double foot_offset = 0;
  for (int s = 0; s < 2; ++s) foot_offset += feet.found[s] ? feet.offset[s] / feet.sides : 0.0;
  const bool feet_agree = feet.sides < 2 || (feet.offset[0] > 0) == (feet.offset[1] > 0);
  const bool feet_ok =
      feet.sides > 0 && feet_agree && std::abs(foot_offset) >= options.min_foot_offset_mm;
  const double nose_cue = MeasureNose(p, height, lat, fwd);
  const bool nose_ok = std::abs(nose_cue) >= options.min_nose_cue_mm;
  double sign = 1.0;
  if (feet_ok) {
    sign = foot_offset > 0 ? 1.0 : -1.0;
    frame.front_source = "feet";
    if (feet.sides == 1) frame.flags.push_back("one_foot_found");
    if (nose_ok && (nose_cue > 0) != (foot_offset > 0))
      frame.flags.push_back("front_cues_disagree");
  } else if (nose_ok) {
    sign = nose_cue > 0 ? 1.0 : -1.0;
    frame.front_source = "nose";
    frame.flags.push_back("front_from_nose");
  } else {
    sign = foot_offset + nose_cue >= 0 ? 1.0 : -1.0;
    frame.front_source = "none";
    frame.flags.push_back("front_uncertain");
  }
  frame.foot_offset_mm = sign * foot_offset;
  frame.nose_cue_mm = sign * nose_cue;
  const Eigen::Vector3d forward = sign * forward0;
  const Eigen::Vector3d right = forward.cross(up).normalized();

  // Origin: between the ankle centres.
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();
  int sides = 0;
  for (int side = 0; side < 2; ++side) {
    std::vector<double> fx, fy;
    for (size_t i = 0; i < p.z.size(); ++i) {
      if ((lat[i] > split) != (side == 1) || !InAnkleBand(options, p.z[i], height)) continue;
      const Eigen::Vector3d x = points.row(static_cast<Eigen::Index>(i)).transpose();
      fx.push_back(right.dot(x));
      fy.push_back(forward.dot(x));
    }
    if (fx.size() < 20) continue;
    origin += Eigen::Vector2d(ExtentCentre(fx), ExtentCentre(fy));
    ++sides;
  }
  if (sides == 0) throw InputError("no points at ankle height: cannot find the feet");
  if (sides == 1) frame.flags.push_back("one_ankle_found");
  origin /= sides;

  Eigen::Matrix3d rotation;
  rotation.row(0) = right.transpose();
  rotation.row(1) = forward.transpose();
  rotation.row(2) = up.transpose();
  frame.body_from_scanner.linear() = rotation;
  frame.body_from_scanner.translation() = Eigen::Vector3d(-origin.x(), -origin.y(), offset);
  return frame;
}

}  // namespace bespoke
