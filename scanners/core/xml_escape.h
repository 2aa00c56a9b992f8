// Text for XML, HTML and SVG documents: the five characters with a meaning
// in markup (& < > " ') replaced by their entities, everything else (UTF-8
// included) copied as it is. Safe in element text and in quoted attributes.
// Used by every writer of markup (reports, SVG patterns, Valentina .vit).
#ifndef BESPOKE_SCANNERS_CORE_XML_ESCAPE_H_
#define BESPOKE_SCANNERS_CORE_XML_ESCAPE_H_

#include <string>

namespace bespoke {

inline std::string XmlEscape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_XML_ESCAPE_H_
