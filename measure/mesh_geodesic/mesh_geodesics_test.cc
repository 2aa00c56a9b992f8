// Algorithms 1-3 against known geodesics: a flat grid (straight lines), an
// open prism tube (straight on the unrolled strip: exact polyhedral answers),
// a sphere (great circles; CGAL exact on the same mesh) and, when ../shared is
// there, the 13k MakeHuman body against CGAL exact.
#include "measure/mesh_geodesic/mesh_geodesics.h"

#include <gtest/gtest.h>

#include <cmath>

#include "measure/mesh_geodesic/path_projection.h"
#include "oracle/truth/exact_geodesics.h"
#include "scanners/core/errors.h"
#include "scanners/io/scan_io.h"
#include "tests/support/test_meshes.h"
#include "tests/support/test_support.h"

namespace bespoke {
namespace {

struct Errors {
  double mean_offset = 0, max_offset = 0, mean_projected = 0, max_projected = 0;
  int counted = 0;
};

// Relative errors over the vertices whose reference distance is >= floor.
template <typename Reference>
Errors Compare(const MeshGeodesics& g, int n, double floor, Reference reference) {
  Errors e;
  for (int v = 0; v < n; ++v) {
    const double d = reference(v);
    if (!(d >= floor)) continue;
    EXPECT_TRUE(g.settled(v)) << v;
    const double off = std::abs(g.offset_distance(v) - d) / d;
    const double proj = std::abs(g.projected_distance(v) - d) / d;
    e.mean_offset += off;
    e.mean_projected += proj;
    e.max_offset = std::max(e.max_offset, off);
    e.max_projected = std::max(e.max_projected, proj);
    ++e.counted;
  }
  e.mean_offset /= std::max(1, e.counted);
  e.mean_projected /= std::max(1, e.counted);
  return e;
}

MeshGeodesics Solve(const MeshSurface& surface, int source, bool accurate, bool keep = false) {
  MeshGeodesicsOptions options;
  options.wavefront.whole_path = accurate;
  options.keep_paths = keep;
  MeshGeodesics g(options, surface, source);
  g.Run();
  return g;
}

TEST(MeshGeodesics, FlatGridGivesStraightLines) {
  const TriangleMesh grid = testing::FlatGrid(30, 30, 5, 0.25);
  const MeshSurface surface(MeshPrepOptions{}, grid, "grid");
  const int source = 15 * 30 + 15;
  for (const bool accurate : {false, true}) {
    const MeshGeodesics g = Solve(surface, source, accurate);
    const Eigen::Vector3d s = surface.position(source);
    const Errors e = Compare(g, surface.num_vertices(), 10,
                             [&](int v) { return (surface.position(v) - s).norm(); });
    EXPECT_LT(e.mean_offset, 0.001) << "accurate " << accurate;
    EXPECT_LT(e.max_offset, 0.02) << "accurate " << accurate;
    EXPECT_LT(e.mean_projected, 0.001) << "accurate " << accurate;
  }
}

TEST(MeshGeodesics, TubeMatchesTheUnrolledPrism) {
  const double r = 50, h = 300;
  const int around = 48, rings = 60;
  const TriangleMesh tube = testing::Tube(r, h, around, rings);
  const MeshSurface surface(MeshPrepOptions{}, tube, "tube");
  const int source = 5 * around;  // ring 5, angle 0
  auto exact = [&](int v) { return testing::TubeDistance(r, h, around, rings, source, v); };
  const Errors approx = Compare(Solve(surface, source, false), surface.num_vertices(), 30, exact);
  const Errors accurate = Compare(Solve(surface, source, true), surface.num_vertices(), 30, exact);
  EXPECT_LT(approx.mean_projected, 0.005);
  EXPECT_LT(accurate.mean_projected, 0.002);
  EXPECT_LT(approx.mean_offset, 0.005);
  EXPECT_LT(accurate.mean_offset, 0.005);
}

TEST(MeshGeodesics, SphereAgainstCgalExactAndGreatCircles) {
  const double radius = 100;
  const TriangleMesh sphere = testing::Icosphere(radius, 4);  // 2562 vertices
  const MeshSurface surface(MeshPrepOptions{}, sphere, "sphere");
  ExactGeodesics exact(sphere);
  const Eigen::VectorXd truth = exact.DistancesToVertices(exact.AtVertex(0));
  const double floor = 5 * surface.mean_edge_length();
  const MeshGeodesics approx = Solve(surface, 0, false);
  const MeshGeodesics accurate = Solve(surface, 0, true);
  const Errors a = Compare(approx, surface.num_vertices(), floor, [&](int v) { return truth[v]; });
  const Errors b =
      Compare(accurate, surface.num_vertices(), floor, [&](int v) { return truth[v]; });
  EXPECT_LT(a.mean_projected, 0.005);
  EXPECT_LT(b.mean_projected, 0.002);
  EXPECT_LT(a.mean_offset, 0.005);
  // The smooth sphere's great circles bound the polyhedral answer from above.
  const Eigen::Vector3d s = surface.position(0).normalized();
  const Errors smooth = Compare(accurate, surface.num_vertices(), floor, [&](int v) {
    return radius * std::acos(std::clamp(s.dot(surface.position(v).normalized()), -1.0, 1.0));
  });
  EXPECT_LT(smooth.mean_offset, 0.01);
  // Eq 3.24 estimate: finite and >= 0 for Algorithm 3, 0 for Algorithm 2.
  for (int v = 0; v < surface.num_vertices(); ++v) {
    EXPECT_GE(approx.error_bound(v), 0);
    EXPECT_TRUE(std::isfinite(approx.error_bound(v)));
    EXPECT_EQ(accurate.error_bound(v), 0);
  }
}

TEST(MeshGeodesics, PathsRebuildAndProjectOntoTheFaces) {
  const TriangleMesh sphere = testing::Icosphere(100, 3);
  const MeshSurface surface(MeshPrepOptions{}, sphere, "sphere");
  const MeshGeodesics g = Solve(surface, 0, false, /*keep=*/true);
  const int target = 300;
  std::vector<int> hints;
  const Eigen::MatrixX3d path = g.Path(target, &hints);
  ASSERT_GE(path.rows(), 3);
  EXPECT_TRUE(path.row(0).isApprox(surface.position(0).transpose()));
  EXPECT_TRUE(path.bottomRows(1).isApprox(surface.position(target).transpose()));
  EXPECT_NEAR(PolylineLength(path), g.offset_distance(target), 1e-6);
  const ProjectedPath projected = ProjectPolyline(surface, path, &hints, nullptr, true);
  EXPECT_NEAR(projected.length, g.projected_distance(target), 1e-6 * projected.length + 1e-9);
  EXPECT_LE(projected.fallbacks, path.rows() / 10);  // chords where a walk fails
  // Every point of the projected path lies on the inscribed faces: inside the
  // sphere, no deeper than the faces' sagitta.
  for (Eigen::Index i = 0; i < projected.points.rows(); ++i) {
    EXPECT_LE(projected.points.row(i).norm(), 100 + 1e-9);
    EXPECT_GE(projected.points.row(i).norm(), 97);
  }
  const MeshGeodesics no_paths = Solve(surface, 0, false);
  EXPECT_THROW(no_paths.Path(target), InputError);
}

TEST(MeshGeodesics, RejectsBadOptionsAndSources) {
  const MeshSurface surface(MeshPrepOptions{}, testing::FlatGrid(4, 4, 1, 0), "grid");
  MeshGeodesicsOptions options;
  options.wavefront.window = 2;
  EXPECT_THROW(MeshGeodesics(options, surface, 0), InputError);
  EXPECT_THROW(MeshGeodesics(MeshGeodesicsOptions{}, surface, 16), InputError);
  EXPECT_THROW(MeshGeodesics(MeshGeodesicsOptions{}, surface, -1), InputError);
}

TEST(MeshGeodesics, MakeHumanBodyAgainstCgalExact) {
  BESPOKE_REQUIRE_SHARED(shared);
  const Mesh body = ReadMesh(ReadOptions{}, shared / "data/meshes/makehuman-body-tri-13k.off");
  const MeshSurface surface(MeshPrepOptions{}, body.mesh, "body");
  ExactGeodesics exact(body.mesh);
  const Eigen::VectorXd truth = exact.DistancesToVertices(exact.AtVertex(0));
  const double floor = 5 * surface.mean_edge_length();
  const Errors a = Compare(Solve(surface, 0, false), surface.num_vertices(), floor,
                           [&](int v) { return truth[v]; });
  RecordProperty("alg3_mean_rel_offset", std::to_string(a.mean_offset));
  RecordProperty("alg3_mean_rel_projected", std::to_string(a.mean_projected));
  EXPECT_LT(a.mean_projected, 0.01);
  EXPECT_LT(a.mean_offset, 0.01);
}

}  // namespace
}  // namespace bespoke
