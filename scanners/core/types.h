// The geometry types every Bespoke library speaks in its public headers.
//
// Conventions (libigl style): one row per element, shapes written as
// `#P x 3`. Positions are doubles. Inside Bespoke every length is in
// millimetres; a cloud fresh from a reader is in the file's own units until
// the units are resolved (see scanners/core/units.h and scanners/io/scan_io.h).
//
// The body frame (what measure/ produces and everything downstream uses):
//   millimetres, +z up, feet on z = 0, origin centred between the feet,
//   the person faces +y, so the person's RIGHT side is +x and LEFT is -x.
// A rigid (or similarity, when units change) transform from frame A to
// frame B is named `b_from_a`, e.g. `body_from_scanner`.
#ifndef BESPOKE_SCANNERS_CORE_TYPES_H_
#define BESPOKE_SCANNERS_CORE_TYPES_H_

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace bespoke {

using ColorMatrix = Eigen::Matrix<std::uint8_t, Eigen::Dynamic, 3>;

// An unorganised point cloud.
struct PointCloud {
  Eigen::MatrixX3d points;   // #P x 3 positions
  Eigen::MatrixX3d normals;  // #P x 3 unit normals, or 0 x 3 when absent
  ColorMatrix colors;        // #P x 3 RGB 0-255, or 0 x 3 when absent
  // Extra per-point scalars kept from the file or added by an algorithm,
  // name -> #P vector, e.g. "intensity", "distance_mm".
  std::map<std::string, Eigen::VectorXd> scalars;

  Eigen::Index size() const { return points.rows(); }
  bool empty() const { return points.rows() == 0; }
  bool has_normals() const { return normals.rows() == points.rows() && !empty(); }
  bool has_colors() const { return colors.rows() == points.rows() && !empty(); }
  // Throws InternalError when an attribute's row count is neither 0 nor #P.
  void CheckShapes() const;
  // Keeps the rows listed in `indices` (any order, repeats allowed), for
  // every attribute.
  PointCloud Select(const std::vector<Eigen::Index>& indices) const;
};

// A triangle mesh. Faces are counter-clockwise seen from outside.
struct TriangleMesh {
  Eigen::MatrixX3d vertices;  // #V x 3 positions
  Eigen::MatrixX3i faces;     // #F x 3 vertex indices into `vertices`

  Eigen::Index num_vertices() const { return vertices.rows(); }
  Eigen::Index num_faces() const { return faces.rows(); }
  // Throws InputError when a face index is out of range.
  void CheckIndices() const;
};

// Applies `b_from_a` (4x4 similarity) to points, and its rotation to normals.
void TransformInPlace(const Eigen::Affine3d& b_from_a, PointCloud* cloud);
void TransformInPlace(const Eigen::Affine3d& b_from_a, TriangleMesh* mesh);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_TYPES_H_
