// MakeHuman bodies (CC0 data in ../shared/data/bodies/makehuman; the tests
// that need it skip when it is absent): the skin-only base mesh, targets,
// seeded bodies (diverse, closed, standing in the body frame, stature solved),
// the fixed datum points against the geometric rules that chose them, and the
// measure/ targets against the reference girths.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "measure/catalogue/catalogue.h"
#include "oracle/body/mesh_checks.h"
#include "oracle/makehuman/landmark_analysis.h"
#include "oracle/makehuman/makehuman_body.h"
#include "oracle/makehuman/makehuman_landmarks.h"
#include "oracle/makehuman/makehuman_model.h"
#include "oracle/makehuman/makehuman_target.h"
#include "oracle/truth/reference_measurements.h"
#include "scanners/core/errors.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

using testing::TempDir;

std::filesystem::path MakeHumanDir(const std::filesystem::path& shared) {
  return shared / "data" / "bodies" / "makehuman";
}

Eigen::Vector3d At(const Body& body, const std::string& name) {
  return PositionOf(body.mesh, body.landmarks.at(name));
}

double Girth(const Body& body, const std::string& name) {
  for (const ReferenceMeasurement& m :
       ComputeReferenceMeasurements(ReferenceOptions(), Catalogue::Builtin(), body).measurements)
    if (m.name == name) return m.value_mm;
  throw InternalError("no " + name);
}

// The body without its toes (z < 30 mm) and its head (above the front neck
// point), where blended targets make small self-intersections on many seeds
// (the toes of women, the lips of men: 16-84 face pairs on 15 of seeds 1-24,
// found with CGAL's self_intersections); an open mesh.
TriangleMesh WithoutToesAndHead(const Body& body) {
  const double top = At(body, "front_neck").z();
  std::vector<Eigen::Index> keep;
  for (Eigen::Index f = 0; f < body.mesh.num_faces(); ++f) {
    double lo = 1e9, hi = -1e9;
    for (int k = 0; k < 3; ++k) {
      lo = std::min(lo, body.mesh.vertices(body.mesh.faces(f, k), 2));
      hi = std::max(hi, body.mesh.vertices(body.mesh.faces(f, k), 2));
    }
    if (lo > 30 && hi < top) keep.push_back(f);
  }
  TriangleMesh out;
  out.vertices = body.mesh.vertices;
  out.faces.resize(static_cast<Eigen::Index>(keep.size()), 3);
  for (std::size_t i = 0; i < keep.size(); ++i)
    out.faces.row(static_cast<Eigen::Index>(i)) = body.mesh.faces.row(keep[i]);
  return out;
}

