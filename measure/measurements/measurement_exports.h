// Measurements for other tools: Valentina / Seamly2D individual measurements
// (.vit) and FreeSewing measurements (JSON), from the result of Measure.
//
// Valentina .vit (the format of ../shared/data/patterns/valentina/*.vit,
// version 0.3.3): XML, unit cm, one <m name=".." value=".."/> per
// measurement that has a Valentina name in the catalogue (bust_girth ->
// bust_circ), values in cm with two decimals; quality flags go into the
// entry's description ("bespoke bust_girth; flags: section_open"), so a pattern maker
// sees them in Valentina's table. Personal data is left empty.
//
// FreeSewing: { "units": "metric", "measurements": { "chest": 912.3, ... } }
// in mm (FreeSewing's own unit), names from the catalogue's freesewing field
// (bust_girth -> chest), the settings object a FreeSewing design takes.
// Measurements without a name in the target tool are left out.
// Writers are atomic; InputError naming the file when its folder is missing.
#ifndef BESPOKE_MEASURE_MEASUREMENTS_MEASUREMENT_EXPORTS_H_
#define BESPOKE_MEASURE_MEASUREMENTS_MEASUREMENT_EXPORTS_H_

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "measure/catalogue/catalogue.h"
#include "measure/measurements/measure.h"

namespace bespoke {

std::string ValentinaVit(const MeasureResult& result, const Catalogue& catalogue);
nlohmann::json FreeSewingMeasurements(const MeasureResult& result, const Catalogue& catalogue);

void WriteValentinaVit(const std::filesystem::path& file, const MeasureResult& result,
                       const Catalogue& catalogue);
void WriteFreeSewingJson(const std::filesystem::path& file, const MeasureResult& result,
                         const Catalogue& catalogue);

}  // namespace bespoke

#endif  // BESPOKE_MEASURE_MEASUREMENTS_MEASUREMENT_EXPORTS_H_
