// The detector's surface graph on shapes with a known answer: two skins that
// touch are not linked, one bent tube is one piece, and distances follow the
// surface.
#include "measure/landmarks/body_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace bespoke::landmarks {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Points and outward normals of a vertical cylinder of `radius` around
// (cx, cy), from z0 to z1, every `step` mm.
void Cylinder(double cx, double cy, double radius, double z0, double z1, double step,
              std::vector<Eigen::Vector3d>* points, std::vector<Eigen::Vector3d>* normals) {
  const int around = static_cast<int>(2 * kPi * radius / step);
  for (double z = z0; z <= z1; z += step)
    for (int k = 0; k < around; ++k) {
      const double a = 2 * kPi * k / around;
      const Eigen::Vector3d n(std::cos(a), std::sin(a), 0);
      points->push_back(Eigen::Vector3d(cx, cy, z) + radius * n);
      normals->push_back(n);
    }
}

Eigen::MatrixX3d Rows(const std::vector<Eigen::Vector3d>& v) {
  Eigen::MatrixX3d m(static_cast<Eigen::Index>(v.size()), 3);
  for (size_t i = 0; i < v.size(); ++i) m.row(static_cast<Eigen::Index>(i)) = v[i].transpose();
  return m;
}

TEST(BodyGraph, TouchingCylindersStayApart) {
  // Two thighs 200 mm thick whose skins touch along x = 0.
  std::vector<Eigen::Vector3d> p, n;
  Cylinder(-100, 0, 100, 0, 300, 4, &p, &n);
  Cylinder(100, 0, 100, 0, 300, 4, &p, &n);
  const BodyGraph with_normals(BodyGraphOptions{}, Rows(p), Rows(n));
  const int left = with_normals.NodeOf(0),
            right = with_normals.NodeOf(static_cast<int>(p.size()) - 1);
  EXPECT_NE(with_normals.Component(left), with_normals.Component(right));
  // Without normals nothing tells the skins apart: they are linked.
  const BodyGraph without(BodyGraphOptions{}, Rows(p), Eigen::MatrixX3d(0, 3));
  EXPECT_EQ(without.Component(without.NodeOf(0)),
            without.Component(without.NodeOf(static_cast<int>(p.size()) - 1)));
}

TEST(BodyGraph, NothingCrossesTheMidlineBelowTheGivenHeight) {
  // The fronts of two feet set together, toe against toe: one strip of skin
  // facing forward (+y) from x = -60 to 60, 40 mm high. Nothing in the
  // normals tells the two toes apart; below midline_apart_below_mm no link
  // crosses x = 0.
  std::vector<Eigen::Vector3d> p, n;
  for (double x = -58; x <= 58; x += 4)
    for (double z = 2; z <= 40; z += 4) p.emplace_back(x, 0, z), n.emplace_back(0, 1, 0);
  const int right = static_cast<int>(p.size()) - 1;
  const BodyGraph linked(BodyGraphOptions{}, Rows(p), Rows(n));
  EXPECT_EQ(linked.Component(linked.NodeOf(0)), linked.Component(linked.NodeOf(right)));
  BodyGraphOptions apart;
  apart.midline_apart_below_mm = 100;
  const BodyGraph g(apart, Rows(p), Rows(n));
  EXPECT_NE(g.Component(g.NodeOf(0)), g.Component(g.NodeOf(right)));
  // Above that height the strip is one piece again.
  apart.midline_apart_below_mm = 1;
  const BodyGraph above(apart, Rows(p), Rows(n));
  EXPECT_EQ(above.Component(above.NodeOf(0)), above.Component(above.NodeOf(right)));
}

TEST(BodyGraph, DistancesFollowTheSurface) {
  // One cylinder of radius 80: from a point to the opposite side at the same
  // height the surface distance is half the circumference (251 mm), not the
  // 160 mm through the inside.
  std::vector<Eigen::Vector3d> p, n;
  Cylinder(0, 0, 80, 0, 200, 4, &p, &n);
  const BodyGraph g(BodyGraphOptions{}, Rows(p), Rows(n));
  const int a = g.Nearest(Eigen::Vector3d(80, 0, 100)), b = g.Nearest(Eigen::Vector3d(-80, 0, 100));
  ASSERT_GE(a, 0);
  ASSERT_GE(b, 0);
  const double d = g.Distances({a})[static_cast<size_t>(b)];
  std::printf("half way round a cylinder of radius 80: %.1f mm (exact 251.3)\n", d);
  EXPECT_NEAR(d, kPi * 80, 0.12 * kPi * 80);
  std::vector<int> parent;
  g.Distances({a}, &parent);
  EXPECT_EQ(BodyGraph::PathTo(parent, b).back(), a);
}

}  // namespace
}  // namespace bespoke::landmarks
