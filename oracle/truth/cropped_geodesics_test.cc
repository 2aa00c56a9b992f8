#include "oracle/truth/cropped_geodesics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>

#include "oracle/body/parametric_body.h"
#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// A light parametric body (about 6k vertices): its CGAL propagations take
// well under a second, and its shapes (arm bends, crotch, shoulders) are the
// ones the cropping has to get right.
Body LightBody() {
  ParametricBodyOptions o;
  o.torso_segments = 48;
  o.arm_segments = 32;
  o.ring_spacing_mm = 30;
  o.girth_ring_segments = 64;
  o.max_girth_deficit_mm = 2;
  return GenerateParametricBody(o);
}

// An octahedron refined `levels` times and projected on a sphere of radius r.
TriangleMesh Sphere(double r, int levels) {
  std::vector<Eigen::Vector3d> v = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                    {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  std::vector<Eigen::Vector3i> f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> mid;
    auto m = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (const auto it = mid.find(key); it != mid.end()) return it->second;
      v.push_back((v[a] + v[b]).normalized());
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<Eigen::Vector3i> next;
    for (const auto& t : f) {
      const int ab = m(t[0], t[1]), bc = m(t[1], t[2]), ca = m(t[2], t[0]);
      next.insert(next.end(), {{t[0], ab, ca}, {t[1], bc, ab}, {t[2], ca, bc}, {ab, bc, ca}});
    }
    f = std::move(next);
  }
  TriangleMesh mesh;
  mesh.vertices.resize(static_cast<Eigen::Index>(v.size()), 3);
  for (std::size_t i = 0; i < v.size(); ++i)
    mesh.vertices.row(static_cast<Eigen::Index>(i)) = r * v[i].transpose();
  mesh.faces.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t i = 0; i < f.size(); ++i)
    mesh.faces.row(static_cast<Eigen::Index>(i)) = f[i].transpose();
  return mesh;
}

SurfacePoint AtVertex(const TriangleMesh& mesh, int vertex) {
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.faces(f, k) == vertex) {
        SurfacePoint p;
        p.face = static_cast<int>(f);
        p.barycentric[k] = 1;
        return p;
      }
  return {};
}

TEST(CroppedGeodesics, SameLengthsAsTheWholeMeshOnABody) {
  const Body body = LightBody();
  ExactGeodesics whole(body.mesh);
  CroppedExactGeodesics cropped(body.mesh);
  // Datum chains of the catalogue, including ones that bend a lot (over the
  // shoulder, through the crotch) and long ones (down the leg, along the arm).
  const std::vector<std::pair<const char*, const char*>> pairs = {
      {"shoulder_right", "back_neck"},
      {"front_waist", "crotch"},
      {"crotch", "back_waist"},
      {"axilla_front_right", "shoulder_right"},
      {"hip_right", "ankle_outside_right"},
      {"armpit_right", "wrist_right"},
      {"bust_right", "bust_left"}};
  for (const auto& [a, b] : pairs) {
    const SurfacePoint& pa = body.landmarks.at(a);
    const SurfacePoint& pb = body.landmarks.at(b);
    const double expected = whole.Distance(pa, pb);
    const GeodesicPath path = cropped.Path(pa, pb);
    EXPECT_NEAR(path.length, expected, 1e-9 * expected) << a << " -> " << b;
    ASSERT_GE(path.points.rows(), 2);
    EXPECT_LT((path.points.row(0).transpose() - PositionOf(body.mesh, pa)).norm(), 1e-6) << a;
    EXPECT_LT((path.points.bottomRows(1).transpose() - PositionOf(body.mesh, pb)).norm(), 1e-6)
        << b;
    double polyline = 0;
    for (Eigen::Index i = 1; i < path.points.rows(); ++i)
      polyline += (path.points.row(i) - path.points.row(i - 1)).norm();
    EXPECT_NEAR(polyline, path.length, 1e-6 * path.length) << a << " -> " << b;
    EXPECT_NEAR(cropped.Distance(pb, pa), path.length, 1e-9 * path.length);  // the other direction
  }
  const CroppedGeodesicsStats& s = cropped.stats();
  EXPECT_EQ(s.queries, 2 * static_cast<std::int64_t>(pairs.size()));
  // The point of cropping: far fewer faces than one propagation per pair over the whole mesh.
  EXPECT_LT(s.faces_used, s.queries * body.mesh.num_faces() / 2)
      << s.propagations << " propagations";
  EXPECT_EQ(s.whole_mesh, 0);
}

TEST(CroppedGeodesics, GrowsTheCropWhenTheFirstIsTooSmall) {
  // A quarter great circle on a sphere: arc pi/2 r, chord sqrt(2) r. With no
  // slack (ratio 1, margin 0) the first crop is a thin band around the chord
  // that misses the arc's middle, so the crop must grow.
  const double r = 100;
  const TriangleMesh sphere = Sphere(r, 5);
  ExactGeodesics whole(sphere);
  const SurfacePoint a = AtVertex(sphere, 0), b = AtVertex(sphere, 2);  // (r,0,0) -> (0,r,0)
  const double expected = whole.Distance(a, b);
  EXPECT_NEAR(expected, M_PI / 2 * r, 1e-3 * r);
  CroppedGeodesicsOptions tight;
  tight.initial_ratio = 1;
  tight.initial_margin = 0;
  CroppedExactGeodesics grown(sphere, tight);
  EXPECT_NEAR(grown.Distance(a, b), expected, 1e-9 * expected);
  EXPECT_GE(grown.stats().propagations, 2);
  // With the default slack one crop, smaller than the sphere, holds it.
  CroppedExactGeodesics cropped(sphere);
  EXPECT_NEAR(cropped.Distance(a, b), expected, 1e-9 * expected);
  EXPECT_EQ(cropped.stats().propagations, 1);
  EXPECT_LT(cropped.stats().faces_used, sphere.num_faces() * 3 / 4);
}

TEST(CroppedGeodesics, ErrorsAsTheWholeMesh) {
  // Two spheres apart: unreachable is an InputError once the crop is the whole mesh.
  const TriangleMesh one = Sphere(50, 2);
  TriangleMesh two;
  two.vertices.resize(2 * one.num_vertices(), 3);
  two.vertices.topRows(one.num_vertices()) = one.vertices;
  two.vertices.bottomRows(one.num_vertices()) =
      one.vertices.rowwise() + Eigen::RowVector3d(300, 0, 0);
  two.faces.resize(2 * one.num_faces(), 3);
  two.faces.topRows(one.num_faces()) = one.faces;
  two.faces.bottomRows(one.num_faces()) = one.faces.array() + static_cast<int>(one.num_vertices());
  CroppedExactGeodesics cropped(two);
  EXPECT_THROW(
      cropped.Distance(AtVertex(two, 0), AtVertex(two, static_cast<int>(one.num_vertices()) + 1)),
      InputError);
  SurfacePoint bad;
  bad.face = static_cast<int>(two.num_faces());
  EXPECT_THROW(cropped.Distance(bad, AtVertex(two, 0)), InputError);
  CroppedGeodesicsOptions options;
  options.initial_ratio = 0.5;
  EXPECT_THROW(CroppedExactGeodesics(two, options), InputError);
}

}  // namespace
}  // namespace bespoke
