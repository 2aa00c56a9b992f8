#include "resize/io/pattern_io.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <sstream>

#include "resize/io/garmentcode.h"
#include "resize/io/pattern_dxf.h"
#include "resize/io/pattern_json.h"
#include "scanners/core/errors.h"
#include "scanners/core/json_io.h"

namespace bespoke {

Pattern LoadPattern(const std::filesystem::path& file, const std::filesystem::path& sidecar) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  Pattern pattern;
  if (extension == ".dxf") {
    pattern = ReadPatternDxf(file);
  } else {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file, "cannot open the pattern file");
    std::ostringstream text;
    text << in.rdbuf();
    const nlohmann::json document = ParseJsonWithComments(text.str(), file.string());
    pattern = IsGarmentCode(document)
                  ? PatternFromGarmentCode(GarmentCodeOptions{}, document, file.string())
                  : PatternFromJson(document, file.string());
  }
  if (!sidecar.empty()) {
    std::ifstream in(sidecar, std::ios::binary);
    if (!in) throw InputError(sidecar, "cannot open the sidecar file");
    std::ostringstream text;
    text << in.rdbuf();
    ApplySidecar(ParseJsonWithComments(text.str(), sidecar.string()), sidecar.string(), &pattern);
  }
  return pattern;
}

}  // namespace bespoke
