// Other systems' measurement names mapped to the catalogue's, so that a
// reference table written with Valentina's, FreeSewing's or a lab's own names
// can be compared (`bespoke accuracy --names MAP`).
//
// A map is a CSV file (pipeline/batch/csv.h; '#' lines are
// comments, e.g. the map's source) with a header naming the columns:
//   their_name  required: the other system's name (matched ignoring case)
//   our_name    required: a catalogue measurement, or empty when the other
//               system's measurement has no counterpart here
//   note        optional: how the definitions differ ("" when they agree)
// Ready maps are built in: "valentina" and "freesewing"
// (eval/accuracy/name_maps/*.csv, compiled into the binary).
//
// Failure: InputError naming the file (and line) for a missing column, an
// our_name the catalogue does not know, or a their_name given twice.
#ifndef BESPOKE_EVAL_ACCURACY_NAME_MAP_H_
#define BESPOKE_EVAL_ACCURACY_NAME_MAP_H_

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "measure/catalogue/catalogue.h"
#include "pipeline/batch/csv.h"

namespace bespoke {

struct NameMapEntry {
  std::string their_name;   // as written in the map
  std::string measurement;  // catalogue name; "" = no counterpart
  std::string note;         // how the definitions differ; "" when they agree
};

struct NameMap {
  std::string source;                          // "valentina", "freesewing" or the file's path
  std::map<std::string, NameMapEntry> by_key;  // key: their_name in lower case

  // The entry for `their_name` (ignoring case), or nullopt.
  std::optional<NameMapEntry> Find(const std::string& their_name) const;
};

// The names of the built-in maps: "freesewing", "valentina".
std::vector<std::string> BuiltinNameMaps();

// A built-in map by name, or the map file `spec`; InputError when `spec` is
// neither a built-in name nor a readable map file.
NameMap LoadNameMap(const std::string& spec, const Catalogue& catalogue);

// The map held by `records` (the header first); `source` names it in errors.
NameMap ParseNameMap(const std::vector<CsvRecord>& records, const std::string& source,
                     const Catalogue& catalogue);

// The text of the built-in maps (generated from eval/accuracy/name_maps/).
const char* BuiltinValentinaNameMap();
const char* BuiltinFreeSewingNameMap();

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_NAME_MAP_H_
