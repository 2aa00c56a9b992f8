// Proportional scaling (thesis Algorithm 6): the seed of the initial
// population, and the "plain proportional grading" baseline of the evidence.
//
// Per piece, every binding term on the piece gives a ratio (its share of the
// target / its current length, where a binding's target is split over its
// terms in proportion to their current lengths); the piece is scaled
// uniformly about its bounding-box centre by the largest ratio (Algorithm 6,
// line 8). Deviation: pieces no binding reaches (collars, cuffs, waistbands)
// take the mean scale of the pieces they are seamed to, propagated until every
// connected piece has one (the thesis leaves them unscaled, 4.2); pieces with
// neither keep scale 1.
#ifndef BESPOKE_RESIZE_GA_GRADING_H_
#define BESPOKE_RESIZE_GA_GRADING_H_

#include <vector>

#include "resize/pattern/measurements.h"
#include "resize/pattern/pattern.h"

namespace bespoke {

// The scale factor of every piece (same order as pattern.pieces).
std::vector<double> ProportionalScales(const Pattern& pattern, const MeasurementSet& body);

// `pattern` with piece k scaled by scales[k] about its bounding-box centre
// (outline, inside landmarks, grain line, internal lines).
Pattern ScalePieces(const Pattern& pattern, const std::vector<double>& scales);

// ScalePieces(pattern, ProportionalScales(pattern, body)).
Pattern ProportionalGrade(const Pattern& pattern, const MeasurementSet& body);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_GA_GRADING_H_
