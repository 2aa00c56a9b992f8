// Which end each geodesic pair is solved from (internal to
// measure/measurements; geodesic_paths.h uses it).
//
// A propagation from a source settles every grid node nearer than the
// farthest of its targets, so its cost grows with the skin inside that
// radius, not with the path: from the hip, the outside leg length (760 mm)
// floods the trunk, both arms and the other leg; from the ankle, one leg and
// the pelvis. The plan estimates a source's cost as the grid sites within
// the Euclidean ball of that radius (the geodesic ball lies inside it) and
// takes the pairs longest first, each from the end whose propagation grows
// least (a source already planned far enough costs nothing more). An end at
// or in a hole is a source only when both ends are (bridges into it are
// found from the other end's propagation). Groups come largest estimated
// cost first, for two workers taking the next one as they come free.
// Frame and units: the body frame, mm.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_GEODESIC_PLAN_H_
#define BESPOKE_MEASURE_MEASUREMENTS_GEODESIC_PLAN_H_

#include <Eigen/Core>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace bespoke {

struct PlanEnd {
  Eigen::Vector3d position_mm = Eigen::Vector3d::Zero();
  bool at_hole = false;  // at the rim of a hole or in one
};

struct SourceGroup {
  std::string source;
  std::vector<std::pair<std::string, std::string>> pairs;  // each holds `source`
  double radius_mm = 0;                                    // its farthest chord
  double cost = 0;                                         // sites in that ball
};

// `sites`: the grid's node sites (#N x 3, mm). `ends`: every name in
// `pairs`. Every pair lands in exactly one group; deterministic.
std::vector<SourceGroup> PlanSources(const Eigen::MatrixX3d& sites,
                                     const std::map<std::string, PlanEnd>& ends,
                                     const std::set<std::pair<std::string, std::string>>& pairs);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_GEODESIC_PLAN_H_
