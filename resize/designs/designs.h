// Built-in designs drafted in code from a published drafting system, so the
// same design can be drafted for any measurements (the reference for what a
// made-to-measure result should look like).
//
// "shirt": Winifred Aldrich, "Metric Pattern Cutting for Menswear", the
//   classic shirt block (body section steps 0-36 followed as published; the
//   sleeve, cuff and one-piece collar drafted in the same book's manner):
//   pieces back (cut 1 on fold), front (cut 2), sleeve (cut 2), cuff (cut 2),
//   collar (cut 1 on fold). Uses chest_girth, neck_girth, back_length,
//   back_width, armhole_length, waist_to_hip, arm_length, wrist_girth.
// "trousers": after the same book's classic trouser block (rise, seat line at
//   a quarter of the rise, quarter-seat widths, fork extensions, knee line
//   above half the leg, raised and sloped centre back): front, back (cut 2
//   each), waistband (cut 2). Uses waist_girth, hip_girth, inside_leg,
//   waist_height, and binds the derived body_rise (= waist_height -
//   inside_leg, measurements.h) that places its crotch line.
// Every piece carries landmarks (tied to body datum names), critical points,
// notches, a grain line; seams and measurement bindings are included, with the
// design ease of each binding and seam taken from the draft itself, so the
// drafted pattern meets its own measurements exactly. Outlines are net (sew
// lines, mm). The vertex count of every piece is the same for any
// measurements, so drafts for different bodies correspond vertex by vertex.
#ifndef BESPOKE_RESIZE_DESIGNS_DESIGNS_H_
#define BESPOKE_RESIZE_DESIGNS_DESIGNS_H_

#include <string>
#include <vector>

#include "resize/pattern/measurements.h"
#include "resize/pattern/pattern.h"

namespace bespoke {

// "shirt", "trousers".
const std::vector<std::string>& DesignNames();

// The measurements the design is drafted from and bound to, with their
// standard-size values (a men's 100 cm chest / 100 cm seat size); derived
// ones (measurements.h) are listed with their derived values.
MeasurementSet BaseMeasurements(const std::string& design);

// Drafts `design` for `measurements` (only the names BaseMeasurements lists
// are read; derived ones are added first, AddDerivedMeasurements). Throws
// InputError for an unknown design, a missing measurement, a derived one
// that disagrees with its derivation,
// or measurements so far out of range that the draft folds over (self-
// intersecting outline).
Pattern DraftDesign(const std::string& design, const MeasurementSet& measurements);

// The individual drafts (called by DraftDesign).
Pattern DraftShirt(const MeasurementSet& measurements);
Pattern DraftTrousers(const MeasurementSet& measurements);

// Reads `name` from `m`, throwing InputError("design <design> needs <name>").
double Need(const MeasurementSet& m, const std::string& name, const std::string& design);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_DESIGNS_DESIGNS_H_
