#include "eval/accuracy/name_map.h"

#include <sstream>

#include "scanners/core/errors.h"

namespace bespoke {
namespace fs = std::filesystem;

std::optional<NameMapEntry> NameMap::Find(const std::string& their_name) const {
  const auto it = by_key.find(AsciiLower(TrimBlanks(their_name)));
  if (it == by_key.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> BuiltinNameMaps() { return {"freesewing", "valentina"}; }

NameMap ParseNameMap(const std::vector<CsvRecord>& records, const std::string& source,
                     const Catalogue& catalogue) {
  if (records.empty()) throw InputError(source + ": empty name map (no header line)");
  const CsvColumns columns(records[0]);
  if (!columns.Has("their_name") || !columns.Has("our_name")) {
    throw InputError(source + ": line " + std::to_string(records[0].line) +
                     ": the header must name the columns their_name and our_name (and "
                     "optionally note)");
  }
  NameMap map;
  map.source = source;
  std::map<std::string, int> line_of;
  for (std::size_t r = 1; r < records.size(); ++r) {
    const std::string where = source + ": line " + std::to_string(records[r].line) + ": ";
    NameMapEntry entry{columns.Field(records[r], "their_name"),
                       columns.Field(records[r], "our_name"), columns.Field(records[r], "note")};
    if (entry.their_name.empty()) throw InputError(where + "empty their_name");
    if (!entry.measurement.empty() && !catalogue.HasMeasurement(entry.measurement)) {
      throw InputError(where + "our_name '" + entry.measurement +
                       "' is not a catalogue measurement (docs/measurements.md)");
    }
    const std::string key = AsciiLower(entry.their_name);
    if (line_of.count(key)) {
      throw InputError(where + "'" + entry.their_name + "' is mapped again (first on line " +
                       std::to_string(line_of[key]) + ")");
    }
    line_of[key] = records[r].line;
    map.by_key[key] = std::move(entry);
  }
  return map;
}

NameMap LoadNameMap(const std::string& spec, const Catalogue& catalogue) {
  const char* text = spec == "valentina"    ? BuiltinValentinaNameMap()
                     : spec == "freesewing" ? BuiltinFreeSewingNameMap()
                                            : nullptr;
  if (text) {
    std::istringstream in(text);
    return ParseNameMap(ParseCsvRecords(in, "built-in name map " + spec), spec, catalogue);
  }
  std::error_code ec;
  if (!fs::exists(spec, ec)) {
    throw InputError(spec, "--names: neither a built-in map (freesewing, valentina) nor a file");
  }
  return ParseNameMap(ReadCsvRecords(spec), spec, catalogue);
}

}  // namespace bespoke