TEST(MakeHumanTarget, ParsesAndNamesBadLines) {
  const MakeHumanTarget t =
      ParseMakeHumanTarget("# comment\n3 0.1 -0.2 0.3\n\n7 1 2 3 # tail\n", "x.target");
  ASSERT_EQ(t.vertex, (std::vector<int>{3, 7}));
  EXPECT_EQ(t.offset.row(0), Eigen::RowVector3d(0.1, -0.2, 0.3));
  for (const char* bad : {"3 0.1 0.2\n", "-1 0 0 0\n", "1.5 0 0 0\n", "1 0 nan 0\n",
                          "1 0 0 0\n1 1 1 1\n", "a b c d\n"}) {
    try {
      ParseMakeHumanTarget(bad, "bad.target");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("bad.target"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("line"), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(ReadMakeHumanTarget("/nonexistent/x.target"), InputError);
}

TEST(MakeHumanModel, RejectsABaseWithoutSkin) {
  TempDir dir;
  std::ofstream(dir / "base.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\ng helper\nf 1 2 3\n";
  EXPECT_THROW(MakeHumanModel model(dir.path()), InputError);
  std::ofstream(dir / "base.obj")
      << "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ng body\nf 1 2 3\nf 1 3 4\n";
  try {
    MakeHumanModel model(dir.path());
    ADD_FAILURE() << "an open skin was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not closed"), std::string::npos) << e.what();
  }
}

TEST(MakeHumanModel, LoadsOnlyTheClosedSkinAndAppliesTargets) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  const TriangleMesh& skin = model.base_body();
  EXPECT_EQ(skin.num_vertices(), 13380);  // the `body` group only (base.obj has 19,158 vertices)
  EXPECT_EQ(skin.num_faces(), 26756);
  EXPECT_EQ(model.num_base_vertices(), 19158);
  EXPECT_TRUE(std::is_sorted(model.base_index().begin(), model.base_index().end()));
  for (int v : {0, 100, 13379})
    EXPECT_EQ(model.BodyVertex(model.base_index()[static_cast<std::size_t>(v)]), v);
  // The skin is closed: eyes and mouth are not holes in it.
  const MeshTopology topology = AnalyzeTopology(skin);
  EXPECT_TRUE(topology.IsClosedSphere()) << topology.Describe();
  EXPECT_GT(model.joint_vertices().size(), 20u);
  EXPECT_EQ(model.joint_vertices().count("joint-r-elbow"), 1u);

  // A target moves exactly its vertices (those of the skin) by weight x offset.
  const std::string name = "measure/measure-waist-circ-incr.target";
  const MakeHumanTarget& target = model.Target(name);
  const TriangleMesh morphed = model.Morph({{name, 0.5}});
  Eigen::MatrixX3d expected = skin.vertices;
  int moved = 0;
  for (std::size_t i = 0; i < target.vertex.size(); ++i) {
    const int v = model.BodyVertex(target.vertex[i]);
    if (v < 0) continue;
    expected.row(v) += 0.5 * target.offset.row(static_cast<Eigen::Index>(i));
    ++moved;
  }
  EXPECT_GT(moved, 100);
  EXPECT_LT((morphed.vertices - expected).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(morphed.faces, skin.faces);
  EXPECT_THROW(model.Target("measure/no-such.target"), InputError);
}

TEST(MakeHumanBody, TenSeedsAreDiverseClosedAndStandInTheBodyFrame) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  const Catalogue& catalogue = Catalogue::Builtin();
  double min_stature = 1e9, max_stature = 0, min_volume = 1e18, max_volume = 0;
  int women = 0, men = 0;
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    MakeHumanBodyOptions o;
    o.seed = seed;
    const Body body = GenerateMakeHumanBody(o, &model);
    SCOPED_TRACE("seed " + std::to_string(seed));
    EXPECT_EQ(body.model, "makehuman");
    const double stature = body.parameters.at("stature_mm");
    // Stature solved by the height targets; soles on z = 0; origin between the ankles.
    EXPECT_NEAR(body.mesh.vertices.col(2).maxCoeff(), stature, 0.01);
    EXPECT_NEAR(body.mesh.vertices.col(2).minCoeff(), 0, 1e-9);
    Eigen::Vector3d ankles = Eigen::Vector3d::Zero();
    for (const char* a :
         {"ankle_inside_left", "ankle_inside_right", "ankle_outside_left", "ankle_outside_right"})
      ankles += At(body, a) / 4;
    EXPECT_LT(ankles.head<2>().norm(), 1e-9);
    const MeshTopology topology = AnalyzeTopology(body.mesh);
    EXPECT_TRUE(topology.IsClosedSphere()) << topology.Describe();
    EXPECT_FALSE(SelfIntersects(WithoutToesAndHead(body))) << "below the neck, above the toes";
    (body.parameters.at("gender") < 0.5 ? women : men) += 1;
    min_stature = std::min(min_stature, stature), max_stature = std::max(max_stature, stature);
    min_volume = std::min(min_volume, topology.signed_volume),
    max_volume = std::max(max_volume, topology.signed_volume);

    // Every catalogue datum point, in anatomical order.
    for (const LandmarkDef& l : catalogue.landmarks())
      EXPECT_EQ(body.landmarks.count(l.name), 1u) << l.name;
    const auto z = [&](const char* name) { return At(body, name).z(); };
    EXPECT_NEAR(z("crown"), stature, 0.01);
    const std::vector<const char*> downwards = {"crown",      "back_neck",   "armpit_right",
                                                "under_bust", "front_waist", "crotch",
                                                "knee_right", "calf_right",  "ankle_inside_right"};
    for (std::size_t i = 0; i + 1 < downwards.size(); ++i)
      EXPECT_GT(z(downwards[i]), z(downwards[i + 1])) << downwards[i];
    EXPECT_GT(z("shoulder_right"), z("armpit_right"));
    EXPECT_GT(z("side_neck_right"), z("shoulder_right"));
    EXPECT_GT(z("elbow_right"), z("wrist_right"));
    EXPECT_GT(z("front_waist"), z("middle_hip_front"));
    EXPECT_GT(z("middle_hip_front"), z("crotch"));
    EXPECT_GT(At(body, "front_neck").y(), At(body, "back_neck").y());
    EXPECT_GT(At(body, "front_waist").y(), At(body, "back_waist").y());
    EXPECT_GT(At(body, "bust_right").y(), At(body, "axilla_back_right").y());
    EXPECT_GT(At(body, "knee_right").y(), At(body, "calf_right").y());
    for (const char* centre : {"crown", "back_neck", "front_neck", "under_bust", "front_waist",
                               "back_waist", "middle_hip_front", "hip_back", "crotch"})
      EXPECT_LT(std::abs(At(body, centre).x()), 5) << centre;
    for (const auto& [name, point] : body.landmarks) {
      const auto at = name.rfind("_right");
      if (at == std::string::npos) continue;
      const Eigen::Vector3d right = At(body, name), left = At(body, name.substr(0, at) + "_left");
      EXPECT_GT(right.x(), 20) << name;  // the person's right is +x
      EXPECT_LT((right - Eigen::Vector3d(-left.x(), left.y(), left.z())).norm(), 1)
          << name << ": not mirrored";
    }
  }
  std::printf("10 seeds: %d women, %d men; stature %.0f-%.0f mm; volume %.1f-%.1f L\n", women, men,
              min_stature, max_stature, min_volume / 1e6, max_volume / 1e6);
  EXPECT_GE(women, 3);
  EXPECT_GE(men, 3);
  EXPECT_GT(max_stature - min_stature, 150);
  EXPECT_GT(max_volume / min_volume, 1.4);  // light to heavy
}

