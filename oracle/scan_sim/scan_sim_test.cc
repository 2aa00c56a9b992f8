#include "oracle/scan_sim/scan_sim.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>

#include "oracle/body/parametric_body.h"
#include "oracle/scan_sim/raycaster.h"
#include "oracle/scan_sim/scan_sim_files.h"
#include "oracle/scan_sim/scan_truth.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

// One default body and its default scan, shared by the tests below.
class DefaultScan : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    body_ = new Body(GenerateParametricBody(ParametricBodyOptions()));
    scan_ = new ScanSimResult(SimulateScan(ScanSimOptions(), body_->mesh));
  }
  static void TearDownTestSuite() {
    delete scan_;
    delete body_;
  }
  static std::vector<Eigen::Index> OfSource(const ScanSimResult& r, ScanSource s) {
    std::vector<Eigen::Index> out;
    const Eigen::VectorXd& source = r.cloud.scalars.at("source");
    for (Eigen::Index i = 0; i < source.size(); ++i) {
      if (source[i] == static_cast<double>(s)) out.push_back(i);
    }
    return out;
  }
  static Eigen::Vector3d At(const std::string& name) {
    return PositionOf(body_->mesh, body_->landmarks.at(name));
  }
  static Body* body_;
  static ScanSimResult* scan_;
};
Body* DefaultScan::body_ = nullptr;
ScanSimResult* DefaultScan::scan_ = nullptr;

TEST_F(DefaultScan, HasTheSizeOfACommercialBoothScan) {
  const ScanSimResult& r = *scan_;
  EXPECT_EQ(r.sensors.size(), 42u);
  EXPECT_EQ(r.rays, 42 * 240 * 180);
  std::cout << "default scan: " << r.cloud.size() << " points, " << r.counts[0] << " body, "
            << r.counts[1] << " floor, " << r.counts[3] << " outliers, " << r.dropped_grazing
            << " grazing returns dropped\n";
  EXPECT_GT(r.cloud.size(), 300000);
  EXPECT_LT(r.cloud.size(), 500000);
  EXPECT_EQ(r.counts[0] + r.counts[1] + r.counts[2] + r.counts[3], r.cloud.size());
  EXPECT_TRUE(r.cloud.has_normals());
  EXPECT_EQ(r.counts[2], 0);  // no stray objects asked for
}

// Point density on the front of the chest, between the under-bust and the
// bust levels within 60 mm of the centre line: points of the body there
// divided by the mesh's area there.
TEST_F(DefaultScan, ChestDensityIsInTheBoothsRange) {
  const double z0 = At("under_bust").z() + 5, z1 = At("bust_right").z() - 5;
  const auto inside = [&](const Eigen::Vector3d& p) {
    return std::abs(p.x()) < 60 && p.y() > 0 && p.z() > z0 && p.z() < z1;
  };
  double area_mm2 = 0;
  const TriangleMesh& m = body_->mesh;
  for (Eigen::Index f = 0; f < m.num_faces(); ++f) {
    const Eigen::Vector3d a = m.vertices.row(m.faces(f, 0)), b = m.vertices.row(m.faces(f, 1)),
                          c = m.vertices.row(m.faces(f, 2));
    if (inside((a + b + c) / 3)) area_mm2 += 0.5 * (b - a).cross(c - a).norm();
  }
  int points = 0;
  for (Eigen::Index i : OfSource(*scan_, ScanSource::kBody))
    points += inside(scan_->cloud.points.row(i).transpose());
  ASSERT_GT(area_mm2, 5000);  // about 120 x 60 mm
  const double per_cm2 = points / (area_mm2 / 100);
  std::cout << "chest density: " << per_cm2 << " points/cm2 over " << area_mm2 / 100 << " cm2\n";
  EXPECT_GT(per_cm2, 15);
  EXPECT_LT(per_cm2, 60);
}

