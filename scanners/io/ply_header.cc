#include "scanners/io/ply_header.h"

#include <optional>
#include <unordered_set>

#include "scanners/io/formats.h"

namespace bespoke::io {
namespace {

std::optional<ScalarType> ParsePlyType(std::string_view name) {
  if (name == "char" || name == "int8") return ScalarType::kInt8;
  if (name == "uchar" || name == "uint8") return ScalarType::kUint8;
  if (name == "short" || name == "int16") return ScalarType::kInt16;
  if (name == "ushort" || name == "uint16") return ScalarType::kUint16;
  if (name == "int" || name == "int32") return ScalarType::kInt32;
  if (name == "uint" || name == "uint32") return ScalarType::kUint32;
  if (name == "float" || name == "float32") return ScalarType::kFloat32;
  if (name == "double" || name == "float64") return ScalarType::kFloat64;
  return std::nullopt;
}

std::string AtLine(std::int64_t line) { return "line " + std::to_string(line); }

class HeaderParser {
 public:
  HeaderParser(const ReadOptions& options, const std::filesystem::path& file,
               std::string_view bytes)
      : options_(options), file_(file), lines_(bytes) {}

  PlyHeader Parse() {
    std::string_view line;
    if (!lines_.Next(&line) || Trim(line) != "ply") {
      Fail(file_, "not a PLY file: the first line must be 'ply'");
    }
    while (true) {
      if (!lines_.Next(&line)) Fail(file_, "PLY header has no 'end_header' line");
      Tokenize(line, &tokens_);
      if (tokens_.empty()) continue;
      const std::string_view key = tokens_[0];
      if (key == "end_header") break;
      if (key == "comment" || key == "obj_info") continue;
      if (key == "format") {
        ParseFormat();
      } else if (key == "element") {
        ParseElement();
      } else if (key == "property") {
        ParseProperty();
      } else {
        Fail(file_, AtLine(lines_.line_number()) + ": unknown PLY header keyword " + Quote(key));
      }
    }
    if (!have_format_) Fail(file_, "PLY header has no 'format' line");
    header_.data_offset = lines_.offset();
    header_.data_line = lines_.line_number() + 1;
    CheckSizes(lines_.remaining());
    return header_;
  }

 private:
  void ParseFormat() {
    const std::string where = AtLine(lines_.line_number());
    if (have_format_) Fail(file_, where + ": a second 'format' line");
    if (tokens_.size() != 3) Fail(file_, where + ": expected 'format <encoding> 1.0'");
    if (tokens_[1] == "ascii") {
      header_.encoding = PlyEncoding::kAscii;
    } else if (tokens_[1] == "binary_little_endian") {
      header_.encoding = PlyEncoding::kBinaryLittleEndian;
    } else if (tokens_[1] == "binary_big_endian") {
      header_.encoding = PlyEncoding::kBinaryBigEndian;
    } else {
      Fail(file_, where + ": unknown PLY format " + Quote(tokens_[1]) +
                      " (expected ascii, binary_little_endian or binary_big_endian)");
    }
    if (tokens_[2] != "1.0" && tokens_[2] != "1") {
      Fail(file_, where + ": unsupported PLY version " + Quote(tokens_[2]));
    }
    have_format_ = true;
  }

  void ParseElement() {
    const std::string where = AtLine(lines_.line_number());
    if (tokens_.size() != 3) Fail(file_, where + ": expected 'element <name> <count>'");
    PlyElement element;
    element.name = std::string(tokens_[1]);
    element.header_line = lines_.line_number();
    if (!ParseInt64(tokens_[2], &element.count)) {
      Fail(file_, where + ": element count " + Quote(tokens_[2]) + " is not an integer");
    }
    CheckCount(options_, file_, element.count, "element '" + element.name + "' count", where);
    // Sets, not scans: a hostile header may declare 100,000s of names.
    if (!element_names_.insert(element.name).second) {
      Fail(file_, where + ": element '" + element.name + "' declared twice");
    }
    property_names_.clear();
    header_.elements.push_back(std::move(element));
  }

  ScalarType Type(std::string_view name, const std::string& where) {
    const auto type = ParsePlyType(name);
    if (!type) Fail(file_, where + ": unknown PLY property type " + Quote(name));
    return *type;
  }

