// The measure chain on a virtual scan of a generated body, with the body's
// own (exact) datum points, against the oracle's exact reference
// measurements on the mesh: every catalogue measurement, per-kind
// tolerances in mm. Landmark detection is not tested here (the datum points
// are the truth's), so the differences are the measuring's own.
#include "measure/measurements/measure.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "measure/landmarks/landmarks.h"
#include "measure/measurements/measurement_document.h"
#include "measure/measurements/uncertainty.h"
#include "oracle/body/parametric_body.h"
#include "oracle/makehuman/makehuman_body.h"
#include "oracle/scan_sim/scan_sim.h"
#include "oracle/scan_sim/scanned_body.h"
#include "oracle/truth/reference_measurements.h"
#include "scanners/clean/clean.h"
#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

struct Fixture {
  Body body;
  ReferenceMeasurements truth;
  CleanResult clean;
  LandmarkSet landmarks;  // the truth's, in the cleaned cloud's body frame
};

// One small body, scanned and cleaned once for every test of this file.
const Fixture& Scanned() {
  static const Fixture* fixture = [] {
    auto* f = new Fixture;
    ParametricBodyOptions shape;  // an average woman, a coarse mesh for fast exact geodesics
    shape.torso_segments = 48;
    shape.arm_segments = 32;
    shape.ring_spacing_mm = 20;
    shape.girth_ring_segments = 64;
    shape.max_girth_deficit_mm = 1.0;  // the coarse rings are what the reference measures
    f->body = GenerateParametricBody(shape);
    f->truth = ComputeReferenceMeasurements({}, Catalogue::Builtin(), f->body);
    ScanSimOptions booth;
    booth.booth.width_px = 200;  // about 200k points
    booth.booth.height_px = 150;
    booth.noise_sigma_mm = 1.0;
    booth.transform = ScanTransform::kRandom;
    const ScanSimResult scan = SimulateScan(booth, f->body.mesh);
    CleanOptions clean;
    clean.threads = 2;
    f->clean = CleanScan(clean, scan.cloud);
    const Eigen::Isometry3d body_from_body =
        f->clean.body_from_scanner * Eigen::Isometry3d(scan.scanner_from_body.matrix());
    for (const auto& [name, point] : f->body.landmarks) {
      Landmark l;
      l.position_mm = body_from_body * PositionOf(f->body.mesh, point);
      l.method = "truth";
      f->landmarks.points[name] = l;
    }
    return f;
  }();
  return *fixture;
}

// Tolerance (mm) per measurement kind: ISO 20685-1's allowances (4 mm
// heights and small girths, 5 mm lengths, 9 mm large girths). One measured
// gap is held to what is achieved (docs/measuring.md): the underarm length
// (+7 mm: the armpit lies in the occluded crease under the arm).
double Tolerance(const ReferenceMeasurement& truth) {
  if (truth.name == "underarm_length") return 12.0;
  if (truth.kind == MeasurementKind::kHeight) return 4.0;
  if (truth.kind == MeasurementKind::kLength) return 5.0;
  return truth.value_mm > 600 ? 9.0 : 4.0;
}

bool Has(const std::vector<std::string>& flags, const std::string& flag) {
  return std::find(flags.begin(), flags.end(), flag) != flags.end();
}

