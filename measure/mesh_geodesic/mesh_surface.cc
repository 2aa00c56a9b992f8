#include "measure/mesh_geodesic/mesh_surface.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "scanners/core/errors.h"

namespace bespoke {

void MeshPrepOptions::Check() const {
  if (!(degenerate_area >= 0) || !std::isfinite(degenerate_area))
    throw InputError("mesh preparation: degenerate_area must be >= 0");
}

namespace {

// Closest point to p on triangle abc (Ericson, Real-Time Collision Detection 5.1.5).
Eigen::Vector3d ClosestOnTriangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                  const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Eigen::Vector3d bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Eigen::Vector3d cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

int Find(std::vector<int>& parent, int x) {
  while (parent[static_cast<size_t>(x)] != x) {
    parent[static_cast<size_t>(x)] = parent[static_cast<size_t>(parent[static_cast<size_t>(x)])];
    x = parent[static_cast<size_t>(x)];
  }
  return x;
}

}  // namespace

MeshSurface::MeshSurface(const MeshPrepOptions& options, const TriangleMesh& mesh,
                         const std::string& name)
    : name_(name) {
  options.Check();
  report_.vertices = mesh.num_vertices();
  report_.faces = mesh.num_faces();
  if (mesh.num_faces() == 0) throw InputError(name, "the mesh has no faces");
  if (mesh.vertices.cols() != 3 || mesh.faces.cols() != 3)
    throw InputError(name, "the mesh is not a triangle mesh with 3-D vertices");
  if (!mesh.vertices.allFinite()) throw InputError(name, "a vertex coordinate is not finite");
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      if (mesh.faces(f, k) < 0 || mesh.faces(f, k) >= mesh.num_vertices())
        throw InputError(name, "face " + std::to_string(f) + " refers to vertex " +
                                   std::to_string(mesh.faces(f, k)) + " but there are " +
                                   std::to_string(mesh.num_vertices()) + " vertices");
  // Degenerate faces: repeated vertex or (relatively) zero area.
  std::vector<double> area(static_cast<size_t>(mesh.num_faces()), 0.0);
  double total = 0;
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const Eigen::Vector3d a = mesh.vertices.row(mesh.faces(f, 0)).transpose();
    const Eigen::Vector3d b = mesh.vertices.row(mesh.faces(f, 1)).transpose();
    const Eigen::Vector3d c = mesh.vertices.row(mesh.faces(f, 2)).transpose();
    area[static_cast<size_t>(f)] = 0.5 * (b - a).cross(c - a).norm();
    total += area[static_cast<size_t>(f)];
  }
  const double threshold = options.degenerate_area * total / static_cast<double>(mesh.num_faces());
  std::vector<int> keep;
  keep.reserve(static_cast<size_t>(mesh.num_faces()));
  for (Eigen::Index f = 0; f < mesh.num_faces(); ++f) {
    const int a = mesh.faces(f, 0), b = mesh.faces(f, 1), c = mesh.faces(f, 2);
    if (a == b || b == c || a == c || !(area[static_cast<size_t>(f)] > threshold)) continue;
    keep.push_back(static_cast<int>(f));
  }
  report_.dropped_faces = mesh.num_faces() - static_cast<std::int64_t>(keep.size());
  if (keep.empty()) throw InputError(name, "every face is degenerate (zero area)");
  if (report_.dropped_faces > 0)
    report_.warnings.push_back(std::to_string(report_.dropped_faces) +
                               " degenerate faces (repeated vertex or zero area) dropped");
  mesh_.vertices = mesh.vertices;
  mesh_.faces.resize(static_cast<Eigen::Index>(keep.size()), 3);
  for (size_t i = 0; i < keep.size(); ++i)
    mesh_.faces.row(static_cast<Eigen::Index>(i)) = mesh.faces.row(keep[i]);
  BuildAdjacency();
  ComputeNormalsAndComponents();
}

