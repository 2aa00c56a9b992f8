#include "oracle/synth/rule_landmarks.h"

#include <map>
#include <string>
#include <vector>

#include "oracle/makehuman/landmark_analysis.h"
#include "scanners/core/errors.h"

namespace bespoke {

void RuleLandmarkOptions::Check() const {
  if (!(rest_abduction_deg >= 15 && rest_abduction_deg <= 40))
    throw InputError("rule landmarks: rest_abduction_deg must be 15-40, not " +
                     std::to_string(rest_abduction_deg));
  if (!(max_shoulder_abduction_deg >= rest_abduction_deg && max_shoulder_abduction_deg <= 90))
    throw InputError(
        "rule landmarks: max_shoulder_abduction_deg must be rest_abduction_deg-90, "
        "not " +
        std::to_string(max_shoulder_abduction_deg));
}

void PlaceRuleLandmarks(const RuleLandmarkOptions& options,
                        const ParametricBodyOptions& body_options,
                        const ParametricBodyDetails& details, Body* body) {
  options.Check();
  // A body built at the rest pose is its own rest body.
  std::map<std::string, AnalysedLandmark> analysed;
  if (body_options.arm_abduction_deg == options.rest_abduction_deg) {
    analysed = AnalyseMakeHumanLandmarks(body->mesh, details.joints);
  } else {
    ParametricBodyOptions rest_options = body_options;
    rest_options.arm_abduction_deg = options.rest_abduction_deg;
    ParametricBodyDetails rest_details;
    const Body rest = GenerateParametricBody(rest_options, &rest_details);
    analysed = AnalyseMakeHumanLandmarks(rest.mesh, rest_details.joints);
  }
  std::vector<std::string> names = {"axilla_front", "axilla_back", "thigh"};
  if (body_options.arm_abduction_deg <= options.max_shoulder_abduction_deg)
    names.push_back("shoulder");
  for (const std::string& name : names) {
    for (const char* side : {"_right", "_left"}) {
      const std::string key = name + side;
      const auto it = analysed.find(key);
      if (it == analysed.end()) throw InternalError("rule landmarks: no " + key);
      body->landmarks[key] = ClosestSurfacePoint(body->mesh, it->second.position);
    }
  }
}

}  // namespace bespoke
