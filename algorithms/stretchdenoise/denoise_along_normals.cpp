#include "stretchdenoise/denoise_along_normals.h"

#include "core/denoised_curve.h"
#include "stretchdenoise/bounded_least_squares.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <numbers>

namespace curvebench {
namespace {

constexpr int kNone = -1;
using State = SampleState;

bool is_linked(State s) { return s == State::Manifold || s == State::Leaf || s == State::Sharp; }

// Polar angle of v in degrees, in [0, 360] (the reference's computeDegreesFromVector + 180).
double degrees(Point2 v) { return (std::atan2(v.y, v.x) + std::numbers::pi) / std::numbers::pi * 180; }

// Links and normals after spec 2.3: slot 0 = predecessor, slot 1 = successor, normals
// consistent along each component. `swapped` records which points had their sides exchanged.
struct Oriented {
  std::vector<std::array<int, 2>> links;
  std::vector<Point2> normals;
  std::vector<char> swapped;
};

Oriented orient(std::span<const Point2> sites, const FittedNeighborhoods& fits) {
  const int n = static_cast<int>(sites.size());
  Oriented o{fits.links, fits.normals, std::vector<char>(n, 0)};
  // cw(x): the arc from x's predecessor to x turns clockwise about x's fit centre.
  auto clockwise = [&](int x) {
    const int before = o.links[x][0];
    if (before == kNone) return false;
    const Point2 c = fits.centers[x];
    return std::fmod(degrees(sites[x] - c) - degrees(sites[before] - c) + 360.0, 360.0) > 180;
  };
  std::vector<char> oriented(n, 0);
  std::vector<int> stack;
  for (int start = 0; start < n; ++start) {
    const State s = fits.states[start];
    if (oriented[start] || (s != State::Manifold && s != State::Sharp)) continue;
    const bool start_clockwise = clockwise(start);
    stack.push_back(start);
    while (!stack.empty()) {
      const int u = stack.back();
      stack.pop_back();
      oriented[u] = 1;
      for (int j = 0; j < 2; ++j) {
        const int w = o.links[u][j];
        if (w == kNone || oriented[w]) continue;
        if (o.links[w][1 - j] != u) {
          std::swap(o.links[w][0], o.links[w][1]);
          o.swapped[w] ^= 1;
        }
        const State ws = fits.states[w];
        if (ws == State::Leaf || ws == State::Sharp) {
          // No usable fit direction at a leaf or corner: follow the neighbour's normal.
          if (dot(o.normals[u], o.normals[w]) < 0) o.normals[w] = -1.0 * o.normals[w];
        } else if (clockwise(w) != start_clockwise) {
          o.normals[w] = -1.0 * o.normals[w];
        }
        oriented[w] = 1;
        if (ws == State::Manifold || ws == State::Sharp) stack.push_back(w);
      }
    }
  }
  return o;
}

// Spec 2.5: the key (first vertex of the segment) each non-manifold sample is assigned to;
// manifold points are their own key, unassigned samples -1.
std::vector<int> assign_samples(std::span<const Point2> sites, const FittedNeighborhoods& fits, const Oriented& o) {
  const int n = static_cast<int>(sites.size());
  std::vector<int> key(n, kNone);
  std::vector<double> best(n, std::numeric_limits<double>::infinity());
  // Candidate of s for segment (a, b) with key a. The reference tests the perpendicular with a
  // segment s +- 1000 * normal (absolute, spec §3); the foot parameter in [0, 1] is the same
  // test without the scale.
  auto offer = [&](int s, int a, int b) {
    const Point2 ab = sites[b] - sites[a], as = sites[s] - sites[a];
    const double length2 = dot(ab, ab);
    const double t = dot(as, ab) / length2;
    int candidate_key;
    double d;
    if (t >= 0 && t <= 1) {
      candidate_key = a;
      d = std::abs(cross(ab, as)) / std::sqrt(length2);
    } else {
      const double da = distance(sites[s], sites[a]), db = distance(sites[s], sites[b]);
      // On equal distances the reference keeps the segment's first vertex.
      candidate_key = db < da ? b : a;
      d = std::min(da, db);
    }
    if (d < best[s]) {  // first inserted wins ties
      best[s] = d;
      key[s] = candidate_key;
    }
  };
  for (int u = 0; u < n; ++u) {
    if (fits.states[u] != State::Manifold) continue;
    key[u] = u;
    const int before = o.links[u][0], after = o.links[u][1];
    for (int j = 0; j < 2; ++j) {
      for (int s : fits.side(u, j ^ o.swapped[u])) {
        if (fits.states[s] == State::Manifold) continue;
        if (before != kNone) offer(s, before, u);
        if (after != kNone) offer(s, u, after);
      }
    }
  }
  for (int u = 0; u < n; ++u)
    if (fits.states[u] == State::Manifold) key[u] = u;
  return key;
}

// Is there a line through every disc (q_i, sigma_i)? Spec 2.6, the reference's hasInsideLine.
bool line_fits(const std::vector<Point2>& q, const std::vector<double>& sigma) {
  const std::size_t m = q.size() - 1;
  const Point2 q0 = q[0], d = q[m] - q0;
  const double length2 = dot(d, d);
  if (length2 == 0) return false;
  Point2 normal = (1 / std::sqrt(length2)) * Point2{d.y, -d.x};
  if (normal.y > 0) normal = -1.0 * normal;
  double lowest_high = std::numeric_limits<double>::infinity(), highest_low = -lowest_high;
  std::vector<double> low(m + 1), high(m + 1);
  for (std::size_t i = 1; i < m; ++i) {
    const double tau = dot(d, q[i] - q0) / length2;
    const double rho = sigma[0] + tau * (sigma[m] - sigma[0]);
    const double h = dot(normal, q[i] - q0);
    low[i] = (h - sigma[i]) / rho;
    high[i] = (h + sigma[i]) / rho;
    highest_low = std::max(highest_low, low[i]);
    lowest_high = std::min(lowest_high, high[i]);
  }
  std::vector<std::size_t> below, above;
  for (std::size_t i = 1; i < m; ++i) {
    if (low[i] > lowest_high) above.push_back(i);
    if (high[i] < highest_low) below.push_back(i);
  }
  // A line whose offsets at both ends are the same fraction of the end extents.
  if (below.empty() && above.empty()) return lowest_high > -1 && highest_low < 1;
  for (std::size_t i : below) {
    for (std::size_t j : above) {
      const double centre_distance = distance(q[i], q[j]);
      const double ratio = (sigma[i] + sigma[j]) / centre_distance;
      if (!(ratio < 1)) continue;
      const double alpha = std::atan2(q[j].y - q[i].y, q[j].x - q[i].x), beta = std::acos(ratio);
      for (double gamma : {alpha - beta, alpha + beta}) {
        const Point2 direction{std::cos(gamma), std::sin(gamma)};
        const Point2 touch = q[i] + sigma[i] * direction;
        const Point2 along = q[j] - sigma[j] * direction - touch;
        const double along_length = norm(along);
        bool through_all = along_length > 0;
        for (std::size_t l = 0; l <= m && through_all; ++l)
          if (l != i && l != j) through_all = std::abs(cross(along, q[l] - touch)) / along_length <= sigma[l];
        if (through_all) return true;
      }
    }
  }
  return false;
}

// A linked component in walking order (slot 1 = next); an open chain runs end to end.
struct Component {
  std::vector<int> members;
  bool cyclic = false;
};

std::vector<Component> components(const FittedNeighborhoods& fits, const Oriented& o) {
  const int n = static_cast<int>(fits.states.size());
  // Only mutual, oriented links are walked: after orientation l[l[a][1]][0] == a along a chain.
  auto successor = [&](int a) {
    const int b = o.links[a][1];
    return (b != kNone && is_linked(fits.states[b]) && o.links[b][0] == a) ? b : kNone;
  };
  auto predecessor = [&](int a) {
    const int b = o.links[a][0];
    return (b != kNone && is_linked(fits.states[b]) && o.links[b][1] == a) ? b : kNone;
  };
  std::vector<char> taken(n, 0);
  std::vector<Component> result;
  for (int a = 0; a < n; ++a) {
    if (taken[a] || !is_linked(fits.states[a])) continue;
    int first = a;
    bool cyclic = false;
    while (true) {
      const int b = predecessor(first);
      if (b == kNone) break;
      if (b == a) {
        cyclic = true;
        break;
      }
      first = b;
    }
    Component component;
    component.cyclic = cyclic;
    for (int x = first; x != kNone && !taken[x]; x = successor(x)) {
      taken[x] = 1;
      component.members.push_back(x);
    }
    if (cyclic) {
      // Spec 2.8 starts at the lowest-index manifold point (the reference's V[0]).
      auto lowest = std::find_if(component.members.begin(), component.members.end(),
                                 [&](int x) { return fits.states[x] == State::Manifold; });
      if (lowest == component.members.end()) continue;
      for (auto it = lowest; it != component.members.end(); ++it)
        if (fits.states[*it] == State::Manifold && *it < *lowest) lowest = it;
      std::rotate(component.members.begin(), lowest, component.members.end());
    }
    result.push_back(std::move(component));
  }
  return result;
}

double signed_distance_right(Point2 s, Point2 a, Point2 b) { return -cross(b - a, s - a) / distance(a, b); }

// Hat weight of vertex a at sample s on edge (a, o), as spec 2.9 has it: above 1 (s projects
// behind a) it is 1; below 0 (s projects beyond o) it is 0.1, not 0, so a sample beyond the
// neighbouring vertex still weighs a little on a. A sample at o itself gets exactly 0 (here in
// double precision; the reference's float32 rounding makes that 0 or 0.1).
double hat_weight(Point2 s, Point2 a, Point2 o) {
  const Point2 edge = o - a;
  const double h = 1 - dot(edge, s - a) / dot(edge, edge);
  return h < 0 ? 0.1 : std::min(h, 1.0);
}

// Signed distance along unit n from p to the line through v0, v1 (positive when the line lies
// in +n); infinite when n is parallel to the line (moving p never reaches it).
double distance_along(Point2 p, Point2 v0, Point2 v1, Point2 n) {
  const Point2 d = v1 - v0;
  const double denominator = cross(d, n);
  if (denominator == 0) return std::numeric_limits<double>::infinity();
  return cross(d, v0 - p) / denominator;
}

class WindowSolver {
 public:
  WindowSolver(std::span<const Point2> sites, std::vector<Point2>& positions, const std::vector<Point2>& normals,
               const std::vector<std::vector<int>>& samples_by_key)
      : sites_(sites), positions_(positions), normals_(normals), samples_by_key_(samples_by_key) {}

