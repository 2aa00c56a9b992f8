// XYZ / CSV / TXT point text: one point per line, values separated by
// spaces, tabs, commas or semicolons (so a decimal comma is NOT supported).
//
// Read: blank lines and '#' comments are skipped. The first other line may be
// a header of column names (any token not a number; a leading "//" as written
// by CloudCompare is removed); a single integer there is a point count (Leica
// PTS) and is skipped. Every data line must have the same number of columns,
// at least 3. With a header: x y z (required, any case), nx ny nz or
// normal_x..z -> normals, r g b or red green blue -> colours (0-255, or 0-1
// when every value is in [0, 1] and one is fractional), other columns ->
// scalars by name. Without one: x y z, then nx ny nz when there are 6 or more
// columns, further columns -> scalars "column_<n>" (1-based).
// Write: a header line, then the values in shortest round-trip text.
#include <algorithm>
#include <cctype>
#include <cmath>

#include "scanners/io/byte_reader.h"
#include "scanners/io/formats.h"

namespace bespoke::io {
namespace {

constexpr std::string_view kSeparators = ",;";

std::string Lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

bool AllNumbers(const std::vector<std::string_view>& tokens) {
  double v = 0.0;
  for (const auto& t : tokens) {
    if (!ParseDouble(t, &v)) return false;
  }
  return true;
}

// Column roles from names: 0-2 xyz, 3-5 normal, 6-8 colour, -1 scalar. The
// first column of each name takes the role.
std::vector<int> Roles(const std::vector<std::string>& names) {
  static const std::vector<std::vector<std::string>> kNames = {{"x"},
                                                               {"y"},
                                                               {"z"},
                                                               {"nx", "normal_x"},
                                                               {"ny", "normal_y"},
                                                               {"nz", "normal_z"},
                                                               {"r", "red"},
                                                               {"g", "green"},
                                                               {"b", "blue"}};
  std::vector<int> roles(names.size(), -1);
  bool taken[9] = {};
  for (std::size_t c = 0; c < names.size(); ++c) {
    const std::string name = Lower(names[c]);
    for (std::size_t r = 0; r < kNames.size() && roles[c] < 0; ++r) {
      const auto& options = kNames[r];
      if (!taken[r] && std::find(options.begin(), options.end(), name) != options.end()) {
        roles[c] = static_cast<int>(r);
        taken[r] = true;
      }
    }
  }
  return roles;
}

bool HasRoles(const std::vector<int>& roles, int first) {
  for (int r = first; r < first + 3; ++r) {
    if (std::find(roles.begin(), roles.end(), r) == roles.end()) return false;
  }
  return true;
}

RawScan Assemble(const std::filesystem::path& file, std::vector<std::string> names,
                 const std::vector<std::vector<double>>& columns, bool have_header) {
  const std::size_t n = columns[0].size();
  if (!have_header) {
    names.clear();
    const char* fixed[] = {"x", "y", "z", "nx", "ny", "nz"};
    const std::size_t named = columns.size() >= 6 ? 6 : 3;
    for (std::size_t c = 0; c < columns.size(); ++c) {
      names.push_back(c < named ? fixed[c] : "column_" + std::to_string(c + 1));
    }
  }
  std::vector<int> roles = Roles(names);
  if (!HasRoles(roles, 0)) Fail(file, "the header names no x, y and z columns");
  const bool normals = HasRoles(roles, 3), colors = HasRoles(roles, 6);
  RawScan raw;
  raw.encoding = "ascii";
  raw.fields = names;
  PointCloud& cloud = raw.cloud;
  const auto rows = static_cast<Eigen::Index>(n);
  cloud.points.resize(rows, 3);
  if (normals) cloud.normals.resize(rows, 3);
  if (colors) cloud.colors.resize(rows, 3);
  // Colours are 0-1 floats when every colour value is in [0, 1] and one is
  // fractional, else 0-255 integers (decided over all three columns).
  bool unit_range = true, fractional = false;
  for (std::size_t c = 0; c < columns.size() && colors; ++c) {
    if (roles[c] < 6) continue;
    for (const double x : columns[c]) {
      unit_range = unit_range && x >= 0.0 && x <= 1.0;
      fractional = fractional || x != std::round(x);
    }
  }
  NameSet scalar_names;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    const std::vector<double>& v = columns[c];
    const int role = roles[c];
    const Eigen::Map<const Eigen::VectorXd> values(v.data(), rows);
    if (role >= 0 && role < 3) {
      cloud.points.col(role) = values;
    } else if (role >= 3 && role < 6 && normals) {
      cloud.normals.col(role - 3) = values;
    } else if (role >= 6 && colors) {
      for (Eigen::Index i = 0; i < rows; ++i) {
        cloud.colors(i, role - 6) =
            ColorByte(v[static_cast<std::size_t>(i)], unit_range && fractional);
      }
    } else {
      cloud.scalars[scalar_names.Unique(names[c])] = values;
    }
  }
  return raw;
}

}  // namespace

