// Small text helpers shared by the readers of text formats (DXF, .vit, CSV).
#ifndef BESPOKE_SCANNERS_CORE_TEXT_H_
#define BESPOKE_SCANNERS_CORE_TEXT_H_

#include <string>
#include <string_view>

namespace bespoke {

// `text` without leading and trailing blanks (space, tab, \r, \n).
inline std::string StripBlanks(std::string_view text) {
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return "";
  return std::string(text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1));
}

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_TEXT_H_
