// libFuzzer target: the points-file parser. Any input either parses or throws
// PointsFileError; every parsed coordinate is finite.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/points_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    for (const auto& p : curvebench::parse_points(text, "fuzz")) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) __builtin_trap();
    }
  } catch (const curvebench::PointsFileError&) {
  }
  return 0;
}
