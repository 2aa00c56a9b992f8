// A grid cell's points split into sheets of surface (thesis Algorithm 4
// keeps one destination per cell; we keep one per sheet, see cloud_grid.h).
//
// SplitSheets: groups of the cell's points connected by steps of at most
// `gap_mm` - and, with unit `normals`, only between points whose normals do
// not point to opposite sides (dot >= 0). Brute force for up to 96 points,
// k-NN (`index`, 12 neighbours, same cell `keys`) for crowded cells.
// MergeCoplanar: then merges groups lying in one plane (within gap_mm / 2 of
// a planar group's PCA plane: a sampling gap, scan lines, grazing angles),
// largest first; groups apart along the normal, or facing the other way by
// their summed normals, stay apart. A group too small or crooked for a plane
// in a cell where no group is planar joins the nearest group.
//
// Inputs: `points` #P x 3 (mm), `normals` #P x 3 unit or null, `run` the
// cell's `count` point indices. Output: groups of point indices. No throws.
#ifndef BESPOKE_MEASURE_CLOUD_GEODESIC_CELL_SHEETS_H_
#define BESPOKE_MEASURE_CLOUD_GEODESIC_CELL_SHEETS_H_

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "measure/cloud_geodesic/point_index.h"

namespace bespoke {

std::vector<std::vector<int>> SplitSheets(const Eigen::MatrixX3d& points,
                                          const Eigen::MatrixX3d* normals, const int* run,
                                          int count, double gap_mm, const PointIndex& index,
                                          const std::vector<std::int64_t>& keys);

std::vector<std::vector<int>> MergeCoplanar(const Eigen::MatrixX3d& points,
                                            const Eigen::MatrixX3d* normals,
                                            std::vector<std::vector<int>> groups, double gap_mm);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_CLOUD_GEODESIC_CELL_SHEETS_H_
