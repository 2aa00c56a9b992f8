#include "oracle/body/parametric_body.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <unordered_map>

#include "measure/catalogue/catalogue.h"
#include "oracle/body/mesh_checks.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

Eigen::Vector3d At(const Body& body, const std::string& name) {
  return PositionOf(body.mesh, body.landmarks.at(name));
}

// A coarse body for the pose sweeps (fewer vertices; girth rings still checked).
ParametricBodyOptions Coarse(double abduction_deg) {
  ParametricBodyOptions o;
  o.arm_abduction_deg = abduction_deg;
  o.torso_segments = 48;
  o.arm_segments = 32;
  o.ring_spacing_mm = 25;
  o.girth_ring_segments = 128;
  o.max_girth_deficit_mm = 1.0;
  return o;
}

// Smallest distance from the points `a` to the points `b` (a uniform grid
// hash; brute force within the neighbouring cells).
double MinDistance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                   double cell) {
  std::unordered_map<long long, std::vector<Eigen::Vector3d>> grid;
  const auto key = [cell](int x, int y, int z) {
    return (static_cast<long long>(x) * 73856093LL) ^ (static_cast<long long>(y) * 19349663LL) ^
           (static_cast<long long>(z) * 83492791LL);
  };
  for (const auto& p : b)
    grid[key(std::floor(p.x() / cell), std::floor(p.y() / cell), std::floor(p.z() / cell))]
        .push_back(p);
  double best = std::numeric_limits<double>::infinity();
  for (const auto& p : a) {
    const int cx = std::floor(p.x() / cell), cy = std::floor(p.y() / cell),
              cz = std::floor(p.z() / cell);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = grid.find(key(cx + dx, cy + dy, cz + dz));
          if (it == grid.end()) continue;
          for (const auto& q : it->second) best = std::min(best, (p - q).norm());
        }
  }
  return best;
}

class DefaultBody : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    details_ = new ParametricBodyDetails();
    body_ = new Body(GenerateParametricBody(ParametricBodyOptions(), details_));
  }
  static void TearDownTestSuite() {
    delete body_;
    delete details_;
  }
  static Body* body_;
  static ParametricBodyDetails* details_;
};
Body* DefaultBody::body_ = nullptr;
ParametricBodyDetails* DefaultBody::details_ = nullptr;

TEST_F(DefaultBody, IsAClosedOrientedSphereWithoutSelfIntersections) {
  const MeshTopology t = AnalyzeTopology(body_->mesh);
  EXPECT_TRUE(t.IsClosedSphere()) << t.Describe();
  EXPECT_EQ(t.euler_characteristic, 2);
  EXPECT_EQ(t.boundary_edges, 0);
  EXPECT_EQ(t.misoriented_edges, 0);
  EXPECT_FALSE(SelfIntersects(body_->mesh));
  // Volume of an average adult, about 60-75 litres.
  EXPECT_GT(t.signed_volume, 50e6);
  EXPECT_LT(t.signed_volume, 90e6);
}

