#include "oracle/truth/mesh_section.h"

#include <gtest/gtest.h>

#include <cmath>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// A closed cylinder of radius r around the vertical axis through `centre`
// (its base), `sides` vertices per ring, rings every `spacing` mm.
TriangleMesh Cylinder(const Eigen::Vector3d& centre, double r, double height, int sides,
                      int rings) {
  TriangleMesh m;
  const int n = sides * rings;
  m.vertices.resize(n + 2, 3);
  for (int k = 0; k < rings; ++k)
    for (int i = 0; i < sides; ++i) {
      const double a = 2 * M_PI * i / sides;
      m.vertices.row(k * sides + i) =
          (centre + Eigen::Vector3d(r * std::cos(a), r * std::sin(a), height * k / (rings - 1)))
              .transpose();
    }
  m.vertices.row(n) = centre.transpose();
  m.vertices.row(n + 1) = (centre + Eigen::Vector3d(0, 0, height)).transpose();
  std::vector<Eigen::Vector3i> f;
  for (int k = 0; k + 1 < rings; ++k)
    for (int i = 0; i < sides; ++i) {
      const int a = k * sides + i, b = k * sides + (i + 1) % sides;
      f.push_back({a, b, b + sides});
      f.push_back({a, b + sides, a + sides});
    }
  for (int i = 0; i < sides; ++i) {
    f.push_back({n, (i + 1) % sides, i});
    f.push_back({n + 1, (rings - 1) * sides + i, (rings - 1) * sides + (i + 1) % sides});
  }
  m.faces.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t i = 0; i < f.size(); ++i) m.faces.row(i) = f[i].transpose();
  return m;
}

TriangleMesh Concatenate(const std::vector<TriangleMesh>& parts) {
  TriangleMesh out;
  Eigen::Index nv = 0, nf = 0;
  for (const auto& p : parts) nv += p.num_vertices(), nf += p.num_faces();
  out.vertices.resize(nv, 3);
  out.faces.resize(nf, 3);
  nv = nf = 0;
  for (const auto& p : parts) {
    out.vertices.middleRows(nv, p.num_vertices()) = p.vertices;
    out.faces.middleRows(nf, p.num_faces()) = (p.faces.array() + static_cast<int>(nv)).matrix();
    nv += p.num_vertices(), nf += p.num_faces();
  }
  return out;
}

TEST(MeshSection, HorizontalCutOfACylinderIsOnePolygonLoop) {
  const int sides = 64;
  const TriangleMesh m = Cylinder({0, 0, 0}, 150, 600, sides, 13);
  const double polygon = sides * 2 * 150 * std::sin(M_PI / sides);
  for (const double z : {123.4, 250.0 /* exactly a ring of vertices */, 0.5}) {
    const auto loops = SectionLoops(m, {0, 0, z}, {0, 0, 1});
    ASSERT_EQ(loops.size(), 1u) << "z " << z;
    EXPECT_TRUE(loops[0].closed);
    EXPECT_NEAR(LoopHullPerimeter(loops[0], {0, 0, 1}), polygon, 1e-9) << "z " << z;
    EXPECT_NEAR(LoopLength(loops[0]), polygon, 1e-9);
    for (Eigen::Index i = 0; i < loops[0].points.rows(); ++i)
      EXPECT_NEAR(loops[0].points(i, 2), z, 1e-12);
  }
}

TEST(MeshSection, TiltedCutOfACylinderIsAnEllipse) {
  const int sides = 720;
  const double r = 60;
  const TriangleMesh m = Cylinder({0, 0, 0}, r, 400, sides, 41);
  const double tilt = 30 * M_PI / 180;  // normal tilted 30 deg from the axis
  const Eigen::Vector3d normal(std::sin(tilt), 0, std::cos(tilt));
  const auto loops = SectionLoops(m, {0, 0, 200}, normal);
  ASSERT_EQ(loops.size(), 1u);
  // Ellipse with semi-axes r / cos(tilt) and r; perimeter by the arc-length
  // integral (midpoint rule, 1e5 steps).
  const double a = r / std::cos(tilt), b = r;
  double ellipse = 0;
  for (int i = 0; i < 100000; ++i) {
    const double t = 2 * M_PI * (i + 0.5) / 100000;
    ellipse += std::hypot(a * std::sin(t), b * std::cos(t)) * 2 * M_PI / 100000;
  }
  // 720-gon inscribed in the cylinder: the section polygon is short of the
  // ellipse by < 1e-3 relative... in practice by 0.001 mm here.
  EXPECT_NEAR(LoopHullPerimeter(loops[0], normal), ellipse, 0.01);
}

