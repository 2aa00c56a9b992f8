// Mesh preparation: every kind of bad mesh is either rejected
// with an InputError naming the mesh and the problem, or handled as
// documented in mesh_surface.h; nothing crashes.
#include "measure/mesh_geodesic/mesh_surface.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "measure/mesh_geodesic/mesh_geodesics.h"
#include "scanners/core/errors.h"
#include "tests/support/test_meshes.h"

namespace bespoke {
namespace {

using ::testing::HasSubstr;

TriangleMesh Append(const TriangleMesh& a, const TriangleMesh& b, const Eigen::Vector3d& shift) {
  TriangleMesh out;
  out.vertices.resize(a.num_vertices() + b.num_vertices(), 3);
  out.vertices << a.vertices, b.vertices.rowwise() + shift.transpose();
  out.faces.resize(a.num_faces() + b.num_faces(), 3);
  out.faces << a.faces, (b.faces.array() + static_cast<int>(a.num_vertices())).matrix();
  return out;
}

std::string ErrorOf(const TriangleMesh& mesh) {
  try {
    MeshSurface surface(MeshPrepOptions{}, mesh, "bad.off");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshSurface, RejectsNonManifoldEdgeNamingFileAndEdge) {
  TriangleMesh mesh = testing::FlatGrid(4, 4, 10, 0);
  // A third face on the inner edge (0, 5): a fin sticking up.
  mesh.vertices.conservativeResize(mesh.num_vertices() + 1, 3);
  mesh.vertices.bottomRows(1) << 5, 5, 10;
  mesh.faces.conservativeResize(mesh.num_faces() + 1, 3);
  mesh.faces.bottomRows(1) << 0, 5, static_cast<int>(mesh.num_vertices() - 1);
  const std::string error = ErrorOf(mesh);
  EXPECT_THAT(error, HasSubstr("bad.off: non-manifold edge between vertices 0 and 5"));
  EXPECT_THAT(error, HasSubstr("3 faces"));
}

TEST(MeshSurface, RejectsEmptyAndAllDegenerateMeshes) {
  TriangleMesh empty;
  empty.vertices = Eigen::MatrixX3d::Zero(3, 3);
  empty.faces.resize(0, 3);
  EXPECT_THAT(ErrorOf(empty), HasSubstr("bad.off: the mesh has no faces"));
  TriangleMesh flat;
  flat.vertices.resize(3, 3);
  flat.vertices << 0, 0, 0, 1, 0, 0, 2, 0, 0;  // collinear
  flat.faces.resize(1, 3);
  flat.faces << 0, 1, 2;
  EXPECT_THAT(ErrorOf(flat), HasSubstr("every face is degenerate"));
  TriangleMesh out_of_range = testing::FlatGrid(3, 3, 1, 0);
  out_of_range.faces(0, 2) = 99;
  EXPECT_THAT(ErrorOf(out_of_range), HasSubstr("refers to vertex 99"));
  TriangleMesh nan = testing::FlatGrid(3, 3, 1, 0);
  nan.vertices(4, 1) = NAN;
  EXPECT_THAT(ErrorOf(nan), HasSubstr("not finite"));
}

TEST(MeshSurface, DropsDegenerateFacesAndKeepsDistances) {
  const TriangleMesh grid = testing::FlatGrid(12, 12, 10, 0);
  TriangleMesh mesh = grid;
  mesh.faces.conservativeResize(mesh.num_faces() + 2, 3);
  mesh.faces.row(mesh.num_faces() - 2) << 5, 5, 6;  // repeated vertex
  mesh.faces.row(mesh.num_faces() - 1) << 0, 1, 2;  // zero area (collinear)
  const MeshSurface surface(MeshPrepOptions{}, mesh, "m");
  EXPECT_EQ(surface.report().dropped_faces, 2);
  EXPECT_EQ(surface.mesh().num_faces(), grid.num_faces());
  ASSERT_FALSE(surface.report().warnings.empty());
  MeshGeodesics geodesics(MeshGeodesicsOptions{}, surface, 0);
  geodesics.Run();
  const int far = 143;  // (11, 11)
  EXPECT_NEAR(geodesics.offset_distance(far), std::hypot(110.0, 110.0), 0.01);
}

TEST(MeshSurface, UnreferencedVerticesAndOtherComponentsAreUnreachable) {
  TriangleMesh mesh =
      Append(testing::FlatGrid(6, 6, 10, 0), testing::FlatGrid(5, 5, 10, 0), {200, 0, 0});
  mesh.vertices.conservativeResize(mesh.num_vertices() + 1, 3);
  mesh.vertices.bottomRows(1) << 0, 0, 50;  // used by no face
  const MeshSurface surface(MeshPrepOptions{}, mesh, "m");
  EXPECT_EQ(surface.report().components, 2);
  EXPECT_EQ(surface.report().unreferenced_vertices, 1);
  EXPECT_FALSE(surface.used(static_cast<int>(mesh.num_vertices() - 1)));
  MeshGeodesics geodesics(MeshGeodesicsOptions{}, surface, 0);
  geodesics.Run();
  EXPECT_TRUE(std::isfinite(geodesics.offset_distance(35)));
  for (int v = 36; v < mesh.num_vertices(); ++v) EXPECT_FALSE(geodesics.settled(v)) << v;
  try {
    MeshGeodesics bad(MeshGeodesicsOptions{}, surface, static_cast<int>(mesh.num_vertices() - 1));
    ADD_FAILURE() << "an unused source must be rejected";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("m: source vertex 61 is used by no face"));
  }
}

TEST(MeshSurface, HandlesBowTieVerticesAndFlippedFaces) {
  // Two grids touching at one corner vertex: a bow tie.
  TriangleMesh a = testing::FlatGrid(5, 5, 10, 0), b = testing::FlatGrid(5, 5, 10, 0);
  TriangleMesh mesh = Append(a, b, {40, 40, 0});
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.faces(f, k) == 25) mesh.faces(f, k) = 24;  // b's corner (0,0) is a's (4,4)
  mesh.faces.row(3).reverseInPlace();                     // a flipped face
  const MeshSurface surface(MeshPrepOptions{}, mesh, "m");
  EXPECT_EQ(surface.report().non_manifold_vertices, 1);
  EXPECT_GT(surface.report().misoriented_edges, 0);
  EXPECT_EQ(surface.report().components, 1);
  MeshGeodesics geodesics(MeshGeodesicsOptions{}, surface, 0);
  geodesics.Run();
  // Through the bow tie: corner to corner is a straight diagonal of 80 * sqrt 2.
  EXPECT_NEAR(geodesics.offset_distance(25 + 24), std::hypot(80.0, 80.0), 0.01);
  EXPECT_NEAR(geodesics.projected_distance(25 + 24), std::hypot(80.0, 80.0), 0.01);
}

TEST(MeshSurface, PcaNormalsAreRadialOnASphere) {
  const TriangleMesh sphere = testing::Icosphere(100, 3);
  const MeshSurface surface(MeshPrepOptions{}, sphere, "sphere");
  double worst = 1;
  for (int v = 0; v < surface.num_vertices(); ++v)
    worst = std::min(worst, surface.normal(v).dot(surface.position(v).normalized()));
  EXPECT_GT(worst, 0.9999);
  int hint = 0;
  TangentPlane plane;
  const Eigen::Vector3d x = Eigen::Vector3d(1, 2, 3).normalized() * 101;
  ASSERT_TRUE(surface.PlaneAt(x, &hint, &plane));
  EXPECT_NEAR(plane.point.norm(), 100, 0.5);           // on the faces
  EXPECT_GT(plane.normal.dot(x.normalized()), 0.999);  // radial
}

}  // namespace
}  // namespace bespoke
