// Cloud geodesics on a virtual scan of a generated body, against CGAL's exact
// geodesics on the body mesh itself, between the catalogue's datum points
// (the lengths a tailor takes with a tape). A small body keeps this to seconds;
// the full-size run is the benchmark (docs/geodesics.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "measure/catalogue/catalogue.h"
#include "measure/cloud_geodesic/cloud_geodesics.h"
#include "oracle/body/parametric_body.h"
#include "oracle/scan_sim/scan_sim.h"
#include "oracle/truth/exact_geodesics.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// A datum point farther than this from every scan point lies in a region no
// sensor saw (the armpit and crotch creases); lengths from such points depend
// on how the gap is crossed and are reported, not held to the target.
constexpr double kSeenMm = 4.0;

// An average woman on a coarse mesh, for a fast exact reference.
Body CoarseWoman() {
  ParametricBodyOptions shape;
  shape.torso_segments = 48;
  shape.arm_segments = 32;
  shape.ring_spacing_mm = 20;
  shape.girth_ring_segments = 64;
  shape.max_girth_deficit_mm = 1.0;  // the girths are not what is tested here
  return GenerateParametricBody(shape);
}

// A lighter booth (about 150k points), no floor or outliers, 0.5 mm noise.
ScanSimResult LightScan(const Body& body, std::uint64_t seed) {
  ScanSimOptions booth;
  booth.booth.width_px = 160;
  booth.booth.height_px = 120;
  booth.floor = false;
  booth.outlier_fraction = 0;
  booth.noise_sigma_mm = 0.5;
  booth.seed = seed;
  return SimulateScan(booth, body.mesh);
}

TEST(BodyGeodesics, DatumPointLengthsOnAVirtualScanMatchExactMeshGeodesics) {
  const Body body = CoarseWoman();
  const ScanSimResult scan = LightScan(body, 1);

  // Every segment of every geodesic measurement's datum chain, once, grouped
  // by start point (CGAL reuses one propagation per start point).
  std::set<std::pair<std::string, std::string>> segments;
  for (const MeasurementDef& m : Catalogue::Builtin().measurements()) {
    if (m.method != MeasurementMethod::kGeodesic) continue;
    for (size_t i = 0; i + 1 < m.datum.size(); ++i)
      if (body.landmarks.count(m.datum[i]) && body.landmarks.count(m.datum[i + 1]))
        segments.emplace(m.datum[i], m.datum[i + 1]);
  }
  CloudGeodesics cloud({}, scan.cloud.points);
  ExactGeodesics exact(body.mesh);
  double sum = 0, worst = 0;
  int compared = 0, unreachable = 0;
  // How far a datum point is from the nearest scan point: a few mm on skin
  // the sensors saw, more in a crease they did not (armpit, crotch).
  auto off_scan = [&](const SurfacePoint& p) {
    double d2 = 0;
    cloud.grid().index().Nearest(PositionOf(body.mesh, p), &d2);
    return std::sqrt(d2);
  };
  double sum_all = 0, worst_all = 0;
  int compared_all = 0;
  for (const auto& [from, to] : segments) {
    const SurfacePoint& a = body.landmarks.at(from);
    const SurfacePoint& b = body.landmarks.at(to);
    const double truth = exact.Distance(a, b);
    const bool seen = off_scan(a) <= kSeenMm && off_scan(b) <= kSeenMm;
    try {
      const double length =
          cloud.Between(PositionOf(body.mesh, a), PositionOf(body.mesh, b)).length_mm;
      std::printf("%-22s -> %-22s cloud %7.1f exact %7.1f diff %+6.2f mm%s\n", from.c_str(),
                  to.c_str(), length, truth, length - truth,
                  seen ? "" : "  (an end point off the scan)");
      sum_all += std::abs(length - truth);
      worst_all = std::max(worst_all, std::abs(length - truth));
      ++compared_all;
      if (seen) {
        sum += std::abs(length - truth);
        worst = std::max(worst, std::abs(length - truth));
        ++compared;
      }
    } catch (const InputError& e) {
      std::printf("%-22s -> %-22s not measurable on the scan: %s\n", from.c_str(), to.c_str(),
                  e.what());
      ++unreachable;
    }
  }
  std::printf("all %d measurable segments (%d not): mean |diff| %.2f mm, max %.2f mm\n",
              compared_all, unreachable, sum_all / std::max(1, compared_all), worst_all);
  std::printf("%d segments with both ends on scanned skin: mean |diff| %.2f mm, max %.2f mm\n",
              compared, sum / std::max(1, compared), worst);
  EXPECT_GE(compared, 15);
  // The crotch datum lies in the scan's occlusion hole, 25 mm from the
  // nearest scan point: it is accepted as unscanned (flagged) and the hole
  // spanned by chords to its rim. Measured: +2.0, +4.9 and +18.6 mm on its
  // three segments (the last down the inner leg, where the thighs nearly
  // touch); 25 mm guards against routing round a leg (+179 mm when the point
  // was merely snapped to the nearest rim point).
  EXPECT_EQ(unreachable, 0);
  EXPECT_LE(worst_all, 25.0);
  EXPECT_LE(sum / compared, 2.0);  // mm, the target of docs/geodesics.md
  EXPECT_LE(worst, 5.0);           // mm (ISO 20685-1 allows 5 mm for segment lengths)
}

// The same body on three scans of the light booth: the crotch datum lies in
// the occlusion hole between the legs, 24-26 mm from the nearest scan point,
// with fewer than 20 scan points within 1.5 times that distance on two of
// them (scanner seeds 2 and 3). It is accepted as unscanned on every scan and
// the path from it to the front waist is bridged, not refused; within 10 mm
// of the exact geodesic (what docs/measuring.md holds a length from a datum
// point in a scan hole to, the inside leg's). The way from the rim-seeded
// wavefront alone is 11.1 mm too long on seed 1 (a kink that no flow
// removes); the way from the front waist is kept there.
TEST(BodyGeodesics, TheCrotchInASparseHoleIsReachedOnEveryScan) {
  const Body body = CoarseWoman();
  const SurfacePoint& crotch = body.landmarks.at("crotch");
  const SurfacePoint& waist = body.landmarks.at("front_waist");
  ExactGeodesics exact(body.mesh);
  const double truth = exact.Distance(crotch, waist);
  for (std::uint64_t seed : {1, 2, 3}) {
    const ScanSimResult scan = LightScan(body, seed);
    CloudGeodesics cloud({}, scan.cloud.points);
    double length = 0;
    ASSERT_NO_THROW(
        length =
            cloud.Between(PositionOf(body.mesh, crotch), PositionOf(body.mesh, waist)).length_mm)
        << "scanner seed " << seed;
    std::printf("scanner seed %d: crotch -> front waist cloud %.1f exact %.1f mm\n",
                static_cast<int>(seed), length, truth);
    EXPECT_NEAR(length, truth, 10.0) << "scanner seed " << seed;
  }
}

}  // namespace
}  // namespace bespoke