TEST_F(DefaultBody, GirthRingsAreTheAnalyticGirthsInTheirPlanes) {
  const ParametricBodyOptions o;
  const std::map<std::string, double> requested = {{"neck_girth", o.neck_girth_mm},
                                                   {"chest_girth", o.chest_girth_mm},
                                                   {"bust_girth", o.bust_girth_mm},
                                                   {"under_bust_girth", o.under_bust_girth_mm},
                                                   {"waist_girth", o.waist_girth_mm},
                                                   {"middle_hip_girth", o.middle_hip_girth_mm},
                                                   {"hip_girth", o.hip_girth_mm},
                                                   {"upper_arm_girth", o.upper_arm_girth_mm},
                                                   {"elbow_girth", 0.87 * o.upper_arm_girth_mm},
                                                   {"wrist_girth", o.wrist_girth_mm},
                                                   {"thigh_girth", o.thigh_girth_mm},
                                                   {"knee_girth", o.knee_girth_mm},
                                                   {"calf_girth", o.calf_girth_mm},
                                                   {"ankle_girth", o.ankle_girth_mm}};
  ASSERT_EQ(details_->girths.size(), 7u + 2 * 7u);
  for (const AnalyticGirth& g : details_->girths) {
    SCOPED_TRACE(g.measurement + " " + g.side);
    ASSERT_TRUE(requested.count(g.measurement));
    EXPECT_NEAR(g.girth_mm, requested.at(g.measurement), 1e-6);
    const double deficit = g.girth_mm - g.polygon_girth_mm;
    EXPECT_GE(deficit, 0);
    EXPECT_LE(deficit, 0.1);
    EXPECT_NEAR(g.plane_normal.norm(), 1, 1e-12);
    // Every ring vertex on the plane; the ring convex in it.
    const Eigen::Vector3d n = g.plane_normal;
    const Eigen::Vector3d u = n.unitOrthogonal(), v = n.cross(u);
    std::vector<Eigen::Vector2d> ring;
    for (int vertex : g.ring) {
      const Eigen::Vector3d p = body_->mesh.vertices.row(vertex).transpose() - g.plane_point;
      EXPECT_NEAR(p.dot(n), 0, 1e-9);
      ring.emplace_back(p.dot(u), p.dot(v));
    }
    int positive = 0, negative = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
      const Eigen::Vector2d a = ring[(i + 1) % ring.size()] - ring[i];
      const Eigen::Vector2d b = ring[(i + 2) % ring.size()] - ring[(i + 1) % ring.size()];
      const double cross = a.x() * b.y() - a.y() * b.x();
      positive += cross > 1e-9;
      negative += cross < -1e-9;
    }
    // Every ring convex but the bust's, which dips into the cleavage (its
    // hull, the tape, is checked above).
    if (g.measurement != "bust_girth")
      EXPECT_TRUE(positive == 0 || negative == 0)
          << positive << " left turns, " << negative << " right turns";
    // The datum point sits on the ring, and the parameters report the value.
    if (!g.landmark.empty()) {
      EXPECT_NEAR((At(*body_, g.landmark) - g.plane_point).dot(n), 0, 1e-9) << g.landmark;
    }
    const std::string key = g.measurement + (g.side.empty() ? "" : "_" + g.side) + "_analytic_mm";
    EXPECT_DOUBLE_EQ(body_->parameters.at(key), g.girth_mm);
  }
}

// The breasts: in the bust ring each bust point is its side's most forward
// point, the skin between them lies back in a cleavage as deep as the
// parameters say, and the tape round the ring is still the analytic girth.
TEST_F(DefaultBody, TheBustPointsStandOutOfACleavage) {
  const ParametricBodyOptions o;
  const double depth = body_->parameters.at("cleavage_depth_mm");
  EXPECT_NEAR(depth, 0.25 * (o.bust_girth_mm - o.under_bust_girth_mm), 1e-9);
  const AnalyticGirth* bust = nullptr;
  for (const AnalyticGirth& g : details_->girths)
    if (g.measurement == "bust_girth") bust = &g;
  ASSERT_NE(bust, nullptr);
  EXPECT_NEAR(bust->polygon_girth_mm, o.bust_girth_mm, 0.1);
  const Eigen::Vector3d right = At(*body_, "bust_right"), left = At(*body_, "bust_left");
  double front_centre_y = -1e9, polygon = 0;
  for (size_t k = 0; k < bust->ring.size(); ++k) {
    const Eigen::Vector3d p = body_->mesh.vertices.row(bust->ring[k]).transpose();
    const Eigen::Vector3d q =
        body_->mesh.vertices.row(bust->ring[(k + 1) % bust->ring.size()]).transpose();
    polygon += (q - p).norm();
    const Eigen::Vector3d& apex = p.x() >= 0 ? right : left;
    EXPECT_LE(p.y(), apex.y() + 0.1) << "ring vertex " << k;  // the apex is on a chord
    if (std::abs(p.x()) < 5) front_centre_y = std::max(front_centre_y, p.y());
  }
  EXPECT_NEAR(right.y() - front_centre_y, depth, 0.5);
  EXPECT_GT(polygon, bust->polygon_girth_mm + 10);  // the skin dips into the cleavage
}