// The hip-section case: a plane at hip height also cuts the hands hanging
// beside the hips. The loop nearest the hip datum point is the trunk only.
TEST(MeshSection, NearestLoopSelectsTheBodyPartNotTheHands) {
  const TriangleMesh trunk = Cylinder({0, 0, 0}, 170, 800, 96, 17);
  const TriangleMesh right_hand = Cylinder({230, 0, 600}, 40, 200, 32, 5);
  const TriangleMesh left_hand = Cylinder({-230, 0, 600}, 40, 200, 32, 5);
  const TriangleMesh m = Concatenate({trunk, right_hand, left_hand});
  const Eigen::Vector3d hip_back(0, -170, 700);
  const auto loops = SectionLoops(m, hip_back, {0, 0, 1});
  ASSERT_EQ(loops.size(), 3u);
  const int hip = NearestLoop(loops, hip_back);
  ASSERT_GE(hip, 0);
  const double trunk_polygon = 96 * 2 * 170 * std::sin(M_PI / 96);
  EXPECT_NEAR(LoopHullPerimeter(loops[hip], {0, 0, 1}), trunk_polygon, 1e-9);
  EXPECT_LT(DistanceToLoop(loops[hip], hip_back), 1e-9);  // a vertex of the 96-gon
  // The hull of everything would be far larger (the hands are 100 mm away).
  Eigen::MatrixX3d all(0, 3);
  for (const auto& loop : loops) {
    all.conservativeResize(all.rows() + loop.points.rows(), 3);
    all.bottomRows(loop.points.rows()) = loop.points;
  }
  EXPECT_GT(LoopHullPerimeter(SectionLoop{all, true}, {0, 0, 1}), trunk_polygon + 100);
}

// A breast the plane cuts apart from the chest wall is part of the trunk's
// girth (a tape passes over it); the arms beside the trunk are not.
TEST(MeshSection, TrunkLoopsTakeALoopInFrontButNotTheArms) {
  const TriangleMesh trunk = Cylinder({0, 0, 0}, 170, 800, 96, 17);
  const TriangleMesh breast = Cylinder({70, 240, 400}, 50, 100, 64, 3);
  const TriangleMesh right_arm = Cylinder({260, 0, 300}, 40, 400, 32, 5);
  const TriangleMesh left_arm = Cylinder({-260, 0, 300}, 40, 400, 32, 5);
  const TriangleMesh m = Concatenate({trunk, right_arm, breast, left_arm});
  const auto loops = SectionLoops(m, {0, 0, 450}, {0, 0, 1});
  ASSERT_EQ(loops.size(), 4u);
  const int main = NearestLoop(loops, {0, -170, 450});
  ASSERT_GE(main, 0);
  const std::vector<int> parts = TrunkLoopIndices(loops, main);
  ASSERT_EQ(parts.size(), 2u);
  EXPECT_EQ(parts[0], main);
  EXPECT_NEAR(loops[parts[1]].points.col(1).mean(), 240, 1);  // the breast
  // Its hull: the trunk's 96-gon wrapped round the breast's 64-gon, longer
  // than the trunk's alone and shorter than the two perimeters together.
  const double trunk_polygon = 96 * 2 * 170 * std::sin(M_PI / 96);
  const double merged = LoopHullPerimeter(MergedLoops(loops, parts), {0, 0, 1});
  EXPECT_GT(merged, trunk_polygon + 20);
  EXPECT_LT(merged, trunk_polygon + 64 * 2 * 50 * std::sin(M_PI / 64));
  EXPECT_TRUE(TrunkLoopIndices(loops, 7).empty());
}

TEST(MeshSection, OpenMeshesGiveOpenChainsAndMissesGiveNothing) {
  TriangleMesh m = Cylinder({0, 0, 0}, 50, 100, 16, 3);
  // Drop the top cap's faces and 2 side faces: the mid-height cut opens.
  m.faces.conservativeResize(m.num_faces() - 16, 3);
  m.faces.row(20) = m.faces.row(m.num_faces() - 1);
  m.faces.row(21) = m.faces.row(m.num_faces() - 2);
  m.faces.conservativeResize(m.num_faces() - 2, 3);
  const auto loops = SectionLoops(m, {0, 0, 25}, {0, 0, 1});
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_FALSE(loops[0].closed);
  EXPECT_TRUE(SectionLoops(m, {0, 0, 500}, {0, 0, 1}).empty());
  EXPECT_EQ(NearestLoop({}, {0, 0, 0}), -1);
  EXPECT_THROW(SectionLoops(m, {0, 0, 0}, {0, 0, 0}), InputError);
}

}  // namespace
}  // namespace bespoke
