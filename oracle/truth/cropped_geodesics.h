// Exact geodesics between pairs of surface points computed on a crop of the
// mesh that provably holds the shortest path: the same answer as
// ExactGeodesics on the whole mesh (exact_geodesics.h), at a fraction of the
// cost when the points are close compared with the mesh's size (a datum
// chain on a body).
//
// Why it is exact: every point p of a path of length L from a to b satisfies
// |p - a| + |p - b| <= L, i.e. the path lies in the ellipsoid
// E(R) = {p : |p - a| + |p - b| <= R} for any R >= L. The crop keeps every
// face that may meet E(R) (a face is kept when one of its vertices v has
// |v - a| + |v - b| <= R + 2 * its longest edge, which covers any face
// meeting E(R)), so a path on the crop is a path on the mesh:
// d_crop >= d_mesh. If the crop's distance d_crop <= R, the mesh's shortest
// path (length d_mesh <= d_crop <= R) lies in E(R), hence on the crop, so
// d_crop = d_mesh. Otherwise R grows to d_crop (then the next crop holds
// the shortest path for sure) or, when b is not reachable on the crop, by
// 1.5x; when the crop would be the whole mesh, the whole mesh is used.
// Vertices where the crop pinches (faces around them forming several fans)
// get their whole star added, so the crop stays a 2-manifold with boundary
// (a vertex on the shortest path has its whole star in the crop anyway).
//
// Inputs: a TriangleMesh with ExactGeodesics' requirements (oriented
// 2-manifold, no degenerate faces), any unit; surface points on it.
// State reused across calls (hence a class): each face's longest edge and
// the faces around each vertex. Not thread-safe; one object per thread.
// Failure: as ExactGeodesics (InputError for an unusable mesh, a bad surface
// point, or points on different connected components).
#ifndef BESPOKE_ORACLE_TRUTH_CROPPED_GEODESICS_H_
#define BESPOKE_ORACLE_TRUTH_CROPPED_GEODESICS_H_

#include <cstdint>
#include <vector>

#include "oracle/body/body.h"
#include "oracle/truth/exact_geodesics.h"
#include "scanners/core/types.h"

namespace bespoke {

struct CroppedGeodesicsOptions {
  // First crop: R = initial_ratio * |a - b| + initial_margin (mesh units).
  double initial_ratio = 1.05;  // default 1.05 (truth_bench compares 1.0-1.3 on bodies)
  double initial_margin = 20;   // default 20 (mm on a body)
  // Throws InputError when initial_ratio < 1 or initial_margin < 0.
  void Check() const;
};

// What the last calls cost (for benchmarks and reports).
struct CroppedGeodesicsStats {
  std::int64_t queries = 0;       // Distance/Path calls
  std::int64_t propagations = 0;  // CGAL shortest-path trees built (crops tried)
  std::int64_t faces_used = 0;    // sum of the crops' face counts over propagations
  std::int64_t whole_mesh = 0;    // propagations that used the whole mesh
};

class CroppedExactGeodesics {
 public:
  // Throws InputError for bad options or face indices out of range; the
  // mesh's other checks happen on the crops (ExactGeodesics).
  explicit CroppedExactGeodesics(const TriangleMesh& mesh,
                                 const CroppedGeodesicsOptions& options = {});

  // Exact geodesic distance and, with `keep_points`, the path (#K x 3, from
  // `from` to `to`; otherwise `points` is empty).
  GeodesicPath Path(const SurfacePoint& from, const SurfacePoint& to, bool keep_points = true);
  double Distance(const SurfacePoint& from, const SurfacePoint& to) {
    return Path(from, to, false).length;
  }

  const CroppedGeodesicsStats& stats() const { return stats_; }

 private:
  // The faces to keep for the ellipsoid with foci a, b and size `radius`,
  // stars of pinched vertices added.
  std::vector<int> CropFaces(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                             double radius) const;
  void AddPinchedStars(std::vector<char>* keep) const;

  TriangleMesh mesh_;  // a copy
  CroppedGeodesicsOptions options_;
  Eigen::VectorXd longest_edge_;                // #F
  std::vector<std::vector<int>> vertex_faces_;  // #V lists of faces
  CroppedGeodesicsStats stats_;
};

}  // namespace bespoke

#endif  // BESPOKE_ORACLE_TRUTH_CROPPED_GEODESICS_H_
