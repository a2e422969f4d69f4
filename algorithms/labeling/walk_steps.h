// The two steps Algorithm 1 of Peethambaran et al. (CGF 2019) takes at each Voronoi vertex it
// reaches, shared by the paper's walk (label_voronoi_vertices.h) and the walks of
// labeling-holes (from a region's frontier, from a pocket's mouth).
//
// `source` holds one entry per sample: its source Voronoi vertex (a triangle), kInfinite for
// a sample of an unbounded cell (Algorithm 2, line 3) or kUnpaired.
#pragma once

#include <span>

#include "labeling/label_voronoi_vertices.h"
#include "labeling/side_of_tangent_line.h"
#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

// Definition 5 (label transition rule), tested before pairing (gap 1 of README.md: otherwise
// the vertex would be its own sample's source and the rule would test nothing): true if
// `vertex` lies strictly across the estimated tangent line of one of its samples that has a
// finite source. A vertex exactly on a tangent line is on neither side. Samples paired with
// the infinite vertex, whose direction is the whole wedge of the cell's two rays, impose no
// constraint. Inline: the walks call it once per vertex.
inline bool crosses_a_tangent_line(const DelaunayVoronoi& dv, std::span<const int> source, int vertex) {
  for (int site : dv.triangles[vertex]) {
    const int s = source[site];
    if (s >= 0 && s != vertex && side_of_tangent_line(dv, site, s, vertex) < 0) return true;
  }
  return false;
}

// Algorithm 1, lines 1-2, for a vertex the walk keeps: an unpaired sample takes it as source;
// a paired sample moves to it if it is farther from the sample (a larger circumradius) than
// its source. Lemma 3.2 wants the source to estimate the pole, the farthest vertex of the cell
// on the walk's side, and a first vertex hugging the curve (the circumcentre of three samples
// around a sharp tip) would tilt the tangent line of Definition 5 by up to a right angle.
inline void pair_samples_with(const DelaunayVoronoi& dv, std::span<int> source, int vertex) {
  for (int site : dv.triangles[vertex]) {
    const int s = source[site];
    if (s == kUnpaired || (s >= 0 && dv.circumradii[vertex] > dv.circumradii[s])) source[site] = vertex;
  }
}

}  // namespace curvebench