TEST(MakeHumanBody, StatureIsSolvedAndOptionsAreChecked) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  for (const double stature : {1500.0, 1950.0}) {
    MakeHumanBodyOptions o;
    o.seed = 4;
    o.stature_mm = stature;
    const Body body = GenerateMakeHumanBody(o, &model);
    EXPECT_NEAR(body.mesh.vertices.col(2).maxCoeff(), stature, 0.01);
    EXPECT_NEAR(body.parameters.at("stature_mm"), stature, 1e-9);
  }
  // Overriding one value keeps the other draws.
  MakeHumanBodyOptions a, b;
  a.seed = b.seed = 9;
  b.weight = 0.9;
  const MakeHumanParameters pa = MakeHumanDraw(a), pb = MakeHumanDraw(b);
  EXPECT_EQ(pb.weight, 0.9);
  EXPECT_EQ(pa.gender, pb.gender);
  EXPECT_EQ(pa.stature_mm, pb.stature_mm);
  EXPECT_EQ(pa.measure, pb.measure);
  MakeHumanBodyOptions bad;
  EXPECT_THROW(bad.Set("no_such", 1), InputError);
  bad.Set("gender", 2);
  EXPECT_THROW(bad.Check(), InputError);
  MakeHumanBodyOptions unknown;
  unknown.Set("measure.no-such-circ", 0.5);
  EXPECT_THROW(unknown.Check(), InputError);
}

TEST(MakeHumanBody, MeasureTargetsChangeTheirGirth) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  const auto body_with = [&](const std::string& measure, double value) {
    MakeHumanBodyOptions o;
    o.seed = 5;
    o.measure_spread = 0;
    o.measure[measure] = value;
    return GenerateMakeHumanBody(o, &model);
  };
  for (const auto& [measure, girth, other] :
       {std::tuple<const char*, const char*, const char*>{"waist-circ", "waist_girth",
                                                          "thigh_girth"},
        {"hips-circ", "hip_girth", "neck_girth"},
        {"upperarm-circ", "upper_arm_girth", "waist_girth"}}) {
    const Body small = body_with(measure, -1), large = body_with(measure, 1);
    const double grown = Girth(large, girth) - Girth(small, girth);
    const double side_effect = std::abs(Girth(large, other) - Girth(small, other));
    std::printf("measure-%s -1 -> +1: %s +%.1f mm, %s %.1f mm\n", measure, girth, grown, other,
                side_effect);
    EXPECT_GT(grown, 20) << measure;
    EXPECT_LT(side_effect, grown / 4) << measure << " changes " << other;
  }
}

