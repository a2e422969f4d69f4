// FitConnect's connectivity, with the per-sample state it ends in: S. Ohrhallinger and
// M. Wimmer, "FitConnect: Connecting Noisy 2D Samples by Fitted Neighborhoods", Computer
// Graphics Forum 2018, specification.md sections 2.1-2.7 (written from the authors' code,
// stefango74/fitconnect). It is also pass 1 of StretchDenoise, whose pass 2 reads the state.
//
// In:  distinct finite sites (the skeleton merges exact duplicates, on which the authors' code
//      writes out of bounds), in the order that decides the result (spec 2.5: the output
//      depends on the input order, as in the reference); `max_neighbors`, the growth cap.
// Out: the edges: every link between two MANIFOLD / LEAF / SHARP sites once, make_edge order,
//      sorted (spec 2.7); and per site its final state, its two link slots, its neighbourhood
//      split into the two sides ordered outwards along its last stored circle fit, that fit
//      (centre, radius, normal = unit(p - centre), whether it took the degenerate branch of
//      collinear neighbours) and the fit's largest radial residual over
//      the site and its neighbours (StretchDenoise's noise estimate). A site whose last growth
//      was undone (spec 2.6 steps 2 and 7) keeps the fit and sides from before it.
//
// Every sample grows its nearest-neighbour list one point per visit, fits a circle to itself
// and that list, orders the list along the circle and links where fitted neighbourhoods
// reciprocate. The reference grows a list until it holds all n - 1 other sites (spec 3,
// "unbounded growth"); `max_neighbors` > 0 treats a list of that many as exhausted, which
// changes only samples that reach it (README.md says on which inputs); 0 grows as the
// reference. Fewer than three sites: no edges, every site ELIMINATED with empty sides.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/parameters.h"
#include "core/phase_timer.h"
#include "core/point.h"

namespace curvebench {

// The states of spec section 2 (the authors' OUTLIER and three other declared states are
// never reached). After the run every site is MANIFOLD, SHARP (two links), LEAF (one) or
// ELIMINATED.
enum class SampleState : std::uint8_t { Initial, Conform, Nonconform, Manifold, Sharp, Leaf, Eliminated };

// The default growth cap. Open-curve ends grow to n - 1 in the reference and what they link
// to on the way decides the edges, so only a cap >= n - 1 reproduces the reference on open
// curves: this one does on every input of up to 4097 sites, the sizes the spec's section 4
// runs (README.md measures what smaller caps change and what this one costs at larger n).
inline constexpr int kDefaultMaxNeighbors = 4096;

struct FittedNeighborhoods {
  std::vector<Edge> edges;
  std::vector<SampleState> states;
  std::vector<std::array<int, 2>> links;       // -1 = empty slot
  std::vector<std::vector<int>> neighborhoods;  // per site: A^0 then A^1, each ordered outwards
  std::vector<int> side0_sizes;                 // |A^0| per site
  std::vector<Point2> centers;
  std::vector<double> radii;
  std::vector<Point2> normals;    // unit(p_i - c_i), not oriented along the curve
  std::vector<std::uint8_t> fits_on_a_line;  // 1: the fit's degenerate branch (FittedCircle::on_a_line)
  std::vector<double> residuals;  // max over i and its neighbours q of | |p_q - c_i| - r_i |

  // A_i^t (t = 0, 1), ordered outwards from site i along its fit.
  std::span<const int> side(int i, int t) const {
    const std::vector<int>& all = neighborhoods[i];
    return t == 0 ? std::span<const int>(all.data(), side0_sizes[i])
                  : std::span<const int>(all.data() + side0_sizes[i], all.size() - side0_sizes[i]);
  }
};

FittedNeighborhoods connect_fitted_neighborhoods(std::span<const Point2> sites,
                                                 int max_neighbors = kDefaultMaxNeighbors);

// The growth cap as the typed parameter "max_neighbors" of every algorithm that runs this
// connectivity (fitconnect, stretchdenoise).
ParameterSpec max_neighbors_parameter();

// connect_fitted_neighborhoods with the checked parameter "max_neighbors", timed as the
// phase "connect".
FittedNeighborhoods connect_fitted_neighborhoods(std::span<const Point2> sites, const ParameterValues& params,
                                                 PhaseTimer& timer);

}  // namespace curvebench
