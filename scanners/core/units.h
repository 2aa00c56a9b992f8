// Length units of input files, and conversion to millimetres.
//
// Everything inside Bespoke is in millimetres. Files arrive in metres
// (most scanners, PCL, Open3D), millimetres, centimetres or decimetres
// (MakeHuman). GuessLengthUnit() decides from a body's extent; the
// `--units` option of the CLI overrides it.
#ifndef BESPOKE_SCANNERS_CORE_UNITS_H_
#define BESPOKE_SCANNERS_CORE_UNITS_H_

#include <optional>
#include <string>
#include <string_view>

namespace bespoke {

enum class LengthUnit { kMillimetre, kCentimetre, kDecimetre, kMetre };

// 1, 10, 100 or 1000.
double MillimetresPer(LengthUnit unit);

// "mm", "cm", "dm", "m".
std::string ToString(LengthUnit unit);

// Accepts "mm", "cm", "dm", "m" (and "millimetres", "metres", ...);
// nullopt for anything else.
std::optional<LengthUnit> ParseLengthUnit(std::string_view text);

// The unit in which a standing person whose largest bounding-box side is
// `extent` (in file units) is between 0.5 m and 2.6 m tall (children to the
// tallest adults, with arms raised); nullopt when no unit gives a plausible
// body size (e.g. extent <= 0 or not finite).
std::optional<LengthUnit> GuessLengthUnit(double extent);

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_UNITS_H_