RawScan ReadXyz(const ReadOptions& options, const std::filesystem::path& file,
                std::string_view bytes) {
  const std::string_view text_bytes = StripBom(bytes);
  LineCursor lines(text_bytes, bytes.size() - text_bytes.size());
  std::string_view line;
  std::vector<std::string_view> tokens;
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  bool first = true, have_header = false;
  while (lines.Next(&line)) {
    std::string_view text = Trim(line);
    const bool slashes = text.substr(0, 2) == "//";
    if (slashes) text.remove_prefix(2);
    if (text.empty() || text.front() == '#' || Tokenize(text, &tokens, kSeparators) == 0) continue;
    const std::string where = "line " + std::to_string(lines.line_number());
    if (first) {
      first = false;
      std::int64_t count = 0;
      if (!AllNumbers(tokens)) {
        for (const auto& t : tokens) names.emplace_back(t);
        have_header = true;
        continue;
      }
      if (tokens.size() == 1 && ParseInt64(tokens[0], &count)) continue;  // PTS point count
    }
    if (slashes) continue;  // a "//" comment
    if (columns.empty()) {
      if (tokens.size() < 3) {
        Fail(file, where + ": a point needs at least 3 values (x y z), found " +
                       std::to_string(tokens.size()));
      }
      if (have_header && names.size() != tokens.size()) {
        Fail(file, where + ": the header names " + std::to_string(names.size()) +
                       " columns but the first point has " + std::to_string(tokens.size()));
      }
      columns.resize(tokens.size());
    }
    if (tokens.size() != columns.size()) {
      Fail(file, where + ": expected " + std::to_string(columns.size()) + " values, found " +
                     std::to_string(tokens.size()));
    }
    CheckCount(options, file, static_cast<std::int64_t>(columns[0].size()) + 1, "number of points",
               where);
    for (std::size_t c = 0; c < tokens.size(); ++c) {
      double v = 0.0;
      if (!ParseDouble(tokens[c], &v))
        Fail(file, where + ": " + Quote(tokens[c]) + " is not a number");
      columns[c].push_back(v);
    }
  }
  if (columns.empty()) Fail(file, "no points: the file has no lines of numbers");
  return Assemble(file, names, columns, have_header);
}

std::string WriteXyz(const WriteOptions& options, const PointCloud& cloud, char separator) {
  cloud.CheckShapes();
  std::string out;
  LineCursor comments(options.comment);
  std::string_view line;
  while (comments.Next(&line)) out += "# " + std::string(line) + "\n";
  std::vector<std::string> names = {"x", "y", "z"};
  if (cloud.has_normals()) names.insert(names.end(), {"nx", "ny", "nz"});
  if (cloud.has_colors()) names.insert(names.end(), {"red", "green", "blue"});
  std::vector<const Eigen::VectorXd*> scalars;
  NameSet used;
  for (const std::string& name : names) used.Unique(name);
  for (const auto& [name, values] : cloud.scalars) {
    if (values.size() != cloud.size()) continue;
    std::string safe = name.empty() ? std::string("scalar") : name;
    for (char& c : safe) {
      if (c == ' ' || c == '\t' || c == ',' || c == ';' || c == '#' || c == '\r' || c == '\n')
        c = '_';
    }
    names.push_back(used.Unique(safe));
    scalars.push_back(&values);
  }
  out += separator == ' ' ? "//" : "";
  for (std::size_t k = 0; k < names.size(); ++k)
    out += (k ? std::string(1, separator) : "") + names[k];
  out += '\n';
  auto put = [&](double v, bool first_value) {
    if (!first_value) out += separator;
    AppendNumber(&out, v);
  };
  for (Eigen::Index i = 0; i < cloud.size(); ++i) {
    for (int c = 0; c < 3; ++c) put(cloud.points(i, c), c == 0);
    for (int c = 0; c < 3 && cloud.has_normals(); ++c) put(cloud.normals(i, c), false);
    for (int c = 0; c < 3 && cloud.has_colors(); ++c) put(cloud.colors(i, c), false);
    for (const Eigen::VectorXd* v : scalars) put((*v)[i], false);
    out += '\n';
  }
  return out;
}

}  // namespace bespoke::io
