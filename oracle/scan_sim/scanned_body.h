// Test and evaluation fixture of the landmark detector: a generated body
// (parametric or MakeHuman) scanned by the simulated booth in a random rigid
// pose, cleaned by scanners/clean, with the body's exact datum points mapped
// into the cleaned cloud's body frame (through the scan's scanner_from_body
// and the cleaning's body_from_scanner), so detected and true points can be
// compared in mm.
#ifndef BESPOKE_ORACLE_SCAN_SIM_SCANNED_BODY_H_
#define BESPOKE_ORACLE_SCAN_SIM_SCANNED_BODY_H_

#include <cstdint>
#include <map>
#include <string>

#include "oracle/body/body.h"
#include "scanners/core/types.h"

namespace bespoke::testing {

struct ScannedBodyOptions {
  std::uint64_t scan_seed = 1;   // default 1: seed of the booth's noise and pose
  int width_px = 160;            // default 160: depth image width per sensor
  int height_px = 120;           // default 120: depth image height per sensor
  double noise_sigma_mm = 1.0;   // default 1 mm: range noise SD
  bool floor = true;             // default true: a floor patch under the feet
  bool random_transform = true;  // default true: the scanner frame a random rigid motion away
};

struct ScannedBody {
  PointCloud cloud;                              // cleaned, body frame (mm)
  std::map<std::string, Eigen::Vector3d> truth;  // exact datum points, the same frame
  double clean_s = 0;                            // time of CleanScan (s)
};

ScannedBody ScanAndClean(const ScannedBodyOptions& options, const Body& body);

// Makes the thighs touch, as on a heavy body: below the true crotch every
// point moves towards x = 0 by up to `squeeze_mm` (ramping in over the 60 mm
// under the crotch and out towards 55 % of the crotch height), and the
// points that cross x = 0 (each thigh's inner side, now inside the other)
// are dropped, so the thighs meet along a contact no sensor sees, as real
// touching thighs do. The true datum points on the legs move with the skin.
void SqueezeThighs(double squeeze_mm, ScannedBody* scan);

}  // namespace bespoke::testing

#endif  // BESPOKE_ORACLE_SCAN_SIM_SCANNED_BODY_H_
