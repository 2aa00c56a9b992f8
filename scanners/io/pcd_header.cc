#include "scanners/io/pcd_header.h"

#include <set>
#include <unordered_set>

#include "scanners/io/formats.h"

namespace bespoke::io {
namespace {

// A point larger than this is not a point cloud (PCL's largest standard
// point types are a few hundred bytes; FPFH histograms 33 floats).
constexpr std::int64_t kMaxPointBytes = 1 << 20;

class PcdHeaderParser {
 public:
  PcdHeaderParser(const ReadOptions& options, const std::filesystem::path& file,
                  std::string_view bytes)
      : options_(options), file_(file), lines_(bytes) {}

  PcdHeader Parse() {
    std::string_view line;
    std::vector<std::string_view> names, sizes, types, counts;
    bool have_points = false, have_data = false;
    while (!have_data && lines_.Next(&line)) {
      if (Tokenize(line, &tokens_) == 0 || tokens_[0].front() == '#') continue;
      const std::string key(tokens_[0]);
      if (!seen_.insert(key).second) Fail(file_, Where() + ": a second " + key + " line");
      const std::vector<std::string_view> values(tokens_.begin() + 1, tokens_.end());
      if (key == "VERSION") {
        continue;
      } else if (key == "FIELDS" || key == "SIZE" || key == "TYPE" || key == "COUNT") {
        if (values.empty()) Fail(file_, Where() + ": " + key + " has no values");
        // The views point into the file's bytes, which outlive the parse.
        (key == "FIELDS" ? names : key == "SIZE" ? sizes : key == "TYPE" ? types : counts) = values;
      } else if (key == "WIDTH") {
        header_.width = Integer(values, key);
      } else if (key == "HEIGHT") {
        header_.height = Integer(values, key);
      } else if (key == "POINTS") {
        header_.points = Integer(values, key);
        have_points = true;
      } else if (key == "VIEWPOINT") {
        double unused = 0.0;
        if (values.size() != 7) Fail(file_, Where() + ": VIEWPOINT needs 7 numbers");
        for (const auto& v : values) {
          if (!ParseDouble(v, &unused)) Fail(file_, Where() + ": " + Quote(v) + " is not a number");
        }
      } else if (key == "DATA") {
        Data(values);
        have_data = true;
      } else {
        Fail(file_, Where() + ": unknown PCD header keyword " + Quote(key));
      }
    }
    if (!have_data) Fail(file_, "PCD header has no DATA line");
    header_.data_offset = lines_.offset();
    header_.data_line = lines_.line_number() + 1;
    Fields(names, sizes, types, counts);
    Counts(have_points);
    return header_;
  }

 private:
  std::string Where() const { return "line " + std::to_string(lines_.line_number()); }

  std::int64_t Integer(const std::vector<std::string_view>& values, const std::string& key) {
    std::int64_t v = 0;
    if (values.size() != 1 || !ParseInt64(values[0], &v)) {
      Fail(file_, Where() + ": " + key + " needs one integer");
    }
    CheckCount(options_, file_, v, key, Where());
    return v;
  }

  void Data(const std::vector<std::string_view>& values) {
    if (values.size() != 1) Fail(file_, Where() + ": DATA needs one encoding");
    if (values[0] == "ascii") {
      header_.encoding = PcdEncoding::kAscii;
    } else if (values[0] == "binary") {
      header_.encoding = PcdEncoding::kBinary;
    } else if (values[0] == "binary_compressed") {
      header_.encoding = PcdEncoding::kBinaryCompressed;
    } else {
      Fail(file_, Where() + ": unknown PCD DATA encoding " + Quote(values[0]) +
                      " (expected ascii, binary or binary_compressed)");
    }
  }

