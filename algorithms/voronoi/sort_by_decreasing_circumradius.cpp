#include "voronoi/sort_by_decreasing_circumradius.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <memory>
#include <numeric>

namespace curvebench {

void sort_by_decreasing_circumradius(const DelaunayVoronoi& dv, std::vector<int>& triangles) {
  struct Keyed {
    std::uint64_t key;
    int triangle;
  };
  const std::size_t count = triangles.size();
  auto key_of = [&](int t) { return ~std::bit_cast<std::uint64_t>(dv.circumradii[t]); };
  constexpr int kDigitBits = 16, kDigits = 64 / kDigitBits;
  constexpr std::uint64_t kDigitMask = (std::uint64_t{1} << kDigitBits) - 1;
  // Every digit's counts in one pass over the radii.
  std::vector<std::size_t> counts(kDigits << kDigitBits, 0);
  for (int t : triangles) {
    const std::uint64_t key = key_of(t);
    for (int digit = 0; digit < kDigits; ++digit) ++counts[(digit << kDigitBits) + ((key >> (digit * kDigitBits)) & kDigitMask)];
  }
  // Radii of one scale share their sign and exponent bits: such a digit moves nothing.
  std::vector<int> digits;
  for (int digit = 0; digit < kDigits; ++digit) {
    const auto first = counts.begin() + (digit << kDigitBits);
    if (*std::max_element(first, first + (1 << kDigitBits)) != count) digits.push_back(digit);
  }
  // The first pass reads the keys straight from the radii, the last writes only the indices.
  // Allocated without zero-filling: every element is written before it is read.
  std::unique_ptr<Keyed[]> items, buffer;
  if (digits.size() > 1) {
    items = std::make_unique_for_overwrite<Keyed[]>(count);
    buffer = std::make_unique_for_overwrite<Keyed[]>(count);
  }
  std::vector<int> order(digits.empty() ? 0 : count);
  for (std::size_t pass = 0; pass < digits.size(); ++pass) {
    const int shift = digits[pass] * kDigitBits;
    std::size_t* next = counts.data() + (digits[pass] << kDigitBits);
    std::exclusive_scan(next, next + (1 << kDigitBits), next, std::size_t{0});
    const bool first = pass == 0, last = pass + 1 == digits.size();
    for (std::size_t i = 0; i < count; ++i) {
      const Keyed item = first ? Keyed{key_of(triangles[i]), triangles[i]} : items[i];
      const std::size_t position = next[(item.key >> shift) & kDigitMask]++;
      if (last) {
        order[position] = item.triangle;
      } else {
        buffer[position] = item;
      }
    }
    items.swap(buffer);
  }
  if (!digits.empty()) triangles.swap(order);
}

}  // namespace curvebench
