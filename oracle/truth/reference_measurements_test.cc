// The reference measurements against what the parametric body knows by
// construction: every girth against its analytic perimeter (within 0.5 mm), heights and the
// shoulder breadth exactly, lengths bounded by the straight-line chain and equal left and right;
// and the flags on bodies made to trip them. Each TEST is its own process under ctest, so the
// default body's reference (about 2 s of CPU) is computed in one TEST.
#include "oracle/truth/reference_measurements.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "oracle/body/parametric_body.h"
#include "oracle/truth/cropped_geodesics.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

const Catalogue& Cat() { return Catalogue::Builtin(); }

Eigen::Vector3d At(const Body& body, const std::string& name) {
  return PositionOf(body.mesh, body.landmarks.at(name));
}

const ReferenceMeasurement& Get(const ReferenceMeasurements& r, const std::string& name) {
  for (const ReferenceMeasurement& m : r.measurements)
    if (m.name == name) return m;
  throw InternalError("no reference measurement " + name);
}

std::string Mirror(const std::string& name) {
  const auto at = name.rfind("_right");
  return at == std::string::npos ? name : name.substr(0, at) + "_left";
}

// A lighter mesh than the default (about 3x fewer vertices), girth rings
// still refined to 256 vertices on the analytic curve.
ParametricBodyOptions Light(ParametricBodyOptions o) {
  o.torso_segments = 48;
  o.arm_segments = 32;
  o.ring_spacing_mm = 30;
  return o;
}

// Every girth of `r` against the body's analytic value; returns the largest difference.
double CheckGirthsAgainstAnalytic(const Body& body, const ReferenceMeasurements& r) {
  double worst = 0;
  int girths = 0;
  for (const ReferenceMeasurement& m : r.measurements) {
    if (m.kind != MeasurementKind::kGirth) continue;
    const MeasurementDef& def = Cat().Measurement(m.name);
    const std::string key = m.name + (def.side == "right" ? "_right" : "") + "_analytic_mm";
    const auto it = body.parameters.find(key);
    if (it == body.parameters.end()) {
      ADD_FAILURE() << "no analytic value " << key;
      continue;
    }
    if (def.method == MeasurementMethod::kGeodesic) {
      // A tape over the skin through points of the ring: no longer than
      // the ring (a path through them), no shorter than the polygon, and
      // close to the ring, which is near a geodesic (1.4-1.5 mm shorter on
      // these bodies).
      double chord = 0;
      for (std::size_t i = 0; i + 1 < def.datum.size(); ++i)
        chord += (At(body, def.datum[i]) - At(body, def.datum[i + 1])).norm();
      std::printf("%s: loop %.2f, ring %.2f, polygon %.2f mm\n", m.name.c_str(), m.value_mm,
                  it->second, chord);
      EXPECT_LE(m.value_mm, it->second + 0.5) << m.name;
      EXPECT_GE(m.value_mm, chord) << m.name;
      EXPECT_GE(m.value_mm, it->second - 3) << m.name;
      ++girths;
      continue;
    }
    EXPECT_NEAR(m.value_mm, it->second, 0.5) << m.name;
    EXPECT_LE(m.value_mm, it->second + 1e-6)
        << m.name << ": a polygon inscribed in the curve is shorter";
    EXPECT_TRUE(m.flags.empty()) << m.name << " flagged " << m.flags.front();
    worst = std::max(worst, std::abs(m.value_mm - it->second));
    ++girths;
  }
  EXPECT_EQ(girths, 14);
  return worst;
}

