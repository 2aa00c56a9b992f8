// A triangle mesh from a scan's points by screened Poisson reconstruction
// (Kazhdan and Hoppe 2013, via Open3D; Open3D types stay in the .cc). Used only
// to VALIDATE the cloud geodesics against exact mesh geodesics
// (`bespoke validate`), never to measure.
//
// Input: points (#P x 3, mm) with normals when the scan has them (#P x 3,
// outward or at least consistently oriented); otherwise normals are estimated
// by PCA of `normal_neighbours` points and oriented consistently over a
// k-NN graph (Hoppe et al. 1992). Poisson closes every hole, so vertices
// farther than trim_distance_mm from any scan point are removed, and the mesh
// is cleaned into an oriented 2-manifold (degenerate and duplicated faces,
// non-manifold edges and vertices removed) that CGAL's exact geodesics accept.
// Meshes above max_vertices are decimated (quadric error) first.
//
// Output in mm. Throws InputError for fewer than 100 points or bad options,
// InternalError when nothing is left after cleaning.
#ifndef BESPOKE_EVAL_VALIDATE_SURFACE_RECONSTRUCTION_H_
#define BESPOKE_EVAL_VALIDATE_SURFACE_RECONSTRUCTION_H_

#include "scanners/core/progress.h"
#include "scanners/core/types.h"

namespace bespoke {

struct PoissonOptions {
  int depth = 9;                // octree depth; default 9 (about 2 mm detail on a body)
  int normal_neighbours = 30;   // k for normal estimation and orientation; default 30
  double trim_distance_mm = 0;  // 0 (default) = 5 x the median point spacing
  int max_vertices = 60000;     // decimate above this (CGAL's memory); default 60,000
  void Check() const;           // InputError when out of range
};

TriangleMesh ReconstructPoisson(const PoissonOptions& options, const PointCloud& cloud,
                                Progress* progress = nullptr);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_VALIDATE_SURFACE_RECONSTRUCTION_H_