TEST_F(DefaultBody, GirthPlanesFollowTheCatalogue) {
  const auto plane = [&](const std::string& name, const std::string& side) {
    for (const AnalyticGirth& g : details_->girths) {
      if (g.measurement == name && g.side == side) return g;
    }
    throw InternalError("no girth " + name);
  };
  // Upper arm perpendicular to shoulder -> elbow, elbow to shoulder -> wrist,
  // wrist to elbow -> wrist; the neck base through back and front neck points.
  const auto axis = [&](const std::string& a, const std::string& b) {
    return (At(*body_, b) - At(*body_, a)).normalized();
  };
  EXPECT_NEAR(
      plane("upper_arm_girth", "right").plane_normal.dot(axis("shoulder_right", "elbow_right")), 1,
      1e-12);
  EXPECT_NEAR(plane("elbow_girth", "right").plane_normal.dot(axis("shoulder_right", "wrist_right")),
              1, 1e-12);
  EXPECT_NEAR(plane("wrist_girth", "right").plane_normal.dot(axis("elbow_right", "wrist_right")), 1,
              1e-9);
  EXPECT_NEAR(plane("wrist_girth", "left").plane_normal.dot(axis("elbow_left", "wrist_left")), 1,
              1e-9);
  const AnalyticGirth neck = plane("neck_girth", "");
  for (const char* p : {"back_neck", "front_neck"})
    EXPECT_NEAR((At(*body_, p) - neck.plane_point).dot(neck.plane_normal), 0, 1e-9);
  EXPECT_NEAR(neck.plane_normal.x(), 0, 1e-12);  // level left-right
  // Chest: horizontal at the axilla points' height.
  EXPECT_NEAR(plane("chest_girth", "").plane_point.z(), At(*body_, "axilla_front_right").z(), 1e-9);
  EXPECT_NEAR(At(*body_, "axilla_back_left").z(), At(*body_, "axilla_front_right").z(), 1e-9);
}

TEST_F(DefaultBody, HeightsAndWidthsAreExact) {
  const ParametricBodyOptions o;
  EXPECT_DOUBLE_EQ(body_->mesh.vertices.col(2).maxCoeff(), o.stature_mm);
  EXPECT_DOUBLE_EQ(At(*body_, "crown").z(), o.stature_mm);
  EXPECT_DOUBLE_EQ(body_->mesh.vertices.col(2).minCoeff(), 0.0);
  EXPECT_NEAR(At(*body_, "crotch").z(), o.crotch_height_mm, 1e-9);
  EXPECT_NEAR(At(*body_, "shoulder_right").x() - At(*body_, "shoulder_left").x(),
              o.shoulder_width_mm, 1e-9);
}

