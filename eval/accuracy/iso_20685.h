// ISO 20685-1 (3-D scanning methodologies for internationally compatible
// anthropometric databases) judges a scanner-extracted measurement by the
// mean difference to traditional measurement: the 95 % confidence interval
// of that mean must lie within the maximum allowable error of the
// measurement's class. The classes and limits used here (mm):
//   height        4 mm  every catalogue measurement of kind "height"
//   small_girth   4 mm  neck, upper arm, elbow, wrist, thigh, knee, calf, ankle
//   large_girth   9 mm  bust, chest, under-bust, waist, middle hip, hip
//   segment_length 5 mm every geodesic length along the surface (kind "length",
//                       method "geodesic"), e.g. back length, arm length
//   breadth       4 mm  straight breadths and depths (method "breadth" or
//                       "point_to_line": shoulder width, sleeve top), which
//                       ISO 20685-1 puts with body depths/breadths, not lengths
// A girth is "large" when it goes round the trunk (catalogue side "centre"
// or "both" and region torso/hip: bust, chest, under_bust, waist,
// middle_hip, hip); the neck girth and every limb girth are "small".
// The "traditional" value is the oracle's exact truth on the mesh, or on real
// subjects the reference measurement (a tape, another scanner).
#ifndef BESPOKE_EVAL_ACCURACY_ISO_20685_H_
#define BESPOKE_EVAL_ACCURACY_ISO_20685_H_

#include <string>

#include "eval/accuracy/accuracy_stats.h"
#include "measure/catalogue/catalogue.h"

namespace bespoke {

enum class IsoClass { kHeight, kSmallGirth, kLargeGirth, kSegmentLength, kBreadth };

// "height", "small_girth", "large_girth", "segment_length", "breadth".
std::string ToString(IsoClass iso_class);

// The class of a catalogue measurement (rules above).
IsoClass IsoClassOf(const MeasurementDef& measurement);

// The maximum allowable error of the class, mm (4, 4, 9, 5, 4).
double IsoToleranceMm(IsoClass iso_class);

enum class IsoVerdict { kPass, kFail, kNotJudged };
std::string ToString(IsoVerdict verdict);  // "pass", "fail", "n/a"

// Pass when the 95 % CI of the mean difference lies within
// [-tolerance, +tolerance]; not judged when the CI is undefined (n < 2).
IsoVerdict JudgeIso20685(const ErrorStats& stats, double tolerance_mm);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_ISO_20685_H_
