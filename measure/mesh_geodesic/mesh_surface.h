// A triangle mesh prepared for the thesis's mesh geodesics (section 3.4):
// validated, with the adjacency the propagation and the projection walk need,
// and the tangent planes of the geodesic curvature flow (Eq 3.13-3.17).
//
// Validation (MeshPrepOptions; every kind of bad mesh):
//   - non-manifold edges (an edge used by more than two faces): REJECTED with
//     InputError "<name>: ..." naming an example edge - the projection walk
//     (Algorithm 1) crosses faces through edges and needs at most two per edge;
//   - degenerate faces (a repeated vertex, or area below `degenerate_area`
//     times the mean face area): DROPPED and counted (a zero-area face carries
//     no surface; its edges stay in the vertex graph through their other faces);
//   - unreferenced (isolated) vertices: kept but unused; their distance is NaN;
//   - several components: handled; vertices on components other than the
//     source's are unreachable (NaN), counted in the report;
//   - non-manifold vertices (bow ties) and misoriented faces: handled; the
//     propagation runs on the vertex graph and the normals come from PCA of
//     n n^T, which does not care about a face normal's sign;
//   - no faces left, or non-finite coordinates: REJECTED.
// Any unit; results are in the mesh's unit.
//
// Tangent planes: every used vertex gets the normal of the PCA of its one-ring
// face normals (Eq 3.13: the dominant eigenvector of sum area_f n_f n_f^T; the
// thesis's "smallest eigenvalue" is the rule for PCA of points, not of
// normals). PlaneAt(x) walks from the hint to the vertex nearest x, takes the
// closest point on that vertex's faces as the plane's point and the
// barycentric blend of the face's vertex normals as its normal.
#ifndef BESPOKE_MEASURE_MESH_GEODESIC_MESH_SURFACE_H_
#define BESPOKE_MEASURE_MESH_GEODESIC_MESH_SURFACE_H_

#include <cstdint>
#include <string>
#include <vector>

#include "measure/mesh_geodesic/curvature_flow.h"
#include "scanners/core/types.h"

namespace bespoke {

struct MeshPrepOptions {
  // A face whose area is below this times the mean face area is degenerate
  // and dropped. Default 1e-10 (dimensionless).
  double degenerate_area = 1e-10;
  void Check() const;  // InputError when out of range
};

struct MeshPrepReport {
  std::int64_t vertices = 0;               // in the file
  std::int64_t unreferenced_vertices = 0;  // used by no face (kept, unreachable)
  std::int64_t faces = 0;                  // in the file
  std::int64_t dropped_faces = 0;          // degenerate faces removed
  std::int64_t boundary_edges = 0;         // edges with one face (holes, open meshes)
  std::int64_t non_manifold_vertices = 0;  // bow-tie vertices (handled)
  std::int64_t misoriented_edges = 0;      // faces disagreeing across an edge (handled)
  std::int64_t components = 0;             // connected components of used vertices
  std::vector<std::string> warnings;       // one line per handled problem
};

// A point on the mesh: inside face `face` at `point` (mesh units).
struct MeshFoot {
  int face = -1;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

class MeshSurface : public TangentPlaneSource {
 public:
  // Validates and indexes `mesh` (copied). `name` (usually the file) starts
  // every error message. Throws InputError as listed above.
  MeshSurface(const MeshPrepOptions& options, const TriangleMesh& mesh, const std::string& name);

  const TriangleMesh& mesh() const { return mesh_; }  // without the dropped faces
  const MeshPrepReport& report() const { return report_; }
  const std::string& name() const { return name_; }
  int num_vertices() const { return static_cast<int>(mesh_.vertices.rows()); }
  bool used(int v) const { return vertex_face_start_[v + 1] > vertex_face_start_[v]; }
  int component(int v) const { return component_[static_cast<size_t>(v)]; }  // -1 unused
  Eigen::Vector3d position(int v) const { return mesh_.vertices.row(v).transpose(); }
  const Eigen::Vector3d& normal(int v) const { return normal_[static_cast<size_t>(v)]; }
  double mean_edge_length() const { return mean_edge_; }
  double max_edge_length() const { return max_edge_; }

  // One-ring neighbour vertices and incident faces of vertex v (CSR ranges).
  const int* neighbours_begin(int v) const { return neighbours_.data() + neighbour_start_[v]; }
  const int* neighbours_end(int v) const { return neighbours_.data() + neighbour_start_[v + 1]; }
  const int* faces_begin(int v) const { return vertex_faces_.data() + vertex_face_start_[v]; }
  const int* faces_end(int v) const { return vertex_faces_.data() + vertex_face_start_[v + 1]; }
  // The face across edge k (vertices k, k+1 mod 3) of face f; -1 on a boundary.
  int adjacent_face(int f, int k) const { return adjacent_[3 * static_cast<size_t>(f) + k]; }

  // The used vertex nearest `x` reached by a greedy walk over the vertex
  // graph from `*hint` (updated). A hint < 0 starts a linear scan.
  int NearestVertex(const Eigen::Vector3d& x, int* hint) const;
  // The closest point to `x` on the faces of NearestVertex(x, hint).
  MeshFoot ClosestPoint(const Eigen::Vector3d& x, int* hint) const;
  // The blended vertex normal at a point of face f (unit).
  Eigen::Vector3d NormalAt(const MeshFoot& foot) const;
  // TangentPlaneSource: false when `x` is more than two longest edges from
  // the mesh near its hint (it left the surface).
  bool PlaneAt(const Eigen::Vector3d& x, int* hint, TangentPlane* plane) const override;

  std::int64_t memory_bytes() const;

 private:
  void BuildAdjacency();
  void ComputeNormalsAndComponents();

  std::string name_;
  TriangleMesh mesh_;
  MeshPrepReport report_;
  std::vector<std::int64_t> neighbour_start_, vertex_face_start_;
  std::vector<int> neighbours_, vertex_faces_, adjacent_, component_;
  std::vector<Eigen::Vector3d> normal_;
  double mean_edge_ = 0, max_edge_ = 0;
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MESH_GEODESIC_MESH_SURFACE_H_
