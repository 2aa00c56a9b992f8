#include "oracle/synth/rule_landmarks.h"

#include <string>

#include "oracle/makehuman/landmark_analysis.h"
#include "scanners/core/errors.h"

namespace bespoke {

void RuleLandmarkOptions::Check() const {
  if (!(rest_abduction_deg >= 15 && rest_abduction_deg <= 40))
    throw InputError("rule landmarks: rest_abduction_deg must be 15-40, not " +
                     std::to_string(rest_abduction_deg));
}

void PlaceRuleLandmarks(const RuleLandmarkOptions& options,
                        const ParametricBodyOptions& body_options, Body* body) {
  options.Check();
  ParametricBodyOptions rest_options = body_options;
  rest_options.arm_abduction_deg = options.rest_abduction_deg;
  ParametricBodyDetails details;
  const Body rest = GenerateParametricBody(rest_options, &details);
  const auto analysed = AnalyseMakeHumanLandmarks(rest.mesh, details.joints);
  for (const char* name : {"shoulder", "axilla_front", "axilla_back", "thigh"}) {
    for (const char* side : {"_right", "_left"}) {
      const std::string key = std::string(name) + side;
      const auto it = analysed.find(key);
      if (it == analysed.end()) throw InternalError("rule landmarks: no " + key);
      body->landmarks[key] = ClosestSurfacePoint(body->mesh, it->second.position);
    }
  }
}

}  // namespace bespoke
