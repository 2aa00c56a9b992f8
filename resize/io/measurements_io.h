// Body measurements from files: the measurement document of
// docs/contracts.md (MEAS.json, TRUTH.json) or a Valentina / Seamly2D
// individual-measurement file (.vit, XML, values in the file's <unit>).
//
// A .vit measurement is taken under the catalogue name whose Valentina name
// it is (measure/catalogue/catalogue.json, field "valentina"; e.g. bust_circ
// -> bust_girth, neck_back_to_waist_b -> back_length, height -> stature),
// converted to mm. Names the catalogue does not know are left out and listed
// in `skipped`. Derived measurements are added (AddDerivedMeasurements).
#ifndef BESPOKE_RESIZE_IO_MEASUREMENTS_IO_H_
#define BESPOKE_RESIZE_IO_MEASUREMENTS_IO_H_

#include <filesystem>
#include <string>
#include <vector>

#include "resize/pattern/measurements.h"

namespace bespoke {

// `text` is the .vit file's content; `what` names it in errors. InputError
// for a file that is not a .vit document, an unknown unit, a value that is
// not a positive number, or a catalogue name given twice.
MeasurementSet MeasurementsFromVit(const std::string& text, const std::string& what,
                                   std::vector<std::string>* skipped = nullptr);

// By extension: .vit (Valentina), anything else a JSON measurement document.
MeasurementSet LoadMeasurements(const std::filesystem::path& file,
                                std::vector<std::string>* skipped = nullptr);

}  // namespace bespoke

#endif  // BESPOKE_RESIZE_IO_MEASUREMENTS_IO_H_