void MeshSurface::BuildAdjacency() {
  const int nv = num_vertices();
  const auto nf = static_cast<size_t>(mesh_.faces.rows());
  vertex_face_start_.assign(static_cast<size_t>(nv) + 1, 0);
  for (size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k) ++vertex_face_start_[static_cast<size_t>(mesh_.faces(f, k)) + 1];
  std::partial_sum(vertex_face_start_.begin(), vertex_face_start_.end(),
                   vertex_face_start_.begin());
  vertex_faces_.resize(3 * nf);
  std::vector<std::int64_t> fill(vertex_face_start_.begin(), vertex_face_start_.end() - 1);
  for (size_t f = 0; f < nf; ++f)
    for (int k = 0; k < 3; ++k)
      vertex_faces_[static_cast<size_t>(fill[static_cast<size_t>(mesh_.faces(f, k))]++)] =
          static_cast<int>(f);
  // Faces across each edge, found among the faces of its first vertex.
  adjacent_.assign(3 * nf, -1);
  for (size_t f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh_.faces(f, k), b = mesh_.faces(f, (k + 1) % 3);
      int others = 0;
      for (const int* g = faces_begin(a); g != faces_end(a); ++g) {
        if (static_cast<size_t>(*g) == f) continue;
        for (int j = 0; j < 3; ++j) {
          if (mesh_.faces(*g, j) != b) continue;
          ++others;
          adjacent_[3 * f + k] = *g;
          if (mesh_.faces(*g, (j + 1) % 3) == a) continue;  // opposite direction: consistent
          if (static_cast<size_t>(*g) > f) ++report_.misoriented_edges;
        }
      }
      if (others > 1)
        throw InputError(name_, "non-manifold edge between vertices " +
                                    std::to_string(std::min(a, b)) + " and " +
                                    std::to_string(std::max(a, b)) + " (used by " +
                                    std::to_string(others + 1) +
                                    " faces); mesh geodesics need every edge on at most two "
                                    "faces - repair the mesh first");
      if (others == 0) ++report_.boundary_edges;
      const double length = (mesh_.vertices.row(a) - mesh_.vertices.row(b)).norm();
      mean_edge_ += length;
      max_edge_ = std::max(max_edge_, length);
    }
  }
  mean_edge_ /= static_cast<double>(3 * nf);
  // One-ring neighbours and bow-tie vertices (faces around v forming > 1 fan).
  neighbour_start_.assign(static_cast<size_t>(nv) + 1, 0);
  neighbours_.clear();
  neighbours_.reserve(6 * static_cast<size_t>(nv));
  std::vector<int> ring, fan;
  for (int v = 0; v < nv; ++v) {
    ring.clear();
    const int degree = static_cast<int>(faces_end(v) - faces_begin(v));
    fan.resize(static_cast<size_t>(degree));
    std::iota(fan.begin(), fan.end(), 0);
    for (int i = 0; i < degree; ++i) {
      const int f = faces_begin(v)[i];
      for (int k = 0; k < 3; ++k) {
        const int u = mesh_.faces(f, k);
        if (u != v) ring.push_back(u);
        if (u != v && mesh_.faces(f, (k + 1) % 3) != v) continue;
        const int g = adjacent_face(f, k);  // an edge through v: join the fans
        for (int j = 0; j < degree && g >= 0; ++j)
          if (faces_begin(v)[j] == g) fan[static_cast<size_t>(Find(fan, i))] = Find(fan, j);
      }
    }
    int fans = 0;
    for (int i = 0; i < degree; ++i) fans += Find(fan, i) == i;
    if (fans > 1) ++report_.non_manifold_vertices;
    std::sort(ring.begin(), ring.end());
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    neighbours_.insert(neighbours_.end(), ring.begin(), ring.end());
    neighbour_start_[static_cast<size_t>(v) + 1] = static_cast<std::int64_t>(neighbours_.size());
  }
  neighbours_.shrink_to_fit();
}

void MeshSurface::ComputeNormalsAndComponents() {
  const int nv = num_vertices();
  normal_.assign(static_cast<size_t>(nv), Eigen::Vector3d::Zero());
  component_.assign(static_cast<size_t>(nv), -1);
  for (int v = 0; v < nv; ++v) {
    if (!used(v)) {
      ++report_.unreferenced_vertices;
      continue;
    }
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (const int* f = faces_begin(v); f != faces_end(v); ++f) {
      const Eigen::Vector3d a = mesh_.vertices.row(mesh_.faces(*f, 0)).transpose();
      const Eigen::Vector3d n = (mesh_.vertices.row(mesh_.faces(*f, 1)).transpose() - a)
                                    .cross(mesh_.vertices.row(mesh_.faces(*f, 2)).transpose() - a);
      const double twice_area = n.norm();
      if (!(twice_area > 0)) continue;
      moment += n * n.transpose() / twice_area;  // area-weighted n n^T (unit n)
      sum += n;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> pca;
    pca.computeDirect(moment);
    Eigen::Vector3d n = pca.eigenvectors().col(2);
    if (n.dot(sum) < 0) n = -n;
    normal_[static_cast<size_t>(v)] = n.allFinite() ? n.normalized() : Eigen::Vector3d::UnitZ();
  }
  // Components by flood fill over the vertex graph.
  std::vector<int> stack;
  for (int v = 0; v < nv; ++v) {
    if (!used(v) || component_[static_cast<size_t>(v)] >= 0) continue;
    const int id = static_cast<int>(report_.components++);
    component_[static_cast<size_t>(v)] = id;
    stack.assign(1, v);
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      for (const int* w = neighbours_begin(u); w != neighbours_end(u); ++w)
        if (component_[static_cast<size_t>(*w)] < 0) {
          component_[static_cast<size_t>(*w)] = id;
          stack.push_back(*w);
        }
    }
  }
  if (report_.unreferenced_vertices > 0)
    report_.warnings.push_back(std::to_string(report_.unreferenced_vertices) +
                               " vertices are used by no face (unreachable, distance NaN)");
  if (report_.components > 1)
    report_.warnings.push_back(std::to_string(report_.components) +
                               " connected components: only the source's is reached");
  if (report_.non_manifold_vertices > 0)
    report_.warnings.push_back(std::to_string(report_.non_manifold_vertices) +
                               " non-manifold (bow-tie) vertices");
  if (report_.misoriented_edges > 0)
    report_.warnings.push_back(std::to_string(report_.misoriented_edges) +
                               " edges between faces of opposite orientation");
}