  void Fields(const std::vector<std::string_view>& names,
              const std::vector<std::string_view>& sizes,
              const std::vector<std::string_view>& types,
              const std::vector<std::string_view>& counts) {
    if (names.empty()) Fail(file_, "PCD header has no FIELDS line");
    if (sizes.size() != names.size() || types.size() != names.size() ||
        (!counts.empty() && counts.size() != names.size())) {
      Fail(file_, "PCD header: FIELDS has " + std::to_string(names.size()) +
                      " names but SIZE has " + std::to_string(sizes.size()) + ", TYPE " +
                      std::to_string(types.size()) + " and COUNT " + std::to_string(counts.size()) +
                      " values");
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      PcdField f;
      f.name = std::string(names[i]);
      std::int64_t size = 0;
      if (!ParseInt64(sizes[i], &size) || (size != 1 && size != 2 && size != 4 && size != 8)) {
        Fail(file_, "PCD field '" + f.name + "': SIZE " + Quote(sizes[i]) + " is not 1, 2, 4 or 8");
      }
      f.size = static_cast<int>(size);
      f.type = types[i].size() == 1 ? types[i][0] : '?';
      if (!counts.empty() && (!ParseInt64(counts[i], &f.count) || f.count < 1)) {
        Fail(file_, "PCD field '" + f.name + "': COUNT " + Quote(counts[i]) + " is not >= 1");
      }
      SetType(&f, types[i]);
      f.offset = header_.point_bytes;
      if (f.count > kMaxPointBytes) f.count = kMaxPointBytes + 1;  // no overflow below
      header_.point_bytes += f.count * f.size;
      if (header_.point_bytes > kMaxPointBytes) {
        Fail(file_, "PCD header: a point of more than " + std::to_string(kMaxPointBytes) +
                        " bytes (corrupt SIZE/COUNT)");
      }
      if (f.name != "_" && !names_.insert(f.name).second) {
        Fail(file_, "PCD header: field '" + f.name + "' appears twice");
      }
      header_.fields.push_back(std::move(f));
    }
    for (const char* axis : {"x", "y", "z"}) {
      const int i = header_.FindField(axis);
      if (i < 0 || header_.fields[static_cast<std::size_t>(i)].count != 1 ||
          !header_.fields[static_cast<std::size_t>(i)].readable) {
        Fail(file_, "PCD header: fields x, y and z (one value each) are required");
      }
    }
  }

  void SetType(PcdField* f, std::string_view type) {
    const int s = f->size;
    if (f->type == 'F' && (s == 4 || s == 8)) {
      f->scalar = s == 4 ? ScalarType::kFloat32 : ScalarType::kFloat64;
    } else if (f->type == 'I' || f->type == 'U') {
      const bool u = f->type == 'U';
      if (s == 1) f->scalar = u ? ScalarType::kUint8 : ScalarType::kInt8;
      if (s == 2) f->scalar = u ? ScalarType::kUint16 : ScalarType::kInt16;
      if (s == 4) f->scalar = u ? ScalarType::kUint32 : ScalarType::kInt32;
      f->readable = s != 8;
    } else {
      Fail(file_, "PCD field '" + f->name + "': TYPE " + Quote(type) + " with SIZE " +
                      std::to_string(s) + " is not F (4/8), I or U (1/2/4/8)");
    }
  }

  void Counts(bool have_points) {
    if (!seen_.count("WIDTH")) Fail(file_, "PCD header has no WIDTH line");
    if (header_.width > 0 && header_.height > options_.max_elements / header_.width) {
      Fail(file_, "PCD header: WIDTH * HEIGHT is more than the limit of " +
                      std::to_string(options_.max_elements) + " points");
    }
    const std::int64_t wh = header_.width * header_.height;
    if (!have_points) header_.points = wh;
    if (header_.points != wh) {
      Fail(file_, "PCD header: POINTS " + std::to_string(header_.points) +
                      " is not WIDTH * HEIGHT = " + std::to_string(wh));
    }
  }

  const ReadOptions& options_;
  const std::filesystem::path& file_;
  LineCursor lines_;
  std::vector<std::string_view> tokens_;
  std::set<std::string> seen_;
  std::unordered_set<std::string> names_;  // a set: FIELDS may list 100,000s of names
  PcdHeader header_;
};

}  // namespace

int PcdHeader::FindField(std::string_view name) const {
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (fields[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

PcdHeader ParsePcdHeader(const ReadOptions& options, const std::filesystem::path& file,
                         std::string_view bytes) {
  return PcdHeaderParser(options, file, bytes).Parse();
}

std::string ToString(PcdEncoding encoding) {
  switch (encoding) {
    case PcdEncoding::kAscii:
      return "ascii";
    case PcdEncoding::kBinary:
      return "binary";
    case PcdEncoding::kBinaryCompressed:
      return "binary_compressed";
  }
  return "ascii";
}

}  // namespace bespoke::io
