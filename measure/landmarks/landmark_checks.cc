// The plausibility checks run on a finished landmark set (landmark_checks.h).
#include "measure/landmarks/landmark_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace bespoke::landmarks {
namespace {

// Left and right points of a pair should mirror each other; a height
// difference beyond 40 mm (people are not that asymmetric) is flagged.
void CheckSymmetry(LandmarkSet* set) {
  for (auto& [name, right] : set->points) {
    const std::string suffix = "_right";
    if (name.size() <= suffix.size() ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    auto left = set->points.find(name.substr(0, name.size() - suffix.size()) + "_left");
    if (left == set->points.end()) continue;
    if (std::abs(left->second.position_mm.z() - right.position_mm.z()) > 40) {
      for (Landmark* l : {&right, &left->second}) {
        l->flags.push_back("asymmetric");
        l->confidence = std::min(l->confidence, 0.4);
      }
    }
  }
}

// Flags `name` as placed against body proportions (confidence <= 0.3) with
// the reason in its method tag.
void Implausible(LandmarkSet* set, const std::string& name, const std::string& why) {
  auto it = set->points.find(name);
  if (it == set->points.end()) return;
  Landmark& l = it->second;
  if (std::find(l.flags.begin(), l.flags.end(), "implausible") != l.flags.end()) return;
  l.flags.push_back("implausible");
  l.method += " (" + why + ")";
  l.confidence = std::min(l.confidence, 0.3);
}

// Heights as shares of stature `h` that adults span with a wide margin
// (anthropometric surveys put the means at crotch 0.47, armpit 0.73,
// acromion 0.82, cervicale 0.85, waist 0.61, buttock 0.50, knee 0.28,
// lateral malleolus 0.04): a point outside is flagged, not passed on.
void CheckProportions(LandmarkSet* set, double h) {
  struct Range {
    const char* name;
    double lo, hi;
  };
  static const Range kRanges[] = {
      {"crotch", 0.40, 0.55},
      {"armpit_right", 0.65, 0.80},
      {"armpit_left", 0.65, 0.80},
      {"shoulder_right", 0.76, 0.88},
      {"shoulder_left", 0.76, 0.88},
      {"back_neck", 0.80, 0.90},
      {"front_neck", 0.76, 0.87},
      {"front_waist", 0.52, 0.70},
      {"back_waist", 0.52, 0.70},
      {"side_waist_right", 0.52, 0.70},
      {"side_waist_left", 0.52, 0.70},
      {"hip_back", 0.42, 0.58},
      {"hip_right", 0.42, 0.58},
      {"hip_left", 0.42, 0.58},
      {"knee_right", 0.22, 0.34},
      {"knee_left", 0.22, 0.34},
      {"ankle_outside_right", 0.02, 0.075},
      {"ankle_outside_left", 0.02, 0.075},
      {"ankle_inside_right", 0.02, 0.075},
      {"ankle_inside_left", 0.02, 0.075},
  };
  for (const Range& r : kRanges) {
    if (!set->Has(r.name)) continue;
    const double share = set->points.at(r.name).position_mm.z() / h;
    if (share < r.lo || share > r.hi) {
      char why[96];
      std::snprintf(why, sizeof(why), "height %.2f of stature, expected %.2f-%.2f", share, r.lo,
                    r.hi);
      Implausible(set, r.name, why);
    }
  }
  // Order down the trunk: bust under the armpit, under-bust under the bust,
  // waist between hip and under-bust, hip above the crotch.
  auto z = [&](const char* name) { return set->points.at(name).position_mm.z(); };
  for (const char* side : {"_right", "_left"}) {
    const std::string bust = std::string("bust") + side, armpit = std::string("armpit") + side;
    if (set->Has(bust) && set->Has(armpit) &&
        (z(bust.c_str()) > z(armpit.c_str()) + 0.01 * h ||
         z(bust.c_str()) < z(armpit.c_str()) - 0.15 * h))
      Implausible(set, bust, "not 0-15 % of stature under the armpit");
  }
  if (set->Has("under_bust") && set->Has("bust_right") && z("under_bust") > z("bust_right"))
    Implausible(set, "under_bust", "above the bust point");
  if (set->Has("hip_back") && set->Has("crotch") && z("hip_back") < z("crotch"))
    Implausible(set, "hip_back", "below the crotch");
  if (set->Has("front_waist") && set->Has("hip_back") && z("front_waist") < z("hip_back"))
    Implausible(set, "front_waist", "below the hip level");
}

// A point placed from an implausible one is no better: the thigh 20 mm
// under an implausible crotch, the hip's sides at an implausible hip
// level. Each such point is flagged `from_implausible` (confidence <= 0.4)
// with its source in the method tag, along the chains below (each entry:
// the point, then the points it is placed from).
void PropagateImplausible(LandmarkSet* set) {
  static const std::vector<std::vector<std::string>> kFrom = {
      {"under_bust", "bust_right", "bust_left"},
      {"hip_back", "crotch", "under_bust"},
      {"hip_right", "hip_back"},
      {"hip_left", "hip_back"},
      {"front_waist", "hip_back", "under_bust"},
      {"back_waist", "front_waist"},
      {"side_waist_right", "front_waist"},
      {"side_waist_left", "front_waist"},
      {"middle_hip_front", "hip_back", "front_waist"},
      {"thigh_right", "crotch"},
      {"thigh_left", "crotch"},
      {"knee_right", "crotch"},
      {"knee_left", "crotch"},
      {"calf_right", "knee_right"},
      {"calf_left", "knee_left"},
      {"side_neck_right", "shoulder_right"},
      {"side_neck_left", "shoulder_left"},
      {"upper_arm_right", "shoulder_right"},
      {"upper_arm_left", "shoulder_left"},
  };
  const auto bad = [&](const std::string& name) {
    if (!set->Has(name)) return false;
    const std::vector<std::string>& f = set->points.at(name).flags;
    return std::find(f.begin(), f.end(), "implausible") != f.end() ||
           std::find(f.begin(), f.end(), "from_implausible") != f.end();
  };
  for (const std::vector<std::string>& entry : kFrom) {  // listed sources first
    if (!set->Has(entry[0]) || bad(entry[0])) continue;
    for (size_t i = 1; i < entry.size(); ++i) {
      if (!bad(entry[i])) continue;
      Landmark& l = set->points.at(entry[0]);
      l.flags.push_back("from_implausible");
      l.method += " (placed from the implausible " + entry[i] + ")";
      l.confidence = std::min(l.confidence, 0.4);
      break;
    }
  }
}

}  // namespace

void CheckLandmarks(LandmarkSet* set, double stature_mm) {
  CheckSymmetry(set);
  CheckProportions(set, stature_mm);
  PropagateImplausible(set);
}

}  // namespace bespoke::landmarks