  // v: v_0 .. v_{k+3} (site indices, -1 past a chain end); extents: the bound of w_1 .. w_k.
  void solve(const std::vector<int>& v, const std::vector<double>& extents) {
    const int k = static_cast<int>(extents.size());
    auto P = [&](int i) { return positions_[v[i]]; };
    auto exists = [&](int i) { return i >= 0 && i < k + 4 && v[i] != kNone; };
    // Objective rows (spec 2.9): the angle proxy at v_{i+1} and its linearisation per moving vertex.
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<double> y;
    for (int i = 0; i <= k + 1; ++i) {
      if (!exists(i) || !exists(i + 1) || !exists(i + 2)) continue;
      const double base = distance(P(i), P(i + 2));
      if (base == 0) continue;
      const int row = static_cast<int>(y.size());
      const double value = std::abs(cross(P(i + 2) - P(i), P(i + 1) - P(i))) / base / base;
      y.push_back(value);
      // The reference floors |delta| at an absolute 1e-6; relative to the triple's base here.
      auto add = [&](int column, int moving, int a, int b) {
        double delta = distance_along(P(moving), P(a), P(b), normals_[v[moving]]);
        if (std::abs(delta) < 1e-6 * base) delta = std::copysign(1e-6 * base, delta);
        entries.emplace_back(row, column, value / delta);
      };
      if (i >= 2) add(i - 2, i, i + 1, i + 2);
      if (i >= 1 && i <= k) add(i - 1, i + 1, i, i + 2);
      if (i <= k - 1) add(i, i + 2, i, i + 1);
    }
    // Constraint row: weighted signed distances of the samples to the moved polygon sum to zero.
    Eigen::VectorXd c = Eigen::VectorXd::Zero(k);
    double b = 0;
    for (int i = 0; i <= k; ++i) {
      if (!exists(i + 1) || !exists(i + 2)) continue;
      for (int s : samples_by_key_[v[i + 1]]) {
        // Half weight for the window's end vertices, whose samples the neighbouring windows
        // share (the reference's intent; its other 0.5 weights come from reading index -1).
        const double weight = (i == 0 && s == v[1]) ? 0.5 : 1.0;
        b += weight * signed_distance_right(sites_[s], P(i + 1), P(i + 2));
        if (i <= k - 1) c[i] += weight * hat_weight(sites_[s], P(i + 2), P(i + 1));
        if (i >= 1) c[i - 1] += weight * hat_weight(sites_[s], P(i + 1), P(i + 2));
      }
    }
    if (exists(k + 2) && exists(k + 3))
      b += 0.5 * signed_distance_right(sites_[v[k + 2]], P(k + 2), P(k + 3));
    // Bounds: the total displacement of each vertex stays within its extent.
    Eigen::VectorXd lower(k), upper(k);
    for (int j = 0; j < k; ++j) {
      const int w = v[j + 2];
      const double moved = dot(normals_[w], positions_[w] - sites_[w]);
      lower[j] = -extents[j] - moved;
      upper[j] = extents[j] - moved;
    }
    const Eigen::VectorXd x = bounded_least_squares(entries, y, c, b, lower, upper);
    for (int j = 0; j < k; ++j) {
      const int w = v[j + 2];
      positions_[w] = positions_[w] + x[j] * normals_[w];
    }
  }

