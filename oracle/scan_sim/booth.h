// The sensors of a virtual body-scanner booth: pinhole depth cameras on
// columns around the subject, at several heights, each aimed at the booth's
// vertical axis (x = y = 0 of the body frame).
//
// Defaults model a commercial booth of the kind shops use: 6 columns x 7
// heights (42 sensors) 1.1 m from the subject, 240 x 180 px depth images with
// a 62 x 48 deg field of view, 0.3-2.5 m working range. With a 1 mm range
// noise this gives a 300-500 thousand point scan of an adult (measured in
// docs/oracle.md). Positions in mm, body frame.
#ifndef BESPOKE_ORACLE_SCAN_SIM_BOOTH_H_
#define BESPOKE_ORACLE_SCAN_SIM_BOOTH_H_

#include <string>
#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

struct BoothOptions {
  int directions = 6;        // columns, evenly around the axis, the first in front (+y); 1-64
  int heights = 7;           // sensors per column, evenly from lowest_mm to highest_mm; 1-32
  double radius_mm = 1100;   // horizontal distance of the sensors from the axis
  double lowest_mm = 200;    // height of the lowest sensor
  double highest_mm = 2000;  // height of the highest sensor
  double azimuth_offset_deg =
      0;  // turns the whole booth about the axis (+ = counter-clockwise from above)
  double aim_low_mm = 250;    // each sensor aims at the axis at its own height,
  double aim_high_mm = 1550;  //   clamped to [aim_low_mm, aim_high_mm] (top sensors look down)
  int width_px = 240;         // depth image size
  int height_px = 180;
  double fov_horizontal_deg = 62;  // field of view (pinhole), 5-150
  double fov_vertical_deg = 48;
  double min_range_mm = 300;  // returns outside [min, max] range are dropped
  double max_range_mm = 2500;
  // Throws InputError naming the field when a value is out of range.
  void Check() const;
};

// A pinhole depth camera. Camera axes: x right, y down, z forward.
struct DepthSensor {
  Eigen::Affine3d body_from_camera = Eigen::Affine3d::Identity();  // rigid, mm
  int width_px = 0, height_px = 0;
  double fx = 0, fy = 0;  // focal lengths, pixels (principal point at the image centre)
  double min_range_mm = 0, max_range_mm = 0;
  Eigen::Vector3d position() const { return body_from_camera.translation(); }
  // Unit ray direction through the centre of pixel (u, v), body frame.
  Eigen::Vector3d Ray(int u, int v) const;
};

std::vector<DepthSensor> MakeBooth(const BoothOptions& options);

// Named booths (docs/oracle.md lists their point counts):
//   "default"    6 x 7 sensors, 240 x 180 px (the defaults above);
//   "sparse"     4 columns x 4 heights at 240 x 180 px: bigger holes under
//                the arms, between the legs and on the sides;
//   "sparse-3"   3 columns x 3 heights at 320 x 240 px: a three-tower booth,
//                the biggest holes;
//   "60k", "120k", "250k", "500k": the default 6 x 7 layout with the depth
//                images scaled so an adult gives about that many points.
// InputError naming the known presets for another name.
BoothOptions BoothPreset(const std::string& name);
const std::vector<std::string>& BoothPresetNames();

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_SCAN_SIM_BOOTH_H_
