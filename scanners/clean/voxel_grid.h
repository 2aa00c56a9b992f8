// Voxel-grid down-sampling: one point per occupied cube of a regular grid, at
// the centroid of the points inside it, so that the cloud has a roughly
// uniform spacing of about one leaf and its noise is averaged down.
//
// The grid is anchored at the origin (cells [i*leaf, (i+1)*leaf)), as PCL's
// VoxelGrid does. Bespoke keeps its own implementation instead of
// pcl::VoxelGrid because PCL's (1) silently returns the input unchanged when
// the bounding box has more than 2^31 cells (a stray point 10 m away at a 4 mm
// leaf is enough) and (2) averages only the fields of one PCL point type,
// while this one averages every attribute of a PointCloud: positions,
// normals (re-normalised), colours and per-point scalars.
//
// Input: cloud, #P points (mm, any frame), finite positions with |coordinate|
// < 1e7 mm (CleanScan drops the others first). Output: #V <= #P points in
// grid-cell order (deterministic).
#ifndef BESPOKE_SCANNERS_CLEAN_VOXEL_GRID_H_
#define BESPOKE_SCANNERS_CLEAN_VOXEL_GRID_H_

#include "scanners/core/types.h"

namespace bespoke {

struct VoxelGridOptions {
  // Cube edge, mm: the output spacing the later stages are tuned for.
  // Default 4 mm.
  double leaf_mm = 4.0;
  // Throws InputError unless 0.1 <= leaf_mm <= 1000.
  void Check() const;
};

PointCloud VoxelGridDownsample(const VoxelGridOptions& options, const PointCloud& cloud);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_VOXEL_GRID_H_
