// Whether the closed curves a region walk found through missed samples stand apart from the
// other samples, as the curves of an epsilon-sample do, or join samples that belong elsewhere.
//
// On an epsilon-sample, both curve edges at a sample s are at most 2 epsilon / (1 - epsilon)
// lfs(s) long (Definition 4), while a sample of another curve lies beyond the medial axis that
// separates the two curves, at least lfs(s) away. So for epsilon < 1/3 every sample of a
// hole's curve stands apart: both its edges on the curve are shorter than each Delaunay edge
// from it to a sample off the curve. Where the paper closed pockets off at their mouths (the
// tips of a sparse star, the slots of a sparse outline), the samples down their walls keep
// all-inner cells, and the walk can join samples of two pockets into a small closed "hole"
// whose edges are longer than the way from most of its samples back to their own walls.
// Random sampling leaves a few large gaps on a true hole too (a glyph's counter at a few
// hundred samples), so a curve is taken when most of its samples stand apart: more than half.
//
// In:  Delaunay/Voronoi arrays, at construction; per call, `curves`, the Delaunay edges of one
//      part's boundary (closed curves), or of a pocket's walls (open chains: step 8 of
//      labeling-holes leaves the mouth out), each sample counted once; `continuations`, curve
//      edges that continue open chains (step 8: the curve edges the pocket keeps at its walls'
//      ends), whose samples count as on the curves without being tested, and whose lengths
//      do not count.
// Out: true if more than half of the samples on `curves` stand apart: the longer of the
//      sample's edges on them (one or two) is shorter than every Delaunay edge from it to a
//      sample not on them.
// An object, so that the per-sample scratch is allocated once for all the parts of a labeling.
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

class MissedCurvesStandApart {
 public:
  explicit MissedCurvesStandApart(const DelaunayVoronoi& dv);
  bool operator()(const std::vector<Edge>& curves, const std::vector<Edge>& continuations = {});

 private:
  bool has_a_nearer_sample_off_the_curves(int site, double squared_edge) const;

  const DelaunayVoronoi& dv_;
  std::vector<double> longest_;  // per sample: its longer edge on the curves (squared), -1 off them
  // Per sample: off the curves, at the end of a continuation only, on the curves, counted.
  enum : std::uint8_t { kOff, kContinuation, kTested, kCounted };
  std::vector<std::uint8_t> counted_;
};

}  // namespace curvebench
