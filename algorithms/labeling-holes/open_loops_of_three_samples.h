// Step 9's first part in labeling-holes: closed curves of three samples, opened, and closed
// again where nothing joins their samples to a curve.
//
// An inner triangle whose three neighbours are outer (or the infinite vertex) makes its three
// edges curve edges: the labels hold a closed curve of three samples. It is sampled far more
// coarsely than any curve the paper's guarantee covers: three samples on a circle leave the
// midpoints of the arcs between them one radius from the nearest sample, epsilon 1
// (Definition 4). What such a loop usually shows is a convex tip of a sparse outline, sampled
// by three samples and cut off by the chord of its neighbours: the tip's triangle is an EVV
// inside Conv(P), inner by Section 3.3, and the walks kept every triangle around it outer (the
// horned shape at 50 random samples, seed 7: the loop 32-33-34 beside the chord 31-35); or,
// where one of the three is on the curve too (four curve edges), a tip pinched off at that
// sample. Relabelled outer, the loop's other samples are lone, and step 9 joins them to the
// curve one triangle at a time (join_lone_samples_to_the_curve.h), or step 11 replaces the
// labels. A loop that shares two samples with curves is left alone: were its one own sample
// left lone, closing the loop again could not be sure to restore it (the triangle across the
// edge between the two shared samples may have changed).
//
// Three samples of a small closed curve of their own (the dot of an `i`) make the same loop,
// and there it is the best curve through them. Distances do not tell it from a sparse tip,
// whose samples lie as far from the chord's ends as a dot's from the stem (both stand apart,
// missed_curves_stand_apart.h), but the repairs do: nothing joins a dot's samples to the
// stem's curve, and a loop whose own samples are all still lone after the other steps is
// closed again (close_loops_left_lone).
#pragma once

#include <cstdint>
#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

// A loop relabelled outer: its triangle, and the sample it shares with a curve (-1 if none).
struct OpenedLoop {
  int triangle;
  int shared_sample;
};

// In:  Delaunay/Voronoi arrays; `inner`, per triangle, 1 for inner (the infinite vertex is
//      outer).
// Out: `inner` with the triangles of such loops set to 0; returns them.
std::vector<OpenedLoop> open_loops_of_three_samples(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner);

// In:  as above, after the other steps; `loops`, what open_loops_of_three_samples returned.
// Out: `inner` with each loop set to 1 again whose own samples (all but the shared one) have
//      no curve edge.
void close_loops_left_lone(const DelaunayVoronoi& dv, std::vector<std::uint8_t>& inner, const std::vector<OpenedLoop>& loops);

}  // namespace curvebench