TEST(Measure, VirtualScanWithTrueLandmarksMatchesTheReference) {
  const Fixture& f = Scanned();
  MeasureOptions options;
  if (std::getenv("MEASURE_SMOOTH"))
    options.section.smooth_arc_mm = std::atof(std::getenv("MEASURE_SMOOTH"));
  if (std::getenv("MEASURE_HALF"))
    options.section.half_thickness_mm = std::atof(std::getenv("MEASURE_HALF"));
  const MeasureResult result = Measure(options, Catalogue::Builtin(), f.clean.cloud, f.landmarks);
  if (std::getenv("MEASURE_DUMP"))
    for (const Measurement& m : result.measurements) {
      FILE* out = std::fopen(("/tmp/measure_" + m.name + ".xyz").c_str(), "w");
      for (Eigen::Index i = 0; i < m.geometry.rows(); ++i)
        std::fprintf(out, "%.2f %.2f %.2f\n", m.geometry(i, 0), m.geometry(i, 1), m.geometry(i, 2));
      std::fclose(out);
    }
  for (const auto& [name, reason] : result.skipped)
    std::printf("skipped %s: %s\n", name.c_str(), reason.c_str());
  int compared = 0, within = 0;
  std::vector<std::string> misses;
  for (const ReferenceMeasurement& truth : f.truth.measurements) {
    const Measurement* m = result.Find(truth.name);
    if (!m) continue;
    const double diff = m->value_mm - truth.value_mm;
    std::string flags;
    for (const std::string& s : m->flags) flags += " " + s;
    std::printf("%-20s %-7s truth %8.1f scan %8.1f diff %+6.1f mm (tol %.0f)%s\n",
                truth.name.c_str(), ToString(truth.kind).c_str(), truth.value_mm, m->value_mm, diff,
                Tolerance(truth), flags.c_str());
    // The truth's crotch lies in the unscanned crease between the legs,
    // 48 mm from the scan: lengths through it are flagged and bridged across
    // the hole; held to 10 mm (measured: +2, +3, +8 mm), not ISO's 5 mm.
    const bool bridged = Has(m->flags, "datum_off_scan");
    if (bridged) {
      EXPECT_NE(std::find(m->datum.begin(), m->datum.end(), "crotch"), m->datum.end())
          << truth.name;
      EXPECT_TRUE(Has(m->flags, "bridged")) << truth.name;
      EXPECT_GT(m->bridged_mm, 20.0) << truth.name;
    }
    ++compared;
    if (std::abs(diff) <= (bridged ? 10.0 : Tolerance(truth)))
      ++within;
    else
      misses.push_back(truth.name);
  }
  std::string missed;
  for (const std::string& s : misses) missed += " " + s;
  std::printf("%d of %d within tolerance; outside:%s\n", within, compared, missed.c_str());
  EXPECT_EQ(result.measurements.size() + result.skipped.size(),
            Catalogue::Builtin().measurements().size());
  EXPECT_GE(compared, 50);
  EXPECT_EQ(within, compared) << "outside:" << missed;
}

// The fixture's body scanned as the 60k booth does (99 x 75 px per sensor;
// 42k points after cleaning), measured at its true datum points:
// every girth within twice its ISO 20685-1 allowance. With the 2.5 mm slab
// and 12 mm piece gap of a dense scan (SlabForSpacing off) a limb's loop
// breaks into pieces and its girth keeps one of them.
TEST(Measure, SparseScanGirthsHoldTheirLoops) {
  const Fixture& f = Scanned();
  ScanSimOptions booth;
  booth.booth.width_px = 99;
  booth.booth.height_px = 75;
  booth.noise_sigma_mm = 1.0;
  booth.seed = 7;
  const ScanSimResult scan = SimulateScan(booth, f.body.mesh);
  CleanOptions clean;
  clean.threads = 2;
  const CleanResult cleaned = CleanScan(clean, scan.cloud);
  LandmarkSet set;
  const Eigen::Isometry3d body_from_body =
      cleaned.body_from_scanner * Eigen::Isometry3d(scan.scanner_from_body.matrix());
  for (const auto& [name, point] : f.landmarks.points) {
    set.points[name] = point;
    set.points[name].position_mm =
        body_from_body * PositionOf(f.body.mesh, f.body.landmarks.at(name));
  }
  MeasureOptions options, fixed;
  for (const ReferenceMeasurement& truth : f.truth.measurements)
    if (truth.kind == MeasurementKind::kGirth) options.only.push_back(truth.name);
  fixed.only = options.only;
  fixed.section.points_per_gap = 0;
  fixed.section.gap_per_spacing = 0;
  const MeasureResult wide = Measure(options, Catalogue::Builtin(), cleaned.cloud, set);
  const MeasureResult thin = Measure(fixed, Catalogue::Builtin(), cleaned.cloud, set);
  std::printf("sparse scan: %ld points cleaned\n", static_cast<long>(cleaned.cloud.size()));
  double worst_thin = 0;
  for (const ReferenceMeasurement& truth : f.truth.measurements) {
    const Measurement* m = wide.Find(truth.name);
    const Measurement* t = thin.Find(truth.name);
    if (truth.kind != MeasurementKind::kGirth) continue;
    ASSERT_NE(m, nullptr) << truth.name;
    ASSERT_NE(t, nullptr) << truth.name;
    std::printf("%-18s truth %7.1f  widened %+7.1f  fixed slab %+7.1f mm\n", truth.name.c_str(),
                truth.value_mm, m->value_mm - truth.value_mm, t->value_mm - truth.value_mm);
    EXPECT_NEAR(m->value_mm, truth.value_mm, 2 * Tolerance(truth)) << truth.name << " (mm)";
    worst_thin = std::max(worst_thin, std::abs(t->value_mm - truth.value_mm));
  }
  EXPECT_GT(worst_thin, 50.0) << "mm: the fixed slab breaks a loop at this density";
}

