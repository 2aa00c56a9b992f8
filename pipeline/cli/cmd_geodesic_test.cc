// `bespoke geodesic` and `bespoke validate` as a user runs them: separate
// processes on a generated scan on disk (a parametric body through the
// virtual scanner), checked against CGAL's exact geodesic on the body mesh;
// bad coordinates and files give exit code 1, a clear message and no output.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "oracle/body/parametric_body.h"
#include "oracle/scan_sim/scan_sim.h"
#include "oracle/truth/exact_geodesics.h"
#include "scanners/core/json_io.h"
#include "scanners/io/scan_io.h"
#include "tests/support/run_command.h"
#include "tests/support/test_support.h"

#ifndef BESPOKE_BINARY
#error "BESPOKE_BINARY (the bespoke executable) must be defined by CMake"
#endif

namespace bespoke {
namespace {

using testing::CommandResult;
using testing::TempDir;

std::string Q(const std::filesystem::path& p) { return testing::Quote(p); }

std::string Xyz(const Eigen::Vector3d& p) {
  char text[128];
  std::snprintf(text, sizeof text, "%.4f,%.4f,%.4f", p.x(), p.y(), p.z());
  return text;
}

// One generated scan (about 80k points, mm) and the exact back length
// (back neck -> back waist over the body mesh), shared by the tests.
class GeodesicCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new TempDir();
    ParametricBodyOptions shape;  // an average woman, coarse mesh: a fast exact reference
    shape.torso_segments = 48;
    shape.arm_segments = 32;
    shape.ring_spacing_mm = 20;
    shape.girth_ring_segments = 64;
    shape.max_girth_deficit_mm = 1.0;
    const Body body = GenerateParametricBody(shape);
    ScanSimOptions booth;
    booth.booth.width_px = 120;
    booth.booth.height_px = 90;
    booth.floor = false;
    booth.outlier_fraction = 0;
    booth.noise_sigma_mm = 0.5;
    const ScanSimResult scan = SimulateScan(booth, body.mesh);
    points_ = scan.cloud.size();
    WriteScan(WriteOptions{}, scan.cloud, *dir_ / "scan.ply");
    const SurfacePoint a = body.landmarks.at("back_neck");
    const SurfacePoint b = body.landmarks.at("back_waist");
    from_ = scan.scanner_from_body * PositionOf(body.mesh, a);
    to_ = scan.scanner_from_body * PositionOf(body.mesh, b);
    ExactGeodesics exact(body.mesh);
    exact_mm_ = exact.Distance(a, b);
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }

  static CommandResult Run(const std::string& args) {
    return testing::RunCommand(std::string("'") + BESPOKE_BINARY + "' -q " + args, dir_->path());
  }
  static std::filesystem::path ScanFile() { return *dir_ / "scan.ply"; }

  static TempDir* dir_;
  static Eigen::Index points_;
  static Eigen::Vector3d from_, to_;
  static double exact_mm_;
};

TempDir* GeodesicCli::dir_ = nullptr;
Eigen::Index GeodesicCli::points_ = 0;
Eigen::Vector3d GeodesicCli::from_, GeodesicCli::to_;
double GeodesicCli::exact_mm_ = 0;

