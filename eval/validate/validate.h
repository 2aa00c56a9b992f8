// Validation of the cloud geodesics against an exact reference: the scan is
// reconstructed into a mesh (Poisson, surface_reconstruction.h) and CGAL's
// exact geodesics (oracle/truth/exact_geodesics.h) are computed on it
// between the same end points. For `bespoke validate`; slow (an exact
// propagation per distinct start point) and memory-hungry (CGAL), so for
// checking a scan or a setting, not for production runs.
//
// Inputs: the scan (points, optional normals; mm) and pairs of end points in
// the same frame (mm). Output per pair: cloud length, mesh length, absolute
// and relative difference; a pair that fails on one side (not connected,
// point off the surface) carries the error text instead and is left out of
// the summary. Throws InputError for an empty pair list or bad options.
#ifndef BESPOKE_EVAL_VALIDATE_VALIDATE_H_
#define BESPOKE_EVAL_VALIDATE_VALIDATE_H_

#include <string>
#include <vector>

#include "eval/validate/surface_reconstruction.h"
#include "measure/cloud_geodesic/cloud_geodesics.h"

namespace bespoke {

struct GeodesicPair {
  std::string name;
  Eigen::Vector3d from = Eigen::Vector3d::Zero();  // mm
  Eigen::Vector3d to = Eigen::Vector3d::Zero();    // mm
};

struct ValidateOptions {
  CloudGeodesicsOptions geodesics;
  PoissonOptions poisson;
  void Check() const;
};

struct PairComparison {
  GeodesicPair pair;
  double cloud_mm = 0, mesh_mm = 0;  // NaN when that side failed
  double abs_diff_mm = 0;            // |cloud - mesh|
  double rel_diff = 0;               // (cloud - mesh) / mesh
  std::string error;                 // empty when both sides succeeded
};

struct ValidationReport {
  std::vector<PairComparison> pairs;
  Eigen::Index mesh_vertices = 0, mesh_faces = 0;
  int compared = 0;                                                   // pairs without error
  double mean_abs_mm = 0, max_abs_mm = 0, mean_rel = 0, max_rel = 0;  // over `compared`
  double cloud_time_s = 0, reconstruction_time_s = 0, exact_time_s = 0;
  TriangleMesh mesh;  // the reference mesh (mm)
};

ValidationReport ValidateGeodesics(const ValidateOptions& options, const PointCloud& cloud,
                                   const std::vector<GeodesicPair>& pairs,
                                   Progress* progress = nullptr);

// `count` pairs of scan points, deterministic (seeded), whose straight-line
// distance lies between 20 % and 60 % of the cloud's bounding-box diagonal.
std::vector<GeodesicPair> SpreadPairs(const PointCloud& cloud, int count, unsigned seed = 1);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_VALIDATE_VALIDATE_H_
