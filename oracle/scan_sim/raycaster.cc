// Ray casting with CGAL's AABB tree (double precision, exact predicates for
// the hit tests), rays spread over threads with OpenMP.
//
// Why not Open3D's RaycastingScene (Embree): Debian 12's Open3D 0.16 is built
// against an Embree with ray masks enabled and leaves the ray mask at 0, so
// CastRays never reports a hit (checked: a ray straight through a triangle
// returns t_hit = inf). CGAL's tree is slower than Embree but fast enough for
// a booth's ~1 million rays in about a second on two cores.
#include "oracle/scan_sim/raycaster.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <limits>
#include <vector>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point ToPoint(const Eigen::Vector3d& p) { return Point(p.x(), p.y(), p.z()); }

}  // namespace

struct MeshRaycaster::Impl {
  std::vector<Triangle> triangles;
  std::vector<int> geometry, face;      // per triangle
  std::vector<Eigen::Vector3d> normal;  // per triangle, unit, (b - a) x (c - a)
  int meshes = 0;
  Tree tree;
  bool built = false;
  void Build() {
    if (built) return;
    if (triangles.empty()) throw InputError("ray casting: no mesh added");
    tree.rebuild(triangles.cbegin(), triangles.cend());
    tree.accelerate_distance_queries();
    built = true;
  }
};

MeshRaycaster::MeshRaycaster() : impl_(std::make_unique<Impl>()) {}
MeshRaycaster::~MeshRaycaster() = default;

int MeshRaycaster::AddMesh(const TriangleMesh& mesh) {
  BESPOKE_CHECK(!impl_->built, "ray casting: AddMesh after the first query");
  if (mesh.num_faces() == 0) throw InputError("ray casting: the mesh has no faces");
  mesh.CheckIndices();
  if (!mesh.vertices.allFinite())
    throw InputError("ray casting: the mesh has a coordinate that is not finite");
  const int id = impl_->meshes++;
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)),
                          b = mesh.vertices.row(mesh.faces(f, 1)),
                          c = mesh.vertices.row(mesh.faces(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (!(n.norm() > 0)) continue;  // degenerate: cannot be hit
    impl_->triangles.emplace_back(ToPoint(a), ToPoint(b), ToPoint(c));
    impl_->geometry.push_back(id);
    impl_->face.push_back(static_cast<int>(f));
    impl_->normal.push_back(n.normalized());
  }
  return id;
}

RayHits MeshRaycaster::Cast(const Eigen::MatrixX3d& origins,
                            const Eigen::MatrixX3d& directions) const {
  if (origins.rows() != directions.rows())
    throw InputError("ray casting: origins and directions differ in count");
  impl_->Build();
  const Eigen::Index n = origins.rows();
  RayHits hits;
  hits.distance.setConstant(n, std::numeric_limits<double>::infinity());
  hits.geometry.setConstant(n, -1);
  hits.face.setConstant(n, -1);
  hits.normal.setZero(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double norm = directions.row(i).norm();
    if (!(norm > 0) || !std::isfinite(norm) || !origins.row(i).allFinite()) {
      throw InputError("ray casting: ray " + std::to_string(i) +
                       " has a zero or non-finite direction/origin");
    }
  }
  const Tree& tree = impl_->tree;
  const Iterator first = impl_->triangles.cbegin();
#pragma omp parallel for schedule(dynamic, 256)
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d o = origins.row(i);
    const Eigen::Vector3d d = directions.row(i).normalized();
    const Kernel::Ray_3 ray(ToPoint(o), Kernel::Vector_3(d.x(), d.y(), d.z()));
    const auto hit = tree.first_intersection(ray);
    if (!hit) continue;
    double t = std::numeric_limits<double>::infinity();
    if (const Point* p = boost::get<Point>(&hit->first)) {
      t = (Eigen::Vector3d(p->x(), p->y(), p->z()) - o).norm();
    } else if (const Kernel::Segment_3* s = boost::get<Kernel::Segment_3>(&hit->first)) {
      for (const Point& p : {s->source(), s->target()}) {
        t = std::min(t, (Eigen::Vector3d(p.x(), p.y(), p.z()) - o).norm());
      }
    }
    const auto k = static_cast<size_t>(hit->second - first);
    hits.distance[i] = t;
    hits.geometry[i] = impl_->geometry[k];
    hits.face[i] = impl_->face[k];
    hits.normal.row(i) = impl_->normal[k];
  }
  return hits;
}

Eigen::VectorXd MeshRaycaster::Distance(const Eigen::MatrixX3d& points) const {
  impl_->Build();
  const Eigen::Index n = points.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    if (!points.row(i).allFinite())
      throw InputError("distance query: point " + std::to_string(i) + " is not finite");
  }
  Eigen::VectorXd out(n);
  const Tree& tree = impl_->tree;
#pragma omp parallel for schedule(dynamic, 256)
  for (Eigen::Index i = 0; i < n; ++i) {
    out[i] = std::sqrt(tree.squared_distance(ToPoint(points.row(i).transpose())));
  }
  return out;
}

}  // namespace bespoke