TEST_F(GeodesicCli, PointToPointPrintsTheLengthAndWritesThePathAndReport) {
  TempDir out;
  const CommandResult run =
      Run("geodesic " + Q(ScanFile()) + " --units mm --from " + Xyz(from_) + " --to " + Xyz(to_) +
          " --path-out " + Q(out / "path.ply") + " --report " + Q(out / "report.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  double printed = 0;
  ASSERT_EQ(std::sscanf(run.out.c_str(), "geodesic length: %lf mm", &printed), 1) << run.out;
  // The scan's back length against the exact one on the body mesh: within
  // ISO 20685-1's 5 mm for segment lengths.
  EXPECT_NEAR(printed, exact_mm_, 5.0);

  ReadOptions read;
  read.units = LengthUnit::kMillimetre;
  read.min_finite_points = 0;  // a path, not a body scan
  const Scan path = ReadScan(read, out / "path.ply");
  ASSERT_GE(path.cloud.size(), 10);
  ASSERT_TRUE(path.cloud.scalars.count("arc_length_mm"));
  const Eigen::VectorXd& arc = path.cloud.scalars.at("arc_length_mm");
  EXPECT_NEAR(arc[arc.size() - 1], printed, 0.02 * printed);  // chord sum vs surface length
  EXPECT_LT((path.cloud.points.row(0).transpose() - from_).norm(), 5.0);  // mm, on the surface
  EXPECT_LT((path.cloud.points.bottomRows(1).transpose() - to_).norm(), 5.0);

  const nlohmann::json report = ReadJsonFile(out / "report.json");
  EXPECT_NEAR(report["length_mm"].get<double>(), printed, 0.01);
  EXPECT_EQ(report["points"].get<Eigen::Index>(), points_);
  EXPECT_GT(report["settings"]["cell_size_mm"].get<double>(), 0);
  // The simulated scan has normals (facing the sensors): used only when asked.
  EXPECT_FALSE(report["settings"]["oriented_normals"].get<bool>());
  const CommandResult oriented =
      Run("geodesic " + Q(ScanFile()) + " --units mm --from " + Xyz(from_) + " --to " + Xyz(to_) +
          " --use-normals --report " + Q(out / "oriented.json"));
  ASSERT_EQ(oriented.exit_code, 0) << oriented.err;
  const nlohmann::json oriented_report = ReadJsonFile(out / "oriented.json");
  EXPECT_TRUE(oriented_report["settings"]["oriented_normals"].get<bool>());
  EXPECT_NEAR(oriented_report["length_mm"].get<double>(), exact_mm_, 5.0);
}

TEST_F(GeodesicCli, FieldOutWritesADistancePerScanPoint) {
  TempDir out;
  const CommandResult run = Run("geodesic " + Q(ScanFile()) + " --units mm --from " + Xyz(from_) +
                                " --field-out " + Q(out / "field.ply"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  ReadOptions read;
  read.units = LengthUnit::kMillimetre;
  const Scan field = ReadScan(read, out / "field.ply");
  ASSERT_EQ(field.cloud.size(), points_);
  ASSERT_TRUE(field.cloud.scalars.count("distance_mm"));
  const Eigen::VectorXd& d = field.cloud.scalars.at("distance_mm");
  Eigen::Index reached = 0, near_from = 0, near_to = 0;
  for (Eigen::Index i = 0; i < d.size(); ++i) {
    if (std::isfinite(d[i])) ++reached;
    const Eigen::Vector3d p = field.cloud.points.row(i).transpose();
    if ((p - from_).squaredNorm() <
        (field.cloud.points.row(near_from).transpose() - from_).squaredNorm())
      near_from = i;
    if ((p - to_).squaredNorm() < (field.cloud.points.row(near_to).transpose() - to_).squaredNorm())
      near_to = i;
  }
  EXPECT_GT(reached, 0.95 * static_cast<double>(points_));  // stray islands may stay unreached
  EXPECT_LT(d[near_from], 5.0);                             // mm, at the source
  // At the scan point nearest the back waist: the back length, up to that
  // point's distance from the datum point.
  EXPECT_NEAR(d[near_to], exact_mm_,
              5.0 + (field.cloud.points.row(near_to).transpose() - to_).norm());

  // --cells-only: the grid cells' distances alone (the thesis), said in the report.
  const CommandResult cells =
      Run("geodesic " + Q(ScanFile()) + " --units mm --from " + Xyz(from_) + " --cells-only" +
          " --field-out " + Q(out / "cells.ply") + " --report " + Q(out / "cells.json"));
  ASSERT_EQ(cells.exit_code, 0) << cells.err;
  EXPECT_FALSE(ReadJsonFile(out / "cells.json")["settings"]["point_field"].get<bool>());
  const Eigen::VectorXd cell_d = ReadScan(read, out / "cells.ply").cloud.scalars.at("distance_mm");
  ASSERT_EQ(cell_d.size(), d.size());
  EXPECT_NEAR(cell_d[near_to], exact_mm_,
              5.0 + (field.cloud.points.row(near_to).transpose() - to_).norm());
  Eigen::Index differ = 0;  // a different field
  for (Eigen::Index i = 0; i < d.size(); ++i)
    differ += std::isfinite(d[i]) && std::isfinite(cell_d[i]) && cell_d[i] != d[i];
  EXPECT_GT(differ, 0);
}

TEST_F(GeodesicCli, BadCoordinatesExitOneWithAClearMessageAndNoOutput) {
  TempDir out;
  const std::string base =
      "geodesic " + Q(ScanFile()) + " --units mm --path-out " + Q(out / "p.ply");
  CommandResult run =
      Run(base + " --from " + Xyz(from_ + Eigen::Vector3d(0, 0, 500)) + " --to " + Xyz(to_));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("from the nearest scan point"), std::string::npos) << run.err;
  run = Run(base + " --from nan,1,2 --to " + Xyz(to_));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("--from"), std::string::npos) << run.err;
  run = Run(base + " --from " + Xyz(from_) + " --to 1,2");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("--to must be X,Y,Z"), std::string::npos) << run.err;
  run = Run("geodesic " + Q(ScanFile()) + " --from " + Xyz(from_));  // nothing to compute
  EXPECT_EQ(run.exit_code, 1);
  run = Run("geodesic " + Q(out / "missing.ply") + " --from 1,2,3 --to 4,5,6");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("missing.ply"), std::string::npos) << run.err;
  // --use-normals on a file without normals.
  ReadOptions read;
  read.units = LengthUnit::kMillimetre;
  Scan bare = ReadScan(read, ScanFile());
  bare.cloud.normals.resize(0, 3);
  WriteScan(WriteOptions{}, bare.cloud, out / "bare.ply");
  run = Run("geodesic " + Q(out / "bare.ply") + " --units mm --from " + Xyz(from_) + " --to " +
            Xyz(to_) + " --use-normals --path-out " + Q(out / "p.ply"));
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_NE(run.err.find("bare.ply: --use-normals given but the file has no normals"),
            std::string::npos)
      << run.err;
  EXPECT_FALSE(std::filesystem::exists(out / "p.ply"));
}

