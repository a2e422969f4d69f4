// How well reconstructed edges agree with the true adjacency of the samples.
//
// In:  reconstructed edges and true edges, both between sample indices (order within an
//      edge and duplicates do not matter).
// Out: the number of reconstructed edges that are true; precision, that number over the
//      reconstructed edges (0 for an empty reconstruction, which finds nothing); recall,
//      that number over the true edges (1 when there are none); F1, their harmonic mean
//      2 P R / (P + R) (0 when both are 0); exactness, whether the two edge sets are equal.
#pragma once

#include <span>

#include "core/point.h"

namespace curvebench {

struct EdgeAgreement {
  int reconstructed_edges = 0;  // distinct
  int true_edges = 0;           // distinct
  int correct_edges = 0;
  double precision = 0.0;
  double recall = 1.0;
  double f1 = 0.0;
  bool exact = false;
};

EdgeAgreement edge_agreement(std::span<const Edge> reconstructed, std::span<const Edge> truth);

}  // namespace curvebench