// A trunk girth with a single datum point (the middle hip) on a scan whose
// holes cut its section apart: two 20 mm strips of the trunk's sides are
// taken out round that level, leaving front, back and side pieces. The
// girth is the tape round the whole trunk section, not the piece at the
// datum point (the front, under half the girth).
TEST(Measure, SingleDatumTrunkGirthSpansTheHolesOfItsSection) {
  const Fixture& f = Scanned();
  const Eigen::Vector3d front = f.landmarks.At("middle_hip_front").position_mm;
  const double side_x = std::min(std::abs(f.landmarks.At("hip_right").position_mm.x()),
                                 std::abs(f.landmarks.At("hip_left").position_mm.x()));
  PointCloud holed;
  std::vector<Eigen::Index> keep;
  for (Eigen::Index i = 0; i < f.clean.cloud.size(); ++i) {
    const Eigen::Vector3d p = f.clean.cloud.points.row(i).transpose();
    const double x = std::abs(p.x());
    if (std::abs(p.z() - front.z()) < 60 && x > side_x - 50 && x < side_x - 30) continue;
    keep.push_back(i);
  }
  holed.points = f.clean.cloud.points(keep, Eigen::all);
  if (f.clean.cloud.normals.rows() == f.clean.cloud.size())
    holed.normals = f.clean.cloud.normals(keep, Eigen::all);
  ASSERT_LT(holed.size(), f.clean.cloud.size());
  MeasureOptions only;
  only.only = {"middle_hip_girth"};
  const MeasureResult result = Measure(only, Catalogue::Builtin(), holed, f.landmarks);
  const Measurement* m = result.Find("middle_hip_girth");
  ASSERT_NE(m, nullptr);
  double truth = 0;
  for (const ReferenceMeasurement& r : f.truth.measurements)
    if (r.name == "middle_hip_girth") truth = r.value_mm;
  ASSERT_GT(truth, 0);
  std::printf("middle hip girth with side holes %.1f mm, truth %.1f mm\n", m->value_mm, truth);
  EXPECT_NEAR(m->value_mm, truth, 9.0) << "mm";
}

// The clean cloud with a sheet of points (140 mm front to back, 80 mm high
// round the girth plane of `name`) `gap_mm` inside the inner side (smallest
// x) of the right-side `part`, labelled `sheet_part` in set->parts (which
// FindBodyParts fills for the clean cloud first).
PointCloud PressSheet(const Fixture& f, const std::string& name, ScanPart part, ScanPart sheet_part,
                      double gap_mm, LandmarkSet* set) {
  set->parts = FindBodyParts(f.clean.cloud);
  EXPECT_EQ(set->parts.size(), static_cast<size_t>(f.clean.cloud.size()));
  const auto [point, normal] = GirthPlane(Catalogue::Builtin().Measurement(name), *set);
  double inner_x = 1e9, y_sum = 0;
  int n = 0;
  for (Eigen::Index i = 0; i < f.clean.cloud.size(); ++i) {
    const Eigen::Vector3d p = f.clean.cloud.points.row(i).transpose();
    if (set->parts[static_cast<size_t>(i)] != part || std::abs((p - point).dot(normal)) > 10)
      continue;
    inner_x = std::min(inner_x, p.x()), y_sum += p.y(), ++n;
  }
  EXPECT_GT(n, 20) << name;
  const double y_mid = y_sum / std::max(n, 1);
  PointCloud pressed = f.clean.cloud;
  std::vector<Eigen::Vector3d> sheet;
  for (double y = -70; y <= 70; y += 3)
    for (double z = -40; z <= 40; z += 3)
      sheet.emplace_back(inner_x - gap_mm, y_mid + y, point.z() + z);
  const Eigen::Index old_rows = pressed.size();
  pressed.points.conservativeResize(old_rows + static_cast<Eigen::Index>(sheet.size()), 3);
  pressed.normals.conservativeResize(pressed.points.rows(), 3);
  for (size_t k = 0; k < sheet.size(); ++k) {
    pressed.points.row(old_rows + static_cast<Eigen::Index>(k)) = sheet[k].transpose();
    pressed.normals.row(old_rows + static_cast<Eigen::Index>(k)) = Eigen::RowVector3d(1, 0, 0);
  }
  set->parts.resize(static_cast<size_t>(pressed.size()), sheet_part);
  return pressed;
}

