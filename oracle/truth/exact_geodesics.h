// Exact geodesic distances and shortest paths on a triangle mesh: the
// reference every approximate geodesic in Bespoke is measured against.
//
// Wraps CGAL's Surface_mesh_shortest_path (Xin and Wang's improvement of the
// Chen-Han algorithm: exact shortest paths over the polyhedral surface, up to
// floating-point rounding). The CGAL types stay in exact_geodesics.cc.
//
// Inputs: a TriangleMesh in any length unit (results are in the same unit).
// It must be an oriented 2-manifold, possibly with boundary, without
// degenerate (zero-area) faces; it need not be connected (points on different
// components are unreachable). Unused vertices are allowed.
//
// State reused across calls (hence a class): the CGAL mesh, its AABB tree for
// point location, and the shortest-path tree of the last source point, so
// chains of queries from one source cost one propagation.
//
// Cost: a propagation is super-linear in #V (measured by the data README on a
// machine like the CI's: 0.5 s on the 13k-vertex MakeHuman body, 30 s on a
// 109k-vertex bunny) and CGAL's memory grows fast: about 5.6 GB peak on the
// 116k-vertex remeshed body. Keep meshes for exact references at tens of
// thousands of vertices. For distances between a few point pairs,
// CroppedExactGeodesics (cropped_geodesics.h) gives the same values on
// provably sufficient crops, 20-50x cheaper on bodies.
//
// Not thread-safe (queries update the cached tree); use one object per thread.
#ifndef BESPOKE_ORACLE_TRUTH_EXACT_GEODESICS_H_
#define BESPOKE_ORACLE_TRUTH_EXACT_GEODESICS_H_

#include <memory>

#include "oracle/body/body.h"
#include "scanners/core/types.h"

namespace bespoke {

struct GeodesicPath {
  double length = 0;        // mesh units
  Eigen::MatrixX3d points;  // #K x 3 polyline from `from` to `to` (K >= 2), mesh units
};

class ExactGeodesics {
 public:
  // Builds the CGAL mesh and AABB tree. Throws InputError naming the face when
  // the mesh is not an oriented 2-manifold (an edge shared by more than two
  // faces, faces with opposite orientation across an edge, a non-manifold
  // vertex), when a face repeats a vertex or is degenerate (zero area), when a
  // coordinate is not finite, or when there are no faces.
  explicit ExactGeodesics(const TriangleMesh& mesh);
  ~ExactGeodesics();
  ExactGeodesics(ExactGeodesics&&) noexcept;
  ExactGeodesics& operator=(ExactGeodesics&&) noexcept;

  const TriangleMesh& mesh() const;

  // The surface point closest to `position` (mesh units), via the AABB tree.
  SurfacePoint Locate(const Eigen::Vector3d& position) const;
  // A surface point exactly at vertex `vertex` (InputError when out of range or
  // not used by any face).
  SurfacePoint AtVertex(int vertex) const;

  // Geodesic distance between two surface points (mesh units). Throws
  // InputError when a point's face is out of range or its barycentric weights
  // are not non-negative summing to 1 (tolerance 1e-6), and when `to` is not
  // reachable from `from` (different connected components).
  double Distance(const SurfacePoint& from, const SurfacePoint& to);
  // The same between 3-D points, each first snapped to the surface (Locate).
  double Distance(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

  // The shortest path itself; its polyline crosses faces along straight
  // segments and bends only at vertices (where the geodesic passes through a
  // saddle vertex). Errors as Distance.
  GeodesicPath Path(const SurfacePoint& from, const SurfacePoint& to);
  GeodesicPath Path(const Eigen::Vector3d& from, const Eigen::Vector3d& to);

  // Geodesic distance from `source` to every vertex: #V vector, mesh units,
  // +infinity for unreachable or unused vertices.
  Eigen::VectorXd DistancesToVertices(const SurfacePoint& source);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_TRUTH_EXACT_GEODESICS_H_
