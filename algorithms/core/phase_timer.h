// Wall-clock time per phase of a reconstruction, in milliseconds, for Reconstruction::timing_ms.
#pragma once

#include <chrono>
#include <string>
#include <utility>
#include <vector>

namespace curvebench {

class PhaseTimer {
 public:
  // Ends the current phase and names it.
  void lap(std::string phase) {
    const auto now = Clock::now();
    phases_.emplace_back(std::move(phase), milliseconds(last_, now));
    last_ = now;
  }
  // The phases so far followed by "total".
  std::vector<std::pair<std::string, double>> finish() {
    auto phases = phases_;
    phases.emplace_back("total", milliseconds(start_, Clock::now()));
    return phases;
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double milliseconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
  }
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_ = start_;
  std::vector<std::pair<std::string, double>> phases_;
};

}  // namespace curvebench
