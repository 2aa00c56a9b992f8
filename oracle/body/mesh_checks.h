// Checks that a triangle mesh is a closed, consistently oriented 2-manifold
// without self-intersections: what the oracle's bodies promise.
//
// AnalyzeTopology is exact combinatorics (no tolerances). SelfIntersects uses
// CGAL's Polygon_mesh_processing::does_self_intersect with exact predicates
// (two faces sharing a vertex or an edge only intersect when they overlap
// beyond it). Meshes in any unit.
#ifndef BESPOKE_ORACLE_BODY_MESH_CHECKS_H_
#define BESPOKE_ORACLE_BODY_MESH_CHECKS_H_

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

struct MeshTopology {
  std::int64_t vertices_used = 0;  // vertices referenced by a face
  std::int64_t edges = 0;          // undirected edges
  std::int64_t faces = 0;
  std::int64_t boundary_edges = 0;         // edges used by one face
  std::int64_t non_manifold_edges = 0;     // edges used by more than two faces
  std::int64_t misoriented_edges = 0;      // edges whose two faces run the same way along them
  std::int64_t non_manifold_vertices = 0;  // vertices whose faces form more than one fan
  std::int64_t degenerate_faces = 0;       // repeated vertex or zero area
  std::int64_t components = 0;             // connected components (through edges)
  std::int64_t euler_characteristic = 0;   // V - E + F over used vertices
  double signed_volume = 0;                // > 0 when the faces point outwards (closed meshes)

  // Closed, 2-manifold, consistently oriented outwards, one component of
  // genus 0 (Euler characteristic 2), no degenerate face.
  bool IsClosedSphere() const;
  std::string Describe() const;  // one line, for test failures and logs
};

MeshTopology AnalyzeTopology(const TriangleMesh& mesh);

// True when two faces intersect other than along their shared vertices/edges.
bool SelfIntersects(const TriangleMesh& mesh);

// The pairs of faces (rows of mesh.faces, first < second) that intersect,
// by the same rule; sorted. Same failures as SelfIntersects.
std::vector<std::pair<int, int>> SelfIntersectingFacePairs(const TriangleMesh& mesh);

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_BODY_MESH_CHECKS_H_