TEST(ReferenceMeasurements, DefaultParametricBodyMatchesItsConstruction) {
  ParametricBodyOptions options;
  const Body body = GenerateParametricBody(options);
  ReferenceOptions ro;
  ro.keep_geometry = true;
  const ReferenceMeasurements r = ComputeReferenceMeasurements(ro, Cat(), body);
  EXPECT_TRUE(r.skipped.empty());
  ASSERT_EQ(r.measurements.size(), Cat().measurements().size());

  const double worst = CheckGirthsAgainstAnalytic(body, r);
  std::printf("largest |reference - analytic| girth: %.4f mm\n", worst);

  // Heights: exact by construction.
  EXPECT_NEAR(Get(r, "stature").value_mm, options.stature_mm, 1e-9);
  EXPECT_NEAR(Get(r, "crotch_height").value_mm, options.crotch_height_mm, 1e-9);
  EXPECT_NEAR(Get(r, "waist_to_knee").value_mm,
              At(body, "side_waist_right").z() - At(body, "knee_right").z(), 1e-9);
  EXPECT_NEAR(Get(r, "shoulder_width").value_mm, options.shoulder_width_mm, 1e-9);
  for (const ReferenceMeasurement& m : r.measurements)
    if (m.kind == MeasurementKind::kHeight) {
      EXPECT_GT(m.value_mm, 0) << m.name;
    }

  // Lengths: a geodesic chain is no shorter than the straight chain through
  // its datum points and, on a body, less than twice it; a right-side
  // chain equals its mirror on the left (the body is an exact mirror).
  CroppedExactGeodesics geodesics(body.mesh);
  for (const ReferenceMeasurement& m : r.measurements) {
    const MeasurementDef& def = Cat().Measurement(m.name);
    if (def.method != MeasurementMethod::kGeodesic) continue;
    double chord = 0, left = 0;
    for (std::size_t i = 0; i + 1 < def.datum.size(); ++i) {
      chord += (At(body, def.datum[i]) - At(body, def.datum[i + 1])).norm();
      left += geodesics.Distance(body.landmarks.at(Mirror(def.datum[i])),
                                 body.landmarks.at(Mirror(def.datum[i + 1])));
    }
    if (def.to_floor)
      chord += At(body, def.datum.back()).z(), left += At(body, Mirror(def.datum.back())).z();
    EXPECT_GE(m.value_mm, chord - 1e-6) << m.name;
    EXPECT_LT(m.value_mm, 2 * chord) << m.name;
    if (def.side == "right") {
      EXPECT_NEAR(m.value_mm, left, 1e-6 * m.value_mm) << m.name << ": left and right differ";
    }
    ASSERT_GE(m.geometry.rows(), 2) << m.name;
    EXPECT_LT((m.geometry.row(0).transpose() - At(body, def.datum[0])).norm(), 1e-6) << m.name;
  }
  EXPECT_GT(Get(r, "outseam").value_mm, At(body, "side_waist_right").z());
  EXPECT_GT(Get(r, "inside_leg").value_mm,
            At(body, "crotch").z() - At(body, "ankle_inside_right").z());

  // The hip girth is the trunk's loop: its hull stays within the hip points
  // (the hands hang beside the hips, outside them).
  const Eigen::MatrixX3d& hip = Get(r, "hip_girth").geometry;
  ASSERT_GT(hip.rows(), 16);
  EXPECT_LE(hip.col(0).maxCoeff(), At(body, "hip_right").x() + 1e-6);
  EXPECT_GE(hip.col(0).minCoeff(), At(body, "hip_left").x() - 1e-6);
  for (Eigen::Index i = 0; i < hip.rows(); ++i)
    EXPECT_NEAR(hip(i, 2), At(body, "hip_right").z(), 1e-6);
}

TEST(ReferenceMeasurements, SeededBodiesAndPosesWithinHalfAMillimetre) {
  // A man and a woman drawn from seeds, in a tight A-pose (hands close to
  // the hips and thighs) and a T-pose (arms level with the armpit sections).
  for (const auto& [seed, abduction] : {std::pair<int, double>{3, 15}, {8, 90}, {11, 22}}) {
    ParametricBodyOptions o;
    o.seed = static_cast<std::uint64_t>(seed);
    o = Light(SeededOptions(o));
    o.arm_abduction_deg = abduction;
    const Body body = GenerateParametricBody(o);
    const ReferenceMeasurements r = ComputeReferenceMeasurements(ReferenceOptions(), Cat(), body);
    SCOPED_TRACE("seed " + std::to_string(seed) + ", arms at " + std::to_string(abduction) +
                 " deg");
    const double worst = CheckGirthsAgainstAnalytic(body, r);
    std::printf("seed %d, %g deg: largest girth difference %.4f mm\n", seed, abduction, worst);
    for (const ReferenceMeasurement& m : r.measurements) EXPECT_TRUE(m.flags.empty()) << m.name;
  }
}

