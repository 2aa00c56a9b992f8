#include "measure/mesh_geodesic/wavefront.h"

#include <string>

#include "scanners/core/errors.h"

namespace bespoke {

namespace {

void RequireFinite(double value, bool ok, const char* what) {
  if (!ok || !std::isfinite(value)) throw InputError(std::string("geodesic propagation: ") + what);
}

}  // namespace

void WavefrontOptions::Check() const {
  if (window < 3)
    throw InputError("geodesic propagation: window must be >= 3, got " + std::to_string(window));
  RequireFinite(band_spacings, band_spacings >= 0, "band_spacings must be >= 0");
  RequireFinite(tie_spacings, tie_spacings >= 0, "tie_spacings must be >= 0");
  if (flow_iterations < 1) throw InputError("geodesic propagation: flow_iterations must be >= 1");
  RequireFinite(flow_tolerance_spacings, flow_tolerance_spacings > 0,
                "flow_tolerance_spacings must be > 0");
  RequireFinite(replan_spacings, replan_spacings >= 0, "replan_spacings must be >= 0");
  RequireFinite(max_step_segments, max_step_segments > 0, "max_step_segments must be > 0");
}

CurvatureFlowOptions FlowOptionsFor(const WavefrontOptions& options, double spacing) {
  CurvatureFlowOptions flow;
  flow.max_iterations = options.flow_iterations;
  flow.tolerance_mm = options.flow_tolerance_spacings * spacing;
  flow.replan_distance_mm = options.replan_spacings * spacing;
  flow.max_step_segments = options.max_step_segments;
  return flow;
}

bool Wavefront::NextRound() {
  if (next_.empty()) {
    done_ = true;
    return false;
  }
  front_.swap(next_);
  next_.clear();
  ++rounds_;
  r_max_ = band_ > 0 ? std::max(r_max_, min_held_) + band_ : std::max(r_max_, max_held_);
  min_held_ = std::numeric_limits<double>::infinity();
  max_held_ = 0;
  return true;
}

}  // namespace bespoke
