#include "labeling-holes/missed_curves_stand_apart.h"

#include <algorithm>

namespace curvebench {

MissedCurvesStandApart::MissedCurvesStandApart(const DelaunayVoronoi& dv)
    : dv_(dv), longest_(dv.site_count(), -1.0), counted_(dv.site_count(), 0) {}

// Whether a Delaunay neighbour of `site` off the curves is no farther than the squared length
// `squared_edge`. Counter-clockwise from site_triangle, the triangles around the site: for a
// hull site its whole fan (delaunay_voronoi.h), whose first and last triangles hold its two
// hull neighbours.
bool MissedCurvesStandApart::has_a_nearer_sample_off_the_curves(int site, double squared_edge) const {
  return any_delaunay_neighbor(dv_, site, [&](int other) {
    return longest_[other] < 0 && squared_distance(dv_.sites[site], dv_.sites[other]) <= squared_edge;
  });
}

bool MissedCurvesStandApart::operator()(const std::vector<Edge>& curves, const std::vector<Edge>& continuations) {
  for (const Edge& e : continuations) {
    for (int site : e) {
      longest_[site] = std::max(longest_[site], 0.0);  // on the curves, with no edge on them yet
      counted_[site] = kContinuation;
    }
  }
  std::size_t samples = 0;
  for (const Edge& e : curves) {
    const double length = squared_distance(dv_.sites[e[0]], dv_.sites[e[1]]);
    for (int site : e) {
      samples += counted_[site] != kTested;
      counted_[site] = kTested;
      longest_[site] = std::max(longest_[site], length);
    }
  }
  std::size_t apart = 0, near = 0;
  for (const Edge& e : curves) {
    for (int site : e) {
      if (counted_[site] == kCounted || 2 * apart > samples || 2 * near >= samples) continue;  // counted, or decided
      counted_[site] = kCounted;
      ++(has_a_nearer_sample_off_the_curves(site, longest_[site]) ? near : apart);
    }
  }
  for (const auto* edges : {&curves, &continuations}) {
    for (const Edge& e : *edges) {
      for (int site : e) {
        longest_[site] = -1.0;
        counted_[site] = kOff;
      }
    }
  }
  return 2 * apart > samples;
}

}  // namespace curvebench