// The light default body with landmarks moved to trip each flag.
TEST(ReferenceMeasurements, FlagsSayWhatWentWrong) {
  const Body base = GenerateParametricBody(Light(ParametricBodyOptions()));
  const auto flags_of = [](const Body& body, const std::string& name) {
    return Get(ComputeReferenceMeasurements(ReferenceOptions(), Cat(), body), name).flags;
  };
  const auto has = [](const std::vector<std::string>& flags, const std::string& flag) {
    return std::find(flags.begin(), flags.end(), flag) != flags.end();
  };
  Body body = base;
  // A bust point on the neck: the plane (mean height) is far from it.
  body.landmarks["bust_right"] = base.landmarks.at("side_neck_right");
  EXPECT_TRUE(has(flags_of(body, "bust_girth"), "datum_off_section"));
  // A knee point on the trunk: the right-limb girth's loop crosses x = 0.
  body = base;
  body.landmarks["knee_right"] = base.landmarks.at("front_waist");
  EXPECT_TRUE(has(flags_of(body, "knee_girth"), "section_crosses_midline"));
  // Side waist points at the centre front: the loop reaches past them, as
  // when arms merge into the trunk's section.
  body = base;
  body.landmarks["side_waist_right"] = body.landmarks["side_waist_left"] =
      base.landmarks.at("front_waist");
  EXPECT_TRUE(has(flags_of(body, "waist_girth"), "section_includes_arms"));
  EXPECT_TRUE(flags_of(base, "waist_girth").empty());
}

