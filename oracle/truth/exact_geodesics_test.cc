#include "oracle/truth/exact_geodesics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "scanners/core/errors.h"
#include "tests/support/test_meshes.h"

namespace bespoke {
namespace {

using testing::Icosphere;

// A cylinder of radius r around the z axis, z in [0, height], `sides`
// vertices per ring and `rings` rings; closed by two fan caps unless `open`.
TriangleMesh Cylinder(double r, double height, int sides, int rings, bool open = false) {
  TriangleMesh mesh;
  const int ring_vertices = sides * rings;
  mesh.vertices.resize(ring_vertices + (open ? 0 : 2), 3);
  for (int k = 0; k < rings; ++k)
    for (int i = 0; i < sides; ++i) {
      const double a = 2 * M_PI * i / sides;
      mesh.vertices.row(k * sides + i) << r * std::cos(a), r * std::sin(a),
          height * k / (rings - 1);
    }
  std::vector<Eigen::Vector3i> f;
  for (int k = 0; k + 1 < rings; ++k)
    for (int i = 0; i < sides; ++i) {
      const int a = k * sides + i, b = k * sides + (i + 1) % sides;
      f.push_back({a, b, b + sides});
      f.push_back({a, b + sides, a + sides});
    }
  if (!open) {
    const int bottom = ring_vertices, top = ring_vertices + 1;
    mesh.vertices.row(bottom) << 0, 0, 0;
    mesh.vertices.row(top) << 0, 0, height;
    for (int i = 0; i < sides; ++i) {
      f.push_back({bottom, (i + 1) % sides, i});
      f.push_back({top, (rings - 1) * sides + i, (rings - 1) * sides + (i + 1) % sides});
    }
  }
  mesh.faces.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t i = 0; i < f.size(); ++i) mesh.faces.row(i) = f[i].transpose();
  return mesh;
}

int NearestVertex(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  Eigen::Index best = 0;
  (mesh.vertices.rowwise() - p.transpose()).rowwise().squaredNorm().minCoeff(&best);
  return static_cast<int>(best);
}

TEST(ExactGeodesics, SphereGreatCirclesWithinPointOnePercent) {
  const double r = 100;                       // mm
  const TriangleMesh mesh = Icosphere(r, 5);  // 10,242 vertices
  ExactGeodesics geodesics(mesh);
  const int from = NearestVertex(mesh, {0, 0, r});
  const Eigen::Vector3d a = mesh.vertices.row(from).transpose();
  for (const Eigen::Vector3d& dir :
       {Eigen::Vector3d(1, 0, 0.2), Eigen::Vector3d(0.3, 1, -0.5), Eigen::Vector3d(-1, 0.4, -1.5),
        Eigen::Vector3d(0.1, 0.2, -1)}) {
    const int to = NearestVertex(mesh, r * dir.normalized());
    const Eigen::Vector3d b = mesh.vertices.row(to).transpose();
    const double analytic = r * std::acos(std::clamp(a.dot(b) / (r * r), -1.0, 1.0));
    const GeodesicPath path = geodesics.Path(geodesics.AtVertex(from), geodesics.AtVertex(to));
    EXPECT_NEAR(path.length, analytic, 1e-3 * analytic) << "to vertex " << to;
    // The polyline runs from `from` to `to`, and its length is the distance.
    EXPECT_LT((path.points.row(0).transpose() - a).norm(), 1e-9);
    EXPECT_LT((path.points.bottomRows<1>().transpose() - b).norm(), 1e-9);
    double polyline = 0;
    for (Eigen::Index i = 0; i + 1 < path.points.rows(); ++i)
      polyline += (path.points.row(i + 1) - path.points.row(i)).norm();
    EXPECT_NEAR(polyline, path.length, 1e-6 * analytic);
    // Every polyline point lies on the mesh surface.
    for (Eigen::Index i = 0; i < path.points.rows(); ++i) {
      const Eigen::Vector3d q = path.points.row(i).transpose();
      EXPECT_LT((PositionOf(mesh, geodesics.Locate(q)) - q).norm(), 1e-9);
    }
  }
}

TEST(ExactGeodesics, DistancesToVerticesMatchGreatCircles) {
  const double r = 50;
  const TriangleMesh mesh = Icosphere(r, 4);
  ExactGeodesics geodesics(mesh);
  const Eigen::VectorXd d = geodesics.DistancesToVertices(geodesics.AtVertex(0));
  const Eigen::Vector3d a = mesh.vertices.row(0).transpose();
  for (Eigen::Index v = 0; v < mesh.num_vertices(); v += 97) {
    const Eigen::Vector3d b = mesh.vertices.row(v).transpose();
    const double analytic = r * std::acos(std::clamp(a.dot(b) / (r * r), -1.0, 1.0));
    // Level 4: edges of ~3.8 mm on r = 50 mm; chords make the polyhedron
    // shorter than the sphere by < 0.5 %.
    EXPECT_NEAR(d[v], analytic, 5e-3 * analytic + 1e-9) << "vertex " << v;
    EXPECT_LE(d[v], analytic + 1e-9);
  }
  EXPECT_EQ(d[0], 0.0);
}

TEST(ExactGeodesics, CylinderHelixMatchesUnrolledRectangle) {
  const double r = 60, height = 400;
  // 96 sides, 21 rings: triangles of 3.9 x 20 mm. (Skinnier triangles make
  // CGAL slower and less exact: with 256 sides and 41 rings, 1.5 x 10 mm, its
  // floating-point unfolding drifted by up to 1.6e-5 relative.)
  const int sides = 96, rings = 21;
  const TriangleMesh mesh = Cylinder(r, height, sides, rings);
  ExactGeodesics geodesics(mesh);
  // From (r, 0, 50) a quarter-to-almost-half turn around and up the side.
  const int start_ring = 5;
  for (const auto& [turn_sides, up_rings] :
       std::vector<std::pair<int, int>>{{24, 10}, {45, 5}, {11, 14}}) {
    const int from = start_ring * sides, to = (start_ring + up_rings) * sides + turn_sides;
    const double rise = height * up_rings / (rings - 1);
    // Smooth cylinder: the helix is the hypotenuse of the unrolled rectangle.
    const double smooth = std::hypot(r * 2 * M_PI * turn_sides / sides, rise);
    // The polygonal cylinder unrolls exactly (developable): arc -> chords.
    const double chord = 2 * r * std::sin(M_PI / sides);
    const double polygonal = std::hypot(turn_sides * chord, rise);
    const double d = geodesics.Distance(geodesics.AtVertex(from), geodesics.AtVertex(to));
    EXPECT_NEAR(d, smooth, 1e-3 * smooth);
    EXPECT_NEAR(d, polygonal, 1e-9 * polygonal);
    EXPECT_NEAR(geodesics.Distance(geodesics.AtVertex(to), geodesics.AtVertex(from)), polygonal,
                1e-9 * polygonal);
  }
}

TEST(ExactGeodesics, LocateSnapsToTheSurfaceAndOpenMeshesWork) {
  const TriangleMesh mesh = Cylinder(10, 100, 64, 11, /*open=*/true);
  ExactGeodesics geodesics(mesh);
  const SurfacePoint p = geodesics.Locate({20, 0, 50});  // outside the tube
  EXPECT_NEAR(PositionOf(mesh, p).x(), 10, 1e-9);
  EXPECT_NEAR(PositionOf(mesh, p).z(), 50, 1e-9);
  EXPECT_NEAR(p.barycentric.sum(), 1, 1e-12);
  // Straight up the side between snapped points: 40 mm.
  EXPECT_NEAR(geodesics.Distance(Eigen::Vector3d(12, 0, 30), Eigen::Vector3d(11, 0, 70)), 40, 1e-9);
  // Same source twice (reuses the tree), then the reverse direction.
  const SurfacePoint q = geodesics.Locate({0, -10, 10});
  const double pq = geodesics.Distance(p, q);
  EXPECT_NEAR(geodesics.Distance(p, q), pq, 1e-12);
  EXPECT_NEAR(geodesics.Distance(q, p), pq, 1e-9);
}

// CGAL 5.5 roots a source lying on an edge wrongly (52.4 mm instead of 43.0
// here before the workaround in ToCgal); the distance must not depend on
// which end is the source.
TEST(ExactGeodesics, SourcesOnEdgesAndNearVerticesAreExact) {
  const TriangleMesh mesh = Cylinder(10, 100, 64, 11);
  ExactGeodesics geodesics(mesh);
  const SurfacePoint p = geodesics.AtVertex(5 * 64);  // (10, 0, 50)
  SurfacePoint q = geodesics.AtVertex(64 + 48);       // (0, -10, 10)
  const int corner = q.barycentric[0] == 1 ? 0 : q.barycentric[1] == 1 ? 1 : 2;
  for (const double t : {1e-14, 1e-9, 1e-6, 1e-2, 0.3}) {
    for (const int other : {(corner + 1) % 3, (corner + 2) % 3}) {
      SurfacePoint e = q;  // on the edge from the corner towards `other`
      e.barycentric.setZero();
      e.barycentric[corner] = 1 - t;
      e.barycentric[other] = t;
      const double forward = geodesics.Distance(p, e), backward = geodesics.Distance(e, p);
      EXPECT_NEAR(backward, forward, 1e-6) << "t " << t << " towards " << other;
      // The helix on the unrolled smooth cylinder, within 0.1 mm (the
      // 64-gon's chords are up to 0.012 mm inside the circle).
      const Eigen::Vector3d a = PositionOf(mesh, p), b = PositionOf(mesh, e);
      const double turn = std::abs(std::atan2(b.y(), b.x()) - std::atan2(a.y(), a.x()));
      EXPECT_NEAR(forward, std::hypot(10 * turn, b.z() - a.z()), 0.1);
    }
  }
}

TEST(ExactGeodesics, UnreachableAndBadPointsAreInputErrors) {
  TriangleMesh two = Cylinder(10, 50, 16, 3);
  TriangleMesh moved = two;
  moved.vertices.col(0).array() += 100;
  TriangleMesh both;
  both.vertices.resize(2 * two.num_vertices(), 3);
  both.vertices << two.vertices, moved.vertices;
  both.faces.resize(2 * two.num_faces(), 3);
  both.faces << two.faces, (two.faces.array() + static_cast<int>(two.num_vertices())).matrix();
  ExactGeodesics geodesics(both);
  EXPECT_THROW(geodesics.Distance(Eigen::Vector3d(10, 0, 20), Eigen::Vector3d(110, 0, 20)),
               InputError);
  const Eigen::VectorXd d = geodesics.DistancesToVertices(geodesics.AtVertex(0));
  EXPECT_TRUE(std::isinf(d[two.num_vertices()]));
  SurfacePoint bad;
  bad.face = static_cast<int>(both.num_faces());
  EXPECT_THROW(geodesics.Distance(bad, geodesics.AtVertex(0)), InputError);
  bad.face = 0;
  bad.barycentric << 0.5, 0.2, 0.1;
  EXPECT_THROW(geodesics.Distance(bad, geodesics.AtVertex(0)), InputError);
}

TEST(ExactGeodesics, RejectsMeshesCgalCannotTake) {
  TriangleMesh fin = Cylinder(10, 50, 16, 3);
  // A third face on the interior edge (0, 1) with the same orientation:
  // an edge shared by more than two faces.
  fin.vertices.conservativeResize(fin.num_vertices() + 1, 3);
  fin.vertices.bottomRows<1>() << 30, 0, 10;
  fin.faces.conservativeResize(fin.num_faces() + 1, 3);
  fin.faces.bottomRows<1>() << 0, 1, static_cast<int>(fin.num_vertices()) - 1;
  EXPECT_THROW(ExactGeodesics{fin}, InputError);

  TriangleMesh flipped = Cylinder(10, 50, 16, 3);
  flipped.faces.row(3) = flipped.faces.row(3).reverse().eval();
  EXPECT_THROW(ExactGeodesics{flipped}, InputError);

  TriangleMesh degenerate = Cylinder(10, 50, 16, 3);
  degenerate.faces(5, 2) = degenerate.faces(5, 1);
  EXPECT_THROW(ExactGeodesics{degenerate}, InputError);

  TriangleMesh collinear = Cylinder(10, 50, 16, 3);
  collinear.vertices.row(collinear.faces(0, 2)) =
      0.5 * (collinear.vertices.row(collinear.faces(0, 0)) +
             collinear.vertices.row(collinear.faces(0, 1)));
  EXPECT_THROW(ExactGeodesics{collinear}, InputError);

  // Two triangles sharing only vertex 0: a non-manifold vertex (two fans).
  TriangleMesh bowtie;
  bowtie.vertices.resize(5, 3);
  bowtie.vertices << 0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0;
  bowtie.faces.resize(2, 3);
  bowtie.faces << 0, 1, 2, 0, 3, 4;
  EXPECT_THROW(ExactGeodesics{bowtie}, InputError);

  EXPECT_THROW(ExactGeodesics{TriangleMesh{}}, InputError);
}

}  // namespace
}  // namespace bespoke
