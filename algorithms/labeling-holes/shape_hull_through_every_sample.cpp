#include "labeling-holes/shape_hull_through_every_sample.h"

#include <algorithm>
#include <array>
#include <numeric>
#include <utility>

#include "core/point.h"
#include "labeling-holes/curve_edges_per_sample.h"
#include "shape-hull/shape_hull_triangles.h"

namespace curvebench {
namespace {

// Whether shape-hull's path a-s-b, for a sample s it brings onto the curve alone, is a spike
// over a curve edge a-b of `inner`: both legs longer than the edge they replace (the angle at
// s below 60 degrees). A sample of the curve that the labels' edge a-b skipped lies nearer a
// or b than they lie to each other unless the curve turns by more than 120 degrees at it; an
// outlier beside the curve lies farther from both. Such a tip is refused with the outliers:
// the labels stay, as before this test.
bool is_a_spike_over_a_curve_edge(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner, int s,
                                  const std::array<int, 2>& ends) {
  const int a = ends[0], b = ends[1];
  bool a_to_b = false;
  for_each_curve_edge_at(dv, inner, a, [&](int end, int, int) { a_to_b = a_to_b || end == b; });
  if (!a_to_b) return false;
  const double base = squared_distance(dv.sites[a], dv.sites[b]);
  return squared_distance(dv.sites[s], dv.sites[a]) > base && squared_distance(dv.sites[s], dv.sites[b]) > base;
}

// Per sample, a representative of the connected curve its curve edges under `inner` put it on
// (itself where it has none): a union-find over the curve edges.
std::vector<int> connected_curve_of_each_sample(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner) {
  std::vector<int> parent(dv.site_count());
  std::iota(parent.begin(), parent.end(), 0);
  auto root = [&](int s) {
    while (parent[s] != s) s = parent[s] = parent[parent[s]];
    return s;
  };
  for_each_curve_edge(dv, inner, [&](int a, int b) {
    a = root(a), b = root(b);
    if (a != b) parent[a] = b;
  });
  for (int s = 0; s < dv.site_count(); ++s) parent[s] = root(s);
  return parent;
}

// Whether every edge of shape-hull's curve that joins two of the labels' curves is no longer
// than the longest curve edge of the labels at one of its ends. Noise and sparse strokes break
// one curve into pieces that lie as close together as samples along them; disjoint curves,
// sampled densely enough to be told apart, lie farther apart than their samples, and
// shape-hull, whose triangles stay one disk, bridges them with edges longer than any of theirs.
bool joins_the_labels_curves_only_across_gaps_no_wider_than_their_edges(const DelaunayVoronoi& dv,
                                                                          const std::vector<std::uint8_t>& inner,
                                                                          const std::vector<std::uint8_t>& shape) {
  const std::vector<int> curve = connected_curve_of_each_sample(dv, inner);
  std::vector<double> longest(dv.site_count(), 0.0);  // squared
  for_each_curve_edge(dv, inner, [&](int a, int b) {
    const double length = squared_distance(dv.sites[a], dv.sites[b]);
    longest[a] = std::max(longest[a], length);
    longest[b] = std::max(longest[b], length);
  });
  bool narrow = true;
  for_each_curve_edge(dv, shape, [&](int a, int b) {
    const bool joins_two_curves = longest[a] > 0 && longest[b] > 0 && curve[a] != curve[b];
    if (joins_two_curves && squared_distance(dv.sites[a], dv.sites[b]) > std::max(longest[a], longest[b])) narrow = false;
  });
  return narrow;
}

}  // namespace

bool curve_edges_form_one_connected_curve(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                                          const std::vector<int>& curve_edges) {
  const std::vector<int> curve = connected_curve_of_each_sample(dv, inner);
  int curves = 0;
  for (int s = 0; s < dv.site_count(); ++s) curves += curve_edges[s] > 0 && curve[s] == s;
  return curves == 1;
}

bool take_the_shape_hull_through_every_sample(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner) {
  if (dv.dimension != 2) return false;
  std::vector<std::uint8_t> shape = shape_hull_triangles(dv);
  if (!every_sample_has_two_curve_edges(dv, curve_edges_per_sample(dv, shape))) return false;
  inner = std::move(shape);
  return true;
}

namespace {

// Whether shape-hull's curve (`shape`, its counts `shape_edges`) explains more of the samples
// than the labels (`inner`, their counts `curve_edges`), as take_the_shape_hull_where_it_puts_
// more_samples_on_the_curve states; with `majority`, only where it leaves at most half as many
// samples off a 1-manifold as the labels.
bool shape_hull_explains_more(const DelaunayVoronoi& dv, const std::vector<std::uint8_t>& inner,
                              const std::vector<int>& curve_edges, const std::vector<std::uint8_t>& shape,
                              const std::vector<int>& shape_edges, bool majority) {
  // Samples off a 1-manifold: under the labels; under shape-hull, and of those how many are
  // off the labels' curve too (neither curve explains them), and the samples it brings onto a
  // 1-manifold from off the labels'.
  int off_the_labels = 0, off_the_shape = 0, off_both = 0, brought_on = 0;
  for (int s = 0; s < dv.site_count(); ++s) {
    if (dv.site_triangle[s] < 0) continue;
    off_the_labels += curve_edges[s] != 2;
    brought_on += curve_edges[s] != 2 && shape_edges[s] == 2;
    if (shape_edges[s] == 2) continue;
    ++off_the_shape;
    off_both += shape_edges[s] == 0 && curve_edges[s] == 0;
  }
  if (off_the_shape >= std::max(off_the_labels, 1)) return false;
  // The samples it takes off the labels' 1-manifold: brought on less taken off is how many
  // fewer it leaves off.
  const int taken_off = brought_on - (off_the_labels - off_the_shape);
  // The balance of brought on against taken off, or the majority (the header says why; labels
  // with several curves need the majority).
  const bool at_most_half_as_many_off = 2 * off_the_shape <= off_the_labels;
  const bool brings_on_twice_as_many = brought_on >= 2 * taken_off;
  if (!at_most_half_as_many_off && (majority || !brings_on_twice_as_many)) return false;
  if (off_both == 0) return true;
  // Per sample brought on from no curve edge: its two neighbours on shape-hull's curve.
  std::vector<std::array<int, 2>> neighbours(dv.site_count(), {-1, -1});
  for_each_curve_edge(dv, shape, [&](int a, int b) {
    if (curve_edges[a] == 0) neighbours[a][neighbours[a][0] < 0 ? 0 : 1] = b;
    if (curve_edges[b] == 0) neighbours[b][neighbours[b][0] < 0 ? 0 : 1] = a;
  });
  for (int s = 0; s < dv.site_count(); ++s) {
    if (curve_edges[s] != 0 || shape_edges[s] != 2) continue;
    const auto [a, b] = neighbours[s];
    const bool alone = curve_edges[a] != 0 && curve_edges[b] != 0;  // neither brought on with it
    if (alone && is_a_spike_over_a_curve_edge(dv, inner, s, neighbours[s])) return false;
  }
  return true;
}

// Shape-hull's triangles into `inner` where its curve explains more of the samples than the
// labels; for labels with several curves, by a majority and as pieces of one curve.
bool take_the_shape_hull_where_it_explains_more(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner,
                                                const std::vector<int>& curve_edges, bool several_curves) {
  if (dv.dimension != 2) return false;
  std::vector<std::uint8_t> shape = shape_hull_triangles(dv);
  if (!shape_hull_explains_more(dv, inner, curve_edges, shape, curve_edges_per_sample(dv, shape), several_curves) ||
      (several_curves && !joins_the_labels_curves_only_across_gaps_no_wider_than_their_edges(dv, inner, shape))) {
    return false;
  }
  inner = std::move(shape);
  return true;
}

}  // namespace

bool take_the_shape_hull_where_it_puts_more_samples_on_the_curve(const DelaunayVoronoi& dv,
                                                                  std::vector<std::uint8_t>& inner,
                                                                  const std::vector<int>& curve_edges) {
  return take_the_shape_hull_where_it_explains_more(dv, inner, curve_edges, false);
}

bool take_the_shape_hull_where_it_joins_pieces_of_one_curve(const DelaunayVoronoi& dv,
                                                             std::vector<std::uint8_t>& inner,
                                                             const std::vector<int>& curve_edges) {
  return take_the_shape_hull_where_it_explains_more(dv, inner, curve_edges, true);
}

}  // namespace curvebench