// `name` measured on `pressed` with the body parts of `set` and with none,
// against the truth: the first within 4 mm, the second taking the sheet in.
void ExpectSheetLeftOut(const Fixture& f, const std::string& name, const PointCloud& pressed,
                        const LandmarkSet& set) {
  MeasureOptions only;
  only.only = {name};
  double truth = 0;
  for (const ReferenceMeasurement& r : f.truth.measurements)
    if (r.name == name) truth = r.value_mm;
  ASSERT_GT(truth, 0);
  const MeasureResult with_parts = Measure(only, Catalogue::Builtin(), pressed, set);
  LandmarkSet no_parts = set;
  no_parts.parts.clear();
  const MeasureResult every_point = Measure(only, Catalogue::Builtin(), pressed, no_parts);
  const Measurement* kept = with_parts.Find(name);
  const Measurement* joined = every_point.Find(name);
  ASSERT_NE(kept, nullptr);
  ASSERT_NE(joined, nullptr);
  std::printf(
      "%s, a sheet pressed against it: %.1f mm with the parts, %.1f mm with every point; "
      "truth %.1f mm\n",
      name.c_str(), kept->value_mm, joined->value_mm, truth);
  EXPECT_NEAR(kept->value_mm, truth, 4.0) << "mm";
  EXPECT_GT(joined->value_mm, truth + 20) << "the sheet joins a section of every point";
}

// An upper arm resting on the trunk: a sheet of trunk points pressed
// against the inside of the right upper arm makes one section with the arm.
// The arm's girth keeps the points of the arm's own part (the body
// structure's); the sheet's are gap points, but they lie where the arm's
// inner side already is and face the arm, so they never join it.
TEST(Measure, ArmGirthKeepsTheArmsOwnPoints) {
  LandmarkSet set = Scanned().landmarks;
  const PointCloud pressed =
      PressSheet(Scanned(), "upper_arm_girth", ScanPart::kArmRight, ScanPart::kTrunk, 2, &set);
  ExpectSheetLeftOut(Scanned(), "upper_arm_girth", pressed, set);
}

// Where arm and trunk meet, the scan's armpit folds are one skin and the
// structure's boundary can run out along them: a fin of points labelled
// trunk from 5 to 50 mm outside the right armpit, 100 mm below it to 10 mm
// above. The chest (arms "lower") keeps the points between the armpits'
// x, so the fin stays out; moving the plane down until the trunk's part is
// free of it cannot get below the fin.
TEST(Measure, ChestKeepsTheTrunkBetweenTheArmpits) {
  const Fixture& f = Scanned();
  LandmarkSet set = f.landmarks;
  set.parts = FindBodyParts(f.clean.cloud);
  const Eigen::Vector3d armpit = set.points.at("armpit_right").position_mm;
  PointCloud folded = f.clean.cloud;
  std::vector<Eigen::Vector3d> fin;
  for (double x = 5; x <= 50; x += 3)
    for (double z = -100; z <= 10; z += 3) fin.push_back(armpit + Eigen::Vector3d(x, 0, z));
  const Eigen::Index rows = folded.size();
  folded.points.conservativeResize(rows + static_cast<Eigen::Index>(fin.size()), 3);
  folded.normals.conservativeResize(folded.points.rows(), 3);
  for (std::size_t k = 0; k < fin.size(); ++k) {
    folded.points.row(rows + static_cast<Eigen::Index>(k)) = fin[k].transpose();
    folded.normals.row(rows + static_cast<Eigen::Index>(k)) = Eigen::RowVector3d(0, 1, 0);
  }
  set.parts.resize(static_cast<std::size_t>(folded.size()), ScanPart::kTrunk);
  MeasureOptions only;
  only.only = {"chest_girth"};
  double truth = 0;
  for (const ReferenceMeasurement& r : f.truth.measurements)
    if (r.name == "chest_girth") truth = r.value_mm;
  const MeasureResult plain_result =
      Measure(only, Catalogue::Builtin(), f.clean.cloud, f.landmarks);
  const MeasureResult folded_result = Measure(only, Catalogue::Builtin(), folded, set);
  const Measurement* plain = plain_result.Find("chest_girth");
  const Measurement* chest = folded_result.Find("chest_girth");
  ASSERT_NE(plain, nullptr);
  ASSERT_NE(chest, nullptr);
  std::printf("chest girth %.1f mm with a fin at the armpit, %.1f without; truth %.1f mm\n",
              chest->value_mm, plain->value_mm, truth);
  EXPECT_NEAR(chest->value_mm, plain->value_mm, 0.5);  // mm: the fin stays out
  EXPECT_NEAR(chest->value_mm, truth, 9.0);            // mm: ISO 20685-1's large-girth limit
}

