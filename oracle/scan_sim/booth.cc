#include "oracle/scan_sim/booth.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "scanners/core/constants.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

void CheckRange(const char* name, double value, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InputError(std::string("scanner booth: ") + name + " = " + std::to_string(value) +
                     " is outside [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  }
}

}  // namespace

void BoothOptions::Check() const {
  CheckRange("directions", directions, 1, 64);
  CheckRange("heights", heights, 1, 32);
  CheckRange("radius_mm", radius_mm, 300, 10000);
  CheckRange("lowest_mm", lowest_mm, -1000, 5000);
  CheckRange("highest_mm", highest_mm, lowest_mm, 5000);
  CheckRange("azimuth_offset_deg", azimuth_offset_deg, -360, 360);
  CheckRange("aim_low_mm", aim_low_mm, -1000, 5000);
  CheckRange("aim_high_mm", aim_high_mm, aim_low_mm, 5000);
  CheckRange("width_px", width_px, 4, 8192);
  CheckRange("height_px", height_px, 4, 8192);
  CheckRange("fov_horizontal_deg", fov_horizontal_deg, 5, 150);
  CheckRange("fov_vertical_deg", fov_vertical_deg, 5, 150);
  CheckRange("min_range_mm", min_range_mm, 0, 1e5);
  CheckRange("max_range_mm", max_range_mm, min_range_mm + 1, 1e5);
  if (static_cast<double>(directions) * heights * width_px * height_px > 2e8) {
    throw InputError(
        "scanner booth: more than 200 million rays; lower the sensor count or resolution");
  }
}

Eigen::Vector3d DepthSensor::Ray(int u, int v) const {
  const Eigen::Vector3d camera((u + 0.5 - 0.5 * width_px) / fx, (v + 0.5 - 0.5 * height_px) / fy,
                               1.0);
  return (body_from_camera.linear() * camera).normalized();
}

std::vector<DepthSensor> MakeBooth(const BoothOptions& o) {
  o.Check();
  std::vector<DepthSensor> sensors;
  for (int d = 0; d < o.directions; ++d) {
    const double azimuth = (o.azimuth_offset_deg + 360.0 * d / o.directions) * kPi / 180;
    for (int h = 0; h < o.heights; ++h) {
      const double z = o.heights == 1
                           ? 0.5 * (o.lowest_mm + o.highest_mm)
                           : o.lowest_mm + (o.highest_mm - o.lowest_mm) * h / (o.heights - 1);
      // Front (+y) at azimuth 0, counter-clockwise seen from above.
      const Eigen::Vector3d eye(-o.radius_mm * std::sin(azimuth), o.radius_mm * std::cos(azimuth),
                                z);
      const Eigen::Vector3d target(0, 0, std::clamp(z, o.aim_low_mm, o.aim_high_mm));
      const Eigen::Vector3d forward = (target - eye).normalized();
      const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
      const Eigen::Vector3d down = forward.cross(right);
      DepthSensor s;
      s.body_from_camera.linear().col(0) = right;
      s.body_from_camera.linear().col(1) = down;
      s.body_from_camera.linear().col(2) = forward;
      s.body_from_camera.translation() = eye;
      s.width_px = o.width_px;
      s.height_px = o.height_px;
      s.fx = 0.5 * o.width_px / std::tan(0.5 * o.fov_horizontal_deg * kPi / 180);
      s.fy = 0.5 * o.height_px / std::tan(0.5 * o.fov_vertical_deg * kPi / 180);
      s.min_range_mm = o.min_range_mm;
      s.max_range_mm = o.max_range_mm;
      sensors.push_back(s);
    }
  }
  return sensors;
}

const std::vector<std::string>& BoothPresetNames() {
  static const std::vector<std::string> names = {"default", "sparse", "sparse-3", "60k",
                                                 "120k",    "250k",   "500k"};
  return names;
}

BoothOptions BoothPreset(const std::string& name) {
  BoothOptions o;
  // Depth image of the 6 x 7 layout for about `points` points of an adult:
  // the count grows with the pixel count (about 350k points of a MakeHuman
  // body at 240 x 180).
  const auto density = [&o](double points) {
    const double scale = std::sqrt(points / 350e3);
    o.width_px = static_cast<int>(std::lround(240 * scale));
    o.height_px = static_cast<int>(std::lround(180 * scale));
  };
  if (name == "default") {
  } else if (name == "sparse") {
    o.directions = 4;
    o.heights = 4;
  } else if (name == "sparse-3") {
    o.directions = 3;
    o.heights = 3;
    o.width_px = 320;
    o.height_px = 240;
  } else if (name == "60k") {
    density(60e3);
  } else if (name == "120k") {
    density(120e3);
  } else if (name == "250k") {
    density(250e3);
  } else if (name == "500k") {
    density(500e3);
  } else {
    std::string known;
    for (const std::string& n : BoothPresetNames()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("unknown booth '" + name + "' (known: " + known + ")");
  }
  return o;
}

}  // namespace bespoke