// Range noise: re-cast each body point's sensor ray through the point; the
// point's range minus the true range is the noise drawn. Mean ~0, SD within
// 10 % of sigma (1 mm).
TEST_F(DefaultScan, RangeNoiseHasTheRequestedStatistics) {
  const std::vector<Eigen::Index> body = OfSource(*scan_, ScanSource::kBody);
  const Eigen::Index n = std::min<Eigen::Index>(static_cast<Eigen::Index>(body.size()), 40000);
  Eigen::MatrixX3d origins(n, 3), directions(n, 3);
  Eigen::VectorXd range(n);
  const size_t stride = body.size() / static_cast<size_t>(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index i = body[static_cast<size_t>(k) * stride];
    const Eigen::Vector3d eye =
        scan_->sensors[static_cast<size_t>(scan_->cloud.scalars.at("sensor")[i])].position();
    const Eigen::Vector3d p = scan_->cloud.points.row(i);
    origins.row(k) = eye;
    directions.row(k) = (p - eye).normalized();
    range[k] = (p - eye).norm();
  }
  MeshRaycaster caster;
  caster.AddMesh(body_->mesh);
  const RayHits hits = caster.Cast(origins, directions);
  double sum = 0, sum2 = 0;
  int used = 0;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (hits.geometry[k] < 0) continue;  // a noisy point grazing a silhouette
    const double e = range[k] - hits.distance[k];
    if (std::abs(e) > 10) continue;  // the ray now hits another surface first
    sum += e;
    sum2 += e * e;
    ++used;
  }
  ASSERT_GT(used, 0.98 * n);
  const double mean = sum / used, sd = std::sqrt(sum2 / used - mean * mean);
  std::cout << "range noise: mean " << mean << " mm, SD " << sd << " mm over " << used
            << " points\n";
  EXPECT_NEAR(mean, 0, 0.03);
  EXPECT_NEAR(sd, 1.0, 0.1);
  // And the points' distance to the mesh (perpendicular) is at most the range error.
  Eigen::MatrixX3d sample(n, 3);
  for (Eigen::Index k = 0; k < n; ++k)
    sample.row(k) = scan_->cloud.points.row(body[static_cast<size_t>(k) * stride]);
  const Eigen::VectorXd d = caster.Distance(sample);
  EXPECT_LT(std::sqrt(d.squaredNorm() / n), 1.0);
  EXPECT_GT(std::sqrt(d.squaredNorm() / n), 0.5);
}

TEST_F(DefaultScan, OutliersAreTheRequestedShareAndOffTheSurface) {
  const std::vector<Eigen::Index> outliers = OfSource(*scan_, ScanSource::kOutlier);
  EXPECT_NEAR(static_cast<double>(outliers.size()) / scan_->cloud.size(), 0.02, 0.001);
  Eigen::MatrixX3d p(static_cast<Eigen::Index>(outliers.size()), 3);
  for (size_t k = 0; k < outliers.size(); ++k)
    p.row(static_cast<Eigen::Index>(k)) = scan_->cloud.points.row(outliers[k]);
  MeshRaycaster caster;
  caster.AddMesh(body_->mesh);
  const Eigen::VectorXd d = caster.Distance(p);
  int far = 0;
  for (Eigen::Index k = 0; k < d.size(); ++k) far += d[k] > 10;
  EXPECT_GT(far,
            0.8 * d.size());  // flying pixels leave the surface by 30-300 mm along oblique rays
}

TEST_F(DefaultScan, FloorPatchLiesOnTheFloor) {
  const std::vector<Eigen::Index> floor = OfSource(*scan_, ScanSource::kFloor);
  ASSERT_GT(floor.size(), 1000u);
  for (Eigen::Index i : floor) {
    const Eigen::Vector3d p = scan_->cloud.points.row(i);
    ASSERT_LT(std::abs(p.z()), 6.0);  // 6 sigma of the range noise
    ASSERT_LE(std::abs(p.x()), 450 + 6);
    ASSERT_LE(std::abs(p.y()), 450 + 6);
  }
}

TEST_F(DefaultScan, NormalsFaceTheirSensor) {
  const Eigen::VectorXd& sensor = scan_->cloud.scalars.at("sensor");
  for (Eigen::Index i = 0; i < scan_->cloud.size(); i += 97) {
    const Eigen::Vector3d eye = scan_->sensors[static_cast<size_t>(sensor[i])].position();
    const Eigen::Vector3d p = scan_->cloud.points.row(i);
    ASSERT_NEAR(scan_->cloud.normals.row(i).norm(), 1, 1e-9);
    ASSERT_GT(scan_->cloud.normals.row(i).dot(eye - p), 0);
  }
}

// Occlusion. Sample the surface within `radius` of a landmark every ~1.5 mm
// and test each sample against every sensor with a ray of its own: a sample
// is seen when the ray reaches it (nothing in front) at an incidence the
// sensor returns (|cos| >= min_incidence_cos, as in SimulateScan). Samples no
// sensor sees form the hidden region; "deep" ones have no seen sample within
// 3 mm. Returns the number of hidden and deep samples and of scan points
// within 1 mm of a deep sample (which must be none).
struct Occlusion {
  size_t samples = 0, hidden = 0, deep = 0;
  int points_inside = 0;
};

