#include "labeling-holes/missed_curves_stand_apart.h"

#include <algorithm>
#include <utility>

namespace curvebench {
namespace {

int corner_of_site(const DelaunayVoronoi& dv, int triangle, int site) {
  const auto& t = dv.triangles[triangle];
  return t[0] == site ? 0 : (t[1] == site ? 1 : 2);
}

}  // namespace

bool missed_curves_stand_apart(const DelaunayVoronoi& dv, const std::vector<Edge>& curves) {
  // Each sample on the curves with the squared length of its longer edge there.
  std::vector<std::pair<int, double>> longest;
  for (const Edge& e : curves) {
    const double length = squared_distance(dv.sites[e[0]], dv.sites[e[1]]);
    longest.push_back({e[0], length});
    longest.push_back({e[1], length});
  }
  std::sort(longest.begin(), longest.end(), [](const auto& a, const auto& b) {
    return a.first < b.first || (a.first == b.first && a.second > b.second);
  });
  longest.erase(std::unique(longest.begin(), longest.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
                longest.end());
  auto on_curves = [&](int site) {
    const auto at = std::lower_bound(longest.begin(), longest.end(), site,
                                     [](const auto& entry, int value) { return entry.first < value; });
    return at != longest.end() && at->first == site;
  };

  // Whether a Delaunay neighbour of `site` off the curves is no farther than `edge` (squared):
  // the triangles around it counter-clockwise from one of them, then clockwise from that one
  // where a hull edge stops the first turn.
  auto has_a_nearer_sample_off_the_curves = [&](int site, double edge) {
    auto nearer_in = [&](int triangle) {
      const int corner = corner_of_site(dv, triangle, site);
      for (int other : {dv.triangles[triangle][(corner + 1) % 3], dv.triangles[triangle][(corner + 2) % 3]}) {
        if (!on_curves(other) && squared_distance(dv.sites[site], dv.sites[other]) <= edge) return true;
      }
      return false;
    };
    const int first = dv.site_triangle[site];
    int t = first;
    do {
      if (nearer_in(t)) return true;
      t = dv.neighbors[t][(corner_of_site(dv, t, site) + 1) % 3];
    } while (t != kInfinite && t != first);
    if (t == kInfinite) {
      for (t = dv.neighbors[first][(corner_of_site(dv, first, site) + 2) % 3]; t != kInfinite;
           t = dv.neighbors[t][(corner_of_site(dv, t, site) + 2) % 3]) {
        if (nearer_in(t)) return true;
      }
    }
    return false;
  };

  std::size_t apart = 0;
  for (const auto& [site, edge] : longest) apart += !has_a_nearer_sample_off_the_curves(site, edge);
  return 2 * apart > longest.size();
}

}  // namespace curvebench
