// The 95 % uncertainty of a measurement (Measurement::uncertainty_mm):
// an interval value +- uncertainty_mm meant to hold the truth in 95 % of
// cases (internal to measure/measurements; Measure fills it).
//
// Three independent parts, combined in quadrature, times 1.96:
//  1. the datum points: each has a position SD per axis (LandmarkSigma: the
//     landmark's typical error, raised by 1 / confidence, doubled when it is
//     flagged; overrides 1 mm), the detected ones times the calibration
//     `scale` fitted on the oracle (how far the detector's real errors
//     exceed that table), carried through the measurement's sensitivity
//     - a girth is remeasured on the scan with its plane moved by that SD along its normal (the
//     change, either way, is the girth's SD; this also holds at a girth's extreme, where the slope
//     is zero); a length's end points move along the path; a height moves with its point;
//  2. the scan: range noise (ScanNoise: the RMS distance of points from
//     their local planes) and the point spacing;
//  3. the bridged part of a length: bridge_share of bridged_mm.
// Units: mm.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_UNCERTAINTY_H_
#define BESPOKE_MEASURE_MEASUREMENTS_UNCERTAINTY_H_

#include <string>

#include "measure/cloud_geodesic/point_index.h"
#include "measure/landmarks/landmarks.h"

namespace bespoke {

struct UncertaintyOptions {
  // Calibration factor on the datum points' part (default 2, fitted on the
  // oracle: docs/measuring.md, "Uncertainty").
  double scale = 2.0;
  double bridge_share = 0.1;     // SD of a bridge per mm bridged (default 0.1)
  double noise_factor = 1.0;     // SD per mm of scan noise (default 1)
  double spacing_factor = 0.25;  // SD per mm of point spacing (default 0.25)
  void Check() const;            // InputError when out of range
};

// Position SD per axis (mm) of a datum point: the typical error of its kind
// (a table from the oracle, docs/measuring.md), times 0.8 / confidence,
// twice that when the detector flagged it, times `scale` (overrides, a
// tailor's points: 1 mm).
double LandmarkSigma(const std::string& name, const Landmark& landmark, double scale = 1);

// The scan's range noise, mm: the RMS distance of up to `samples` evenly
// spread points from the plane through their 16 nearest neighbours; the
// median point spacing (mm) in `spacing_mm`; and, when not null, in
// `surface_spacing_mm` the side of the square of skin each point covers
// (mm): sqrt(pi r^2 / 15), r the distance to the 15th neighbour, median over
// the same points. Scanners sample in rows, so the nearest neighbour along a
// row says little about the density; the disc round 15 neighbours spans rows.
double ScanNoise(const PointIndex& index, double* spacing_mm, double* surface_spacing_mm = nullptr,
                 int samples = 2000);

// 1.96 * sqrt(landmark_sd^2 + scan_sd^2 + bridge_sd^2), where
// scan_sd = noise_factor * noise + spacing_factor * spacing and bridge_sd =
// bridge_share * bridged_mm.
double Uncertainty95(const UncertaintyOptions& options, double landmark_sd_mm, double noise_mm,
                     double spacing_mm, double bridged_mm);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_UNCERTAINTY_H_
