// Ray casting and point-to-surface distances against triangle meshes, over
// CGAL's AABB tree (double precision), rays spread over threads (OpenMP).
// The virtual scanner casts its sensors' rays with it; tests measure scan
// noise against the mesh with Distance().
//
// State (the tree) is built at the first query and reused, hence a class.
// Queries are const and may run concurrently once the tree is built.
#ifndef BESPOKE_ORACLE_SCAN_SIM_RAYCASTER_H_
#define BESPOKE_ORACLE_SCAN_SIM_RAYCASTER_H_

#include <memory>

#include "scanners/core/types.h"

namespace bespoke {

struct RayHits {
  Eigen::VectorXd distance;  // #R, along the (unit) ray; +infinity for a miss
  Eigen::VectorXi geometry;  // #R, id returned by AddMesh; -1 for a miss
  Eigen::VectorXi face;      // #R, face of that mesh; -1 for a miss
  Eigen::MatrixX3d
      normal;  // #R x 3, unit normal of the hit face, (b - a) x (c - a): outwards for CCW faces
};

class MeshRaycaster {
 public:
  MeshRaycaster();
  ~MeshRaycaster();
  MeshRaycaster(const MeshRaycaster&) = delete;
  MeshRaycaster& operator=(const MeshRaycaster&) = delete;

  // Adds a mesh (any unit; rays and distances use the same). Returns its id
  // (0, 1, ... in order). InputError for an empty mesh, bad indices or
  // non-finite coordinates. Must not be called after the first query.
  int AddMesh(const TriangleMesh& mesh);

  // First hit of each ray: origins #R x 3, directions #R x 3 (normalised
  // here). InputError for shape mismatches or zero directions.
  RayHits Cast(const Eigen::MatrixX3d& origins, const Eigen::MatrixX3d& directions) const;

  // Unsigned distance from each point (#P x 3) to the nearest surface.
  Eigen::VectorXd Distance(const Eigen::MatrixX3d& points) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_SCAN_SIM_RAYCASTER_H_
