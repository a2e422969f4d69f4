// In: a finite number. Out: the shortest text that reads back as it ("0.2", "8192", "1e+30"):
// how settings are shown in help and in messages.
#pragma once

#include <charconv>
#include <string>

namespace curvebench {

inline std::string number_text(double value) {
  char text[32];
  return {text, std::to_chars(text, text + sizeof text, value).ptr};
}

}  // namespace curvebench
