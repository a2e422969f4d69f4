#include "shape-hull/shape_hull_triangles.h"

#include <CGAL/Exact_rational.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <optional>
#include <queue>
#include <span>
#include <tuple>
#include <utility>

#include "voronoi/sort_by_decreasing_circumradius.h"

namespace curvebench {
namespace {

using Rational = CGAL::Exact_rational;

struct RationalPoint {
  Rational x, y;
};

RationalPoint exactly(Point2 p) { return {Rational(p.x), Rational(p.y)}; }

int exact_orientation(const RationalPoint& a, const RationalPoint& b, const RationalPoint& c) {
  return CGAL::sign((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// The sign of cross(b - a, c - a) for points known only approximately, each coordinate of
// a, b, c within error_a, error_b, error_c of the true one: +1 or -1 when the approximations
// prove it, 0 when they cannot (then the caller decides exactly). A non-finite value never
// proves anything.
int filtered_orientation(Point2 a, double error_a, Point2 b, double error_b, Point2 c, double error_c) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const Point2 u = b - a, v = c - a;
  const double left = u.x * v.y, right = u.y * v.x;
  const double det = left - right;
  // Moving the points changes det by cross(du, v) + cross(u, dv) + cross(du, dv); the eps
  // term is Shewchuk's bound for the rounding of orient2d itself. Doubled to cover the
  // rounding of the bound.
  const double du = error_a + error_b, dv = error_a + error_c;
  const double bound = 2 * (du * (std::abs(v.x) + std::abs(v.y)) + dv * (std::abs(u.x) + std::abs(u.y)) +
                            2 * du * dv + 4 * eps * (std::abs(left) + std::abs(right)));
  if (std::abs(det) > bound) return det > 0 ? 1 : -1;
  return 0;
}

// The segment from the centroid g of a triangle to its circumcentre c (spec step 2c), and
// the exact orientation tests a walk along it needs. The layer's circumcentres are rounded,
// and a circumcentre exactly on an edge (a right angle; common on grids) must count as
// inside, so each test is decided for the true g and c: in double precision when the
// rounding errors cannot change its sign, else in rational arithmetic from the sites.
class CentroidToCircumcentre {
 public:
  // `corners` are those of dv.triangles[triangle], passed in so that the caller can read them
  // from memory it already has.
  CentroidToCircumcentre(const DelaunayVoronoi& dv, int triangle, const std::array<int, 3>& corners)
      : dv_(dv), corners_(corners) {
    constexpr double eps = std::numeric_limits<double>::epsilon();
    const Point2 a = dv.sites[corners[0]], b = dv.sites[corners[1]], d = dv.sites[corners[2]];
    centroid_ = {(a.x + b.x + d.x) / 3, (a.y + b.y + d.y) / 3};
    // Two additions and a division, each rounding by at most eps of the sum of magnitudes.
    centroid_error_ = 2 * eps * (std::abs(a.x) + std::abs(b.x) + std::abs(d.x) + std::abs(a.y) + std::abs(b.y) + std::abs(d.y));
    circumcentre_ = dv.circumcenters[triangle];
    circumcentre_error_ = dv.circumcenter_errors[triangle];
  }

  // The sign of cross(to - from, c - from): >= 0 when c lies left of from -> to or on its
  // line, i.e. not strictly beyond that edge of a counter-clockwise triangle.
  int side_of_edge(int from, int to) {
    const int sign = filtered_orientation(dv_.sites[from], 0, dv_.sites[to], 0, circumcentre_, circumcentre_error_);
    if (sign != 0) return sign;
    return exact_orientation(exactly(dv_.sites[from]), exactly(dv_.sites[to]), exact_circumcentre());
  }

  // True if the site lies left of the line from g to c. A site on that line counts as left:
  // a symbolic perturbation of the line to the right, so that a segment through a vertex
  // still crosses one edge at a time and every site is on one side, consistently.
  bool left_of_segment(int site) {
    int sign = filtered_orientation(centroid_, centroid_error_, circumcentre_, circumcentre_error_, dv_.sites[site], 0);
    if (sign == 0) sign = exact_orientation(exact_centroid(), exact_circumcentre(), exactly(dv_.sites[site]));
    return sign >= 0;
  }

 private:
  const RationalPoint& exact_centroid() {
    if (!exact_centroid_) {
      const RationalPoint a = exactly(dv_.sites[corners_[0]]), b = exactly(dv_.sites[corners_[1]]), d = exactly(dv_.sites[corners_[2]]);
      exact_centroid_ = RationalPoint{(a.x + b.x + d.x) / 3, (a.y + b.y + d.y) / 3};
    }
    return *exact_centroid_;
  }

  const RationalPoint& exact_circumcentre() {
    if (!exact_circumcentre_) {
      const RationalPoint a = exactly(dv_.sites[corners_[0]]);
      const Rational bx = Rational(dv_.sites[corners_[1]].x) - a.x, by = Rational(dv_.sites[corners_[1]].y) - a.y;
      const Rational cx = Rational(dv_.sites[corners_[2]].x) - a.x, cy = Rational(dv_.sites[corners_[2]].y) - a.y;
      const Rational d = 2 * (bx * cy - by * cx);  // nonzero: Delaunay triangles are never flat
      const Rational b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
      exact_circumcentre_ = RationalPoint{a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
    }
    return *exact_circumcentre_;
  }

  const DelaunayVoronoi& dv_;
  std::array<int, 3> corners_;
  Point2 centroid_, circumcentre_;
  double centroid_error_, circumcentre_error_;
  std::optional<RationalPoint> exact_centroid_, exact_circumcentre_;
};

// The sign of dot(b - a, c - a), exact: in double precision when the rounding cannot change
// it, else in rational arithmetic.
int dot_sign(Point2 a, Point2 b, Point2 c) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const Point2 u = b - a, v = c - a;
  const double along_x = u.x * v.x, along_y = u.y * v.y;
  const double dot = along_x + along_y;
  // Shewchuk's bound for orient2d, an expression of the same shape, more than doubled.
  if (std::abs(dot) > 4 * eps * (std::abs(along_x) + std::abs(along_y))) return dot > 0 ? 1 : -1;
  const RationalPoint ea = exactly(a), eb = exactly(b), ec = exactly(c);
  return CGAL::sign((eb.x - ea.x) * (ec.x - ea.x) + (eb.y - ea.y) * (ec.y - ea.y));
}

// Where the segment from the centroid of `triangle` to its circumcentre leaves it: the
// corner opposite the edge it crosses, or kCircumcentreInside if the circumcentre lies in the
// closed triangle. By the inscribed angle theorem the circumcentre lies strictly beyond the
// edge opposite a corner exactly when the angle at that corner is obtuse. At most one is,
// and the circumcentre is then strictly inside the other two edges' half-planes, so the
// segment from the centroid leaves through that edge's interior. A right angle puts the
// circumcentre on the edge: inside (spec step 2c). Depends on the triangle alone.
constexpr std::uint8_t kCircumcentreInside = 3;

std::uint8_t first_exit_corner(const DelaunayVoronoi& dv, int triangle) {
  const auto& tri = dv.triangles[triangle];
  for (std::uint8_t corner = 0; corner < 3; ++corner) {
    if (dot_sign(dv.sites[tri[corner]], dv.sites[tri[(corner + 1) % 3]], dv.sites[tri[(corner + 2) % 3]]) < 0) return corner;
  }
  return kCircumcentreInside;
}

// Everything a decision reads about one triangle, in half a cache line. Sculpting takes the
// triangles in order of circumradius, from all over the plane, so each visit would otherwise
// miss the cache once for each of the layer's arrays it reads; half a line rather than a
// whole one halves the memory the visits range over.
struct alignas(32) TriangleState {
  std::array<int, 3> corners;
  std::array<int, 3> neighbors;
  int rank;                     // position in the order of spec step 1
  std::uint8_t boundary_edges;  // bit i: the outside is across the edge opposite corner i
  std::uint8_t first_exit;      // first_exit_corner
  bool kept;
};

// True if exactly one bit of `edges` is set: a triangle with one boundary edge (spec rule a).
// Not std::popcount, which without a POPCNT target becomes a library call.
bool one_edge(std::uint8_t edges) { return edges != 0 && (edges & (edges - 1)) == 0; }

// The corner of `s` opposite its edge shared with `neighbor` (two triangles share at most one).
int corner_facing(const TriangleState& s, int neighbor) {
  return s.neighbors[0] == neighbor ? 0 : (s.neighbors[1] == neighbor ? 1 : 2);
}

// Spec step 2c for a triangle whose circumcentre is not in it: true if the circumcentre lies
// outside the current shape (the kept triangles). The spec recommends a straight walk over
// the reference's CGAL locate, whose zig-zag depends on CGAL's vertex numbering: from the
// triangle's centroid along the segment to its circumcentre, the answer is "outside" as
// soon as the segment crosses a boundary edge, "inside" when it ends in (or on the border
// of) a kept triangle. The walk never leaves the segment, so it terminates. The exit from
// the first triangle is precomputed, and most walks end there.
bool circumcentre_outside(const DelaunayVoronoi& dv, std::span<const TriangleState> state, int triangle) {
  int exit_corner = state[triangle].first_exit;
  if (state[triangle].boundary_edges >> exit_corner & 1) return true;
  CentroidToCircumcentre segment(dv, triangle, state[triangle].corners);
  for (int current = triangle;;) {
    const int next = state[current].neighbors[exit_corner];  // kept: the edge is not on the boundary
    const auto& corners = state[next].corners;
    const int entry_corner = corner_facing(state[next], current);
    // From entry_corner, `next` is (s, q, p) with q left of the segment and p right of it:
    // it leaves through p -> s if s is left, else through s -> q.
    exit_corner = segment.left_of_segment(corners[entry_corner]) ? (entry_corner + 1) % 3 : (entry_corner + 2) % 3;
    if (segment.side_of_edge(corners[(exit_corner + 1) % 3], corners[(exit_corner + 2) % 3]) >= 0) return false;
    if (state[next].boundary_edges >> exit_corner & 1) return true;
    current = next;
  }
}

// Requests the memory the pop of `triangle` will read, a few pops before it, so that it can
// arrive meanwhile: its apex's boundary flag, its neighbours (for the pushes of spec step 3)
// and, when a walk will follow, its corners and circumcentre. Nothing for a triangle that
// will be kept without a walk (dangling, or its circumcentre inside it): boundary edges only
// ever increase. `assumed_boundary` adds edges it will have on the boundary by its pop.
// Returns true if its pop may remove it (rules a and c as far as they are known now).
bool request_pop_memory(const DelaunayVoronoi& dv, std::span<const TriangleState> state, const std::vector<std::uint8_t>& on_boundary,
                        int triangle, std::uint8_t assumed_boundary) {
  const auto& s = state[triangle];
  const std::uint8_t boundary = s.boundary_edges | assumed_boundary;
  if (!one_edge(boundary) || s.first_exit == kCircumcentreInside) return false;
  __builtin_prefetch(&on_boundary[s.corners[std::countr_zero(boundary)]]);
  for (int corner = 0; corner < 3; ++corner) {
    if (!(boundary >> corner & 1)) __builtin_prefetch(&state[s.neighbors[corner]]);
  }
  if (!(boundary >> s.first_exit & 1)) {
    for (int corner = 0; corner < 3; ++corner) __builtin_prefetch(&dv.sites[s.corners[corner]]);
    __builtin_prefetch(&dv.circumcenters[triangle]);
    __builtin_prefetch(&dv.circumcenter_errors[triangle]);
  }
  return true;
}

// The walk of spec step 2c for an upcoming pop, run ahead of it only to request the memory
// the real walk will read: the triangles along the segment and the one site each adds. It
// starts after request_pop_memory; each advance() does one stage of loads, which can then
// arrive while the sculpting does other work before the next advance(). It decides nothing:
// its tests are approximate (plain double precision), the sculpting may change before the
// pop, and circumcentre_outside walks again regardless. It stops where the real walk would
// certainly not go on (a junction: boundary sites only ever increase; the circumcentre's
// triangle reached), at a boundary edge, or once its pop has passed.
class WalkRehearsal {
 public:
  WalkRehearsal() = default;
  // `until_rank`: the rank of the pop after which the rehearsal is of no more use;
  // `assumed_boundary` as for request_pop_memory.
  WalkRehearsal(int triangle, std::uint8_t assumed_boundary, int until_rank)
      : triangle_(triangle), current_(triangle), until_rank_(until_rank), assumed_boundary_(assumed_boundary) {}

  // True once it has nothing more to request for a pop of `rank` or later.
  bool done(int rank) const { return stage_ == Stage::kDone || rank >= until_rank_; }

  // Does the next stage. `rehearse(triangle, assumed_boundary, until_rank)` receives the
  // neighbours whose walks follow at once if this triangle is removed (see leads_outside).
  template <class Rehearse>
  void advance(const DelaunayVoronoi& dv, std::span<const TriangleState> state, const std::vector<std::uint8_t>& on_boundary,
               Rehearse&& rehearse) {
    switch (stage_) {
      case Stage::kWait:  // for request_pop_memory's loads, which take longer than one pop
        stage_ = Stage::kStart;
        return;
      case Stage::kStart: {  // request_pop_memory's loads have arrived: the first crossing
        const auto& s = state[current_];
        const std::uint8_t boundary = s.boundary_edges | assumed_boundary_;
        if (!one_edge(boundary) || on_boundary[s.corners[std::countr_zero(boundary)]]) {
          stage_ = Stage::kDone;
          return;
        }
        if (boundary >> s.first_exit & 1) {
          leads_outside(dv, state, on_boundary, rehearse);
          return;
        }
        const Point2 a = dv.sites[s.corners[0]], b = dv.sites[s.corners[1]], c = dv.sites[s.corners[2]];
        from_ = {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3};
        to_ = dv.circumcenters[current_];
        cross_to(state, s.first_exit);
        return;
      }
      case Stage::kEntered: {  // the next triangle's state has arrived: request its new site
        const auto& s = state[next_];
        entry_corner_ = static_cast<std::uint8_t>(corner_facing(s, current_));
        __builtin_prefetch(&dv.sites[s.corners[entry_corner_]]);
        stage_ = Stage::kSiteRequested;
        return;
      }
      case Stage::kSiteRequested: {  // the site has arrived: where the segment leaves next_
        const auto& s = state[next_];
        const int exit_corner = left_of_segment(dv.sites[s.corners[entry_corner_]]) ? (entry_corner_ + 1) % 3 : (entry_corner_ + 2) % 3;
        const Point2 p = dv.sites[s.corners[(exit_corner + 1) % 3]], q = dv.sites[s.corners[(exit_corner + 2) % 3]];
        if (cross(q - p, to_ - p) >= 0) {
          stage_ = Stage::kDone;
          return;
        }
        if (s.boundary_edges >> exit_corner & 1) {
          leads_outside(dv, state, on_boundary, rehearse);
          return;
        }
        current_ = next_;
        cross_to(state, exit_corner);
        return;
      }
      case Stage::kDone:
        return;
    }
  }

 private:
  enum class Stage : std::uint8_t { kWait, kStart, kEntered, kSiteRequested, kDone };

  bool left_of_segment(Point2 site) const { return cross(to_ - from_, site - from_) >= 0; }

  // The walk reached the outside, so the triangle is likely removed at its pop. Its
  // neighbours with a larger radius that are interior now then pop at once (from the queue's
  // heap, never announced), with the shared edge as their one boundary edge: their pops are
  // prepared and their walks rehearsed too. Not further: theirs are rarely removed.
  template <class Rehearse>
  void leads_outside(const DelaunayVoronoi& dv, std::span<const TriangleState> state, const std::vector<std::uint8_t>& on_boundary,
                     Rehearse&& rehearse) {
    stage_ = Stage::kDone;
    if (assumed_boundary_ != 0) return;
    const auto& s = state[triangle_];
    for (int corner = 0; corner < 3; ++corner) {
      if (s.boundary_edges >> corner & 1) continue;
      const int neighbor = s.neighbors[corner];
      if (state[neighbor].rank > s.rank || state[neighbor].boundary_edges != 0) continue;
      const auto shared_edge = static_cast<std::uint8_t>(1 << corner_facing(state[neighbor], triangle_));
      if (request_pop_memory(dv, state, on_boundary, neighbor, shared_edge)) rehearse(neighbor, shared_edge, until_rank_);
    }
  }

  // Requests the triangle across the edge of current_ opposite exit_corner.
  void cross_to(std::span<const TriangleState> state, int exit_corner) {
    next_ = state[current_].neighbors[exit_corner];
    __builtin_prefetch(&state[next_]);
    stage_ = Stage::kEntered;
  }

  Point2 from_{}, to_{};
  int triangle_ = 0, current_ = 0, next_ = 0;
  int until_rank_ = 0;
  std::uint8_t entry_corner_ = 0;
  std::uint8_t assumed_boundary_ = 0;
  Stage stage_ = Stage::kWait;
};

// The order of spec step 1: the triangles by decreasing circumradius. The reference leaves
// equal radii in heap order; here the smaller triangle index goes first, so that the result
// is deterministic (a stable sort of the triangles in index order). Radii are the layer's
// rounded ones, as the reference's are its own rounded ones.
std::vector<int> triangles_by_decreasing_circumradius(const DelaunayVoronoi& dv) {
  std::vector<int> order(dv.triangle_count());
  std::iota(order.begin(), order.end(), 0);
  sort_by_decreasing_circumradius(dv, order);
  return order;
}

// The queue of spec steps 1-3, over ranks in that order, smallest first. It does what a
// binary heap does, without the heap's cache misses: at 10^6 points the heap holds hundreds
// of thousands of entries and every pop would walk it from top to bottom. Ranks not yet
// reached are bits above a cursor that only moves forward, so finding the next one is a
// single sweep over all the bits. A triangle pushed after the cursor passed its rank (its
// radius exceeds that of the triangle just removed) waits in a small heap instead, whose
// ranks, all below the cursor, pop first. A rank pushed twice before it pops comes out
// once: the reference's second pop finds the triangle dangling and changes nothing. The
// heap keeps each rank's triangle with it: its pops come in no order of memory.
class RankQueue {
 public:
  explicit RankQueue(const std::vector<int>& triangle_of_rank)
      : triangle_of_rank_(triangle_of_rank), bits_((triangle_of_rank.size() + 63) / 64, 0) {}

  void push(int rank, int triangle) {
    if (rank >= cursor_) {
      bits_[rank >> 6] |= std::uint64_t{1} << (rank & 63);
    } else {
      passed_.push({rank, triangle});
    }
  }

  // The next rank the sweep will reach after the last one announced here, or -1 if there is
  // none: a forecast of the pops, so that their memory can be requested early. A rank pushed
  // later between the cursor and the forecast pops without having been announced.
  int announce() {
    announced_ = std::max(announced_, cursor_);
    for (std::size_t word = static_cast<std::size_t>(announced_) >> 6; word < bits_.size(); ++word) {
      std::uint64_t unannounced = bits_[word];
      if (word == static_cast<std::size_t>(announced_) >> 6) unannounced &= ~std::uint64_t{0} << (announced_ & 63);
      if (unannounced == 0) continue;
      const int rank = static_cast<int>(word * 64) + std::countr_zero(unannounced);
      announced_ = rank + 1;
      return rank;
    }
    announced_ = static_cast<int>(bits_.size() * 64);
    return -1;
  }

  // The smallest rank in the queue and its triangle, taken out, or rank -1 if the queue is empty.
  std::pair<int, int> pop() {
    if (!passed_.empty()) {
      const auto smallest = passed_.top();
      passed_.pop();
      return smallest;
    }
    // Bits below the cursor are all clear: popped, and later pushes go to passed_.
    for (std::size_t word = static_cast<std::size_t>(cursor_) >> 6; word < bits_.size(); ++word) {
      if (bits_[word] == 0) continue;
      const int rank = static_cast<int>(word * 64) + std::countr_zero(bits_[word]);
      bits_[word] &= bits_[word] - 1;
      cursor_ = rank + 1;
      return {rank, triangle_of_rank_[rank]};
    }
    return {-1, -1};
  }

 private:
  const std::vector<int>& triangle_of_rank_;
  std::vector<std::uint64_t> bits_;
  int cursor_ = 0;
  int announced_ = 0;  // ranks below it have been announced or popped
  std::priority_queue<std::pair<int, int>, std::vector<std::pair<int, int>>, std::greater<>> passed_;
};

}  // namespace

std::vector<std::uint8_t> shape_hull_triangles(const DelaunayVoronoi& dv) {
  if (dv.dimension != 2) return {};
  const int triangle_count = dv.triangle_count();
  const std::vector<int> triangle_of_rank = triangles_by_decreasing_circumradius(dv);
  // Inverted in an array of a quarter of the state's size, whose scattered writes stay in
  // cache, rather than in the state.
  std::vector<int> rank_of_triangle(triangle_count);
  for (int rank = 0; rank < triangle_count; ++rank) rank_of_triangle[triangle_of_rank[rank]] = rank;
  // Sites touching the outside: at first the hull sites, including those inside hull edges.
  std::vector<std::uint8_t> on_boundary(dv.on_hull.begin(), dv.on_hull.end());
  // Whether a pop of the triangle could remove it. One that fails rule a (dangling), rule b
  // (junction) or has its circumcentre inside it (rule c) fails it at every later pop too:
  // boundary edges and boundary sites only ever increase, and the circumcentre is fixed. Its
  // pop would change nothing, so it is not queued.
  auto removable = [&](const TriangleState& s) {
    return one_edge(s.boundary_edges) && s.first_exit != kCircumcentreInside &&
           !on_boundary[s.corners[std::countr_zero(s.boundary_edges)]];
  };
  RankQueue queue(triangle_of_rank);
  const auto state_storage = std::make_unique_for_overwrite<TriangleState[]>(triangle_count);  // all written below
  const std::span<TriangleState> state(state_storage.get(), triangle_count);
  for (int t = 0; t < triangle_count; ++t) {
    auto& s = state[t];
    s.rank = rank_of_triangle[t];
    s.corners = dv.triangles[t];
    s.neighbors = dv.neighbors[t];
    s.boundary_edges = 0;
    for (int i = 0; i < 3; ++i) s.boundary_edges |= (s.neighbors[i] == kInfinite) << i;
    s.first_exit = first_exit_corner(dv, t);
    s.kept = true;
    if (s.boundary_edges && removable(s)) queue.push(s.rank, t);  // spec step 1: each triangle with a hull edge, once
  }

  // The pops announced and not yet popped, in rank order. A decision is a chain of loads that
  // each wait for the one before (the triangle, then its corners, its neighbours, the walk),
  // and on large input every link is a cache miss. The triangle of a rank announced now is
  // requested at once; kLookahead pops before its own pop, when that has arrived, what its
  // pop reads is requested (request_pop_memory) and, on large input, its walk is rehearsed
  // (WalkRehearsal), one stage per pop, so that the misses of many upcoming pops overlap
  // instead of following one another.
  constexpr int kLookahead = 16;
  constexpr int kMaxRehearsals = 64;
  // Below this many triangles the arrays mostly fit a last-level cache, the misses are short,
  // and rehearsing the walks costs more than it hides (harness/bench/README.md).
  constexpr int kRehearsedWalksMinTriangles = 1 << 20;
  const bool rehearse_walks = triangle_count >= kRehearsedWalksMinTriangles;
  std::array<int, 2 * kLookahead> announced{};
  int oldest = 0, announced_count = 0, requested_count = 0;  // the oldest requested_count are requested
  auto announced_at = [&](int i) -> int& { return announced[(oldest + i) % announced.size()]; };
  std::array<WalkRehearsal, kMaxRehearsals> rehearsals;
  int rehearsal_count = 0;
  auto rehearse = [&](int triangle, std::uint8_t assumed_boundary, int until_rank) {
    if (rehearsal_count < kMaxRehearsals) rehearsals[rehearsal_count++] = WalkRehearsal(triangle, assumed_boundary, until_rank);
  };
  for (auto [rank, t] = queue.pop(); rank >= 0; std::tie(rank, t) = queue.pop()) {
    while (announced_count > 0 && announced_at(0) <= rank) {
      oldest = (oldest + 1) % announced.size(), --announced_count;
      requested_count = std::max(requested_count - 1, 0);
    }
    for (int more = 0; more < 2 && announced_count < static_cast<int>(announced.size()); ++more) {
      const int upcoming = queue.announce();
      if (upcoming < 0) break;
      __builtin_prefetch(&state[triangle_of_rank[upcoming]]);
      announced_at(announced_count++) = upcoming;
    }
    for (; requested_count < announced_count - kLookahead; ++requested_count) {
      const int upcoming = announced_at(requested_count);
      if (request_pop_memory(dv, state, on_boundary, triangle_of_rank[upcoming], 0) && rehearse_walks) {
        rehearse(triangle_of_rank[upcoming], 0, upcoming);
      }
    }
    for (int i = 0; i < rehearsal_count;) {
      rehearsals[i].advance(dv, state, on_boundary, rehearse);
      if (rehearsals[i].done(rank)) {
        rehearsals[i] = rehearsals[--rehearsal_count];
      } else {
        ++i;
      }
    }
    // A popped triangle is always kept: it is removed only at a pop where it has one boundary
    // edge, and it has at most one queue entry per boundary edge, so none is left behind.
    auto& s = state[t];
    // Spec step 2 tests the circumcentre first; here the tests go cheapest first, which
    // changes no outcome (all three must hold).
    if (!one_edge(s.boundary_edges)) continue;            // rule a: dangling
    if (s.first_exit == kCircumcentreInside) continue;     // rule c, circumcentre in t
    const int boundary_corner = std::countr_zero(s.boundary_edges);
    const int apex = s.corners[boundary_corner];
    if (on_boundary[apex]) continue;                     // rule b: junction
    if (!circumcentre_outside(dv, state, t)) continue;   // rule c
    s.kept = false;  // spec step 3
    on_boundary[apex] = 1;
    for (int corner = 0; corner < 3; ++corner) {
      if (corner == boundary_corner) continue;
      auto& other = state[s.neighbors[corner]];
      other.boundary_edges |= 1 << corner_facing(other, t);
      if (removable(other)) queue.push(other.rank, s.neighbors[corner]);
    }
  }
  std::vector<std::uint8_t> kept(triangle_count);
  for (int t = 0; t < triangle_count; ++t) kept[t] = state[t].kept;
  return kept;
}

}  // namespace curvebench
