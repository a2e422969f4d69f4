#include "voronoi/sort_by_decreasing_circumradius.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>

namespace curvebench {

void sort_by_decreasing_circumradius(const DelaunayVoronoi& dv, std::vector<int>& triangles) {
  struct Keyed {
    std::uint64_t key;
    int triangle;
  };
  const std::size_t count = triangles.size();
  std::vector<Keyed> items(count), buffer(count);
  for (std::size_t i = 0; i < count; ++i) {
    items[i] = {~std::bit_cast<std::uint64_t>(dv.circumradii[triangles[i]]), triangles[i]};
  }
  constexpr int kDigitBits = 16;
  constexpr std::uint64_t kDigitMask = (1u << kDigitBits) - 1;
  std::vector<std::size_t> start(kDigitMask + 2);
  for (int shift = 0; shift < 64; shift += kDigitBits) {
    std::fill(start.begin(), start.end(), 0);
    for (const auto& item : items) ++start[((item.key >> shift) & kDigitMask) + 1];
    // Radii of one scale share their sign and exponent bits: such a digit moves nothing.
    if (*std::max_element(start.begin(), start.end()) == count) continue;
    std::partial_sum(start.begin(), start.end(), start.begin());
    for (const auto& item : items) buffer[start[(item.key >> shift) & kDigitMask]++] = item;
    items.swap(buffer);
  }
  for (std::size_t i = 0; i < count; ++i) triangles[i] = items[i].triangle;
}

}  // namespace curvebench
