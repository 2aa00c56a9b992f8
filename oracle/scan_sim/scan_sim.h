// The virtual body scanner: what a booth of depth sensors would record of a
// body mesh, with the imperfections of real scans, deterministically from a
// seed. The test oracle's scans (bespoke scan-sim).
//
// Input: a closed body mesh in the body frame (mm, feet on z = 0, centred
// on the booth axis x = y = 0). Each sensor of the booth (booth.h) casts one
// ray per pixel against the body, the floor patch and stray objects (Embree
// via Open3D); so regions no sensor sees (armpits, crotch, between the legs,
// under the chin, soles) have no points, as in real scans. Then:
//  - range noise: Gaussian, sigma noise_sigma_mm, along each ray;
//  - grazing returns (|cos incidence| < min_incidence_cos) and returns
//    outside the sensor's range are dropped;
//  - misalignment: each sensor's true pose differs from its calibrated pose
//    by a random rigid error; points are reported with the calibrated pose;
//  - outliers: 80 % flying pixels (moved along their ray by 30-300 mm),
//    20 % clutter uniform in the booth; outlier_fraction of the output;
//  - normals: the hit face's normal, turned towards the sensor (outliers:
//    towards their sensor);
//  - finally the rigid scanner_from_body is applied (none, random, y-up).
// Output units stay mm; a writer may scale to metres (cmd_scan_sim.cc).
//
// Failure: InputError for bad options or an empty mesh. Cost: one ray per
// pixel (1,814,400 for the default booth); see docs/oracle.md for timings.
#ifndef BESPOKE_ORACLE_SCAN_SIM_SCAN_SIM_H_
#define BESPOKE_ORACLE_SCAN_SIM_SCAN_SIM_H_

#include <cstdint>
#include <string>
#include <vector>

#include "oracle/scan_sim/booth.h"
#include "scanners/core/progress.h"
#include "scanners/core/types.h"

namespace bespoke {

enum class ScanTransform { kNone, kRandom, kYUp };
// "none", "random", "y-up"; nullopt-like InputError for anything else.
ScanTransform ParseScanTransform(const std::string& text);
std::string ToString(ScanTransform transform);

struct ScanSimOptions {
  BoothOptions booth;
  double noise_sigma_mm = 1.0;      // range noise SD along the ray (0-50)
  double outlier_fraction = 0.02;   // share of output points that are outliers (0-0.5)
  double min_incidence_cos = 0.1;   // drop returns hitting the surface more obliquely (0-0.99)
  bool floor = true;                // a square floor patch on z = 0 around the feet
  double floor_half_size_mm = 450;  // half the side of the floor patch
  int stray_objects = 0;            // poles and boxes standing in the booth (0-8)
  double misalign_mm = 0;           // per-sensor translation error SD, each axis (0-100)
  double misalign_deg = 0;          // per-sensor rotation error SD (0-10)
  ScanTransform transform = ScanTransform::kNone;  // scanner_from_body applied to the output
  std::uint64_t seed = 1;                          // everything random derives from it
  // Throws InputError naming the field when a value is out of range.
  void Check() const;
};

// Label of each output point (PointCloud scalar "source").
enum class ScanSource { kBody = 0, kFloor = 1, kStray = 2, kOutlier = 3 };

struct ScanSimResult {
  // Scanner frame, mm: points, normals, scalars "source" (ScanSource) and
  // "sensor" (index into `sensors`).
  PointCloud cloud;
  Eigen::Affine3d scanner_from_body = Eigen::Affine3d::Identity();  // rigid
  std::vector<DepthSensor> sensors;                                 // calibrated poses, body frame
  std::int64_t rays = 0;                                            // cast
  std::int64_t counts[4] = {0, 0, 0, 0};                            // points by ScanSource
  std::int64_t dropped_grazing = 0, dropped_range = 0;
  int stray_objects_placed = 0;  // fewer than asked when no free place was found
};

ScanSimResult SimulateScan(const ScanSimOptions& options, const TriangleMesh& body,
                           Progress* progress = nullptr);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_SCAN_SIM_SCAN_SIM_H_
