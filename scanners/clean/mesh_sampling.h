// Meshes as scans: a booth's mesh export (OBJ, PLY, STL, OFF; often
// decimated, with uneven triangles, watertight or not) is sampled over its
// faces into an even cloud at the density the pipeline wants, never taken
// as its vertices (a decimated mesh's vertices are few and uneven: dense on
// the face and hands, sparse on the trunk).
//
// Sampling: Open3D's area-weighted uniform sampling of the triangles
// (TriangleMesh::SamplePointsUniformly): the expected number of points in
// any part of the surface is its area x points_per_cm2, whatever the
// triangles' sizes. Each point gets its face's normal (the mesh's winding;
// cleaning re-estimates normals anyway). Deterministic for a seed.
#ifndef BESPOKE_SCANNERS_CLEAN_MESH_SAMPLING_H_
#define BESPOKE_SCANNERS_CLEAN_MESH_SAMPLING_H_

#include <cstdint>
#include <filesystem>

#include "scanners/core/types.h"
#include "scanners/io/scan_io.h"

namespace bespoke {

struct MeshSamplingOptions {
  // Points per square centimetre of surface; default 20 (about a booth
  // scan's density, several points per 4 mm cleaning voxel). 0.1-1000.
  double points_per_cm2 = 20;
  // At most this many points (the density is lowered to fit); default 5
  // million.
  std::int64_t max_points = 5'000'000;
  // Seed of the sampling; default 1.
  int seed = 1;
  // Throws InputError naming the field when a value is out of range.
  void Check() const;
};

// Samples `mesh` over its faces.
// @param[in] mesh  #V x 3 vertex positions (mm, any frame) and #F x 3 faces.
// @return a cloud in the mesh's frame (mm): round(area_cm2 x points_per_cm2)
//   points (at least 1 per non-degenerate mesh, capped by max_points), each
//   with its face's unit normal. Degenerate faces get no points.
// Throws InputError for a mesh without faces or of zero area.
PointCloud SampleMeshSurface(const MeshSamplingOptions& options, const TriangleMesh& mesh);

// Reads a scan for measuring: a point cloud as ReadScan reads it; a file
// with faces (a mesh) is read with ReadMesh, put in millimetres with the
// same unit rule as a cloud (ReadOptions::units, else the guess from the
// extent), and sampled with SampleMeshSurface. The report keeps the file's
// counts (points_in_file = vertices, faces_in_file) and says in `warnings`
// that the faces were sampled and how many points they gave.
// Throws InputError for malformed files (ReadScan's and ReadMesh's errors).
Scan ReadScanSamplingMeshes(const ReadOptions& read, const MeshSamplingOptions& sampling,
                            const std::filesystem::path& file);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_MESH_SAMPLING_H_
