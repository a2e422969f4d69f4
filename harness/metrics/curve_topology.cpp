#include "metrics/curve_topology.h"

#include <algorithm>
#include <map>
#include <set>
#include <vector>

namespace curvebench {

CurveTopology curve_topology(std::span<const Edge> edges) {
  const std::set<Edge> distinct(edges.begin(), edges.end());
  std::map<int, std::vector<int>> neighbours;
  for (const Edge& e : distinct) {
    neighbours[e[0]].push_back(e[1]);
    neighbours[e[1]].push_back(e[0]);
  }
  CurveTopology topology;
  for (const auto& [vertex, adjacent] : neighbours) {
    if (adjacent.size() == 1) ++topology.dangling_vertices;
    if (adjacent.size() >= 3) ++topology.branching_vertices;
  }
  topology.manifold = !distinct.empty() && topology.dangling_vertices == 0 && topology.branching_vertices == 0;

  std::set<int> visited;
  for (const auto& [start, unused] : neighbours) {
    if (visited.contains(start)) continue;
    ++topology.components;
    bool every_degree_two = true;
    std::vector<int> stack{start};
    visited.insert(start);
    while (!stack.empty()) {
      const int vertex = stack.back();
      stack.pop_back();
      const std::vector<int>& adjacent = neighbours.at(vertex);
      every_degree_two = every_degree_two && adjacent.size() == 2;
      for (int next : adjacent) {
        if (visited.insert(next).second) stack.push_back(next);
      }
    }
    if (every_degree_two) ++topology.closed_components;
  }
  return topology;
}

}  // namespace curvebench
