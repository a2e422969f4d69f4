#include "metrics/edge_agreement.h"

#include <set>

namespace curvebench {
namespace {

std::set<Edge> normalised(std::span<const Edge> edges) {
  std::set<Edge> set;
  for (const Edge& e : edges) set.insert(make_edge(e[0], e[1]));
  return set;
}

}  // namespace

EdgeAgreement edge_agreement(std::span<const Edge> reconstructed, std::span<const Edge> truth) {
  const std::set<Edge> found = normalised(reconstructed);
  const std::set<Edge> expected = normalised(truth);
  EdgeAgreement agreement;
  agreement.reconstructed_edges = static_cast<int>(found.size());
  agreement.true_edges = static_cast<int>(expected.size());
  for (const Edge& e : found) agreement.correct_edges += expected.contains(e) ? 1 : 0;
  if (!found.empty()) agreement.precision = static_cast<double>(agreement.correct_edges) / agreement.reconstructed_edges;
  if (!expected.empty()) agreement.recall = static_cast<double>(agreement.correct_edges) / agreement.true_edges;
  const double sum = agreement.precision + agreement.recall;
  if (sum > 0.0) agreement.f1 = 2.0 * agreement.precision * agreement.recall / sum;
  agreement.exact = found == expected;
  return agreement;
}

}  // namespace curvebench
