#include "pipeline/batch/csv.h"

#include <algorithm>
#include <cctype>
#include <fstream>

#include "scanners/core/errors.h"

namespace bespoke {
namespace fs = std::filesystem;

std::vector<std::string> SplitCsvRecord(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c != '\r') {
      fields.back() += c;
    }
  }
  return fields;
}

std::string CsvField(const std::string& value) {
  if (value.find_first_of(",\"\r\n") == std::string::npos) return value;
  std::string out = "\"";
  for (char c : value) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<CsvRecord> ParseCsvRecords(std::istream& in, const fs::path& source) {
  std::vector<CsvRecord> records;
  std::string line, record;
  int line_number = 0, record_line = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (record.empty()) record_line = line_number;
    record += record.empty() ? line : "\n" + line;
    if (std::count(record.begin(), record.end(), '"') % 2 == 1) continue;  // quoted newline
    const std::string text = std::move(record);
    record.clear();
    if (text.find_first_not_of(" \t\r") == std::string::npos || text[0] == '#') continue;
    records.push_back({record_line, SplitCsvRecord(text)});
  }
  if (!record.empty())
    throw InputError(source, "line " + std::to_string(record_line) + ": unterminated quote");
  return records;
}

std::vector<CsvRecord> ReadCsvRecords(const fs::path& file) {
  std::error_code ec;
  if (!fs::exists(file, ec)) throw InputError(file, "no such file");
  if (!fs::is_regular_file(file, ec)) throw InputError(file, "not a regular file");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open");
  return ParseCsvRecords(in, file);
}

CsvColumns::CsvColumns(const CsvRecord& header) {
  for (std::size_t i = 0; i < header.fields.size(); ++i)
    index_.emplace(AsciiLower(TrimBlanks(header.fields[i])), i);
}

bool CsvColumns::Has(const std::string& name) const { return index_.count(name) > 0; }

std::string CsvColumns::Field(const CsvRecord& record, const std::string& name) const {
  const auto it = index_.find(name);
  return it != index_.end() && it->second < record.fields.size()
             ? TrimBlanks(record.fields[it->second])
             : std::string();
}

std::string AsciiLower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

std::string TrimBlanks(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

}  // namespace bespoke
