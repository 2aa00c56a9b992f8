// Geodesic paths between pairs of datum points over one scan, for the
// lengths of Measure (internal to measure/measurements; measure.h is the
// interface).
//
// Each pair is solved from the end whose propagation floods the least skin,
// sharing sources where one already reaches far enough (geodesic_plan.h),
// on two worker threads that each take the next group of pairs when free.
// A tape crosses the scan's
// holes (the crotch and the armpits no sensor saw): where a datum point
// lies in a hole (farther than tolerance_mm from every scan point, up to
// max_bridge_mm), at one (its nearest scan point lies on the rim of an
// unscanned region), or where the path over the scan is a detour (longer
// than detour_ratio times the chord, as a whole or in its part within
// first_bridge_mm of either end, as round a buttock when the skin under
// a crotch was not seen but the thighs round the datum point were), the
// path may end with a bridge from a scan point p to the datum point, chosen
// to minimise geodesic(other end, p) + bridge, p within first_bridge_mm of
// the datum point, or within max_bridge_mm when that finds none or still
// detours. The bridge is the circular arc meeting p's tangent plane and the
// hidden skin's (the mean normal around the datum point) at equal angles,
// not the straight chord, which cuts inside a curved crease. Except from a
// hole, the chord must leave the surface (cross the hole, not cut through
// skin) and the bridge is taken only when shorter than the path over the
// scan. Each entry says how much of its length was bridged.
// Frame and units: the body frame, mm.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_GEODESIC_PATHS_H_
#define BESPOKE_MEASURE_MEASUREMENTS_GEODESIC_PATHS_H_

#include <Eigen/Core>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "measure/cloud_geodesic/cloud_geodesics.h"
#include "measure/landmarks/landmarks.h"
#include "scanners/core/progress.h"

namespace bespoke {

struct GeodesicPathOptions {
  double tolerance_mm = 20;     // default 20: a datum point farther from the scan is in a hole
  double first_bridge_mm = 80;  // default 80: bridges are sought this far first...
  double max_bridge_mm = 120;   // default 120: ...then this far (none found, or still a detour)
  double rim_radius_mm = 25;    // default 25: neighbourhood telling a hole's rim from open skin
  double rim_offset = 0.45;     // default 0.45: a rim's neighbours' mean unit direction length
  double off_surface_mm = 4;    // default 4: a bridge crossing a hole stays this far off the scan
  double detour_ratio = 1.25;   // default 1.25: a path this many chords long seeks bridges
  int threads = 2;              // default 2: workers (sharing one grid, each its own cache)
};

struct GeodesicPath {
  double length_mm = 0;
  double bridged_mm = 0;    // of length_mm, the bridges (arcs) over unscanned skin
  Eigen::MatrixX3d points;  // #K x 3, from the pair's first point to its second
  std::string error;        // non-empty: no path over the scan
};

class GeodesicPaths {
 public:
  void Need(const std::string& a, const std::string& b) {
    if (a != b) pending_.insert(std::minmax(a, b));
  }
  bool empty() const { return pending_.empty(); }
  // `normals`: the cloud's outward unit normals (#P x 3, the points of
  // `geodesics`), or 0 x 3: the rim test then uses the raw directions.
  void Solve(const GeodesicPathOptions& options, CloudGeodesics& geodesics,
             const Eigen::MatrixX3d& normals, const LandmarkSet& set, Progress* progress);
  // The path from a to b (a == b: a single point); nullptr when not solved.
  const GeodesicPath* Get(const std::string& a, const std::string& b) const;

 private:
  struct End {
    Eigen::Vector3d start = Eigen::Vector3d::Zero();  // where the path starts on the scan
    double bridge_mm = 0;  // in a hole: straight bridge from `start` to the datum point
    bool in_hole = false;  // farther than tolerance_mm from the scan
    bool at_rim = false;   // on the scan but at the rim of a hole
  };
  End Classify(const GeodesicPathOptions& o, const CloudGeodesics& geodesics,
               const Eigen::MatrixX3d& normals, const Eigen::Vector3d& x) const;
  GeodesicPath SolvePair(const GeodesicPathOptions& o, CloudGeodesics& geodesics,
                         const LandmarkSet& set, const std::string& source,
                         const std::pair<std::string, std::string>& pair) const;

  // Replaces `path` (from `from` to `datum`) by the path from `from` to a
  // scan point plus a bridge across a hole into `datum`, when one is shorter.
  void BridgeInto(const GeodesicPathOptions& o, CloudGeodesics& geodesics,
                  const Eigen::Vector3d& from, const Eigen::Vector3d& datum,
                  GeodesicPath* path) const;

  std::set<std::pair<std::string, std::string>> pending_;
  std::map<std::pair<std::string, std::string>, GeodesicPath> solved_;
  std::map<std::string, End> ends_;
  Eigen::MatrixX3d normals_;  // the scan's normals, or 0 x 3
  GeodesicPath self_;
};

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_GEODESIC_PATHS_H_
