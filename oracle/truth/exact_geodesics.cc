#include "oracle/truth/exact_geodesics.h"

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>
#include <CGAL/boost/graph/iterator.h>

#include <array>
#include <cmath>
#include <iterator>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using CgalMesh = CGAL::Surface_mesh<Point3>;
using VertexIndex = CgalMesh::Vertex_index;
using FaceIndex = CgalMesh::Face_index;
using Traits = CGAL::Surface_mesh_shortest_path_traits<Kernel, CgalMesh>;
using ShortestPath = CGAL::Surface_mesh_shortest_path<Traits>;
using Primitive = CGAL::AABB_face_graph_triangle_primitive<CgalMesh>;
using AabbTraits = CGAL::AABB_traits<Kernel, Primitive>;
using AabbTree = CGAL::AABB_tree<AabbTraits>;
using FaceLocation = ShortestPath::Face_location;

// Barycentric weights below this are treated as exactly 0, and a source on an
// edge is moved this far into its face (see ToCgal).
constexpr double kZeroWeight = 1e-8;
constexpr double kEdgeNudge = 1e-8;

std::string FaceName(Eigen::Index f) { return "face " + std::to_string(f); }

// Copies `mesh` into a CGAL Surface_mesh with the same vertex and face
// indices, or throws InputError saying what makes it unusable.
void BuildCgalMesh(const TriangleMesh& mesh, CgalMesh* out) {
  mesh.CheckIndices();
  if (mesh.num_faces() == 0) throw InputError("exact geodesics: the mesh has no faces");
  if (!mesh.vertices.allFinite())
    throw InputError("exact geodesics: the mesh has non-finite vertex coordinates");
  out->reserve(mesh.num_vertices(), 3 * mesh.num_faces() / 2, mesh.num_faces());
  for (Eigen::Index v = 0; v < mesh.num_vertices(); ++v)
    out->add_vertex(Point3(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2)));
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const int a = mesh.faces(f, 0), b = mesh.faces(f, 1), c = mesh.faces(f, 2);
    if (a == b || b == c || a == c)
      throw InputError("exact geodesics: " + FaceName(f) + " repeats a vertex");
    const FaceIndex added = out->add_face(VertexIndex(a), VertexIndex(b), VertexIndex(c));
    if (added == CgalMesh::null_face())
      throw InputError("exact geodesics: " + FaceName(f) +
                       " makes the mesh non-manifold (an edge shared by more than two faces, "
                       "or neighbouring faces with opposite orientation)");
    BESPOKE_CHECK(static_cast<Eigen::Index>(added) == f, "CGAL face index differs from row");
  }
  // A vertex is manifold when circulating around it reaches every face that
  // uses it and crosses at most one border. (PMP::is_non_manifold_vertex
  // answers the same but took 2.4 s on a 13k-vertex body.)
  std::vector<int> uses(static_cast<std::size_t>(mesh.num_vertices()), 0);
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) ++uses[static_cast<std::size_t>(mesh.faces(f, k))];
  for (const VertexIndex v : out->vertices()) {
    if (out->is_isolated(v)) continue;
    int fan = 0, borders = 0;
    for (const auto h : CGAL::halfedges_around_target(out->halfedge(v), *out))
      (out->is_border(h) ? borders : fan) += 1;
    // Surface_mesh chains a pinched vertex's fans through their borders:
    // more than one border halfedge into v means more than one fan.
    if (fan != uses[static_cast<std::size_t>(static_cast<int>(v))] || borders > 1)
      throw InputError("exact geodesics: vertex " + std::to_string(static_cast<int>(v)) +
                       " is non-manifold (faces around it form more than one fan)");
  }
  for (const FaceIndex f : out->faces()) {
    if (CGAL::Polygon_mesh_processing::is_degenerate_triangle_face(f, *out))
      throw InputError("exact geodesics: " + FaceName(static_cast<int>(f)) +
                       " is degenerate (zero area)");
  }
}

}  // namespace

struct ExactGeodesics::Impl {
  TriangleMesh mesh;
  CgalMesh cgal;
  std::optional<ShortestPath> paths;  // built after `cgal` is complete
  AabbTree tree;
  // Vertex rows of each face in CGAL's barycentric order: source(h),
  // target(h), target(next(h)) with h = halfedge(f).
  std::vector<std::array<int, 3>> cgal_order;
  std::optional<FaceLocation> current_source;

