// The noise-removal step of Peeling the Longest (Parakkat, Methirumangalath, Muthuganapathy,
// Computers & Graphics 74, 2018; the authors' separate Noise_Removal program; spec
// specification.md, "Noise removal"). It reduces a noisy point set, which is then
// triangulated afresh and peeled (peel_edges.h).
//
// In:  the Delaunay/Voronoi arrays of the samples; `radius` > 0, the authors' tau.
// Out: the sites kept as representatives, in visiting order. Sites are visited in the order
//      in which CGAL's range insertion (spatial sort, fixed internal seed) would insert them,
//      given in order of first occurrence in the input, which is the authors' vertex order. A
//      site not yet deleted that is not on the convex hull and whose longest Delaunay edge is
//      shorter than twice its shortest becomes a representative and deletes every site
//      closer to it than `radius`. Every other site is dropped: representatives are pairwise
//      at least `radius` apart, and every site closer than `radius` to none of them failed
//      the ratio test or is on the hull. Below dimension 2 every site is on the hull: none is kept.
#pragma once

#include <vector>

#include "voronoi/delaunay_voronoi.h"

namespace curvebench {

std::vector<int> noise_representatives(const DelaunayVoronoi& dv, double radius);

}  // namespace curvebench
