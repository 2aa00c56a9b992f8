// Numeric constants shared by the libraries (C++17 has no std::numbers).
// One definition, so that sources compiled together (a unity build) do not
// each bring their own.
#ifndef BESPOKE_SCANNERS_CORE_CONSTANTS_H_
#define BESPOKE_SCANNERS_CORE_CONSTANTS_H_

#include <limits>

namespace bespoke {

inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kInf = std::numeric_limits<double>::infinity();
// "No value" in tables and plots (missing measurements, undefined statistics).
inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_CONSTANTS_H_