TEST_F(DefaultBody, HasEveryCatalogueLandmarkInAnatomicalOrder) {
  ASSERT_GT(Catalogue::Builtin().landmarks().size(), 30u);
  for (const LandmarkDef& l : Catalogue::Builtin().landmarks())
    EXPECT_TRUE(body_->landmarks.count(l.name)) << l.name;
  const auto z = [&](const std::string& n) { return At(*body_, n).z(); };
  const std::vector<std::string> top_down = {"crown",
                                             "back_neck",
                                             "front_neck",
                                             "shoulder_right",
                                             "armpit_right",
                                             "bust_right",
                                             "under_bust",
                                             "front_waist",
                                             "middle_hip_front",
                                             "hip_back",
                                             "crotch",
                                             "thigh_right",
                                             "knee_right",
                                             "calf_right",
                                             "ankle_inside_right",
                                             "ankle_outside_right"};
  for (size_t i = 0; i + 1 < top_down.size(); ++i)
    EXPECT_GT(z(top_down[i]), z(top_down[i + 1])) << top_down[i];
  EXPECT_GT(z("ankle_outside_right"), 0);
  EXPECT_GT(z("shoulder_right"), z("elbow_right"));
  EXPECT_GT(z("elbow_right"), z("wrist_right"));
  for (const auto& [name, point] : body_->landmarks) {
    const Eigen::Vector3d p = PositionOf(body_->mesh, point);
    EXPECT_NEAR(point.barycentric.sum(), 1, 1e-12);
    if (name.size() > 5 && name.substr(name.size() - 5) == "_left") {
      const Eigen::Vector3d r = At(*body_, name.substr(0, name.size() - 5) + "_right");
      EXPECT_LT(p.x(), 0) << name;
      EXPECT_NEAR(p.x(), -r.x(), 1e-9) << name;  // the left side mirrors the right
      EXPECT_NEAR(p.y(), r.y(), 1e-9) << name;
      EXPECT_NEAR(p.z(), r.z(), 1e-9) << name;
    } else if (name.size() > 6 && name.substr(name.size() - 6) == "_right") {
      EXPECT_GT(p.x(), 0) << name;
    } else {
      EXPECT_NEAR(p.x(), 0, 1e-9) << name;  // centre line
    }
  }
  EXPECT_GT(At(*body_, "front_waist").y(), At(*body_, "back_waist").y());
  EXPECT_GT(At(*body_, "bust_right").y(), At(*body_, "under_bust").y());
  EXPECT_GT(At(*body_, "knee_right").y(), At(*body_, "calf_right").y());
  EXPECT_GT(At(*body_, "ankle_outside_right").x(), At(*body_, "ankle_inside_right").x());
  // Toes point forwards: the body's front-most vertex near the floor is a toe.
  double toe = -1e9, heel = 1e9;
  for (Eigen::Index v = 0; v < body_->mesh.num_vertices(); ++v) {
    if (body_->mesh.vertices(v, 2) > 30) continue;
    toe = std::max(toe, body_->mesh.vertices(v, 1));
    heel = std::min(heel, body_->mesh.vertices(v, 1));
  }
  EXPECT_GT(toe, 150);
  EXPECT_LT(heel, -40);
}

TEST_F(DefaultBody, PartsAreLabelledSymmetrically) {
  std::map<BodyPart, int> count;
  for (BodyPart p : details_->part) ++count[p];
  EXPECT_EQ(details_->part.size(), static_cast<size_t>(body_->mesh.num_vertices()));
  EXPECT_GT(count[BodyPart::kArmRight], 1000);
  EXPECT_EQ(count[BodyPart::kArmRight], count[BodyPart::kArmLeft]);
  EXPECT_EQ(count[BodyPart::kLegRight], count[BodyPart::kLegLeft]);
  EXPECT_GT(count[BodyPart::kTorso], count[BodyPart::kLegRight]);
}

// Whether p is inside the closed mesh: the parity of the crossings of a ray
// from p (direction skewed so that it misses edges and vertices).
bool Inside(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  const Eigen::Vector3d d = Eigen::Vector3d(0.31, 0.17, 0.93).normalized();
  int crossings = 0;
  for (Eigen::Index f = 0; f < mesh.faces.rows(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)).transpose(),
                          b = mesh.vertices.row(mesh.faces(f, 1)).transpose(),
                          c = mesh.vertices.row(mesh.faces(f, 2)).transpose();
    const Eigen::Vector3d e1 = b - a, e2 = c - a, h = d.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-12) continue;
    const Eigen::Vector3d s = p - a, q = s.cross(e1);
    const double u = s.dot(h) / det, v = d.dot(q) / det, t = e2.dot(q) / det;
    if (u >= 0 && v >= 0 && u + v <= 1 && t > 0) ++crossings;
  }
  return crossings % 2 == 1;
}

