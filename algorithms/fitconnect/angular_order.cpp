#include "fitconnect/angular_order.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace curvebench {
namespace {

// Keys this far apart order their angles as theta does: a thousand times the rounding of
// both computations (angular_order.h).
constexpr double kKeyMargin = 1e-12;

struct Entry {
  double key;    // diamond angle in (-2, 2], monotone in the exact angle; NaN if undefined
  int index;     // into the neighbours, the list order that breaks ties
  bool settled;  // key_settles(key)
};

// The sort state of one call, kept between calls so that growing neighbourhoods allocate
// nothing.
struct Scratch {
  std::vector<Entry> entries;
  std::vector<double> theta;
  std::vector<char> have_theta, seen;
};

// Whether the key alone settles the side and the order: keys near 0 or +-2 (theta near 0 or
// +-pi, where rounding and the wrap decide) or undefined ones do not.
bool key_settles(double key) {
  const double magnitude = std::fabs(key);
  return magnitude >= kKeyMargin && magnitude <= 2 - kKeyMargin;
}

}  // namespace

int sort_by_angle_about(Point2 center, Point2 site, std::span<const Point2> neighbors, std::vector<int>& order) {
  static thread_local Scratch scratch;
  const int k = static_cast<int>(neighbors.size());
  const Point2 u = site - center;
  bool have_own = false;
  double own = 0.0;

  scratch.theta.resize(k);
  scratch.have_theta.assign(k, 0);
  // theta exactly as the authors' code computes it (in double).
  auto theta = [&](int j) {
    if (!scratch.have_theta[j]) {
      if (!have_own) {
        own = std::atan2(u.y, u.x);
        have_own = true;
      }
      const Point2 d = neighbors[j] - center;
      double value = std::atan2(d.y, d.x) - own;
      if (value < -std::numbers::pi) value += 2 * std::numbers::pi;
      else if (value > std::numbers::pi) value -= 2 * std::numbers::pi;
      scratch.theta[j] = value;
      scratch.have_theta[j] = 1;
    }
    return scratch.theta[j];
  };
  auto less = [&](const Entry& a, const Entry& b) {
    if (a.settled && b.settled && std::fabs(a.key - b.key) > kKeyMargin) return a.key < b.key;
    const double ta = theta(a.index), tb = theta(b.index);
    return ta < tb || (ta == tb && a.index < b.index);
  };

  // The guess, then whatever it misses, in list order.
  std::vector<Entry>& entries = scratch.entries;
  entries.clear();
  scratch.seen.assign(k, 0);
  auto add = [&](int j) {
    if (j < 0 || j >= k || scratch.seen[j]) return;
    scratch.seen[j] = 1;
    const Point2 d = neighbors[j] - center;
    const double key = diamond_angle({dot(u, d), cross(u, d)});  // of the angle from u to d
    entries.push_back({key, j, key_settles(key)});
  };
  for (int j : order) add(j);
  for (int j = 0; j < k; ++j) add(j);

  // Insertion sort from the guess while it stays cheap; otherwise the same order by std::sort.
  const long long move_budget = 4LL * k + 16;
  long long moves = 0;
  bool sorted = true;
  for (int j = 1; j < k && sorted; ++j) {
    const Entry moving = entries[j];
    int slot = j;
    while (slot > 0 && less(moving, entries[slot - 1])) {
      entries[slot] = entries[slot - 1];
      --slot;
      if (++moves > move_budget) break;
    }
    entries[slot] = moving;
    if (moves > move_budget) sorted = false;
  }
  if (!sorted) std::sort(entries.begin(), entries.end(), less);

  order.resize(k);
  int negative = 0;
  for (int j = 0; j < k; ++j) {
    order[j] = entries[j].index;
    if (entries[j].settled ? entries[j].key < 0 : theta(entries[j].index) < 0) negative = j + 1;
  }
  return negative;
}

}  // namespace curvebench
