#include "oracle/scan_sim/scanned_body.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "oracle/scan_sim/scan_sim.h"
#include "scanners/clean/clean.h"

namespace bespoke::testing {

ScannedBody ScanAndClean(const ScannedBodyOptions& options, const Body& body) {
  ScanSimOptions sim;
  sim.seed = options.scan_seed;
  sim.transform = options.random_transform ? ScanTransform::kRandom : ScanTransform::kNone;
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

void SqueezeThighs(double squeeze_mm, ScannedBody* scan) {
  const double crotch = scan->truth.at("crotch").z();
  auto shift = [&](const Eigen::Vector3d& p) {
    const double z = p.z();
    if (z >= crotch || z <= 0.55 * crotch) return 0.0;
    const double in = std::min(1.0, (crotch - z) / 60),
                 out = std::min(1.0, (z - 0.55 * crotch) / 80);
    return squeeze_mm * std::min(in, out);
  };
  std::vector<Eigen::Index> keep;
  for (Eigen::Index r = 0; r < scan->cloud.size(); ++r) {
    Eigen::Vector3d p = scan->cloud.points.row(r).transpose();
    const double s = shift(p), x = p.x();
    if (s == 0) {
      keep.push_back(r);
      continue;
    }
    p.x() = x > 0 ? x - s : x + s;
    if (p.x() * x <= 0) continue;  // crossed into the other thigh
    scan->cloud.points.row(r) = p.transpose();
    keep.push_back(r);
  }
  scan->cloud = scan->cloud.Select(keep);
  for (auto& [name, p] : scan->truth) {
    const double s = shift(p);
    p.x() += p.x() > 0 ? -s : s;
  }
}

}  // namespace bespoke::testing
