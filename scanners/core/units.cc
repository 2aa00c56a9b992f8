#include "scanners/core/units.h"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace bespoke {

double MillimetresPer(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kMillimetre:
      return 1.0;
    case LengthUnit::kCentimetre:
      return 10.0;
    case LengthUnit::kDecimetre:
      return 100.0;
    case LengthUnit::kMetre:
      return 1000.0;
  }
  return 1.0;
}

std::string ToString(LengthUnit unit) {
  switch (unit) {
    case LengthUnit::kMillimetre:
      return "mm";
    case LengthUnit::kCentimetre:
      return "cm";
    case LengthUnit::kDecimetre:
      return "dm";
    case LengthUnit::kMetre:
      return "m";
  }
  return "mm";
}

std::optional<LengthUnit> ParseLengthUnit(std::string_view text) {
  std::string s(text);
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  if (s == "mm" || s == "millimetre" || s == "millimetres" || s == "millimeter" ||
      s == "millimeters")
    return LengthUnit::kMillimetre;
  if (s == "cm" || s == "centimetre" || s == "centimetres" || s == "centimeter" ||
      s == "centimeters")
    return LengthUnit::kCentimetre;
  if (s == "dm" || s == "decimetre" || s == "decimetres" || s == "decimeter" || s == "decimeters")
    return LengthUnit::kDecimetre;
  if (s == "m" || s == "metre" || s == "metres" || s == "meter" || s == "meters")
    return LengthUnit::kMetre;
  return std::nullopt;
}

std::optional<LengthUnit> GuessLengthUnit(double extent) {
  if (!std::isfinite(extent) || extent <= 0.0) return std::nullopt;
  constexpr double kMinBodyMm = 500.0;
  constexpr double kMaxBodyMm = 2600.0;
  for (LengthUnit unit : {LengthUnit::kMillimetre, LengthUnit::kCentimetre, LengthUnit::kDecimetre,
                          LengthUnit::kMetre}) {
    const double mm = extent * MillimetresPer(unit);
    if (mm >= kMinBodyMm && mm <= kMaxBodyMm) return unit;
  }
  return std::nullopt;
}

}  // namespace bespoke
