#include "oracle/body/mesh_checks.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <vector>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(static_cast<size_t>(n)) {
    std::iota(parent.begin(), parent.end(), 0);
  }
  int Find(int x) {
    while (parent[static_cast<size_t>(x)] != x)
      x = parent[static_cast<size_t>(x)] =
          parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
    return x;
  }
  void Join(int a, int b) { parent[static_cast<size_t>(Find(a))] = Find(b); }
};

// Number of separate fans of faces around each vertex (1 for a manifold
// vertex): faces around v are joined when they share an edge through v.
std::int64_t CountNonManifoldVertices(const TriangleMesh& mesh) {
  const int nv = static_cast<int>(mesh.num_vertices());
  std::vector<std::vector<int>> faces_of(static_cast<size_t>(nv));
  for (int f = 0; f < mesh.num_faces(); ++f) {
    for (int c = 0; c < 3; ++c) faces_of[static_cast<size_t>(mesh.faces(f, c))].push_back(f);
  }
  std::int64_t bad = 0;
  for (int v = 0; v < nv; ++v) {
    const auto& fs = faces_of[static_cast<size_t>(v)];
    if (fs.empty()) continue;
    std::map<int, std::vector<size_t>> by_other;  // other vertex -> local face indices
    for (size_t i = 0; i < fs.size(); ++i) {
      for (int c = 0; c < 3; ++c) {
        const int w = mesh.faces(fs[i], c);
        if (w != v) by_other[w].push_back(i);
      }
    }
    UnionFind uf(static_cast<int>(fs.size()));
    for (const auto& [w, list] : by_other) {
      for (size_t k = 1; k < list.size(); ++k)
        uf.Join(static_cast<int>(list[0]), static_cast<int>(list[k]));
    }
    int roots = 0;
    for (size_t i = 0; i < fs.size(); ++i)
      roots += uf.Find(static_cast<int>(i)) == static_cast<int>(i);
    if (roots > 1) ++bad;
  }
  return bad;
}

}  // namespace

bool MeshTopology::IsClosedSphere() const {
  return faces > 0 && boundary_edges == 0 && non_manifold_edges == 0 && misoriented_edges == 0 &&
         non_manifold_vertices == 0 && degenerate_faces == 0 && components == 1 &&
         euler_characteristic == 2 && signed_volume > 0;
}

std::string MeshTopology::Describe() const {
  std::ostringstream s;
  s << "V=" << vertices_used << " E=" << edges << " F=" << faces << " chi=" << euler_characteristic
    << " boundary=" << boundary_edges << " non-manifold-edges=" << non_manifold_edges
    << " misoriented=" << misoriented_edges << " non-manifold-vertices=" << non_manifold_vertices
    << " degenerate=" << degenerate_faces << " components=" << components
    << " volume=" << signed_volume;
  return s.str();
}

MeshTopology AnalyzeTopology(const TriangleMesh& mesh) {
  mesh.CheckIndices();
  MeshTopology t;
  t.faces = mesh.num_faces();
  const int nv = static_cast<int>(mesh.num_vertices());
  // Directed edge counts keyed by (min, max) with the direction tallied.
  struct EdgeUse {
    int forward = 0, backward = 0;
  };
  std::unordered_map<std::uint64_t, EdgeUse> edges;
  std::vector<char> used(static_cast<size_t>(nv), 0);
  UnionFind uf(nv);
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const int v[3] = {mesh.faces(f, 0), mesh.faces(f, 1), mesh.faces(f, 2)};
    const Eigen::Vector3d a = mesh.vertices.row(v[0]), b = mesh.vertices.row(v[1]),
                          c = mesh.vertices.row(v[2]);
    const Eigen::Vector3d n = (b - a).cross(c - a);
    if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2] || n.norm() == 0) ++t.degenerate_faces;
    t.signed_volume += a.dot(b.cross(c)) / 6.0;
    for (int e = 0; e < 3; ++e) {
      const int p = v[e], q = v[(e + 1) % 3];
      used[static_cast<size_t>(p)] = 1;
      uf.Join(p, q);
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(p, q)) << 32) |
                                static_cast<std::uint32_t>(std::max(p, q));
      (p < q ? edges[key].forward : edges[key].backward)++;
    }
  }
  t.edges = static_cast<std::int64_t>(edges.size());
  for (const auto& [key, use] : edges) {
    const int total = use.forward + use.backward;
    if (total == 1) ++t.boundary_edges;
    if (total > 2) ++t.non_manifold_edges;
    if (total == 2 && use.forward != 1) ++t.misoriented_edges;
  }
  for (int v = 0; v < nv; ++v) {
    if (!used[static_cast<size_t>(v)]) continue;
    ++t.vertices_used;
    if (uf.Find(v) == v) ++t.components;
  }
  t.euler_characteristic = t.vertices_used - t.edges + t.faces;
  t.non_manifold_vertices = CountNonManifoldVertices(mesh);
  return t;
}

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

// The mesh as a CGAL surface mesh with the same vertex and face indices.
SurfaceMesh ToSurfaceMesh(const TriangleMesh& mesh) {
  mesh.CheckIndices();
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> index;
  index.reserve(static_cast<size_t>(mesh.num_vertices()));
  for (Eigen::Index v = 0; v < mesh.num_vertices(); ++v) {
    index.push_back(sm.add_vertex(
        Kernel::Point_3(mesh.vertices(v, 0), mesh.vertices(v, 1), mesh.vertices(v, 2))));
  }
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const auto face = sm.add_face(index[static_cast<size_t>(mesh.faces(f, 0))],
                                  index[static_cast<size_t>(mesh.faces(f, 1))],
                                  index[static_cast<size_t>(mesh.faces(f, 2))]);
    if (face == SurfaceMesh::null_face()) {
      throw InputError("face " + std::to_string(f) +
                       " cannot be added: the mesh is not an oriented 2-manifold");
    }
  }
  return sm;
}

}  // namespace

bool SelfIntersects(const TriangleMesh& mesh) {
  return CGAL::Polygon_mesh_processing::does_self_intersect(ToSurfaceMesh(mesh));
}

std::vector<std::pair<int, int>> SelfIntersectingFacePairs(const TriangleMesh& mesh) {
  const SurfaceMesh sm = ToSurfaceMesh(mesh);
  std::vector<std::pair<SurfaceMesh::Face_index, SurfaceMesh::Face_index>> found;
  CGAL::Polygon_mesh_processing::self_intersections(sm, std::back_inserter(found));
  std::vector<std::pair<int, int>> pairs;
  pairs.reserve(found.size());
  for (const auto& [a, b] : found) {
    const int i = static_cast<int>(a.idx()), j = static_cast<int>(b.idx());
    pairs.emplace_back(std::min(i, j), std::max(i, j));
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace bespoke
