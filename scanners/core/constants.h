// Mathematical constants shared by the libraries (C++17 has no std::numbers).
// One definition, so that sources compiled together (a unity build) do not
// each bring their own.
#ifndef BESPOKE_SCANNERS_CORE_CONSTANTS_H_
#define BESPOKE_SCANNERS_CORE_CONSTANTS_H_

namespace bespoke {

inline constexpr double kPi = 3.14159265358979323846;

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_CONSTANTS_H_