// The fixed table against the rules that chose it (landmark_analysis.h), on
// seeds the table was not chosen on (it used seeds 1-24).
TEST(MakeHumanLandmarks, TableStaysNearTheRulesOnUnseenBodies) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(MakeHumanDir(shared));
  std::vector<double> all;
  for (std::uint64_t seed : {101, 202}) {
    MakeHumanBodyOptions o;
    o.seed = seed;
    const Body body = GenerateMakeHumanBody(o, &model);
    const MakeHumanParameters p = MakeHumanDraw(o);
    const MakeHumanModel::Morphed morphed =
        model.MorphWithJoints(MakeHumanTargetWeights(p, body.parameters.at("height_weight")));
    const Eigen::Affine3d to_body = MakeHumanModel::BodyFromMakeHuman();
    // GenerateMakeHumanBody's translation onto the floor, recovered from vertex 0.
    const Eigen::Vector3d shift =
        body.mesh.vertices.row(0).transpose() - to_body * morphed.body.vertices.row(0).transpose();
    std::map<std::string, Eigen::Vector3d> joints;
    for (const auto& [name, centre] : morphed.joints)
      joints[name.substr(6)] = to_body * centre + shift;
    const auto analysed = AnalyseMakeHumanLandmarks(body.mesh, joints);
    const bool woman = p.gender < 0.5;
    for (const auto& [name, found] : analysed) {
      if (!woman && (name.rfind("bust", 0) == 0 || name == "under_bust"))
        continue;  // rules for women
      const double d = (found.position - At(body, name)).norm();
      EXPECT_LT(d, 100) << "seed " << seed << ": " << name << " is " << d
                        << " mm from its rule's point";
      all.push_back(d);
    }
  }
  ASSERT_GT(all.size(), 40u);
  std::nth_element(all.begin(), all.begin() + static_cast<long>(all.size() / 2), all.end());
  const double median = all[all.size() / 2];
  std::printf("table vs rules, seeds 101 and 202: median %.1f mm over %zu landmarks\n", median,
              all.size());
  EXPECT_LT(median, 20);
}

// Limb labels from the rig's skin weights, and a limb girth's truth cut on
// the limb's own surface where the posed limb passes into the trunk or the
// other leg (full population, arms 30 deg: seed 1048's right upper arm sinks
// into the trunk at its plane, seed 1028's thighs into each other; on the
// whole mesh the loops take in the trunk's or both thighs' skin).
TEST(MakeHumanBody, LimbGirthTruthKeepsToTheLimb) {
  BESPOKE_REQUIRE_SHARED(shared);
  MakeHumanModel model(shared / "data/bodies/makehuman");
  nlohmann::json document = nlohmann::json::parse(BuiltinCatalogueJson());
  nlohmann::json limbs_only = nlohmann::json::array();
  for (const nlohmann::json& m : document["measurements"])
    if (m["name"] == "upper_arm_girth" || m["name"] == "thigh_girth") limbs_only.push_back(m);
  document["measurements"] = limbs_only;
  const Catalogue catalogue = Catalogue::FromJson(document, "limb girths");
  for (const auto& [seed, name] : {std::pair{1048, "upper_arm_girth"}, {1028, "thigh_girth"}}) {
    MakeHumanBodyOptions options;
    options.seed = seed;
    options.population = "full";
    options.posture = ParseMakeHumanPosture("arms-30");
    const Body body = GenerateMakeHumanBody(options, &model);
    ASSERT_EQ(body.limbs.size(), static_cast<size_t>(body.mesh.num_vertices()));
    Eigen::Vector3d right = Eigen::Vector3d::Zero(), left = Eigen::Vector3d::Zero();
    const BodyLimb r =
        std::string(name) == "thigh_girth" ? BodyLimb::kLegRight : BodyLimb::kArmRight;
    const BodyLimb l = std::string(name) == "thigh_girth" ? BodyLimb::kLegLeft : BodyLimb::kArmLeft;
    int nr = 0, nl = 0;
    for (Eigen::Index v = 0; v < body.mesh.num_vertices(); ++v) {
      const BodyLimb limb = body.limbs[static_cast<size_t>(v)];
      if (limb == r) right += body.mesh.vertices.row(v).transpose(), ++nr;
      if (limb == l) left += body.mesh.vertices.row(v).transpose(), ++nl;
    }
    ASSERT_GT(nr, 100);
    ASSERT_GT(nl, 100);
    EXPECT_GT(right.x() / nr, 80) << "the right limb is at +x";
    EXPECT_LT(left.x() / nl, -80);
    const ReferenceMeasurements truth = ComputeReferenceMeasurements({}, catalogue, body);
    const ReferenceMeasurement& girth = truth.measurements.front().name == name
                                            ? truth.measurements.front()
                                            : truth.measurements.back();
    std::printf("seed %d %s: %.1f mm, flags", seed, name, girth.value_mm);
    for (const std::string& f : girth.flags) std::printf(" %s", f.c_str());
    std::printf("\n");
    EXPECT_NE(std::find(girth.flags.begin(), girth.flags.end(), "section_limb_only"),
              girth.flags.end());
    EXPECT_EQ(std::find(girth.flags.begin(), girth.flags.end(), "section_crosses_midline"),
              girth.flags.end());
    EXPECT_LT(girth.value_mm, std::string(name) == "thigh_girth" ? 800 : 500) << "mm";
  }
}

}  // namespace
}  // namespace bespoke
