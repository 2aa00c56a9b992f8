// Internal to scanners/io: bounds-checked access to a file's bytes, for the
// format readers. Nothing here allocates more than the file's own size.
//
// MappedFile: the whole file, memory-mapped read-only (no copy, no allocation
//   proportional to the size). Throws InputError naming the file when it is
//   missing, a folder, unreadable or empty.
// LineCursor: walks text one line at a time ("\n" or "\r\n"), counting lines
//   (1-based) and byte offsets, for "line N" in error messages.
// Tokenize / ParseDouble / ParseInt64: whitespace (or separator) splitting and
//   locale-independent number parsing (std::from_chars) of whole tokens.
// ScalarType / LoadScalar: the binary scalar types of PLY and PCD, read from
//   little- or big-endian bytes. Callers check the byte ranges first.
#ifndef BESPOKE_SCANNERS_IO_BYTE_READER_H_
#define BESPOKE_SCANNERS_IO_BYTE_READER_H_

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace bespoke::io {

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "scanners/io assumes a little-endian host");

// Throws InputError("<file>: <what>").
[[noreturn]] void Fail(const std::filesystem::path& file, const std::string& what);

class MappedFile {
 public:
  explicit MappedFile(const std::filesystem::path& file);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  std::string_view bytes() const { return {data_, size_}; }

 private:
  const char* data_ = nullptr;
  std::size_t size_ = 0;
};

class LineCursor {
 public:
  // `text` starts at byte `base_offset` of the file and on line `first_line`.
  explicit LineCursor(std::string_view text, std::size_t base_offset = 0,
                      std::int64_t first_line = 1)
      : text_(text), base_(base_offset), next_line_(first_line) {}
  // The next line without its terminator; false at the end of the text.
  bool Next(std::string_view* line);
  // 1-based number of the line Next() returned last.
  std::int64_t line_number() const { return next_line_ - 1; }
  // File byte offset just past the last line returned (its terminator included).
  std::size_t offset() const { return base_ + pos_; }
  std::size_t remaining() const { return text_.size() - pos_; }

 private:
  std::string_view text_;
  std::size_t base_ = 0;
  std::size_t pos_ = 0;
  std::int64_t next_line_ = 1;
};

// Splits `line` at runs of spaces/tabs (and of `extra_separators`, e.g. ",;")
// into `tokens` (cleared first). Returns the number of tokens.
std::size_t Tokenize(std::string_view line, std::vector<std::string_view>* tokens,
                     std::string_view extra_separators = {});

// `text` without a leading UTF-8 byte order mark (Windows text exports).
std::string_view StripBom(std::string_view text);

// `line` with leading and trailing whitespace (space, tab, \r, \v, \f) removed.
std::string_view Trim(std::string_view line);

// Whole-token parses; false for junk, empty or out-of-range tokens. A single
// leading '+' is accepted; "nan"/"inf" parse (and are dropped later as
// non-finite points).
bool ParseDouble(std::string_view token, double* value);
bool ParseInt64(std::string_view token, std::int64_t* value);

// A token for an error message: at most 40 characters, control bytes escaped.
std::string Quote(std::string_view token);

enum class ScalarType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

int SizeOf(ScalarType type);  // bytes: 1, 2, 4 or 8
bool IsInteger(ScalarType type);

// The value at `p` (SizeOf(type) readable bytes), converted to double.
double LoadScalar(const char* p, ScalarType type, bool big_endian);

// `value` rounded to float precision without undefined behaviour: values
// beyond the float range become +-inf (then dropped as non-finite points).
float SafeFloat(double value);

// Converts `count` values of `type` at src, src + stride, src + 2 * stride, ...
// into dst[0], dst[1], ... (a tight loop per type; the caller checked that
// (count - 1) * stride + SizeOf(type) bytes are readable).
void ConvertColumn(const char* src, std::int64_t stride, ScalarType type, bool big_endian,
                   std::int64_t count, double* dst);

// Reads an unsigned little-endian 32-bit value (4 readable bytes at `p`).
std::uint32_t LoadUint32Le(const char* p);

// Appends values in the given byte order, for the binary writers.
void AppendScalar(std::string* out, double value, ScalarType type, bool big_endian);

// Shortest text that parses back to exactly `value` (std::to_chars).
void AppendNumber(std::string* out, double value);
void AppendNumber(std::string* out, float value);
void AppendNumber(std::string* out, std::int64_t value);

}  // namespace bespoke::io

#endif  // BESPOKE_SCANNERS_IO_BYTE_READER_H_