 private:
  std::span<const Point2> sites_;
  std::vector<Point2>& positions_;
  const std::vector<Point2>& normals_;
  const std::vector<std::vector<int>>& samples_by_key_;
};

// Spec 2.8 on one component: grow each window forward then backward while one line fits the
// noise discs, solve, continue from where the forward growth stopped. A window stops growing
// at `max_window` vertices (0: never) as it stops where no line fits: the reference lets one
// window take a whole straight component, and each growth step re-tests the whole window.
void denoise_component(const Component& component, std::span<const Point2> sites, const FittedNeighborhoods& fits,
                       const std::vector<double>& sigma, std::size_t max_window, WindowSolver& solver) {
  const std::vector<int>& members = component.members;
  const int length = static_cast<int>(members.size());
  const bool cyclic = component.cyclic;
  if (length < 3) return;
  auto next = [&](int pos) { return pos == kNone ? kNone : cyclic ? (pos + 1) % length : (pos + 1 < length ? pos + 1 : kNone); };
  auto prev = [&](int pos) {
    return pos == kNone ? kNone : cyclic ? (pos + length - 1) % length : (pos > 0 ? pos - 1 : kNone);
  };
  // Chain ends are fixed (the reference writes to position -1 there, spec §3).
  auto fixed = [&](int pos) { return !cyclic && (pos == 0 || pos == length - 1); };
  // sharp(v) = no line through the discs of v and its two neighbours (spec 2.7), read for the
  // vertex itself (the reference reads it by position in V). Corners, leaves and chain ends
  // count as sharp: a window may end at them, never pass through.
  std::vector<char> sharp(length);
  for (int pos = 0; pos < length; ++pos) {
    const int v = members[pos];
    sharp[pos] = fits.states[v] != State::Manifold || fixed(pos) ||
                 !line_fits({sites[members[prev(pos)]], sites[v], sites[members[next(pos)]]},
                            {sigma[members[prev(pos)]], sigma[v], sigma[members[next(pos)]]});
  }
  std::vector<Point2> q;
  std::vector<double> s;
  auto fits_window = [&](const std::deque<int>& window) {
    q.clear();
    s.clear();
    for (int pos : window) q.push_back(sites[members[pos]]), s.push_back(sigma[members[pos]]);
    return line_fits(q, s);
  };
  const std::size_t cap = static_cast<std::size_t>(length - 1);  // cyclic windows never wrap onto themselves
  int start = 0;
  bool last_window = false;
  while (!last_window) {
    std::deque<int> window{start, next(start)};
    int next_start = kNone;
    while (true) {
      const int e = window.back();
      if (last_window || (cyclic && e == 0))
        last_window = true;
      else
        next_start = e;
      const int after = next(e);
      if (after == kNone) {  // open chain: its end closes the last window
        last_window = true;
        break;
      }
      window.push_back(after);
      const bool grows = !sharp[e] && fits_window(window);
      if (!grows || (cyclic && window.size() >= cap) || (max_window > 0 && window.size() > max_window)) {
        window.pop_back();
        break;
      }
    }
    while (true) {
      const int f = window.front();
      const int before = prev(f);
      if (before == kNone) break;
      window.push_front(before);
      const bool grows = !sharp[f] && fits_window(window);
      if (!grows || (cyclic && window.size() >= cap) || (max_window > 0 && window.size() > max_window)) {
        window.pop_front();
        break;
      }
    }
    std::vector<int> v;
    const int first = window.front(), last = window.back();
    for (int pos : {prev(prev(first)), prev(first)}) v.push_back(pos == kNone ? kNone : members[pos]);
    std::vector<double> extents;
    for (int pos : window) {
      v.push_back(members[pos]);
      extents.push_back(fixed(pos) ? 0.0 : sigma[members[pos]]);
    }
    for (int pos : {next(last), next(next(last))}) v.push_back(pos == kNone ? kNone : members[pos]);
    solver.solve(v, extents);
    if (!last_window) start = next_start;
  }
}

}  // namespace

std::vector<Point2> denoise_along_normals(std::span<const Point2> sites, const FittedNeighborhoods& fits,
                                          std::span<const double> noise_extents, int max_window) {
  std::vector<Point2> positions(sites.begin(), sites.end());
  const int n = static_cast<int>(sites.size());
  if (n < 3 || static_cast<int>(fits.states.size()) != n || static_cast<int>(noise_extents.size()) != n)
    return positions;
  // Zero extents would divide by zero in line_fits; floor them relative to the input's size
  // (the reference's absolute 1e-6 floor is applied to a copy and never takes effect).
  double min_x = sites[0].x, max_x = min_x, min_y = sites[0].y, max_y = min_y;
  for (Point2 p : sites) min_x = std::min(min_x, p.x), max_x = std::max(max_x, p.x), min_y = std::min(min_y, p.y), max_y = std::max(max_y, p.y);
  const double floor = std::max(1e-12 * std::hypot(max_x - min_x, max_y - min_y), std::numeric_limits<double>::min());
  std::vector<double> sigma(n);
  for (int i = 0; i < n; ++i) sigma[i] = std::isfinite(noise_extents[i]) ? std::max(noise_extents[i], floor) : floor;

  const Oriented o = orient(sites, fits);
  const std::vector<int> key = assign_samples(sites, fits, o);
  std::vector<std::vector<int>> samples_by_key(n);
  for (int s = 0; s < n; ++s)
    if (key[s] != kNone) samples_by_key[key[s]].push_back(s);
  WindowSolver solver(sites, positions, o.normals, samples_by_key);
  // Every component is denoised (the reference only the one holding V[0], spec §3).
  for (const Component& component : components(fits, o)) denoise_component(component, sites, fits, sigma, static_cast<std::size_t>(std::max(max_window, 0)), solver);
  keep_finite_positions(sites, positions);
  return positions;
}

}  // namespace curvebench