// The skeleton MakeHuman's landmark rules read: every joint inside the
// body, in its own part (the nearest vertex's), the limbs' in anatomical
// order and the left side the mirror of the right.
TEST_F(DefaultBody, JointsLieInsideTheirParts) {
  const auto& j = details_->joints;
  const std::map<std::string, BodyPart> part = {
      {"pelvis", BodyPart::kTorso},     {"spine-1", BodyPart::kTorso},
      {"neck", BodyPart::kTorso},       {"head", BodyPart::kTorso},
      {"r-elbow", BodyPart::kArmRight}, {"r-hand", BodyPart::kArmRight},
      {"r-knee", BodyPart::kLegRight},  {"r-ankle", BodyPart::kLegRight},
      {"l-elbow", BodyPart::kArmLeft},  {"l-knee", BodyPart::kLegLeft}};
  for (const char* name : {"pelvis", "spine-4", "spine-3", "spine-2", "spine-1", "neck", "head",
                           "r-shoulder", "r-elbow", "r-hand", "r-upper-leg", "r-knee", "r-ankle",
                           "l-shoulder", "l-elbow", "l-hand", "l-upper-leg", "l-knee", "l-ankle"}) {
    ASSERT_TRUE(j.count(name)) << name;
    EXPECT_TRUE(Inside(body_->mesh, j.at(name))) << name;
    if (!part.count(name)) continue;
    Eigen::Index v = 0;
    (body_->mesh.vertices.rowwise() - j.at(name).transpose()).rowwise().squaredNorm().minCoeff(&v);
    EXPECT_EQ(details_->part[static_cast<size_t>(v)], part.at(name)) << name;
  }
  EXPECT_GT(j.at("r-shoulder").z(), j.at("r-elbow").z());
  EXPECT_GT(j.at("r-elbow").z(), j.at("r-hand").z());
  EXPECT_GT(j.at("r-upper-leg").z(), j.at("r-knee").z());
  EXPECT_GT(j.at("r-knee").z(), j.at("r-ankle").z());
  EXPECT_GT(j.at("neck").z(), j.at("spine-1").z());
  EXPECT_FALSE(Inside(body_->mesh, Eigen::Vector3d(0, 0, -10)));  // below the soles
  const Eigen::Vector3d flip(-1, 1, 1);
  EXPECT_LT((j.at("l-hand") - j.at("r-hand").cwiseProduct(flip)).norm(), 1e-9);
}

// Arms stay clear of the torso and legs from a tight A-pose to a T-pose:
// every arm vertex more than 100 mm from the armscye (the torso vertices the
// arm is stitched to) is at least 20 mm from every torso and leg vertex, and
// the mesh stays a closed sphere without self-intersections.
TEST(ParametricBody, ArmsClearOfTheTorsoFromAToTPose) {
  for (double abduction : {15.0, 22.0, 35.0, 60.0, 90.0}) {
    SCOPED_TRACE("abduction " + std::to_string(abduction));
    ParametricBodyDetails d;
    const Body body = GenerateParametricBody(Coarse(abduction), &d);
    const MeshTopology t = AnalyzeTopology(body.mesh);
    EXPECT_TRUE(t.IsClosedSphere()) << t.Describe();
    EXPECT_FALSE(SelfIntersects(body.mesh));
    const auto is_arm = [&](int v) {
      return d.part[static_cast<size_t>(v)] == BodyPart::kArmRight ||
             d.part[static_cast<size_t>(v)] == BodyPart::kArmLeft;
    };
    std::vector<Eigen::Vector3d> armscye, rest;
    for (Eigen::Index f = 0; f < body.mesh.num_faces(); ++f) {
      bool arm = false;
      for (int c = 0; c < 3; ++c) arm |= is_arm(body.mesh.faces(f, c));
      for (int c = 0; c < 3 && arm; ++c) {
        if (!is_arm(body.mesh.faces(f, c)))
          armscye.push_back(body.mesh.vertices.row(body.mesh.faces(f, c)));
      }
    }
    ASSERT_FALSE(armscye.empty());
    std::vector<Eigen::Vector3d> far_arm;
    for (Eigen::Index v = 0; v < body.mesh.num_vertices(); ++v) {
      const Eigen::Vector3d p = body.mesh.vertices.row(v);
      if (!is_arm(static_cast<int>(v))) {
        rest.push_back(p);
        continue;
      }
      double nearest = 1e300;
      for (const Eigen::Vector3d& q : armscye) nearest = std::min(nearest, (p - q).norm());
      if (nearest > 100) far_arm.push_back(p);
    }
    ASSERT_GT(far_arm.size(), 1000u);
    const double clearance = MinDistance(far_arm, rest, 60.0);  // exact below 60 mm
    std::cout << "abduction " << abduction << " deg: arm clearance " << clearance
              << " mm (exact below 60 mm)\n";
    EXPECT_GT(clearance, 20.0);
  }
}

