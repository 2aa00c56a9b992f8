// Incremental construction of a closed triangle mesh from rings of vertices
// (a helper of the parametric body): quads split along their shorter
// diagonal, ring-to-ring stitching, fans to a pole, and patch orientation.
//
// Orientation: faces are added with the vertex order given; a patch (the
// faces added since a mark) can then be made consistent with the faces
// before it through the edges they share (OrientPatchLike).
#ifndef BESPOKE_ORACLE_BODY_MESH_BUILDER_H_
#define BESPOKE_ORACLE_BODY_MESH_BUILDER_H_

#include <array>
#include <vector>

#include "scanners/core/types.h"

namespace bespoke {

class MeshBuilder {
 public:
  int Add(const Eigen::Vector3d& position);
  std::vector<int> AddRing(const std::vector<Eigen::Vector3d>& positions);
  const Eigen::Vector3d& position(int vertex) const {
    return vertices_[static_cast<size_t>(vertex)];
  }
  // Moves an existing vertex (faces unchanged). InternalError when the
  // position is not finite.
  void Move(int vertex, const Eigen::Vector3d& position);
  int num_vertices() const { return static_cast<int>(vertices_.size()); }
  size_t num_faces() const { return faces_.size(); }

  void Triangle(int a, int b, int c);
  // The quad a-b-c-d (in this cyclic order) as two triangles, split along
  // the shorter diagonal.
  void Quad(int a, int b, int c, int d);
  // Quads (r0[m], r0[m+1], r1[m+1], r1[m]) between two closed rings of
  // equal length.
  void Stitch(const std::vector<int>& r0, const std::vector<int>& r1);
  // Triangles closing `ring` at `pole`, oriented like Stitch(ring, {pole...}).
  void Fan(const std::vector<int>& ring, int pole);

  // Splits edges: each entry is an edge (a, b) of the mesh (either
  // direction) and the new vertices between a and b, in order from a. Every
  // face using the edge is replaced by a fan from its opposite vertex, so the
  // mesh stays closed and consistently oriented. InternalError when an edge
  // is missing or a face would be split twice.
  void SplitEdges(const std::vector<std::pair<std::pair<int, int>, std::vector<int>>>& splits);

  // Flips faces [first, num_faces()) when they disagree with the faces
  // before `first` on a shared edge. InternalError when they share no edge
  // or disagree among themselves.
  void OrientPatchLike(size_t first);
  // Reverses every face.
  void FlipAll();

  TriangleMesh Build() const;

 private:
  std::vector<Eigen::Vector3d> vertices_;
  std::vector<std::array<int, 3>> faces_;
};

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_BODY_MESH_BUILDER_H_