// A booth sees little of the trunk's sides under the arms: the trunk's
// points within 60 mm of the armpits' x and y, from 60 mm below them to 30 mm
// above, taken out (a 120 mm hole on each side). The chest's tape passes
// over the armpits, two chords either side of each, and reads within 5 mm of
// the whole scan; one chord across each hole reads 9.6 mm short.
TEST(Measure, ChestTapeReachesTheArmpitsAcrossAHole) {
  const Fixture& f = Scanned();
  const std::vector<ScanPart> parts = FindBodyParts(f.clean.cloud);
  const Eigen::Vector3d right = f.landmarks.points.at("armpit_right").position_mm;
  const Eigen::Vector3d left = f.landmarks.points.at("armpit_left").position_mm;
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < f.clean.cloud.size(); ++i) {
    const Eigen::Vector3d p = f.clean.cloud.points.row(i).transpose();
    const double y = p.x() > 0 ? right.y() : left.y();
    const bool side = std::abs(p.x()) > right.x() - 60 && std::abs(p.y() - y) < 60;
    const bool band = p.z() > right.z() - 60 && p.z() < right.z() + 30;
    if (!(side && band && parts[static_cast<std::size_t>(i)] == ScanPart::kTrunk))
      kept.push_back(i);
  }
  PointCloud holed;
  holed.points = f.clean.cloud.points(kept, Eigen::all);
  holed.normals = f.clean.cloud.normals(kept, Eigen::all);
  LandmarkSet full = f.landmarks, set = f.landmarks;
  full.parts = parts, set.parts.clear();
  for (Eigen::Index i : kept) set.parts.push_back(parts[static_cast<std::size_t>(i)]);
  MeasureOptions only;
  only.only = {"chest_girth"};
  const MeasureResult whole_result = Measure(only, Catalogue::Builtin(), f.clean.cloud, full);
  const MeasureResult holed_result = Measure(only, Catalogue::Builtin(), holed, set);
  const Measurement* whole = whole_result.Find("chest_girth");
  const Measurement* chest = holed_result.Find("chest_girth");
  ASSERT_NE(whole, nullptr);
  ASSERT_NE(chest, nullptr);
  std::printf(
      "chest girth %.1f mm with the sides under the arms unscanned, %.1f on the whole scan\n",
      chest->value_mm, whole->value_mm);
  EXPECT_NEAR(chest->value_mm, whole->value_mm, 5.0);  // mm
  EXPECT_NE(std::find(chest->flags.begin(), chest->flags.end(), "section_open"),
            chest->flags.end());  // the hole is still reported
}

// Thighs that touch: the other leg's skin 8 mm from the inside of the right
// thigh (closer than the 12 mm piece gap) is one section with it; a leg's
// girth leaves the other leg out.
TEST(Measure, LegGirthLeavesOutTheOtherLeg) {
  LandmarkSet set = Scanned().landmarks;
  const PointCloud pressed =
      PressSheet(Scanned(), "thigh_girth", ScanPart::kLegRight, ScanPart::kLegLeft, 8, &set);
  ExpectSheetLeftOut(Scanned(), "thigh_girth", pressed, set);
}