  FaceLocation ToCgal(const SurfacePoint& p, bool as_source) const {
    if (p.face < 0 || p.face >= mesh.num_faces())
      throw InputError("exact geodesics: surface point on face " + std::to_string(p.face) +
                       ", but the mesh has " + std::to_string(mesh.num_faces()) + " faces");
    const Eigen::Vector3d& w = p.barycentric;
    if (!w.allFinite() || w.minCoeff() < -1e-6 || std::abs(w.sum() - 1.0) > 1e-6)
      throw InputError("exact geodesics: surface point on face " + std::to_string(p.face) +
                       " has barycentric weights that are not non-negative summing to 1");
    double coords[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        if (cgal_order[p.face][i] == mesh.faces(p.face, k)) coords[i] = w[k];
    // CGAL 5.5 is exact for sources at vertices and inside faces but not on
    // edges: it classifies a location by exact comparisons of its weights, and
    // a source on an edge (one weight 0) or a hair inside one (1e-12) roots its
    // wavefront wrongly (measured on a cylinder: 52.4 or 42.6 mm instead of
    // 43.0; cf. CGAL issues #1179, #9646). So weights below kZeroWeight become
    // 0 (two zeros: exactly a vertex), and a source left on an edge is moved
    // kEdgeNudge into its face, i.e. by 1e-8 of the face's size.
    int zeros = 0;
    for (double& c : coords)
      if (c < kZeroWeight) c = 0, ++zeros;
    if (zeros == 1 && as_source)
      for (double& c : coords)
        if (c == 0) c = kEdgeNudge;
    const double sum = coords[0] + coords[1] + coords[2];
    const Traits::Barycentric_coordinates b = {coords[0] / sum, coords[1] / sum, coords[2] / sum};
    return FaceLocation(FaceIndex(p.face), b);
  }

  SurfacePoint FromCgal(const FaceLocation& loc) const {
    SurfacePoint p;
    p.face = static_cast<int>(loc.first);
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        if (cgal_order[p.face][i] == mesh.faces(p.face, k)) p.barycentric[k] = loc.second[i];
    return p;
  }

  // Makes `source` the only source point (reusing the tree when unchanged).
  void SetSource(const FaceLocation& source) {
    if (current_source && current_source->first == source.first &&
        current_source->second == source.second)
      return;
    paths->clear();
    paths->add_source_point(source);
    paths->build_sequence_tree();
    current_source = source;
  }
};

ExactGeodesics::ExactGeodesics(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>()) {
  impl_->mesh = mesh;
  BuildCgalMesh(mesh, &impl_->cgal);
  impl_->cgal_order.resize(mesh.num_faces());
  for (const FaceIndex f : impl_->cgal.faces()) {
    const auto h = impl_->cgal.halfedge(f);
    impl_->cgal_order[static_cast<int>(f)] = {
        static_cast<int>(impl_->cgal.source(h)), static_cast<int>(impl_->cgal.target(h)),
        static_cast<int>(impl_->cgal.target(impl_->cgal.next(h)))};
  }
  impl_->paths.emplace(impl_->cgal);
  impl_->paths->build_aabb_tree(impl_->tree);
}

ExactGeodesics::~ExactGeodesics() = default;
ExactGeodesics::ExactGeodesics(ExactGeodesics&&) noexcept = default;
ExactGeodesics& ExactGeodesics::operator=(ExactGeodesics&&) noexcept = default;

const TriangleMesh& ExactGeodesics::mesh() const { return impl_->mesh; }

SurfacePoint ExactGeodesics::Locate(const Eigen::Vector3d& position) const {
  if (!position.allFinite()) throw InputError("exact geodesics: locating a non-finite point");
  const FaceLocation loc =
      impl_->paths->locate(Point3(position.x(), position.y(), position.z()), impl_->tree);
  return impl_->FromCgal(loc);
}

SurfacePoint ExactGeodesics::AtVertex(int vertex) const {
  if (vertex < 0 || vertex >= impl_->mesh.num_vertices() ||
      impl_->cgal.is_isolated(VertexIndex(vertex)))
    throw InputError("exact geodesics: vertex " + std::to_string(vertex) +
                     " is out of range or not used by any face");
  const auto h = impl_->cgal.halfedge(VertexIndex(vertex));  // its target is `vertex`
  FaceIndex f = impl_->cgal.face(h);
  if (f == CgalMesh::null_face()) f = impl_->cgal.face(impl_->cgal.opposite(h));
  SurfacePoint p;
  p.face = static_cast<int>(f);
  for (int k = 0; k < 3; ++k) p.barycentric[k] = impl_->mesh.faces(p.face, k) == vertex ? 1 : 0;
  return p;
}

double ExactGeodesics::Distance(const SurfacePoint& from, const SurfacePoint& to) {
  const FaceLocation target = impl_->ToCgal(to, /*as_source=*/false);
  impl_->SetSource(impl_->ToCgal(from, /*as_source=*/true));
  const double d =
      impl_->paths->shortest_distance_to_source_points(target.first, target.second).first;
  if (!(d >= 0))
    throw InputError("exact geodesics: the two points lie on different connected components");
  return d;
}

double ExactGeodesics::Distance(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  return Distance(Locate(from), Locate(to));
}

GeodesicPath ExactGeodesics::Path(const SurfacePoint& from, const SurfacePoint& to) {
  GeodesicPath path;
  path.length = Distance(from, to);  // checks reachability and sets the source
  const FaceLocation target = impl_->ToCgal(to, /*as_source=*/false);
  std::vector<Point3> points;  // CGAL writes them from `to` back to the source
  impl_->paths->shortest_path_points_to_source_points(target.first, target.second,
                                                      std::back_inserter(points));
  if (points.size() < 2) {  // coincident points: a zero-length path
    const Eigen::Vector3d p = PositionOf(impl_->mesh, from);
    path.points.resize(2, 3);
    path.points.row(0) = p.transpose();
    path.points.row(1) = p.transpose();
    return path;
  }
  path.points.resize(static_cast<Eigen::Index>(points.size()), 3);
  const Eigen::Index n = path.points.rows();
  for (Eigen::Index i = 0; i < n; ++i) {
    const Point3& q = points[static_cast<std::size_t>(n - 1 - i)];
    path.points.row(i) << q.x(), q.y(), q.z();
  }
  return path;
}

GeodesicPath ExactGeodesics::Path(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  return Path(Locate(from), Locate(to));
}

Eigen::VectorXd ExactGeodesics::DistancesToVertices(const SurfacePoint& source) {
  impl_->SetSource(impl_->ToCgal(source, /*as_source=*/true));
  Eigen::VectorXd d(impl_->mesh.num_vertices());
  for (const VertexIndex v : impl_->cgal.vertices()) {
    double value = std::numeric_limits<double>::infinity();
    if (!impl_->cgal.is_isolated(v)) {
      const double r = impl_->paths->shortest_distance_to_source_points(v).first;
      if (r >= 0) value = r;
    }
    d[static_cast<int>(v)] = value;
  }
  return d;
}

}  // namespace bespoke
