#include "fitconnect/fitconnect.h"

#include "core/denoised_curve.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace curvebench {
namespace {

using State = SampleState;

constexpr int kNone = -1;

// Polar angle of v in degrees, in [0, 360] (spec 2.8 measures arcs this way).
double degrees(Point2 v) { return (std::atan2(v.y, v.x) + std::numbers::pi) / std::numbers::pi * 180.0; }

// Whether site i and its neighbourhood lie on one line up to the rounding of their
// coordinates: their distances from the total-least-squares line through them are all within
// 256 units in the last place of their largest coordinate. A circle fitted to such points is
// decided by rounding alone (spec 2.1's determinant is then a difference of rounding errors:
// radii of hundreds of spacings that miss their own points by whole spacings), whether or not
// the fit took its degenerate branch.
bool collinear_up_to_rounding(std::span<const Point2> sites, const FittedNeighborhoods& fits, int i) {
  const std::vector<int>& around = fits.neighborhoods[i];
  Point2 mean = sites[i];
  double largest = std::max(std::fabs(sites[i].x), std::fabs(sites[i].y));
  for (int q : around) {
    mean = mean + sites[q];
    largest = std::max({largest, std::fabs(sites[q].x), std::fabs(sites[q].y)});
  }
  mean = (1.0 / static_cast<double>(around.size() + 1)) * mean;
  double xx = 0.0, yy = 0.0, xy = 0.0;
  auto scatter = [&](Point2 p) {
    const Point2 d = p - mean;
    xx += d.x * d.x;
    yy += d.y * d.y;
    xy += d.x * d.y;
  };
  scatter(sites[i]);
  for (int q : around) scatter(sites[q]);
  // The line's normal: the eigenvector of the scatter matrix's smaller eigenvalue.
  const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);
  const Point2 normal{-std::sin(angle), std::cos(angle)};
  const double tolerance = 256.0 * std::numeric_limits<double>::epsilon() * largest;
  auto on_the_line = [&](Point2 p) { return std::fabs(dot(p - mean, normal)) <= tolerance; };
  return on_the_line(sites[i]) && std::all_of(around.begin(), around.end(), [&](int q) { return on_the_line(sites[q]); });
}

}  // namespace

std::vector<Point2> blended_positions(std::span<const Point2> sites, const FittedNeighborhoods& fits) {
  const int n = static_cast<int>(sites.size());
  const auto& state = fits.states;
  auto touches_sharp = [&](int i) {
    auto sharp = [&](int q) { return q != kNone && state[q] == State::Sharp; };  // state[-1] is no state
    return sharp(i) || sharp(fits.links[i][0]) || sharp(fits.links[i][1]);
  };
  // A fit on a line: its degenerate branch (an absolute threshold), or points collinear up to
  // rounding (a relative one, spec 3).
  std::vector<std::uint8_t> on_a_line(n, 0);
  for (int i = 0; i < n; ++i) {
    on_a_line[i] = state[i] == State::Manifold && (fits.fits_on_a_line[i] || collinear_up_to_rounding(sites, fits, i));
  }
  std::vector<Point2> sum(n);
  std::vector<int> weight(n, 0);
  for (int i = 0; i < n; ++i) {
    if (touches_sharp(i)) {
      sum[i] = sites[i];
      weight[i] = 1;
    } else if (state[i] == State::Manifold) {
      // A fit on a line has no circle to blend onto: the degenerate branch's fallback lies
      // about one input unit off the line whatever the scale, and a fit of points collinear
      // up to rounding is a circle made of rounding errors; either would throw the samples
      // whole units off their curve. The curve such a fit stands for is the line through the
      // samples, which they already lie on: the sample stays, and the fit moves no neighbour.
      sum[i] = on_a_line[i] ? sites[i] : fits.centers[i] + fits.radii[i] * fits.normals[i];
      weight[i] = 1;
    }
  }
  for (int i = 0; i < n; ++i) {
    if (state[i] != State::Manifold || on_a_line[i]) continue;
    const Point2 c = fits.centers[i];
    const double r = fits.radii[i];
    // The arc of i's fit runs from the outermost point of A_i^0 through p_i to that of A_i^1.
    // The authors read back() of both sides; the spec is silent when one is empty (possible
    // for a former LEAF), so the arc then ends at p_i on that side.
    const std::span<const int> sides[2] = {fits.side(i, 0), fits.side(i, 1)};
    const int end0 = sides[0].empty() ? i : sides[0].back();
    const int end1 = sides[1].empty() ? i : sides[1].back();
    // The arc's angles depend on i only: computed once, not once per neighbour.
    const double arc_degrees[3] = {degrees(sites[end0] - c), degrees(sites[end1] - c), degrees(sites[i] - c)};
    for (const std::span<const int> side : sides) {
      for (int k : side) {
        if (touches_sharp(k)) continue;
        // Line p_k + s * normal_k against circle i (the authors' closed form).
        const double a = -fits.normals[k].y, b = fits.normals[k].x;
        const double offset = a * (sites[k].x - c.x) + b * (sites[k].y - c.y);
        const double d2 = a * a + b * b;
        const double det = r * r * d2 - offset * offset;
        if (det < 0.0) continue;
        const double root = std::sqrt(det);
        const Point2 hit[2] = {{c.x + (a * offset + b * root) / d2, c.y + (b * offset - a * root) / d2},
                               {c.x + (a * offset - b * root) / d2, c.y + (b * offset + a * root) / d2}};
        double deg[6] = {arc_degrees[0],        arc_degrees[1],      arc_degrees[2],
                         degrees(sites[k] - c), degrees(hit[0] - c), degrees(hit[1] - c)};
        // Orient the arc positively, then measure every angle from its start.
        if (std::fmod(deg[2] + 360.0 - deg[0], 360.0) > std::fmod(deg[1] + 360.0 - deg[0], 360.0))
          std::swap(deg[0], deg[1]);
        for (int l = 1; l < 6; ++l) deg[l] = std::fmod(deg[l] + 360.0 - deg[0], 360.0);
        const bool before_i = deg[3] < deg[2];
        int chosen = kNone;
        for (int l = 0; l < 2; ++l) {
          // Inside the arc and on k's side of p_i; of two, the one angularly nearer k.
          if (deg[4 + l] <= deg[1] && before_i == (deg[4 + l] < deg[2]))
            chosen = chosen == kNone ? l : (std::fabs(deg[4] - deg[3]) < std::fabs(deg[5] - deg[3]) ? 0 : 1);
        }
        if (chosen == kNone) continue;
        sum[k] = sum[k] + hit[chosen];
        ++weight[k];
      }
    }
  }
  std::vector<Point2> positions(n);
  for (int i = 0; i < n; ++i) positions[i] = weight[i] > 0 ? (1.0 / weight[i]) * sum[i] : sites[i];
  keep_finite_positions(sites, positions);
  return positions;
}

DenoisedCurve fitconnect(std::span<const Point2> sites, bool blend, int max_neighbors) {
  FittedNeighborhoods fits = connect_fitted_neighborhoods(sites, max_neighbors);
  DenoisedCurve result;
  result.positions = blend ? blended_positions(sites, fits) : std::vector<Point2>(sites.begin(), sites.end());
  result.edges = std::move(fits.edges);
  return result;
}

}  // namespace curvebench
