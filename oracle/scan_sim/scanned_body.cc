#include "oracle/scan_sim/scanned_body.h"

#include <chrono>

#include "oracle/scan_sim/scan_sim.h"
#include "scanners/clean/clean.h"

namespace bespoke::testing {

ScannedBody ScanAndClean(const ScannedBodyOptions& options, const Body& body) {
  ScanSimOptions sim;
  sim.seed = options.scan_seed;
  sim.transform = ScanTransform::kRandom;
  sim.floor = options.floor;
  sim.noise_sigma_mm = options.noise_sigma_mm;
  sim.booth.width_px = options.width_px;
  sim.booth.height_px = options.height_px;
  const ScanSimResult scan = SimulateScan(sim, body.mesh);
  const auto start = std::chrono::steady_clock::now();
  CleanResult clean = CleanScan(CleanOptions{}, scan.cloud);
  ScannedBody out;
  out.clean_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  for (const auto& [name, point] : body.landmarks) {
    out.truth[name] =
        clean.body_from_scanner * (scan.scanner_from_body * PositionOf(body.mesh, point));
  }
  out.cloud = std::move(clean.cloud);
  return out;
}

}  // namespace bespoke::testing
