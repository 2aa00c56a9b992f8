// Surface normals of a cleaned body cloud, oriented outwards.
//
// Direction: a least-squares plane through each point and its k nearest
// neighbours (the smallest-eigenvalue eigenvector of their covariance, as
// PCL's NormalEstimation computes it), on the neighbour lists the cleaning
// chain has already built (scanners/clean/neighbours.h).
//
// Orientation (which of n and -n points out of the body), in three steps:
//  1. Exterior test. The points are rasterised into an occupancy grid of
//     `grid_cell_mm` cells, dilated by `hole_close_mm` so that scan holes up
//     to about twice that size are closed, and sealed below the feet (the
//     soles are never scanned, the floor closes them). A flood fill from the
//     grid's border marks the space outside the body. Along +n and -n we step
//     up to `probe_mm`; the side whose first outside cell is nearer is "out".
//     This is right for convex and concave regions alike (feet tops, the
//     crown, under the chin, the small of the back), and undecided where the
//     outside is closed off within the probe (armpit, crotch, touching
//     thighs) or where it leaks inside through a hole larger than the
//     closing. Leaks are caught where it matters most: if the flood reaches
//     a point inside the torso (median x, y of the points 55-65 % up, at
//     60 % of the height), the closing grows by 10 mm, the probe in
//     proportion, up to 3 times (where the inside leaks, forearms in front of
//     the chest block the outward probe and whole patches turn inwards). The
//     closing used is reported.
//  2. Propagation. Undecided points take the orientation that agrees with
//     their already-decided neighbours (sum of n_i . n_j over decided
//     neighbours j), sweep after sweep until nothing changes.
//  3. Fallback. Points with no decided neighbour (a separate fragment) point
//     away from the vertical body axis through the origin.
// The counts of each are reported; a wrong orientation can only come from a
// point whose outside probe is blocked while the inside leaks (a large hole
// in a thin part).
//
// Input: points #P x 3 in the BODY frame (mm, z up, soles at z ~ 0) and
// their neighbour lists. Output: #P x 3 unit normals.
#ifndef BESPOKE_SCANNERS_CLEAN_NORMALS_H_
#define BESPOKE_SCANNERS_CLEAN_NORMALS_H_

#include <Eigen/Core>
#include <cstdint>

#include "scanners/clean/neighbours.h"

namespace bespoke {

struct NormalOptions {
  int k = 16;                   // neighbours in the plane fit. Default 16.
  double grid_cell_mm = 8.0;    // exterior-test grid cell. Default 8 mm.
  double hole_close_mm = 20.0;  // occupancy dilation. Default 20 mm.
  double probe_mm = 48.0;       // longest step along +-n. Default 48 mm.
  int threads = 0;              // <= 0: all available. Default 0.
  // Throws InputError when a value is out of range (needs probe_mm > hole_close_mm).
  void Check() const;
};

struct NormalReport {
  std::int64_t by_exterior = 0;     // oriented by the exterior test
  std::int64_t by_propagation = 0;  // by agreeing with decided neighbours
  std::int64_t by_fallback = 0;     // away from the vertical axis
  std::int64_t degenerate = 0;      // fewer than 2 neighbours: normal from the fallback direction
  double closing_mm = 0;            // hole closing used (hole_close_mm, more if the inside leaked)
};

struct OrientedNormals {
  Eigen::MatrixX3d normals;  // #P x 3, unit
  NormalReport report;
};

// neighbours.k must be >= options.k (InternalError otherwise); lists may be
// shorter where points were removed.
OrientedNormals EstimateOutwardNormals(const NormalOptions& options,
                                       const Eigen::MatrixX3d& body_points,
                                       const NeighbourLists& neighbours);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CLEAN_NORMALS_H_
