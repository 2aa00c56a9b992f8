#include "resize/designs/designs.h"

#include "resize/pattern/edit.h"
#include "resize/pattern/geometry.h"
#include "scanners/core/errors.h"

namespace bespoke {

const std::vector<std::string>& DesignNames() {
  static const std::vector<std::string> names = {"shirt", "trousers"};
  return names;
}

MeasurementSet BaseMeasurements(const std::string& design) {
  // Standard men's size: 100 cm chest, 40 cm neck; 84 cm waist, 100 cm seat.
  if (design == "shirt")
    return {{"chest_girth", 1000}, {"neck_girth", 400},     {"back_length", 450},
            {"back_width", 390},   {"armhole_length", 460}, {"waist_to_hip", 200},
            {"arm_length", 640},   {"wrist_girth", 175}};
  if (design == "trousers") {
    MeasurementSet m = {
        {"waist_girth", 840}, {"hip_girth", 1000}, {"inside_leg", 810}, {"waist_height", 1060}};
    AddDerivedMeasurements(&m, "design trousers");  // body_rise
    return m;
  }
  throw InputError("unknown design '" + design + "' (known: shirt, trousers)");
}

double Need(const MeasurementSet& m, const std::string& name, const std::string& design) {
  const auto it = m.find(name);
  if (it == m.end()) throw InputError("design " + design + " needs measurement '" + name + "'");
  return it->second;
}

Pattern DraftDesign(const std::string& design, const MeasurementSet& given) {
  MeasurementSet measurements = given;
  AddDerivedMeasurements(&measurements, "design " + design);
  Pattern pattern;
  if (design == "shirt")
    pattern = DraftShirt(measurements);
  else if (design == "trousers")
    pattern = DraftTrousers(measurements);
  else
    throw InputError("unknown design '" + design + "' (known: shirt, trousers)");
  // Design ease (fixed bindings have none): what the draft gives minus the
  // body measurement; seam ease:
  // the drafted length difference (e.g. sleeve-head ease), so the draft meets
  // its own bindings and seams exactly.
  for (MeasurementBinding& b : pattern.bindings)
    if (!b.fixed) b.ease_mm = BindingValue(pattern, b) - Need(measurements, b.measurement, design);
  for (Seam& s : pattern.seams)
    s.ease_mm = SeamLength(pattern.pieces[pattern.FindPiece(s.a.piece)], s.a) -
                SeamLength(pattern.pieces[pattern.FindPiece(s.b.piece)], s.b);
  // The design's structure, as an importer infers it (straight edges, folds,
  // square corners), so resizing keeps it.
  InferStructure(StructureOptions{}, &pattern);
  AddStructureCriticalPoints(&pattern);
  for (const Piece& piece : pattern.pieces)
    if (FindSelfIntersection(piece.outline).first >= 0)
      throw InputError("design " + design + ": measurements out of the drafting range (piece '" +
                       piece.name + "' folds over)");
  ValidatePattern(pattern, "design " + design);
  return pattern;
}

}  // namespace bespoke