TEST(ParametricBody, SeedsDrawDifferentValidBodiesDeterministically) {
  ParametricBodyOptions o;  // default resolution: the girth rings' deficit is checked too
  std::map<double, int> statures;
  double worst_deficit = 0;
  for (std::uint64_t seed : {1, 2, 3, 4, 5, 6, 7, 8}) {
    o.seed = seed;
    ParametricBodyDetails d;
    const Body a = GenerateParametricBody(o, &d);
    for (const AnalyticGirth& g : d.girths) {
      if (g.measurement != "elbow_girth") {  // the elbow is 0.87 x the upper arm, not a parameter
        EXPECT_NEAR(g.girth_mm, a.parameters.at(g.measurement + "_mm"), 1e-6) << g.measurement;
      }
      worst_deficit = std::max(worst_deficit, g.girth_mm - g.polygon_girth_mm);
    }
    const MeshTopology t = AnalyzeTopology(a.mesh);
    EXPECT_TRUE(t.IsClosedSphere()) << "seed " << seed << ": " << t.Describe();
    EXPECT_EQ(a.parameters.at("drawn_from_seed"), static_cast<double>(seed));
    ++statures[a.parameters.at("stature_mm")];
    if (seed == 1) {
      const Body b = GenerateParametricBody(o);
      EXPECT_TRUE(a.mesh.vertices == b.mesh.vertices);  // bit for bit
    }
  }
  std::cout << "largest girth-ring deficit over 8 seeded bodies: " << worst_deficit << " mm\n";
  EXPECT_LT(worst_deficit, 0.1);
  EXPECT_EQ(statures.size(), 8u);
  for (const auto& [stature, n] : statures) {
    EXPECT_GT(stature, 1400);
    EXPECT_LT(stature, 2050);
  }
}

TEST(ParametricBody, OptionsAreCheckedAndSetByName) {
  ParametricBodyOptions o;
  EXPECT_NO_THROW(o.Check());
  o.arm_abduction_deg = 10;
  EXPECT_THROW(o.Check(), InputError);
  o = ParametricBodyOptions();
  o.waist_girth_mm = 1400;  // 1.4 x the hip
  EXPECT_THROW(o.Check(), InputError);
  o = ParametricBodyOptions();
  o.torso_segments = 100;  // not a multiple of 8
  EXPECT_THROW(o.Check(), InputError);
  o = ParametricBodyOptions();
  o.Set("waist_girth_mm", 700);
  EXPECT_EQ(o.waist_girth_mm, 700);
  o.Set("seed", 12);
  EXPECT_EQ(o.seed, 12u);
  EXPECT_THROW(o.Set("waist", 700), InputError);
  EXPECT_THROW(o.Set("seed", -1), InputError);
  EXPECT_EQ(o.ToMap().at("waist_girth_mm"), 700);
  EXPECT_NO_THROW(ParametricBodyOptions::AverageMan().Check());
  // A man's body: its requested girths are built exactly too.
  ParametricBodyOptions man = ParametricBodyOptions::AverageMan();
  man.ring_spacing_mm = 30;
  ParametricBodyDetails d;
  const Body body = GenerateParametricBody(man, &d);
  for (const AnalyticGirth& g : d.girths) {
    if (g.measurement == "waist_girth") {
      EXPECT_NEAR(g.girth_mm, man.waist_girth_mm, 1e-6);
    }
    if (g.measurement == "bust_girth") {
      EXPECT_NEAR(g.girth_mm, man.bust_girth_mm, 1e-6);
    }
  }
}

}  // namespace
}  // namespace bespoke

