// Measurement sets of bodies far from a design's standard size, generated in
// code for tests and the evidence run until the oracle's TRUTH.json bodies
// (`bespoke synth-body`) can be used instead.
//
// A body scales every girth by g in [0.85, 1.35] (never within 8 % of the
// standard size) and every length by l in [0.90, 1.12], independently, then
// each measurement by its own factor in [0.94, 1.06]: so proportions differ
// from the standard figure (a stocky or a lanky build), which is what
// proportional grading cannot follow. Derived measurements (body_rise) are
// not drawn but derived from the drawn ones. Deterministic for a seed.
#ifndef BESPOKE_RESIZE_DESIGNS_BODY_VARIANTS_H_
#define BESPOKE_RESIZE_DESIGNS_BODY_VARIANTS_H_

#include <cstdint>
#include <string>

#include "resize/pattern/measurements.h"

namespace bespoke {

// For the measurements of BaseMeasurements(design).
MeasurementSet VariedMeasurements(const std::string& design, std::uint64_t seed);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_DESIGNS_BODY_VARIANTS_H_
