#include "labeling-holes/missed_curves_stand_apart.h"

#include <algorithm>

namespace curvebench {

MissedCurvesStandApart::MissedCurvesStandApart(const DelaunayVoronoi& dv)
    : dv_(dv), longest_(dv.site_count(), -1.0), counted_(dv.site_count(), 0) {}

// Whether a Delaunay neighbour of `site` off the curves is no farther than the squared length
// `squared_edge`: the triangles around it counter-clockwise from one of them, then clockwise
// from that one where a hull edge stops the first turn.
bool MissedCurvesStandApart::has_a_nearer_sample_off_the_curves(int site, double squared_edge) const {
  auto nearer_in = [&](int triangle) {
    const int corner = corner_of_site(dv_, triangle, site);
    for (int other : {dv_.triangles[triangle][(corner + 1) % 3], dv_.triangles[triangle][(corner + 2) % 3]}) {
      if (longest_[other] < 0 && squared_distance(dv_.sites[site], dv_.sites[other]) <= squared_edge) return true;
    }
    return false;
  };
  const int first = dv_.site_triangle[site];
  int t = first;
  do {
    if (nearer_in(t)) return true;
    t = dv_.neighbors[t][(corner_of_site(dv_, t, site) + 1) % 3];
  } while (t != kInfinite && t != first);
  if (t == kInfinite) {
    for (t = dv_.neighbors[first][(corner_of_site(dv_, first, site) + 2) % 3]; t != kInfinite;
         t = dv_.neighbors[t][(corner_of_site(dv_, t, site) + 2) % 3]) {
      if (nearer_in(t)) return true;
    }
  }
  return false;
}

bool MissedCurvesStandApart::operator()(const std::vector<Edge>& curves) {
  for (const Edge& e : curves) {
    const double length = squared_distance(dv_.sites[e[0]], dv_.sites[e[1]]);
    for (int site : e) longest_[site] = std::max(longest_[site], length);
  }
  // Every sample on the curves has two edges there, so there are as many samples as edges.
  const std::size_t samples = curves.size();
  std::size_t apart = 0, near = 0;
  for (const Edge& e : curves) {
    for (int site : e) {
      if (counted_[site] || 2 * apart > samples || 2 * near >= samples) continue;  // counted, or decided
      counted_[site] = 1;
      ++(has_a_nearer_sample_off_the_curves(site, longest_[site]) ? near : apart);
    }
  }
  for (const Edge& e : curves) {
    for (int site : e) {
      longest_[site] = -1.0;
      counted_[site] = 0;
    }
  }
  return 2 * apart > samples;
}

}  // namespace curvebench
