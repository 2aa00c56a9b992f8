#include "measure/measurements/measurement_exports.h"

#include <cmath>
#include <cstdio>

#include "scanners/core/atomic_file.h"
#include "scanners/core/json_io.h"
#include "scanners/core/xml_escape.h"

namespace bespoke {
namespace {}  // namespace

std::string ValentinaVit(const MeasureResult& result, const Catalogue& catalogue) {
  std::string out =
      "<?xml version='1.0' encoding='UTF-8'?>\n"
      "<vit>\n"
      "    <!--Measurements taken from a 3-D scan by Bespoke; values in cm.-->\n"
      "    <version>0.3.3</version>\n"
      "    <read-only>false</read-only>\n"
      "    <notes/>\n"
      "    <unit>cm</unit>\n"
      "    <pm_system>998</pm_system>\n"
      "    <personal>\n"
      "        <family-name/>\n"
      "        <given-name/>\n"
      "        <birth-date>1800-01-01</birth-date>\n"
      "        <gender>unknown</gender>\n"
      "        <email/>\n"
      "    </personal>\n"
      "    <body-measurements>\n";
  char value[64];
  for (const Measurement& m : result.measurements) {
    const MeasurementDef& def = catalogue.Measurement(m.name);
    if (def.valentina.empty()) continue;
    std::snprintf(value, sizeof(value), "%.2f", m.value_mm / 10.0);
    std::string description = "bespoke " + m.name;
    if (!m.flags.empty()) {
      description += "; flags:";
      for (const std::string& f : m.flags) description += " " + f;
    }
    out += "        <m name=\"" + XmlEscape(def.valentina) + "\" value=\"" + value +
           "\" description=\"" + XmlEscape(description) + "\" full_name=\"\"/>\n";
  }
  out += "    </body-measurements>\n</vit>\n";
  return out;
}

nlohmann::json FreeSewingMeasurements(const MeasureResult& result, const Catalogue& catalogue) {
  nlohmann::json measurements = nlohmann::json::object();
  for (const Measurement& m : result.measurements) {
    const MeasurementDef& def = catalogue.Measurement(m.name);
    if (!def.freesewing.empty())
      measurements[def.freesewing] = std::round(m.value_mm * 10.0) / 10.0;
  }
  return {{"units", "metric"}, {"measurements", measurements}};
}

void WriteValentinaVit(const std::filesystem::path& file, const MeasureResult& result,
                       const Catalogue& catalogue) {
  WriteFileAtomically(file, ValentinaVit(result, catalogue));
}

void WriteFreeSewingJson(const std::filesystem::path& file, const MeasureResult& result,
                         const Catalogue& catalogue) {
  WriteJsonFile(file, FreeSewingMeasurements(result, catalogue));
}

}  // namespace bespoke