  void ParseProperty() {
    const std::string where = AtLine(lines_.line_number());
    if (header_.elements.empty()) Fail(file_, where + ": property before any element");
    PlyElement& element = header_.elements.back();
    PlyProperty property;
    if (tokens_.size() >= 2 && tokens_[1] == "list") {
      if (tokens_.size() != 5) {
        Fail(file_, where + ": expected 'property list <count type> <item type> <name>'");
      }
      property.is_list = true;
      property.count_type = Type(tokens_[2], where);
      if (!IsInteger(property.count_type)) {
        Fail(file_, where + ": list count type " + Quote(tokens_[2]) + " is not an integer type");
      }
      property.type = Type(tokens_[3], where);
      property.name = std::string(tokens_[4]);
    } else {
      if (tokens_.size() != 3) Fail(file_, where + ": expected 'property <type> <name>'");
      property.type = Type(tokens_[1], where);
      property.name = std::string(tokens_[2]);
    }
    if (!property_names_.insert(property.name).second) {
      Fail(file_, where + ": property '" + property.name + "' declared twice in element '" +
                      element.name + "'");
    }
    element.properties.push_back(std::move(property));
  }

  // Every element's minimum size must fit in what follows the header.
  void CheckSizes(std::size_t data_bytes) {
    const bool ascii = header_.encoding == PlyEncoding::kAscii;
    auto left = static_cast<std::int64_t>(data_bytes);
    for (const PlyElement& element : header_.elements) {
      if (element.count == 0) continue;
      if (element.properties.empty()) {
        Fail(file_, AtLine(element.header_line) + ": element '" + element.name + "' has " +
                        std::to_string(element.count) + " items but no properties");
      }
      // ascii: each value is at least one character and one separator.
      const std::int64_t item = ascii ? 2 * static_cast<std::int64_t>(element.properties.size())
                                      : element.MinBinaryBytes();
      const std::int64_t slack = ascii ? 1 : 0;  // the last value needs no separator
      if (element.count > (left + slack) / item) {
        Fail(file_, AtLine(element.header_line) + ": element '" + element.name + "' declares " +
                        std::to_string(element.count) + " items of at least " +
                        std::to_string(item) + " bytes, but only " + std::to_string(left) +
                        " bytes of data are left (truncated file or wrong count)");
      }
      left -= element.count * item;
      if (left < 0) left = 0;
    }
  }

  const ReadOptions& options_;
  const std::filesystem::path& file_;
  LineCursor lines_;
  std::vector<std::string_view> tokens_;
  PlyHeader header_;
  bool have_format_ = false;
  std::unordered_set<std::string> element_names_;
  std::unordered_set<std::string> property_names_;  // of the current element
};

}  // namespace

std::int64_t PlyElement::MinBinaryBytes() const {
  std::int64_t bytes = 0;
  for (const PlyProperty& p : properties) bytes += SizeOf(p.is_list ? p.count_type : p.type);
  return bytes;
}

bool PlyElement::HasLists() const {
  for (const PlyProperty& p : properties) {
    if (p.is_list) return true;
  }
  return false;
}

int PlyElement::FindProperty(std::string_view property_name) const {
  for (std::size_t i = 0; i < properties.size(); ++i) {
    if (properties[i].name == property_name) return static_cast<int>(i);
  }
  return -1;
}

PlyHeader ParsePlyHeader(const ReadOptions& options, const std::filesystem::path& file,
                         std::string_view bytes) {
  return HeaderParser(options, file, bytes).Parse();
}

std::string ToString(PlyEncoding encoding) {
  switch (encoding) {
    case PlyEncoding::kAscii:
      return "ascii";
    case PlyEncoding::kBinaryLittleEndian:
      return "binary_little_endian";
    case PlyEncoding::kBinaryBigEndian:
      return "binary_big_endian";
  }
  return "ascii";
}

const char* PlyTypeName(ScalarType type) {
  switch (type) {
    case ScalarType::kInt8:
      return "char";
    case ScalarType::kUint8:
      return "uchar";
    case ScalarType::kInt16:
      return "short";
    case ScalarType::kUint16:
      return "ushort";
    case ScalarType::kInt32:
      return "int";
    case ScalarType::kUint32:
      return "uint";
    case ScalarType::kFloat32:
      return "float";
    case ScalarType::kFloat64:
      return "double";
  }
  return "float";
}

}  // namespace bespoke::io
