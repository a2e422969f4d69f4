// The sites in Z (Morton) order of the cells of a grid over their bounding box: the order in
// which to run one nearest-neighbour query per site, so that consecutive queries walk the same
// k-d tree nodes whatever the input order (shuffled input stays cache friendly).
//
// In:  sites (finite; any order, duplicates allowed).
// Out: a permutation of 0 .. n-1: the sites by cell in Z order, one to four sites a cell on
//      average, by index within a cell (a counting sort); index order when the bounding box's
//      extent is zero or overflows.
#pragma once

#include <span>
#include <vector>

#include "core/point.h"

namespace curvebench {

std::vector<int> z_order(std::span<const Point2> sites);

}  // namespace curvebench
