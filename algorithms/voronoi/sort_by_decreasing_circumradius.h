// The priority order of the labeling walks (Algorithm 2 of Peethambaran et al.) and of
// shape-hull's sculpting: Voronoi vertices by decreasing circumradius.
//
// In:  the layer and a list of its finite triangles.
// Out: the list reordered by decreasing circumradius; equal radii keep their order in the
//      list (stable), so a list in index order breaks ties by the smaller index. A
//      least-significant-digit radix sort on the radii's bits: non-negative doubles order
//      like their bit patterns, complemented the largest comes first. Linear in the list's
//      length, and it reads the radii in list order, not at random as a comparison sort
//      through the indices would.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <numeric>
#include <span>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

void sort_by_decreasing_circumradius(const DelaunayVoronoi& dv, std::vector<int>& triangles);

// The same order for a walk whose roots are mostly reached by earlier roots' walks before their
// turn (labeling-holes' region walk, walk_region_from_its_boundary.h), so that most of a full
// sort would order roots that are skipped. Calls visit(t) for every t of `triangles` for which
// reached(t) is false when its turn comes, by decreasing circumradius, ties by the smaller
// index (the order of sort_by_decreasing_circumradius on a list in index order). The list is split into buckets by the radius's leading bits
// (the sign, the exponent and 4 bits of the mantissa: radii within a factor 2^(1/16)) in one
// counting pass, and a bucket is sorted only when the walk gets to it, after dropping what is
// reached by then. reached(t) may turn true during visits, never back to false. Each entry
// left in a bucket is announced (announce(t)) a few turns before its own, so that the walk can
// request its memory: in radius order the roots lie all over the plane, and most walks from
// them are a few vertices long (earlier walks surround them), so their first loads would
// otherwise be waited for one root at a time.
template <class Reached, class Visit, class Announce>
void for_each_by_decreasing_circumradius(const DelaunayVoronoi& dv, std::span<const int> triangles, Reached reached,
                                         Visit visit, Announce announce) {
  struct Keyed {
    std::uint64_t key;
    int triangle;
  };
  // Complemented, the bits of non-negative doubles order the largest first (as in the sort).
  auto key_of = [&](int t) { return ~std::bit_cast<std::uint64_t>(dv.circumradii[t]); };
  constexpr int kBucketBits = 16;
  auto bucket_of = [&](int t) { return static_cast<std::size_t>(key_of(t) >> (64 - kBucketBits)); };
  std::vector<std::uint32_t> starts((std::size_t{1} << kBucketBits) + 1, 0);
  for (int t : triangles) ++starts[bucket_of(t) + 1];
  std::partial_sum(starts.begin(), starts.end(), starts.begin());
  std::vector<std::uint32_t> next(starts.begin(), starts.end() - 1);
  std::vector<int> bucketed(triangles.size());
  for (int t : triangles) bucketed[next[bucket_of(t)]++] = t;  // stable: index order within a bucket
  std::vector<Keyed> pending;
  for (std::size_t bucket = 0; bucket + 1 < starts.size(); ++bucket) {
    if (starts[bucket] == starts[bucket + 1]) continue;
    pending.clear();
    for (std::uint32_t i = starts[bucket]; i < starts[bucket + 1]; ++i) {
      if (!reached(bucketed[i])) pending.push_back({key_of(bucketed[i]), bucketed[i]});
    }
    std::sort(pending.begin(), pending.end(), [](const Keyed& a, const Keyed& b) {
      return a.key < b.key || (a.key == b.key && a.triangle < b.triangle);
    });
    constexpr std::size_t kLookahead = 4;
    for (std::size_t i = 0; i < pending.size(); ++i) {
      if (i + kLookahead < pending.size()) announce(pending[i + kLookahead].triangle);
      if (!reached(pending[i].triangle)) visit(pending[i].triangle);
    }
  }
}

}  // namespace curvebench