namespace bespoke {
namespace {

// The full-range population: statures and waists far beyond the default
// spread; its extremes still build closed bodies.
TEST(ParametricBody, FullPopulationSpansTheRangeAndBuilds) {
  ParametricBodyOptions o;
  double s_lo = 1e9, s_hi = 0, wh_lo = 1e9, wh_hi = 0, d_lo = 1e9, d_hi = 0;
  std::uint64_t tallest = 0, widest = 0;
  for (std::uint64_t seed = 1; seed <= 200; ++seed) {
    o.seed = seed;
    const ParametricBodyOptions f = SeededOptions(o, "full");
    EXPECT_NO_THROW(f.Check());
    if (f.stature_mm > s_hi) tallest = seed;
    s_lo = std::min(s_lo, f.stature_mm), s_hi = std::max(s_hi, f.stature_mm);
    const double wh = f.waist_girth_mm;
    if (wh > wh_hi) widest = seed;
    wh_lo = std::min(wh_lo, wh), wh_hi = std::max(wh_hi, wh);
    o.seed = seed;
    const double d = SeededOptions(o).waist_girth_mm;
    d_lo = std::min(d_lo, d), d_hi = std::max(d_hi, d);
  }
  std::printf("full: stature %.0f-%.0f mm, waist %.0f-%.0f mm (default draw %.0f-%.0f)\n", s_lo,
              s_hi, wh_lo, wh_hi, d_lo, d_hi);
  EXPECT_LT(s_lo, 1500);
  EXPECT_GT(s_hi, 1950);
  EXPECT_LT(wh_lo, d_lo - 50);  // thinner than the default draw's thinnest
  EXPECT_GT(wh_hi, d_hi + 50);  // and heavier than its heaviest
  for (const std::uint64_t seed : {tallest, widest}) {
    o.seed = seed;
    const Body body = GenerateParametricBody(SeededOptions(o, "full"));
    EXPECT_TRUE(AnalyzeTopology(body.mesh).IsClosedSphere()) << seed;
  }
  EXPECT_THROW(SeededOptions(o, "no-such"), InputError);
}

// A woman's chest girth, at the armpits above the breasts, lies between her
// under-bust and her bust girths (MakeHuman's women: chest below bust on all
// but the flattest); a chest above the bust leaves no breast to find.
TEST(ParametricBody, WomenHaveTheChestBetweenUnderBustAndBust) {
  ParametricBodyOptions o;
  int women = 0;
  for (const char* population : {"default", "full"}) {
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
      o.seed = seed;
      const ParametricBodyOptions f = SeededOptions(o, population);
      if (f.chest_girth_mm == f.bust_girth_mm) continue;  // a man: chest = bust
      ++women;
      const double rise_mm = f.bust_girth_mm - f.under_bust_girth_mm;
      EXPECT_GT(f.chest_girth_mm, f.under_bust_girth_mm) << population << " seed " << seed;
      EXPECT_LT(f.chest_girth_mm, f.bust_girth_mm - 0.02 * rise_mm)
          << population << " seed " << seed;
    }
  }
  EXPECT_GT(women, 120);
}

}  // namespace
}  // namespace bespoke