Occlusion CheckOcclusion(const Body& body, const ScanSimOptions& so, const ScanSimResult& scan,
                         const std::string& landmark, double radius) {
  const Eigen::Vector3d centre = PositionOf(body.mesh, body.landmarks.at(landmark));
  std::vector<Eigen::Vector3d> samples;
  const TriangleMesh& m = body.mesh;
  for (Eigen::Index f = 0; f < m.num_faces(); ++f) {
    const Eigen::Vector3d a = m.vertices.row(m.faces(f, 0)), b = m.vertices.row(m.faces(f, 1)),
                          c = m.vertices.row(m.faces(f, 2));
    if (((a + b + c) / 3 - centre).norm() > radius) continue;
    const int k = std::max(
        2, static_cast<int>(
               std::ceil(std::max({(b - a).norm(), (c - a).norm(), (c - b).norm()}) / 1.5)));
    for (int i = 0; i <= k; ++i)
      for (int j = 0; i + j <= k; ++j) samples.push_back(a + (b - a) * i / k + (c - a) * j / k);
  }
  MeshRaycaster caster;
  caster.AddMesh(body.mesh);
  std::vector<char> seen(samples.size(), 0);
  const auto n = static_cast<Eigen::Index>(samples.size());
  for (const DepthSensor& s : scan.sensors) {
    Eigen::MatrixX3d o(n, 3), d(n, 3);
    for (Eigen::Index i = 0; i < n; ++i) {
      o.row(i) = s.position();
      d.row(i) = (samples[static_cast<size_t>(i)] - s.position()).normalized();
    }
    const RayHits h = caster.Cast(o, d);
    for (Eigen::Index i = 0; i < n; ++i) {
      const double dist = (samples[static_cast<size_t>(i)] - s.position()).norm();
      if (h.geometry[i] >= 0 && h.distance[i] > dist - 0.5 &&
          std::abs(h.normal.row(i).dot(d.row(i))) >= so.min_incidence_cos) {
        seen[static_cast<size_t>(i)] = 1;
      }
    }
  }
  // Seen samples in a 3 mm hash grid; a hidden sample is deep when no seen
  // sample lies within 3 mm.
  const auto cell = [](const Eigen::Vector3d& p) {
    return std::array<long, 3>{static_cast<long>(std::floor(p.x() / 3)),
                               static_cast<long>(std::floor(p.y() / 3)),
                               static_cast<long>(std::floor(p.z() / 3))};
  };
  std::map<std::array<long, 3>, std::vector<Eigen::Vector3d>> seen_grid;
  std::vector<Eigen::Vector3d> hidden, deep;
  for (size_t i = 0; i < samples.size(); ++i) {
    if (seen[i])
      seen_grid[cell(samples[i])].push_back(samples[i]);
    else
      hidden.push_back(samples[i]);
  }
  for (const Eigen::Vector3d& p : hidden) {
    const auto c = cell(p);
    bool near_visible = false;
    for (long dx = -1; dx <= 1 && !near_visible; ++dx)
      for (long dy = -1; dy <= 1 && !near_visible; ++dy)
        for (long dz = -1; dz <= 1 && !near_visible; ++dz) {
          const auto it = seen_grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == seen_grid.end()) continue;
          for (const Eigen::Vector3d& q : it->second)
            near_visible = near_visible || (p - q).squaredNorm() < 9;
        }
    if (!near_visible) deep.push_back(p);
  }
  Occlusion out{samples.size(), hidden.size(), deep.size(), 0};
  for (Eigen::Index i = 0; i < scan.cloud.size(); ++i) {
    const Eigen::Vector3d p = scan.cloud.points.row(i);
    if ((p - centre).norm() > radius + 10) continue;
    for (const Eigen::Vector3d& q : deep) {
      if ((p - q).squaredNorm() < 1.0) {
        ++out.points_inside;
        break;
      }
    }
  }
  std::cout << landmark << ": " << out.hidden << " of " << out.samples << " surface samples within "
            << radius << " mm hidden from every sensor, " << out.deep
            << " deep; scan points in the deep region: " << out.points_inside << "\n";
  return out;
}