TEST_F(GeodesicCli, ValidateComparesCloudAndReconstructedMeshLengths) {
  TempDir out;
  nlohmann::json pairs = {{"pairs", nlohmann::json::array()}};
  pairs["pairs"].push_back({{"name", "back_length"},
                            {"from", {from_.x(), from_.y(), from_.z()}},
                            {"to", {to_.x(), to_.y(), to_.z()}}});
  WriteJsonFile(out / "pairs.json", pairs);
  // A coarse reference (Poisson depth 7, <= 8000 vertices) keeps this quick.
  const CommandResult run =
      Run("validate " + Q(ScanFile()) + " --units mm --pairs " + Q(out / "pairs.json") +
          " --depth 7 --max-mesh-vertices 8000 -o " + Q(out / "validation.json"));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("back_length"), std::string::npos) << run.out;
  const nlohmann::json report = ReadJsonFile(out / "validation.json");
  EXPECT_EQ(report["format"], "bespoke-geodesic-validation");
  ASSERT_EQ(report["compared"].get<int>(), 1) << report.dump(2);
  const nlohmann::json& pair = report["pairs"][0];
  EXPECT_NEAR(pair["cloud_mm"].get<double>(), exact_mm_, 5.0);
  // The Poisson mesh smooths the surface and is coarse: its length is an
  // independent check within 1 % here, not the exact answer.
  EXPECT_LT(std::abs(pair["rel_diff"].get<double>()), 0.01) << pair.dump();
  EXPECT_GT(report["mesh_vertices"].get<int>(), 1000);

  const CommandResult bad =
      Run("validate " + Q(ScanFile()) + " --pairs " + Q(out / "missing.json"));
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.err.find("missing.json"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace bespoke
