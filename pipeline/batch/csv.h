// CSV as Bespoke reads and writes it: RFC 4180 quoting (quotes, commas and
// newlines inside quoted fields), one header line naming the columns, blank
// lines and lines starting with '#' skipped. Used by the batch's manifests
// and summaries and by the accuracy report's reference tables and name maps.
#ifndef BESPOKE_PIPELINE_BATCH_CSV_H_
#define BESPOKE_PIPELINE_BATCH_CSV_H_

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <map>
#include <string>
#include <vector>

namespace bespoke {

// Splits one CSV record (no trailing newline) into fields (RFC 4180 quotes).
std::vector<std::string> SplitCsvRecord(const std::string& line);

// Quotes a CSV field when it holds a comma, quote, CR or LF.
std::string CsvField(const std::string& value);

// One record of a CSV file: its fields and the line it starts on (1-based).
struct CsvRecord {
  int line = 0;
  std::vector<std::string> fields;
};

// Every record of CSV text (quotes also across lines), the header included;
// blank and '#' lines skipped. InputError naming `source` (the file) and the
// line when a quote is left open.
std::vector<CsvRecord> ParseCsvRecords(std::istream& in, const std::filesystem::path& source);

// ParseCsvRecords of a file; InputError naming it when it is missing, not a
// regular file or cannot be opened.
std::vector<CsvRecord> ReadCsvRecords(const std::filesystem::path& file);

// The columns a header record names, looked up ignoring case and the blanks
// around names and fields.
class CsvColumns {
 public:
  explicit CsvColumns(const CsvRecord& header);
  bool Has(const std::string& name) const;  // `name` in lower case
  // Field `name` of `record`, blanks around it trimmed; "" when the column or
  // the field is absent.
  std::string Field(const CsvRecord& record, const std::string& name) const;
  const std::map<std::string, std::size_t>& index() const { return index_; }

 private:
  std::map<std::string, std::size_t> index_;  // lower-case name -> field index
};

// `text` with ASCII letters in lower case.
std::string AsciiLower(std::string text);

// `text` without the spaces and tabs around it.
std::string TrimBlanks(const std::string& text);

}  // namespace bespoke

#endif  // BESPOKE_PIPELINE_BATCH_CSV_H_
