#include "core/registry.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace curvebench {
namespace {

// Function-local, so that registrations from other translation units' static initialisers
// find it constructed whatever the order of initialisation.
std::vector<std::unique_ptr<Algorithm>>& registered() {
  static std::vector<std::unique_ptr<Algorithm>> algorithms;
  return algorithms;
}

class EdgesFromDelaunay final : public Algorithm {
 public:
  EdgesFromDelaunay(std::string name, std::string citation, DelaunayEdgeFunction edges, CollinearInput collinear)
      : info_{std::move(name), std::move(citation), kCurve, {}, SiteInput::kDelaunay, collinear}, edges_(edges) {}
  const AlgorithmInfo& info() const override { return info_; }
  SiteResult run(const Sites& sites, const ParameterValues&, PhaseTimer& timer) const override {
    SiteResult result;
    result.curve_edges = edges_(*sites.delaunay);
    timer.lap(info_.name);
    return result;
  }

 private:
  AlgorithmInfo info_;
  DelaunayEdgeFunction edges_;
};

bool valid_name(const std::string& name) {
  if (name.empty() || name.front() == '-' || name.back() == '-') return false;
  return std::all_of(name.begin(), name.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; });
}

}  // namespace

bool register_algorithm(std::unique_ptr<Algorithm> algorithm) {
  const std::string name = algorithm->name();
  if (!valid_name(name)) throw std::logic_error("algorithm name '" + name + "' is not lower-case words joined by '-'");
  auto& list = registered();
  for (const auto& known : list) {
    if (known->name() == name) throw std::logic_error("two algorithms are named '" + name + "'");
  }
  list.push_back(std::move(algorithm));
  return true;
}

bool register_delaunay_curve_algorithm(std::string name, std::string citation, DelaunayEdgeFunction edges,
                                       CollinearInput collinear) {
  return register_algorithm(std::make_unique<EdgesFromDelaunay>(std::move(name), std::move(citation), edges, collinear));
}

std::vector<const Algorithm*> all_algorithms() {
  std::vector<const Algorithm*> list;
  for (const auto& algorithm : registered()) list.push_back(algorithm.get());
  std::sort(list.begin(), list.end(), [](const Algorithm* a, const Algorithm* b) { return a->name() < b->name(); });
  return list;
}

const Algorithm& find_algorithm(const std::string& name) {
  std::string known;
  for (const Algorithm* algorithm : all_algorithms()) {
    if (algorithm->name() == name) return *algorithm;
    known += (known.empty() ? "" : ", ") + algorithm->name();
  }
  throw InputError("unknown algorithm '" + name + "' (known: " + known + ")");
}

}  // namespace curvebench
