// The reference table of a real-subject accuracy report (REF.csv): each
// subject's measurements taken another way (a tape, another scanner), to be
// compared with what Bespoke measures on the subject's scans.
//
// Format: CSV (pipeline/batch/csv.h; blank and '#' lines skipped)
// with a header naming the columns, in any order, ignoring case:
//   subject      required: the subject; its scans are SUBJECT.<ext> or SUBJECT_<k>.<ext>
//   measurement  required: a catalogue name, or a name the name map knows
//   value_mm     required: the value in millimetres
//   method       optional: how it was taken, e.g. "tape" or another system's name
//   unit         optional: "mm" when given (empty = mm)
// Other columns are ignored.
//
// Whole-file problems are an InputError naming the file (nothing is
// compared): no file, no header, a required column missing, a value column
// in another unit ("value_cm", "value_in", "value"), several methods in the
// file without `method` choosing one. Problems of single rows leave the row
// out, listed with the reason (`not_compared`): an empty subject, an unknown
// measurement name, a name the map says has no counterpart, a value that is
// not a positive number, a unit other than mm, another method than the one
// chosen, and duplicates: a second row for the same subject and measurement
// (after mapping names) with the same value is counted once and listed; rows
// that disagree are all left out and listed.
#ifndef BESPOKE_EVAL_ACCURACY_REFERENCE_TABLE_H_
#define BESPOKE_EVAL_ACCURACY_REFERENCE_TABLE_H_

#include <filesystem>
#include <string>
#include <vector>

#include "eval/accuracy/accuracy_report.h"
#include "eval/accuracy/name_map.h"
#include "measure/catalogue/catalogue.h"

namespace bespoke {

struct ReferenceTableOptions {
  const NameMap* names = nullptr;  // other systems' names; null (default) = catalogue names only
  std::string method;              // compare only rows of this method; "" (default) = the only one
};

struct ReferenceValue {
  std::string subject;
  std::string measurement;  // catalogue name
  double value_mm = 0;
  std::string method;  // "" when the file has no method column
  int line = 0;        // line in the file
};

struct ReferenceTable {
  std::filesystem::path file;
  std::vector<ReferenceValue> values;     // file order, one per subject and measurement
  std::vector<NotCompared> not_compared;  // rows left out, file order
  std::vector<MappedName> mapped_names;   // names read through the map, map order
  std::string method;                     // the method compared ("" = not given)
  std::vector<std::string> subjects;      // with at least one value, first-appearance order
};

ReferenceTable ReadReferenceTable(const ReferenceTableOptions& options,
                                  const std::filesystem::path& file, const Catalogue& catalogue);

}  // namespace bespoke

#endif  // BESPOKE_EVAL_ACCURACY_REFERENCE_TABLE_H_
