// `bespoke mesh-geodesic` as a user runs it: a separate process on mesh files.
// A sphere gives great-circle lengths with every algorithm and writes its
// outputs; bad meshes and bad options give exit code 1 naming the problem.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "scanners/io/scan_io.h"
#include "tests/support/run_command.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_support.h"

#ifndef BESPOKE_BINARY
#error "BESPOKE_BINARY (the bespoke executable) must be defined by CMake"
#endif

namespace bespoke {
namespace {

using ::testing::HasSubstr;
using testing::TempDir;

testing::CommandResult MeshGeodesic(const TempDir& dir, const std::string& args) {
  return testing::RunCommand(std::string("'") + BESPOKE_BINARY + "' mesh-geodesic " + args,
                             dir.path());
}

std::string Q(const std::filesystem::path& file) { return testing::Quote(file); }

class MeshGeodesicCli : public ::testing::Test {
 protected:
  void SetUp() override {
    sphere_ = testing::Icosphere(100, 3);  // 642 vertices, radius 100 mm
    WriteMesh(WriteOptions{}, sphere_, dir_ / "sphere.off");
  }
  double GreatCircle(int a, int b) const {
    const Eigen::Vector3d p = sphere_.vertices.row(a).normalized(),
                          q = sphere_.vertices.row(b).normalized();
    return 100 * std::acos(std::clamp(p.dot(q), -1.0, 1.0));
  }
  TempDir dir_;
  TriangleMesh sphere_;
};

TEST_F(MeshGeodesicCli, SphereLengthsPathAndFieldForEveryAlgorithm) {
  const double expected = GreatCircle(0, 300);
  for (const std::string algorithm : {"approx", "accurate", "exact"}) {
    SCOPED_TRACE(algorithm);
    const auto report = dir_ / (algorithm + ".json");
    const auto field = dir_ / (algorithm + "_field.ply");
    const auto path = dir_ / (algorithm + "_path.ply");
    const auto run =
        MeshGeodesic(dir_, Q(dir_ / "sphere.off") + " --units mm --source 0 --target 300" +
                               " --algorithm " + algorithm + " --field-out " + Q(field) +
                               " --path-out " + Q(path) + " --report " + Q(report));
    ASSERT_EQ(run.exit_code, 0) << run.err;
    EXPECT_THAT(run.out, HasSubstr("geodesic length"));
    EXPECT_THAT(run.out, HasSubstr("642 of 642 vertices reached"));
    const auto json = nlohmann::json::parse(testing::ReadText(report));
    const double length =
        algorithm == "exact" ? json["offset_mm"].get<double>() : json["projected_mm"].get<double>();
    EXPECT_NEAR(length, expected, 0.01 * expected);  // the inscribed mesh is a little shorter
    ReadOptions read;
    read.min_finite_points = 0;
    read.units = LengthUnit::kMillimetre;
    const Scan f = ReadScan(read, field);
    ASSERT_EQ(f.cloud.size(), 642);
    ASSERT_TRUE(f.cloud.scalars.count("distance_mm"));
    EXPECT_EQ(f.cloud.scalars.at("distance_mm")[0], 0);
    const Scan p = ReadScan(read, path);
    ASSERT_GE(p.cloud.size(), 2);
    EXPECT_NEAR(p.cloud.scalars.at("arc_length_mm").maxCoeff(), length, 0.02 * length);
  }
}

TEST_F(MeshGeodesicCli, BadMeshesAndOptionsExitOne) {
  // A non-manifold edge: a third face on the edge (0, 1) of the sphere.
  TriangleMesh fin = sphere_;
  fin.vertices.conservativeResize(fin.num_vertices() + 1, 3);
  fin.vertices.bottomRows(1) << 0, 0, 300;
  fin.faces.conservativeResize(fin.num_faces() + 1, 3);
  const int a = fin.faces(0, 0), b = fin.faces(0, 1);
  fin.faces.bottomRows(1) << a, b, static_cast<int>(fin.num_vertices() - 1);
  WriteMesh(WriteOptions{}, fin, dir_ / "fin.off");
  auto run = MeshGeodesic(dir_, Q(dir_ / "fin.off") + " --source 0 --target 5");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr((dir_ / "fin.off").string() + ": non-manifold edge"));
  // A truncated file.
  std::ofstream(dir_ / "broken.off") << "OFF\n10 10 0\n0 0 0\n";
  run = MeshGeodesic(dir_, Q(dir_ / "broken.off") + " --source 0 --target 5");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("broken.off"));
  // Bad options.
  run = MeshGeodesic(dir_, Q(dir_ / "sphere.off") + " --source 0 --target 5 --algorithm fast");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("--algorithm must be approx, accurate or exact"));
  run = MeshGeodesic(dir_, Q(dir_ / "sphere.off") + " --source 9999 --target 5");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("sphere.off: --source 9999 is out of range"));
  run = MeshGeodesic(dir_, Q(dir_ / "sphere.off") + " --source 0");
  EXPECT_EQ(run.exit_code, 1);
  EXPECT_THAT(run.err, HasSubstr("--target"));
}

TEST_F(MeshGeodesicCli, TargetOnAnotherComponentIsUnreachable) {
  TriangleMesh two = sphere_;
  const auto n = static_cast<int>(sphere_.num_vertices());
  two.vertices.conservativeResize(2 * n, 3);
  two.vertices.bottomRows(n) = sphere_.vertices.rowwise() + Eigen::RowVector3d(500, 0, 0);
  two.faces.conservativeResize(2 * sphere_.num_faces(), 3);
  two.faces.bottomRows(sphere_.num_faces()) = sphere_.faces.array() + n;
  WriteMesh(WriteOptions{}, two, dir_ / "two.off");
  const auto run = MeshGeodesic(
      dir_, Q(dir_ / "two.off") + " --units mm --source 0 --target " + std::to_string(n + 3));
  EXPECT_EQ(run.exit_code, 1) << run.err;
  EXPECT_THAT(run.err, HasSubstr("cannot be reached"));
  EXPECT_THAT(run.err, HasSubstr("2 connected components"));
}

}  // namespace
}  // namespace bespoke
