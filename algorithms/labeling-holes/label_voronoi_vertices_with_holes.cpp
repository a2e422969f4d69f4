#include "labeling-holes/label_voronoi_vertices_with_holes.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "labeling-holes/curve_edges_per_sample.h"
#include "labeling-holes/enclosed_samples.h"
#include "labeling-holes/join_lone_samples_to_the_curve.h"
#include "labeling-holes/missed_curves_stand_apart.h"
#include "labeling-holes/open_loops_of_three_samples.h"
#include "labeling-holes/open_pockets_closed_at_their_mouths.h"
#include "labeling-holes/relabel_bridging_ears.h"
#include "labeling-holes/relabel_inner_vertices_outside_the_hull.h"
#include "labeling-holes/shape_hull_through_every_sample.h"
#include "labeling-holes/shape_hull_where_it_is_shorter.h"
#include "labeling-holes/split_curves_joined_across_a_corridor.h"
#include "labeling-holes/walk_region_from_its_boundary.h"

namespace curvebench {
namespace {

// The vertices of the parts of `region` the walk did not keep that lie across missed closed
// curves, each once, in no particular order. A part is grown through the Voronoi edges
// between unkept vertices all three of whose samples are enclosed; its boundary is the
// Delaunay edges dual to the Voronoi edges leaving it. A part is taken when its boundary is a
// set of closed curves through enclosed samples (every one of its samples has two boundary
// edges). Such a part is cut off by samples that no walk reached, and its new curve edges
// leave every curve the paper found as it was (the part meets no outer vertex: the frontier
// is kept).
//
// A pinched part is one whose boundary also faces unkept vertices left out of it for
// touching a found sample. Where a sparse missed curve passes within one Delaunay triangle of
// a found curve, the triangle's vertex has a found sample, whose cell holds outer vertices, so
// it lies on the shape's side: the walk stopped it only because the tangent estimates of the
// sparse curve are poor. It keeps its label, and the missed curve closes across the
// triangle's edge between its two missed samples. Pinched parts are taken only when the taken
// curves explain all the evidence, every enclosed sample lying on one of them. An enclosed
// sample left over means the paper closed a pocket off at its mouth: the frontier then lies on
// the pocket's side of its walls, the walk runs down the pocket as if it were the interior,
// and a pinched part there (a glyph's crossbar inside the closed-off pocket of a `G`) is the
// walk going astray. A part with a branching boundary keeps the paper's labels too.
std::vector<int> parts_across_missed_curves(const DelaunayVoronoi& dv, const std::vector<int>& unkept_vertices,
                                            const std::vector<int>& enclosed_samples) {
  std::vector<int> across;
  std::vector<std::uint8_t> enclosed(dv.site_count(), 0);
  for (int site : enclosed_samples) enclosed[site] = 1;
  // Per vertex: whether the walk left it unkept, whether it belongs to a part (found once for
  // the unkept vertices), and whether a part has grown through it, so that growing reads one
  // byte per neighbour.
  enum : std::uint8_t { kUnkept = 1, kInAPart = 2, kSeen = 4 };
  std::vector<std::uint8_t> part_state(dv.triangle_count(), 0);
  for (int t : unkept_vertices) {
    const auto& tri = dv.triangles[t];
    const bool all_enclosed = enclosed[tri[0]] && enclosed[tri[1]] && enclosed[tri[2]];
    part_state[t] = all_enclosed ? kUnkept | kInAPart : kUnkept;
  }
  std::vector<int> boundary_degree(dv.site_count(), 0);
  std::vector<int> part, stack;
  std::vector<Edge> boundary;
  auto unkept = [&](int t) { return t != kInfinite && (part_state[t] & kUnkept) != 0; };
  auto in_a_part = [&](int t) { return t != kInfinite && (part_state[t] & kInAPart) != 0; };

  bool pinched = false;
  auto grow_part = [&](int start) {
    pinched = false;
    part.clear();
    boundary.clear();
    part_state[start] |= kSeen;
    stack.push_back(start);
    while (!stack.empty()) {
      const int vertex = stack.back();
      stack.pop_back();
      part.push_back(vertex);
      for (int k = 0; k < 3; ++k) {
        const int next = dv.neighbors[vertex][k];
        if (!in_a_part(next)) {
          pinched = pinched || unkept(next);
          boundary.push_back({dv.triangles[vertex][(k + 1) % 3], dv.triangles[vertex][(k + 2) % 3]});
        } else if (!(part_state[next] & kSeen)) {
          part_state[next] |= kSeen;
          stack.push_back(next);
        }
      }
    }
  };
  // Whether the boundary is closed curves through enclosed samples (each with two edges).
  auto closed_through_enclosed_samples = [&] {
    for (const Edge& e : boundary) {
      ++boundary_degree[e[0]];
      ++boundary_degree[e[1]];
    }
    bool closed = true;
    for (const Edge& e : boundary) {
      for (int site : e) closed = closed && enclosed[site] && boundary_degree[site] == 2;
    }
    for (const Edge& e : boundary) boundary_degree[e[0]] = boundary_degree[e[1]] = 0;
    return closed;
  };
  std::optional<MissedCurvesStandApart> stand_apart;  // made for the first closed boundary
  auto stands_apart = [&](const std::vector<Edge>& curves) {
    if (!stand_apart) stand_apart.emplace(dv);
    return (*stand_apart)(curves);
  };

  // Per sample: on the curves of a part taken, or on the closed boundary of a pinched part.
  enum : std::uint8_t { kOnATakenCurve = 1, kOnAPinchedBoundary = 2 };
  std::vector<std::uint8_t> on_a_curve(dv.site_count(), 0);
  // The pinched parts with closed boundaries, their vertices and boundaries one after another.
  std::vector<int> pinched_vertices;
  std::vector<Edge> pinched_boundaries;
  std::vector<std::array<std::size_t, 2>> pinched_ends;
  // Every vertex of a part is one the walk did not keep, so a scan of those finds every part.
  for (int t : unkept_vertices) {
    if ((part_state[t] & (kInAPart | kSeen)) != kInAPart) continue;  // in no part, or in one grown already
    grow_part(t);
    if (!closed_through_enclosed_samples()) continue;
    if (pinched) {
      pinched_vertices.insert(pinched_vertices.end(), part.begin(), part.end());
      pinched_boundaries.insert(pinched_boundaries.end(), boundary.begin(), boundary.end());
      pinched_ends.push_back({pinched_vertices.size(), pinched_boundaries.size()});
      for (const Edge& e : boundary) {
        for (int site : e) on_a_curve[site] |= kOnAPinchedBoundary;
      }
    } else if (stands_apart(boundary)) {
      for (const Edge& e : boundary) {
        for (int site : e) on_a_curve[site] |= kOnATakenCurve;
      }
      across.insert(across.end(), part.begin(), part.end());
    }
  }
  // Pinched parts only when the taken curves explain all the evidence (see above). The
  // stand-apart test of each is needed only if they could: if every pinched part were taken,
  // would every enclosed sample lie on a taken curve? (Noise leaves many pinched parts and
  // evidence none of them explains.)
  auto every_enclosed_sample_on = [&](std::uint8_t curves) {
    return std::all_of(enclosed_samples.begin(), enclosed_samples.end(), [&](int site) { return (on_a_curve[site] & curves) != 0; });
  };
  if (pinched_ends.empty() || !every_enclosed_sample_on(kOnATakenCurve | kOnAPinchedBoundary)) return across;
  std::vector<int> pinched_parts;
  std::size_t vertices_from = 0, boundary_from = 0;
  for (const auto& [vertices_to, boundary_to] : pinched_ends) {
    boundary.assign(pinched_boundaries.begin() + boundary_from, pinched_boundaries.begin() + boundary_to);
    if (stands_apart(boundary)) {
      for (const Edge& e : boundary) {
        for (int site : e) on_a_curve[site] |= kOnATakenCurve;
      }
      pinched_parts.insert(pinched_parts.end(), pinched_vertices.begin() + vertices_from, pinched_vertices.begin() + vertices_to);
    }
    vertices_from = vertices_to;
    boundary_from = boundary_to;
  }
  if (every_enclosed_sample_on(kOnATakenCurve)) across.insert(across.end(), pinched_parts.begin(), pinched_parts.end());
  return across;
}

// Whether no two samples without a curve edge (`curve_edges` 0) are Delaunay neighbours: with
// evidence left, the condition for step 9. An enclosed sample the curve passes by, alone, lies
// in a one-triangle pocket a-s-b the paper closed at its mouth a-b, the mirror of a tip cut off
// by its chord. Step 8's walk from that mouth runs on through the sample's whole fan, whose
// triangles all hold an enclosed sample, and its pocket is refused; step 9 joins the sample
// through the triangle (noise.json's ellipse at noise 0.1, seed 2: sample 84 beside the curve
// edge 83-85, its fan reaching across the ellipse). A run of neighbouring lone samples is a
// pocket's wall that step 8 could not open without leaving evidence, and joined one triangle
// at a time it becomes a path through the pocket (the horned shape at 30 random samples, seed
// 8: the horn's inner side, seven lone samples, joined into a tour across the shape).
bool lone_samples_stand_alone(const DelaunayVoronoi& dv, const std::vector<int>& curve_edges) {
  auto lone = [&](int site) { return curve_edges[site] == 0; };
  for (int site = 0; site < dv.site_count(); ++site) {
    if (dv.site_triangle[site] >= 0 && lone(site) && any_delaunay_neighbor(dv, site, lone)) return false;
  }
  return true;
}

}  // namespace

VoronoiLabels label_voronoi_vertices_with_holes(const DelaunayVoronoi& dv) {
  VoronoiLabels labels = label_voronoi_vertices(dv);
  // After the paper's walks, a sample's cell holds an outer vertex exactly when a walk paired
  // the sample: every outer vertex is one a walk kept, keeping it pairs its unpaired samples
  // (Algorithm 1, lines 1-2), a sample is paired only by a vertex a walk keeps, and hull
  // samples are paired with the infinite vertex. So the paper's enclosed samples are its
  // unpaired ones (with a cell), read off the sources without a pass over the triangles.
  std::vector<int> enclosed;
  for (int s = 0; s < dv.site_count(); ++s) {
    if (labels.source_vertex[s] == kUnpaired && dv.site_triangle[s] >= 0) enclosed.push_back(s);
  }
  // Step 12 compares only labels the rule changed. With evidence it always has where it gets
  // there (an enclosed sample has no curve edge under the paper's labels, two there);
  // without, steps 6, 7, 9 and 10 say so by what they relabel.
  bool repaired = !enclosed.empty();
  // Steps 2-5, one nesting level at a time from the inner region; true when no part was
  // taken at the first level (the region is still every inner vertex).
  std::vector<std::uint8_t> region;
  std::vector<int> region_vertices;
  bool found_missed_curves = false;  // closed curves of their own: not one curve, no step 11
  bool pockets_split_one_curve = false;  // step 8 left the one curve of the labels in two
  auto take_missed_curves = [&] {
    region = labels.inner;
    region_vertices.resize(dv.triangle_count() - std::count(region.begin(), region.end(), 0) + 1);
    std::size_t count = 0;
    for (int t = 0; t < dv.triangle_count(); ++t) {
      region_vertices[count] = t;  // kept when inner: no branch on the labels' pattern
      count += region[t] != 0;
    }
    region_vertices.resize(count);
    bool first_level = true;
    while (!enclosed.empty()) {
      const std::vector<int> unkept = walk_region_from_its_boundary(dv, region, region_vertices);
      std::vector<int> flipped = parts_across_missed_curves(dv, unkept, enclosed);
      if (flipped.empty()) break;  // no next region, so no evidence in it
      first_level = false;
      found_missed_curves = true;
      for (int t : region_vertices) region[t] = 0;
      for (int t : flipped) {
        region[t] = 1;
        labels.inner[t] ^= 1;
      }
      std::sort(flipped.begin(), flipped.end());
      region_vertices = std::move(flipped);
      enclosed = samples_enclosed_by_region(dv, region, region_vertices);
    }
    return first_level;
  };
  // Step 10 where evidence is left: a corridor between two curves may have swallowed the
  // enclosed samples, and it is grown from the triangles around them. As pinches and step 8's
  // pockets, the corridors stand only if then every enclosed sample is on the curve; true if
  // they do, else the labels are as they came.
  auto open_corridors_over_the_evidence = [&] {
    std::vector<int> around;
    for (int site : enclosed) {  // an enclosed sample's fan is closed and all inner
      for_each_voronoi_vertex_around(dv, site, [&](int t) { around.push_back(t); });
    }
    const std::vector<int> opened = split_curves_joined_across_a_corridor(dv, labels.inner, around);
    if (opened.empty()) return false;
    const std::vector<std::uint8_t>& inner = labels.inner;
    if (std::any_of(enclosed.begin(), enclosed.end(), [&](int site) { return curve_edges_at(dv, inner, site) == 0; })) {
      for (int t : opened) labels.inner[t] = 1;  // they were inner
      return false;
    }
    return true;
  };
  // Without enclosed samples the paper's walks reached every sample's curve.
  if (!enclosed.empty() && take_missed_curves() && !enclosed.empty()) {
    std::vector<std::uint8_t> before_pockets = labels.inner;
    const OpenedPockets pockets = open_pockets_closed_at_their_mouths(dv, labels.inner, enclosed);
    if (pockets.relabelled > 0) {
      // Step 8 opened pockets: their walls are on the curve, and the levels run again for the
      // holes the pockets' walls kept from being taken. As with pinches, the opened pockets
      // stand only if then every enclosed sample lies on a curve, here or through the
      // corridors of step 10 (sharp_corners.json's 8-pointed star at epsilon 0.2, seed 3:
      // step 8 opens the pocket over samples 396-516 and 519-640, step 10 puts the samples 27,
      // 93, 765 and 948 at four concave corners back on the curve):
      // evidence left over means the walk from a mouth went astray (a sparse outline whose
      // stroke is narrower than the gaps between its samples), and the labels go back to what
      // they were.
      std::vector<int> evidence = std::move(enclosed);
      enclosed = samples_enclosed_by_region(dv, labels.inner, region_vertices);
      take_missed_curves();
      if (!enclosed.empty() && !open_corridors_over_the_evidence()) {
        labels.inner = std::move(before_pockets);
        enclosed = std::move(evidence);
        found_missed_curves = false;  // as before the pockets: the first level took none
      } else {
        enclosed.clear();
        pockets_split_one_curve =
            pockets.split_a_curve &&
            curve_edges_form_one_connected_curve(dv, before_pockets, curve_edges_per_sample(dv, before_pockets));
      }
    }
  }
  // Step 11 (shape_hull_through_every_sample.h) where the labels end with a fault, or where
  // step 8 split their one curve; true if it took shape-hull's triangles.
  auto take_the_shape_hull_where_one_curve_is_wrong = [&](const std::vector<int>& curve_edges) {
    if (pockets_split_one_curve) {
      return take_the_shape_hull_where_it_puts_more_samples_on_the_curve(dv, labels.inner, curve_edges);
    }
    if (every_sample_has_two_curve_edges(dv, curve_edges)) return false;
    if (!curve_edges_form_one_connected_curve(dv, labels.inner, curve_edges)) {
      return take_the_shape_hull_where_it_joins_pieces_of_one_curve(dv, labels.inner, curve_edges);
    }
    // Where the only faults are pinches (every sample an even number of curve edges), the
    // labels' curve is a closed tour through every sample that touches itself: as in step 12,
    // shape-hull's tour replaces it only if shorter.
    auto on_a_tour = [](int edges) { return edges >= 2 && edges % 2 == 0; };
    if (std::all_of(curve_edges.begin(), curve_edges.end(), on_a_tour)) {
      return take_the_shape_hull_where_it_is_shorter(dv, labels.inner);
    }
    return take_the_shape_hull_where_it_puts_more_samples_on_the_curve(dv, labels.inner, curve_edges);
  };
  // Step 9's first part (open_loops_of_three_samples.h), before the counts of step 11 and the
  // repairs: the samples of a tip cut off into a loop of its own are lone once it is opened.
  // Missed curves keep their loops, as they keep the other repairs.
  const std::vector<OpenedLoop> loops =
      found_missed_curves ? std::vector<OpenedLoop>{} : open_loops_of_three_samples(dv, labels.inner);
  repaired = repaired || !loops.empty();
  // Steps 6-12 (where evidence is left, step 10 over it and step 11 first), left at the first
  // step that settles the labels; the loops are looked at again after whichever that is.
  auto repair = [&] {
    // The loop stops with evidence left only where no part was taken: those samples' cells lie
    // in the last region, all of one label, so they have no curve edge, and steps 6, 7 and 10
    // change nothing while a sample has none. Labels that end with a sample off the curve or on
    // a pinch go to step 11, unless missed curves were found, which shape-hull's one curve cannot
    // hold (tested first: noisy input, where step 4 takes such curves, pays no pass counting
    // curve edges). Where step 11 keeps the labels, lone samples apart from each other are
    // joined by step 9 (lone_samples_stand_alone), and the repairs of a 1-manifold follow.
    if (!enclosed.empty() && !open_corridors_over_the_evidence()) {
      if (found_missed_curves) return;
      const std::vector<int> counts = curve_edges_per_sample(dv, labels.inner);
      if (take_the_shape_hull_where_one_curve_is_wrong(counts) || !lone_samples_stand_alone(dv, counts) ||
          join_lone_samples_to_the_curve(dv, labels.inner, counts) == 0) {
        return;
      }
      repaired = true;
    }
    // One count of curve edges serves both repairs unless the first changes the labels.
    std::vector<int> curve_edges = curve_edges_per_sample(dv, labels.inner);
    if (relabel_bridging_ears(dv, labels.inner, curve_edges) > 0) {
      repaired = true;
      curve_edges = curve_edges_per_sample(dv, labels.inner);
    }
    repaired |= relabel_inner_vertices_outside_the_hull(dv, labels.inner, curve_edges) > 0;
    // Steps 6 and 7 change nothing while a sample has no curve edge, so the counts still hold.
    if (join_lone_samples_to_the_curve(dv, labels.inner, curve_edges) > 0) {
      repaired = true;
      curve_edges = curve_edges_per_sample(dv, labels.inner);
    }
    if (!every_sample_has_two_curve_edges(dv, curve_edges)) {
      if (found_missed_curves) return;
      // Step 10 with the labels swapped: outer corridors the crust reads as inside (a stroke
      // the paper's walk entered through a triangle spanning it), relabelled inner, stand only
      // if the curve is then a 1-manifold through every sample.
      const std::vector<int> filled = split_curves_joined_across_a_corridor(dv, labels.inner, 0);
      std::vector<int> counts;
      if (!filled.empty()) counts = curve_edges_per_sample(dv, labels.inner);
      if (filled.empty() || !every_sample_has_two_curve_edges(dv, counts)) {
        for (int t : filled) labels.inner[t] = 0;
        take_the_shape_hull_where_one_curve_is_wrong(curve_edges);
        return;
      }
      curve_edges = std::move(counts);
      repaired = true;
    }
    // Corridors without swallowed samples, on a 1-manifold: from every triangle.
    repaired |= !split_curves_joined_across_a_corridor(dv, labels.inner).empty();
    if (found_missed_curves) return;
    if (pockets_split_one_curve) {
      take_the_shape_hull_through_every_sample(dv, labels.inner);
    } else if (repaired && curve_edges_form_one_connected_curve(dv, labels.inner, curve_edges)) {
      // Step 12 (shape_hull_where_it_is_shorter.h): repaired labels, one closed curve through
      // every sample, against shape-hull's tour. Step 10 leaves every sample two curve edges,
      // so the counts from before it still say which samples are on the curve.
      take_the_shape_hull_where_it_is_shorter(dv, labels.inner);
    }
  };
  repair();
  close_loops_left_lone(dv, labels.inner, loops);
  return labels;
}

}  // namespace curvebench