// Appends a closed box (outward faces) centred at `centre` with half-sizes `half` (mm).
void AddBox(const Eigen::Vector3d& centre, const Eigen::Vector3d& half, TriangleMesh* mesh) {
  const Eigen::Index base = mesh->num_vertices();
  mesh->vertices.conservativeResize(base + 8, 3);
  for (int i = 0; i < 8; ++i)
    mesh->vertices.row(base + i) =
        centre + Eigen::Vector3d((i & 1) ? half.x() : -half.x(), (i & 2) ? half.y() : -half.y(),
                                 (i & 4) ? half.z() : -half.z());
  const int faces[12][3] = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                            {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
  const Eigen::Index f0 = mesh->num_faces();
  mesh->faces.conservativeResize(f0 + 12, 3);
  for (int f = 0; f < 12; ++f)
    for (int k = 0; k < 3; ++k) mesh->faces(f0 + f, k) = static_cast<int>(base) + faces[f][k];
}

TEST(ReferenceMeasurements, BreastsHangingClearOfTheChestCountInTheBust) {
  // The bust girth alone: no geodesic has to cross between the body and the
  // detached breasts.
  nlohmann::json document = nlohmann::json::parse(BuiltinCatalogueJson());
  nlohmann::json bust_only = nlohmann::json::array();
  for (const nlohmann::json& m : document["measurements"])
    if (m["name"] == "bust_girth") bust_only.push_back(m);
  document["measurements"] = bust_only;
  const Catalogue catalogue = Catalogue::FromJson(document, "bust girth only");
  const Body base = GenerateParametricBody(Light(ParametricBodyOptions()));
  const ReferenceOptions options;
  const double plain =
      Get(ComputeReferenceMeasurements(options, catalogue, base), "bust_girth").value_mm;
  // Two breasts cut clear of the chest wall by the bust plane, 15 mm in
  // front of it, with the bust points on their fronts: the points' centroid
  // lies in the air between them, inside no loop.
  Body body = base;
  const Eigen::Vector3d bust = At(base, "bust_right");
  const Eigen::Vector3d half(45, 30, 40);
  for (const double side : {1.0, -1.0}) {
    const Eigen::Vector3d centre(side * 90, bust.y() + 15 + half.y(), bust.z());
    AddBox(centre, half, &body.mesh);
    body.landmarks[side > 0 ? "bust_right" : "bust_left"] =
        ClosestSurfacePoint(body.mesh, centre + Eigen::Vector3d(0, half.y(), 0));
  }
  const ReferenceMeasurement girth =
      Get(ComputeReferenceMeasurements(options, catalogue, body), "bust_girth");
  // The tape passes round the chest and over both breasts: longer than the
  // plain chest, never one breast's 300 mm box.
  EXPECT_GT(girth.value_mm, plain + 50);
  EXPECT_TRUE(girth.flags.empty()) << girth.flags.front();
}

TEST(ReferenceMeasurements, OpenSectionsAndMissingLandmarks) {
  Body body = GenerateParametricBody(Light(ParametricBodyOptions()));
  // Keep only the waist's datum points: everything else is skipped, named.
  std::map<std::string, SurfacePoint> waist;
  for (const char* name : {"front_waist", "back_waist", "side_waist_right", "side_waist_left"})
    waist[name] = body.landmarks.at(name);
  body.landmarks = waist;
  // Cut a hole: drop the faces crossing the waist plane at the back centre.
  const double z = At(body, "front_waist").z();
  const Eigen::Vector3d back = At(body, "back_waist");
  std::vector<int> keep;
  for (Eigen::Index f = 0; f < body.mesh.num_faces(); ++f) {
    double lo = 1e9, hi = -1e9, dx = 1e9;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d p = body.mesh.vertices.row(body.mesh.faces(f, k));
      lo = std::min(lo, p.z()), hi = std::max(hi, p.z()), dx = std::min(dx, (p - back).norm());
    }
    if (!(lo < z + 20 && hi > z - 20 && dx < 30)) keep.push_back(static_cast<int>(f));
  }
  ASSERT_LT(keep.size(), static_cast<std::size_t>(body.mesh.num_faces()));
  TriangleMesh cut = body.mesh;
  cut.faces.resize(static_cast<Eigen::Index>(keep.size()), 3);
  for (std::size_t i = 0; i < keep.size(); ++i)
    cut.faces.row(static_cast<Eigen::Index>(i)) = body.mesh.faces.row(keep[i]);
  for (auto& [name, point] : body.landmarks)
    point = ClosestSurfacePoint(cut, PositionOf(body.mesh, point));
  body.mesh = cut;
  const ReferenceMeasurements r = ComputeReferenceMeasurements(ReferenceOptions(), Cat(), body);
  const ReferenceMeasurement& girth = Get(r, "waist_girth");
  EXPECT_NE(std::find(girth.flags.begin(), girth.flags.end(), "section_open"), girth.flags.end());
  EXPECT_EQ(r.measurements.size() + r.skipped.size(), Cat().measurements().size());
  for (const auto& [name, reason] : r.skipped)
    EXPECT_NE(reason.find("has no landmark '"), std::string::npos) << name;
  EXPECT_NO_THROW(Get(r, "waist_height"));
  ReferenceOptions bad;
  bad.datum_tolerance_mm = 0;
  EXPECT_THROW(ComputeReferenceMeasurements(bad, Cat(), body), InputError);
}

TEST(ReferenceMeasurements, GirthPlanesFollowTheCatalogue) {
  const Body body = GenerateParametricBody(Light(ParametricBodyOptions()));
  const auto [p, n] = GirthPlaneOf(Cat().Measurement("upper_arm_girth"), body);
  EXPECT_LT((p - At(body, "upper_arm_right")).norm(), 1e-9);
  EXPECT_LT((n - (At(body, "elbow_right") - At(body, "shoulder_right")).normalized()).norm(), 1e-9);
  MeasurementDef tilted = Cat().Measurement("waist_girth");
  tilted.plane = GirthPlane::kThroughPoints;
  tilted.datum = {"front_neck", "side_neck_right", "side_neck_left"};
  const auto [q, m] = GirthPlaneOf(tilted, body);
  for (const char* name : {"front_neck", "side_neck_right", "side_neck_left"})
    EXPECT_NEAR(m.dot(At(body, name) - q), 0, 1e-9) << name;
  EXPECT_GT(m.z(), 0);
  const auto [w, up] = GirthPlaneOf(Cat().Measurement("waist_girth"), body);
  EXPECT_EQ(up, Eigen::Vector3d::UnitZ());
  EXPECT_THROW(GirthPlaneOf(Cat().Measurement("back_length"), body), InputError);
}

}  // namespace
}  // namespace bespoke
