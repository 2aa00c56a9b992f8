#include "eval/accuracy/iso_20685.h"

#include <cmath>

namespace bespoke {

std::string ToString(IsoClass iso_class) {
  switch (iso_class) {
    case IsoClass::kHeight:
      return "height";
    case IsoClass::kSmallGirth:
      return "small_girth";
    case IsoClass::kLargeGirth:
      return "large_girth";
    case IsoClass::kSegmentLength:
      return "segment_length";
    case IsoClass::kBreadth:
      return "breadth";
  }
  return "unknown";
}

IsoClass IsoClassOf(const MeasurementDef& measurement) {
  switch (measurement.kind) {
    case MeasurementKind::kHeight:
      return IsoClass::kHeight;
    case MeasurementKind::kGirth: {
      // Trunk girths are measured once, across the body ("centre"/"both");
      // limb girths on one side. The neck is a centre girth but small.
      const bool trunk = measurement.side == "centre" || measurement.side == "both";
      return trunk && measurement.name != "neck_girth" ? IsoClass::kLargeGirth
                                                       : IsoClass::kSmallGirth;
    }
    case MeasurementKind::kLength:
      return measurement.method == MeasurementMethod::kGeodesic ? IsoClass::kSegmentLength
                                                                : IsoClass::kBreadth;
  }
  return IsoClass::kSegmentLength;
}

double IsoToleranceMm(IsoClass iso_class) {
  switch (iso_class) {
    case IsoClass::kHeight:
      return 4;
    case IsoClass::kSmallGirth:
      return 4;
    case IsoClass::kLargeGirth:
      return 9;
    case IsoClass::kSegmentLength:
      return 5;
    case IsoClass::kBreadth:
      return 4;
  }
  return 4;
}

std::string ToString(IsoVerdict verdict) {
  switch (verdict) {
    case IsoVerdict::kPass:
      return "pass";
    case IsoVerdict::kFail:
      return "fail";
    case IsoVerdict::kNotJudged:
      return "n/a";
  }
  return "n/a";
}

IsoVerdict JudgeIso20685(const ErrorStats& stats, double tolerance_mm) {
  if (stats.n < 2 || !std::isfinite(stats.ci_low_mm) || !std::isfinite(stats.ci_high_mm)) {
    return IsoVerdict::kNotJudged;
  }
  return stats.ci_low_mm >= -tolerance_mm && stats.ci_high_mm <= tolerance_mm ? IsoVerdict::kPass
                                                                              : IsoVerdict::kFail;
}

}  // namespace bespoke
