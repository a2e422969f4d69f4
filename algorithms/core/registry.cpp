#include "core/registry.h"

#include "alpha-shape/alpha_shape.h"
#include "crust/crust.h"
#include "labeling/labeling.h"
#include "local-crust/local_crust.h"
#include "nn-crust/nn_crust.h"
#include "optimal-transport/optimal_transport.h"

namespace curvebench {

const std::vector<std::unique_ptr<Algorithm>>& all_algorithms() {
  static const auto algorithms = [] {
    std::vector<std::unique_ptr<Algorithm>> list;
    list.push_back(make_labeling_algorithm());
    list.push_back(make_crust_algorithm());
    list.push_back(make_nn_crust_algorithm());
    list.push_back(make_local_crust_algorithm());
    list.push_back(make_alpha_shape_algorithm());
    list.push_back(make_optimal_transport_algorithm());
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
