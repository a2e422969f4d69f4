#include "core/registry.h"

#include "labeling/labeling.h"

namespace curvebench {

const std::vector<std::unique_ptr<Algorithm>>& all_algorithms() {
  static const auto algorithms = [] {
    std::vector<std::unique_ptr<Algorithm>> list;
    list.push_back(make_labeling_algorithm());
    return list;
  }();
  return algorithms;
}

const Algorithm& find_algorithm(const std::string& name) {
  std::string known;
  for (const auto& algorithm : all_algorithms()) {
    if (algorithm->name() == name) return *algorithm;
    known += (known.empty() ? "" : ", ") + algorithm->name();
  }
  throw InputError("unknown algorithm '" + name + "' (known: " + known + ")");
}

}  // namespace curvebench