int MeshSurface::NearestVertex(const Eigen::Vector3d& x, int* hint) const {
  int v = hint ? *hint : -1;
  if (v < 0 || v >= num_vertices() || !used(v)) {
    double best = std::numeric_limits<double>::infinity();
    for (int u = 0; u < num_vertices(); ++u) {
      const double d = used(u) ? (position(u) - x).squaredNorm() : best;
      if (d < best) {
        best = d;
        v = u;
      }
    }
  }
  double d = (position(v) - x).squaredNorm();
  for (int step = 0; step < 10000; ++step) {
    int next = v;
    for (const int* u = neighbours_begin(v); u != neighbours_end(v); ++u) {
      const double du = (mesh_.vertices.row(*u).transpose() - x).squaredNorm();
      if (du < d) {
        d = du;
        next = *u;
      }
    }
    if (next == v) break;
    v = next;
  }
  if (hint) *hint = v;
  return v;
}

MeshFoot MeshSurface::ClosestPoint(const Eigen::Vector3d& x, int* hint) const {
  const int v = NearestVertex(x, hint);
  MeshFoot foot;
  double best = std::numeric_limits<double>::infinity();
  for (const int* f = faces_begin(v); f != faces_end(v); ++f) {
    const Eigen::Vector3d p =
        ClosestOnTriangle(x, mesh_.vertices.row(mesh_.faces(*f, 0)).transpose(),
                          mesh_.vertices.row(mesh_.faces(*f, 1)).transpose(),
                          mesh_.vertices.row(mesh_.faces(*f, 2)).transpose());
    const double d = (p - x).squaredNorm();
    if (d < best) {
      best = d;
      foot.face = *f;
      foot.point = p;
    }
  }
  return foot;
}

Eigen::Vector3d MeshSurface::NormalAt(const MeshFoot& foot) const {
  const Eigen::Vector3d a = position(mesh_.faces(foot.face, 0));
  const Eigen::Vector3d b = position(mesh_.faces(foot.face, 1));
  const Eigen::Vector3d c = position(mesh_.faces(foot.face, 2));
  const Eigen::Vector3d n = (b - a).cross(c - a);
  const double area2 = n.squaredNorm();
  Eigen::Vector3d w;
  w[1] = (foot.point - a).cross(c - a).dot(n) / area2;
  w[2] = (b - a).cross(foot.point - a).dot(n) / area2;
  w[0] = 1 - w[1] - w[2];
  const Eigen::Vector3d& n0 = normal(mesh_.faces(foot.face, 0));
  Eigen::Vector3d blend = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d& nk = normal(mesh_.faces(foot.face, k));
    blend += std::clamp(w[k], 0.0, 1.0) * (nk.dot(n0) < 0 ? -nk : nk);
  }
  return blend.norm() > 0 ? blend.normalized() : n0;
}

bool MeshSurface::PlaneAt(const Eigen::Vector3d& x, int* hint, TangentPlane* plane) const {
  const MeshFoot foot = ClosestPoint(x, hint);
  if (foot.face < 0 || (foot.point - x).norm() > 2 * max_edge_) return false;
  plane->point = foot.point;
  plane->normal = NormalAt(foot);
  return true;
}

std::int64_t MeshSurface::memory_bytes() const {
  return mesh_.vertices.size() * 8 + mesh_.faces.size() * 4 +
         static_cast<std::int64_t>(neighbour_start_.size() + vertex_face_start_.size()) * 8 +
         static_cast<std::int64_t>(neighbours_.size() + vertex_faces_.size() + adjacent_.size() +
                                   component_.size()) *
             4 +
         static_cast<std::int64_t>(normal_.size()) * 24;
}

}  // namespace bespoke