// Between the legs (a tight A-pose body, no noise, no outliers): the inner
// thighs below the crotch are hidden from every sensor, and no scan point
// lies there. The armpit region is checked the same way; the parametric
// armpit is an open arch (no pectoral or latissimus folds) which the default
// six-column booth sees whole (0 hidden samples), so the hidden armpit is
// asserted with a four-column booth.
TEST(ScanSim, NothingIsScannedWhereNoSensorSees) {
  ParametricBodyOptions bo;
  bo.arm_abduction_deg = 15;
  const Body body = GenerateParametricBody(bo);
  ScanSimOptions so;
  so.noise_sigma_mm = 0;
  so.outlier_fraction = 0;
  const ScanSimResult scan = SimulateScan(so, body.mesh);
  const Occlusion crotch = CheckOcclusion(body, so, scan, "crotch", 50);
  EXPECT_GT(crotch.deep, 300u);  // samples about 1.5 mm apart: several cm2
  EXPECT_EQ(crotch.points_inside, 0);
  const Occlusion armpit = CheckOcclusion(body, so, scan, "armpit_right", 40);
  EXPECT_EQ(armpit.points_inside, 0);
  // A four-column booth (front, back and the sides, as four-tower scanners
  // are built) has no diagonal view under the arm: the armpit hollow is
  // hidden from every sensor (measured: 2,281 deep samples of 12,294), and
  // no scan point lies there.
  ScanSimOptions four = so;
  four.booth.directions = 4;
  four.booth.heights = 4;
  four.booth.lowest_mm = 600;
  const ScanSimResult four_scan = SimulateScan(four, body.mesh);
  const Occlusion four_armpit = CheckOcclusion(body, four, four_scan, "armpit_right", 40);
  EXPECT_GT(four_armpit.deep, 1000u);
  EXPECT_EQ(four_armpit.points_inside, 0);
}

TEST_F(DefaultScan, IsDeterministicForASeed) {
  ScanSimOptions o;
  o.booth.width_px = 60;
  o.booth.height_px = 45;
  const ScanSimResult a = SimulateScan(o, body_->mesh), b = SimulateScan(o, body_->mesh);
  ASSERT_EQ(a.cloud.size(), b.cloud.size());
  EXPECT_TRUE(a.cloud.points == b.cloud.points);
  o.seed = 2;
  const ScanSimResult c = SimulateScan(o, body_->mesh);
  EXPECT_FALSE(c.cloud.size() == a.cloud.size() && c.cloud.points == a.cloud.points);
}

