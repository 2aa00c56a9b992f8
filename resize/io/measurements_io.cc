#include "resize/io/measurements_io.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "measure/catalogue/catalogue.h"
#include "scanners/core/errors.h"
#include "scanners/core/text.h"

namespace bespoke {
namespace {

// The catalogue name whose Valentina name is `valentina`, or "".
std::string CatalogueName(const std::string& valentina) {
  for (const MeasurementDef& m : Catalogue::Builtin().measurements())
    if (m.valentina == valentina) return m.name;
  return "";
}

}  // namespace

MeasurementSet MeasurementsFromVit(const std::string& text, const std::string& what,
                                   std::vector<std::string>* skipped) {
  if (text.find("<vit>") == std::string::npos)
    throw InputError(what + ": not a Valentina individual-measurement file (no <vit>)");
  double unit_mm = 10;  // Valentina's default unit is cm
  std::smatch match;
  if (std::regex_search(text, match, std::regex("<unit>\\s*([a-z]+)\\s*</unit>"))) {
    const std::string unit = match[1];
    if (unit == "mm")
      unit_mm = 1;
    else if (unit == "cm")
      unit_mm = 10;
    else if (unit == "inch")
      unit_mm = 25.4;
    else
      throw InputError(what + ": unknown unit '" + unit + "' (mm, cm or inch)");
  }
  MeasurementSet values;
  const std::regex m_tag("<m\\s+([^>]*)/?>");
  const std::regex name_attr("name=\"([^\"]*)\""), value_attr("value=\"([^\"]*)\"");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), m_tag);
       it != std::sregex_iterator(); ++it) {
    const std::string attributes = (*it)[1];
    std::smatch n, v;
    if (!std::regex_search(attributes, n, name_attr) ||
        !std::regex_search(attributes, v, value_attr))
      throw InputError(what + ": a measurement <m> needs name and value");
    const std::string name = n[1], value_text = StripBlanks(v[1].str());
    double value = 0;
    try {
      size_t used = 0;
      value = std::stod(value_text, &used);
      if (used != value_text.size()) throw std::invalid_argument("formula");
    } catch (const std::exception&) {
      throw InputError(what + ": measurement '" + name + "' has value '" + value_text +
                       "' (only plain numbers are read)");
    }
    if (!std::isfinite(value) || value <= 0)
      throw InputError(what + ": measurement '" + name + "' must be positive");
    const std::string ours = CatalogueName(name);
    if (ours.empty()) {
      if (skipped) skipped->push_back(name);
      continue;
    }
    if (!values.emplace(ours, value * unit_mm).second)
      throw InputError(what + ": measurement '" + ours + "' given twice");
  }
  AddDerivedMeasurements(&values, what);
  return values;
}

MeasurementSet LoadMeasurements(const std::filesystem::path& file,
                                std::vector<std::string>* skipped) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".vit") return ReadMeasurements(file);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open the measurement file");
  std::ostringstream text;
  text << in.rdbuf();
  return MeasurementsFromVit(text.str(), file.string(), skipped);
}

}  // namespace bespoke
