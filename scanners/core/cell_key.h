// Hash keys: a cell of a 2-D grid, an undirected mesh edge.
//
// A hash key for a cell of a 2-D grid: the cell's integer indices (any sign,
// e.g. floor(x / cell_mm)) packed into one 64-bit value, for
// std::unordered_map. Distinct for indices in [-2^31, 2^31); computed on the
// unsigned bit patterns, because shifting a negative signed value left is
// undefined behaviour before C++20 (UBSan reported it for cells left of x = 0).
#ifndef BESPOKE_SCANNERS_CORE_CELL_KEY_H_
#define BESPOKE_SCANNERS_CORE_CELL_KEY_H_

#include <cstdint>
#include <utility>

namespace bespoke {

inline std::int64_t CellKey2(std::int64_t ix, std::int64_t iy) {
  return static_cast<std::int64_t>((static_cast<std::uint64_t>(ix) << 32) ^
                                   (static_cast<std::uint64_t>(iy) & 0xffffffffu));
}

// A hash key for the undirected mesh edge between vertices a and b (indices
// >= 0): the same for (a, b) and (b, a).
inline std::uint64_t EdgeKey(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

}  // namespace bespoke

#endif  // BESPOKE_SCANNERS_CORE_CELL_KEY_H_