TEST_F(DefaultScan, TransformsAndUnitsRoundTrip) {
  ScanSimOptions o;
  o.booth.width_px = 60;
  o.booth.height_px = 45;
  const ScanSimResult plain = SimulateScan(o, body_->mesh);
  for (ScanTransform t : {ScanTransform::kRandom, ScanTransform::kYUp}) {
    o.transform = t;
    const ScanSimResult moved = SimulateScan(o, body_->mesh);
    const Eigen::Matrix3d r = moved.scanner_from_body.linear();
    EXPECT_TRUE((r.transpose() * r).isIdentity(1e-12));
    EXPECT_NEAR(r.determinant(), 1, 1e-12);
    PointCloud back = moved.cloud;
    TransformInPlace(moved.scanner_from_body.inverse(), &back);
    ASSERT_EQ(back.size(), plain.cloud.size());
    EXPECT_LT((back.points - plain.cloud.points).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_LT((back.normals - plain.cloud.normals).cwiseAbs().maxCoeff(), 1e-9);
  }
  // Written in metres, read back in millimetres.
  testing::TempDir dir;
  ScanSimFiles files;
  files.scan = dir / "scan.ply";
  files.truth_in = dir / "truth.json";
  nlohmann::json truth = {
      {"format", "bespoke-measurements"}, {"version", 1}, {"units", "mm"}, {"frame", "body"}};
  truth["landmarks"]["crown"] = ToJson(At("crown"));
  truth["measurements"] =
      nlohmann::json::array({{{"name", "stature"}, {"kind", "height"}, {"value_mm", 1660.0}}});
  WriteJsonFile(files.truth_in, truth);
  o.transform = ScanTransform::kRandom;
  const ScanSimResult written = SimulateScanToFiles(o, files, body_->mesh);
  ReadOptions read;
  read.units = LengthUnit::kMetre;
  const Scan again = ReadScan(read, files.scan);
  ASSERT_EQ(again.cloud.size(), written.cloud.size());
  EXPECT_LT((again.cloud.points - written.cloud.points).cwiseAbs().maxCoeff(),
            1e-3);  // float in the file
  EXPECT_TRUE(again.cloud.has_normals());
  EXPECT_EQ(again.cloud.scalars.count("source"), 0u);  // labels only with ScanSimFiles::labels
  const nlohmann::json scan_truth = ReadJsonFile(dir / "scan.truth.json");
  EXPECT_EQ(scan_truth["frame"], "scanner");
  EXPECT_EQ(scan_truth["file_unit"], "m");
  const Eigen::Affine3d t = AffineFromJson(scan_truth["scanner_from_body"], "scanner_from_body");
  EXPECT_TRUE(t.matrix().isApprox(written.scanner_from_body.matrix(), 1e-12));
  const Eigen::Vector3d crown = Vector3FromJson(scan_truth["landmarks"]["crown"], "crown");
  EXPECT_LT((t.inverse() * crown - At("crown")).norm(), 1e-9);
  EXPECT_LT((Vector3FromJson(scan_truth["landmarks_body"]["crown"], "crown") - At("crown")).norm(),
            1e-9);
  EXPECT_EQ(scan_truth["measurements"][0]["value_mm"], 1660.0);
  EXPECT_TRUE(std::filesystem::exists(dir / "scan.scan.json"));
}

TEST_F(DefaultScan, MisalignmentMovesEachSensorRigidly) {
  ScanSimOptions o;
  o.booth.width_px = 60;
  o.booth.height_px = 45;
  o.outlier_fraction = 0;
  o.noise_sigma_mm = 0;
  const ScanSimResult a = SimulateScan(o, body_->mesh);
  o.misalign_mm = 3;
  o.misalign_deg = 0.3;
  const ScanSimResult b = SimulateScan(o, body_->mesh);
  // Same sensors, points moved: several mm on average, but no more than a
  // rigid error of this size can move a point at the booth's range.
  MeshRaycaster caster;
  caster.AddMesh(body_->mesh);
  std::vector<Eigen::Index> body_b = OfSource(b, ScanSource::kBody);
  Eigen::MatrixX3d p(static_cast<Eigen::Index>(body_b.size()), 3);
  for (size_t k = 0; k < body_b.size(); ++k)
    p.row(static_cast<Eigen::Index>(k)) = b.cloud.points.row(body_b[k]);
  const Eigen::VectorXd d = caster.Distance(p);
  std::vector<Eigen::Index> body_a = OfSource(a, ScanSource::kBody);
  Eigen::MatrixX3d p0(static_cast<Eigen::Index>(body_a.size()), 3);
  for (size_t k = 0; k < body_a.size(); ++k)
    p0.row(static_cast<Eigen::Index>(k)) = a.cloud.points.row(body_a[k]);
  const Eigen::VectorXd d0 = caster.Distance(p0);
  EXPECT_LT(d0.maxCoeff(), 0.01);  // noise-free, aligned: on the surface
  EXPECT_GT(d.mean(), 0.5);
  EXPECT_LT(d.maxCoeff(), 30);
}

TEST_F(DefaultScan, StrayObjectsStandClearOfTheBody) {
  ScanSimOptions o;
  o.booth.width_px = 80;
  o.booth.height_px = 60;
  o.stray_objects = 3;
  const ScanSimResult r = SimulateScan(o, body_->mesh);
  EXPECT_EQ(r.stray_objects_placed, 3);
  EXPECT_GT(r.counts[2], 100);
  std::vector<Eigen::Index> stray = OfSource(r, ScanSource::kStray);
  Eigen::MatrixX3d p(static_cast<Eigen::Index>(stray.size()), 3);
  for (size_t k = 0; k < stray.size(); ++k)
    p.row(static_cast<Eigen::Index>(k)) = r.cloud.points.row(stray[k]);
  MeshRaycaster caster;
  caster.AddMesh(body_->mesh);
  EXPECT_GT(caster.Distance(p).minCoeff(), 50);
  o.floor = false;
  EXPECT_EQ(SimulateScan(o, body_->mesh).counts[1], 0);
}

TEST(ScanSim, OptionsAreChecked) {
  ScanSimOptions o;
  o.noise_sigma_mm = -1;
  EXPECT_THROW(o.Check(), InputError);
  o = ScanSimOptions();
  o.outlier_fraction = 0.9;
  EXPECT_THROW(o.Check(), InputError);
  o = ScanSimOptions();
  o.booth.directions = 0;
  EXPECT_THROW(o.Check(), InputError);
  EXPECT_THROW(ParseScanTransform("sideways"), InputError);
  EXPECT_EQ(ParseScanTransform("y-up"), ScanTransform::kYUp);
  EXPECT_THROW(SimulateScan(ScanSimOptions(), TriangleMesh()), InputError);
}

}  // namespace
}  // namespace bespoke
