// Catalogue::ToMarkdown: docs/measurements.md, generated from catalogue.json.
#include <sstream>

#include "measure/catalogue/catalogue.h"

namespace bespoke {
namespace {

// Table cells must not contain '|' or line breaks.
std::string Cell(const std::string& text) {
  std::string out;
  for (const char c : text) out += (c == '|') ? '/' : (c == '\n' ? ' ' : c);
  return out.empty() ? "–" : out;
}

std::string Code(const std::string& text) { return text.empty() ? "–" : "`" + text + "`"; }

std::string Join(const std::vector<std::string>& items, const char* separator, bool code) {
  std::string out;
  for (const std::string& item : items)
    out += (out.empty() ? "" : separator) + (code ? Code(item) : item);
  return out;
}

std::string MethodText(const MeasurementDef& m) {
  switch (m.method) {
    case MeasurementMethod::kSectionHull:
      if (m.plane == GirthPlane::kPerpendicularToAxis)
        return "hull of the section ⟂ axis " + Code(m.axis[0]) + " → " + Code(m.axis[1]);
      if (m.plane == GirthPlane::kThroughPoints)
        return "hull of the section in the plane through the three datum points";
      if (!m.narrowest_up_to.empty())
        return "hull of the smallest horizontal section up to " + Code(m.narrowest_up_to);
      return "hull of the horizontal section";
    case MeasurementMethod::kGeodesic:
      if (m.kind == MeasurementKind::kGirth) return "closed geodesic chain (a tape over the skin)";
      return m.to_floor ? "geodesic chain, + height of the last point" : "geodesic chain";
    case MeasurementMethod::kBreadth:
      return "horizontal straight distance";
    case MeasurementMethod::kPointToLine:
      return "distance from the first point to the line through the others";
    case MeasurementMethod::kHeight:
      return m.datum.size() == 1 ? "height above the floor" : "vertical distance";
  }
  return "";
}

}  // namespace

std::string Catalogue::ToMarkdown() const {
  std::ostringstream md;
  md << "# Landmarks and measurements\n\n"
     << "<!-- Generated from measure/catalogue/catalogue.json; do not edit. Regenerate with\n"
     << "     BESPOKE_UPDATE_DOCS=1 build/measure/catalogue/catalogue_tests "
        "--gtest_filter=Catalogue.MarkdownDocIsCurrent -->\n\n";
  for (const std::string& note : notes_) md << "- " << note << "\n";
  md << "\n## Landmarks (datum points)\n\n"
     << landmarks_.size() << " landmarks (left/right pairs share a row).\n\n"
     << "| name | region | definition | also called | standard |\n"
     << "|---|---|---|---|---|\n";
  auto ends_with = [](const std::string& s, const std::string& tail) {
    return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
  };
  for (const LandmarkDef& l : landmarks_) {
    std::string names = Code(l.name);
    if (ends_with(l.name, "_right") && HasLandmark(l.name.substr(0, l.name.size() - 6) + "_left"))
      continue;  // shown with its left twin
    if (ends_with(l.name, "_left")) {
      const std::string right = l.name.substr(0, l.name.size() - 5) + "_right";
      if (HasLandmark(right)) names += ", " + Code(right);
    }
    const std::string definition =
        l.definition + (l.level ? " Defined by its level: its height is what counts." : "");
    md << "| " << names << " | " << l.region << " | " << Cell(definition) << " | "
       << Cell(Join(l.aliases, ", ", false)) << " | " << Cell(l.standard) << " |\n";
  }
  md << "\n## Measurements\n\n"
     << measurements_.size() << " measurements. Valentina names are those of its `.vit` "
     << "individual measurement files (values in cm there); FreeSewing names those of its "
     << "measurement JSON (mm).\n\n"
     << "| name | kind | datum points | method | side | definition | standard | thesis | "
        "Valentina | FreeSewing |\n"
     << "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const MeasurementDef& m : measurements_) {
    std::string definition = m.definition;
    if (!m.deviation.empty()) definition += " *Deviation:* " + m.deviation;
    md << "| " << Code(m.name) << " | " << ToString(m.kind) << " | " << Join(m.datum, " → ", true)
       << " | " << MethodText(m) << " | " << m.side << " | " << Cell(definition) << " | "
       << Cell(m.standard) << " | " << Cell(m.thesis) << " | " << Code(m.valentina) << " | "
       << Code(m.freesewing) << " |\n";
  }
  return md.str();
}

}  // namespace bespoke