// MakeHuman bodies (../shared) at their true datum points, on the default
// booth: from the armpit, in the crease no sensor saw, down the side to the
// waist. On these two the whole path's final flow cuts across the crease's
// gap and is undone, and the propagated path it leaves zigzags (checked:
// more than 5 mm long without splits). Split at that step, each part flows
// on the surface.
TEST(Measure, WaistToArmpitFlowsPastTheArmpitsGap) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  for (std::uint64_t seed : {1019, 1023}) {
    MakeHumanBodyOptions options;
    options.seed = seed;
    const Body body = GenerateMakeHumanBody(options, &model);
    MeasureOptions only;
    only.only = {"waist_to_armpit"};
    const ReferenceMeasurements truth =
        ComputeReferenceMeasurements({}, Catalogue::Builtin(), body);
    testing::ScannedBodyOptions booth;
    booth.scan_seed = seed;
    booth.width_px = 240, booth.height_px = 180;  // the default booth's
    const testing::ScannedBody scan = testing::ScanAndClean(booth, body);
    LandmarkSet set;
    for (const auto& [name, x] : scan.truth) set.points[name].position_mm = x;
    const MeasureResult split = Measure(only, Catalogue::Builtin(), scan.cloud, set);
    only.geodesics.polish_splits = 0;
    const MeasureResult whole = Measure(only, Catalogue::Builtin(), scan.cloud, set);
    double reference = 0;
    for (const ReferenceMeasurement& r : truth.measurements)
      if (r.name == "waist_to_armpit") reference = r.value_mm;
    ASSERT_NE(split.Find("waist_to_armpit"), nullptr);
    const double got = split.Find("waist_to_armpit")->value_mm;
    std::printf("seed %d: waist to armpit %.1f mm, %.1f without splits; truth %.1f\n",
                static_cast<int>(seed), got, whole.Find("waist_to_armpit")->value_mm, reference);
    EXPECT_NEAR(got, reference, 5.0) << seed;  // mm: ISO 20685-1's length limit
    EXPECT_GT(whole.Find("waist_to_armpit")->value_mm - reference, 5.0) << seed;  // mm
  }
}

// The 95 % interval: at datum points known to 1 mm (overrides) it is the
// scan's and the bridges' share - a few mm, more where a girth changes fast
// with its plane (the neck's meets the shoulders) or a length is bridged -
// and holds the truth for at least 90 % of the measurements; a doubtful
// datum point widens its measurements'.
TEST(Measure, UncertaintyHoldsTheTruth) {
  const Fixture& f = Scanned();
  LandmarkSet exact = f.landmarks;
  for (auto& [name, l] : exact.points) l.flags = {"override"};
  const MeasureResult result =
      Measure(MeasureOptions{}, Catalogue::Builtin(), f.clean.cloud, exact);
  int compared = 0, inside = 0;
  for (const ReferenceMeasurement& truth : f.truth.measurements) {
    const Measurement* m = result.Find(truth.name);
    if (!m) continue;
    ++compared;
    EXPECT_GT(m->uncertainty_mm, 0.0) << m->name;
    // Not vacuous: under 35 mm once the bridge's own share is taken out (a
    // length over the crotch's hole bridges 160-200 mm on this body across
    // scanner seeds, and its interval is then mostly the bridge's, which the
    // coverage below judges).
    const double bridge_sd = UncertaintyOptions{}.bridge_share * m->bridged_mm;
    const double sd = m->uncertainty_mm / 1.96;
    EXPECT_LT(1.96 * std::sqrt(std::max(0.0, sd * sd - bridge_sd * bridge_sd)), 35.0) << m->name;
    const bool holds = std::abs(m->value_mm - truth.value_mm) <= m->uncertainty_mm;
    inside += holds;
    std::printf("%-20s diff %+6.1f mm  95 %% +-%5.1f mm  bridged %5.1f mm %s\n", m->name.c_str(),
                m->value_mm - truth.value_mm, m->uncertainty_mm, m->bridged_mm,
                holds ? "" : "OUTSIDE");
  }
  std::printf("%d of %d within their 95 %% interval\n", inside, compared);
  EXPECT_GE(inside, 0.9 * compared);
  // The crotch placed with doubt (as the detector flags it): wider.
  LandmarkSet doubtful = exact;
  doubtful.points["crotch"].flags = {"implausible"};
  doubtful.points["crotch"].confidence = 0.3;
  MeasureOptions some;
  some.only = {"crotch_height", "inside_leg", "stature"};
  const MeasureResult sure = Measure(some, Catalogue::Builtin(), f.clean.cloud, exact);
  const MeasureResult unsure = Measure(some, Catalogue::Builtin(), f.clean.cloud, doubtful);
  for (const char* name : {"crotch_height", "inside_leg"})
    EXPECT_GT(unsure.Find(name)->uncertainty_mm, 3 * sure.Find(name)->uncertainty_mm) << name;
  EXPECT_DOUBLE_EQ(unsure.Find("stature")->uncertainty_mm, sure.Find("stature")->uncertainty_mm);
}

}  // namespace
}  // namespace bespoke
