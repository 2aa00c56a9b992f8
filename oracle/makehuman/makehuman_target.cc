#include "oracle/makehuman/makehuman_target.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_set>

#include "scanners/core/errors.h"

namespace bespoke {
namespace {

// Splits `line` at spaces/tabs into at most 5 tokens; returns the count.
int Tokens(std::string_view line, std::string_view* tokens) {
  int n = 0;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size()) break;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r') ++i;
    if (n < 5) tokens[n] = line.substr(start, i - start);
    ++n;
  }
  return n;
}

bool ParseNumber(std::string_view token, double* value) {
  // from_chars rejects a leading '+'; MakeHuman writes "-.097" and ".41".
  if (!token.empty() && token[0] == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), *value);
  return ec == std::errc() && end == token.data() + token.size() && std::isfinite(*value);
}

}  // namespace

MakeHumanTarget ParseMakeHumanTarget(std::string_view text, const std::filesystem::path& file) {
  std::vector<int> vertex;
  std::vector<double> offsets;
  std::unordered_set<int> seen;
  std::size_t line_number = 0, pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    std::string_view t[5];
    const int n = Tokens(line, t);
    if (n == 0) continue;
    const std::string where = "line " + std::to_string(line_number) + ": ";
    if (n != 4)
      throw InputError(file,
                       where + "expected 'index dx dy dz', found " + std::to_string(n) + " fields");
    double index = 0, d[3];
    if (!ParseNumber(t[0], &index) || index < 0 || index != std::floor(index) || index > 1e9)
      throw InputError(file, where + "'" + std::string(t[0]) + "' is not a vertex index");
    for (int k = 0; k < 3; ++k)
      if (!ParseNumber(t[k + 1], &d[k]))
        throw InputError(file, where + "'" + std::string(t[k + 1]) + "' is not a finite number");
    if (!seen.insert(static_cast<int>(index)).second)
      throw InputError(file, where + "vertex " + std::string(t[0]) + " appears twice");
    vertex.push_back(static_cast<int>(index));
    offsets.insert(offsets.end(), d, d + 3);
  }
  MakeHumanTarget target;
  target.vertex = std::move(vertex);
  target.offset = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(
      offsets.data(), static_cast<Eigen::Index>(target.vertex.size()), 3);
  return target;
}

MakeHumanTarget ReadMakeHumanTarget(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file, "cannot open the target file");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(file, "cannot read the target file");
  return ParseMakeHumanTarget(text.str(), file);
}

}  // namespace bespoke
