#include "scanners/scan_sim/scan_sim.h"

#include <gtest/gtest.h>

#include "scanners/body/parametric_body.h"

namespace bespoke {
namespace {

TEST(ScanSim, Smoke) {
  const Body body = GenerateParametricBody(ParametricBodyOptions());
  ScanSimOptions o;
  const ScanSimResult r = SimulateScan(o, body.mesh);
  std::cout << "points " << r.cloud.size() << " body " << r.counts[0] << " floor " << r.counts[1]
            << " outliers " << r.counts[3] << " grazing " << r.dropped_grazing << " rays " << r.rays << "\n";
  EXPECT_GT(r.counts[0], 100000);
}

}  // namespace
}  // namespace bespoke
