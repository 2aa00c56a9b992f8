// Plausibility checks on a finished landmark set (internal to
// measure/landmarks; DetectLandmarks runs them last). A detector can place a
// point where no body has one; these rules flag such points, and the points
// placed from them, instead of passing them on (docs/landmarks.md, steps
// 10-12).
#ifndef BESPOKE_MEASURE_LANDMARKS_LANDMARK_CHECKS_H_
#define BESPOKE_MEASURE_LANDMARKS_LANDMARK_CHECKS_H_

#include "measure/landmarks/landmarks.h"

namespace bespoke::landmarks {

// Flags the points of `set` (body frame, mm; in place):
// - `asymmetric` (confidence <= 0.4): both points of a left/right pair
//   whose heights differ by more than 40 mm;
// - `implausible` (confidence <= 0.3, the reason appended to `method`): a
//   height outside its wide adult range as a share of `stature_mm` (crotch
//   0.40-0.55, ...), or trunk levels out of order (a bust point above its
//   armpit or more than 15 % of stature under it, an under-bust above the
//   bust, a hip below the crotch, a front waist below the hip);
// - `from_implausible` (confidence <= 0.4, the source named in `method`): a
//   point the detector places from an implausible or from_implausible one
//   (the thighs and knees from the crotch, the hip's sides from the hip
//   level, the calf from the knee, ...).
// Points already flagged keep their flags; missing points are skipped.
void CheckLandmarks(LandmarkSet* set, double stature_mm);

}  // namespace bespoke::landmarks

#endif  // BESPOKE_MEASURE_LANDMARKS_LANDMARK_CHECKS_H_
