#include "fitconnect/fitted_neighborhoods.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <utility>
#include <vector>

#include "core/nearest_neighbors.h"
#include "core/z_order.h"
#include "fitconnect/angular_order.h"
#include "fitconnect/hyper_circle_fit.h"

namespace curvebench {
namespace {

using State = SampleState;

constexpr int kNone = -1;
constexpr int kMaxPasses = 99999;  // the authors' pass cap (spec 2.5)

// The open set U as a bit set, with the pass cursor of spec 2.5: the cursor holds the next
// member to visit; removing that member moves it to the next larger one, insertions leave it.
class OpenSet {
 public:
  explicit OpenSet(int n) : n_(n), words_((n + 63) / 64, 0), cursor_(n) {}
  bool contains(int i) const { return (words_[i >> 6] >> (i & 63)) & 1u; }
  bool empty() const { return count_ == 0; }
  void insert(int i) {
    if (contains(i)) return;
    words_[i >> 6] |= std::uint64_t{1} << (i & 63);
    ++count_;
  }
  void erase(int i) {
    if (!contains(i)) return;
    if (i == cursor_) cursor_ = next_member(i + 1);
    words_[i >> 6] &= ~(std::uint64_t{1} << (i & 63));
    --count_;
  }
  // The first member >= from, or n.
  int next_member(int from) const {
    if (from >= n_) return n_;
    int w = from >> 6;
    std::uint64_t bits = words_[w] & (~std::uint64_t{0} << (from & 63));
    while (bits == 0) {
      if (++w == static_cast<int>(words_.size())) return n_;
      bits = words_[w];
    }
    return std::min(n_, w * 64 + std::countr_zero(bits));
  }
  int cursor() const { return cursor_; }
  void set_cursor(int c) { cursor_ = c; }

 private:
  int n_;
  std::vector<std::uint64_t> words_;
  int count_ = 0;
  int cursor_;
};

// The affected set of spec 2.6 step 6, a sorted vector (it holds a handful of points).
class AffectedSet {
 public:
  bool empty() const { return points_.empty(); }
  int first() const { return points_.front(); }
  void insert(int i) {
    const auto at = std::lower_bound(points_.begin(), points_.end(), i);
    if (at == points_.end() || *at != i) points_.insert(at, i);
  }
  // Removes member i and returns the next larger member, or kNone.
  int erase_and_next(int i) {
    const auto at = points_.erase(std::lower_bound(points_.begin(), points_.end(), i));
    return at == points_.end() ? kNone : *at;
  }

 private:
  std::vector<int> points_;
};

// A reusable membership set over point indices: O(1) clear by bumping a stamp.
class Marks {
 public:
  explicit Marks(int n) : stamp_(n, 0) {}
  void clear() {
    if (++current_ == 0) {
      std::fill(stamp_.begin(), stamp_.end(), 0);
      current_ = 1;
    }
  }
  void set(int i) { stamp_[i] = current_; }
  bool has(int i) const { return i >= 0 && stamp_[i] == current_; }

 private:
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_ = 0;
};

// Per-point lists of indices in one array rather than millions of small heap blocks: each
// list owns a block of it; one that outgrows its block moves to a new one at the end, with
// room to double.
class ListPool {
 public:
  ListPool() = default;
  // One empty list per entry of `capacities`, with a block of that size; blocks in list order,
  // so that lists of nearby indices are near in memory.
  explicit ListPool(const std::vector<int>& capacities) : blocks_(capacities.size()) {
    std::size_t total = 0;
    for (std::size_t i = 0; i < capacities.size(); ++i) {
      blocks_[i] = {total, 0, capacities[i]};
      total += capacities[i];
    }
    items_.resize(total);
  }
  int size(int i) const { return blocks_[i].size; }
  std::span<const int> list(int i) const { return {items_.data() + blocks_[i].begin, std::size_t(blocks_[i].size)}; }
  std::span<int> list(int i) { return {items_.data() + blocks_[i].begin, std::size_t(blocks_[i].size)}; }
  // Resizes list i, keeping its first entries; entries past the old size are unset.
  void resize(int i, int size) {
    Block& block = blocks_[i];
    if (size > block.capacity) {
      const std::size_t moved = items_.size();
      block.capacity = std::max(size, 2 * block.capacity);
      items_.resize(moved + block.capacity);
      std::copy_n(items_.begin() + block.begin, block.size, items_.begin() + moved);
      block.begin = moved;
    }
    block.size = size;
  }
  // `values` must lie outside this pool, whose array a move may reallocate.
  void assign(int i, std::span<const int> values) {
    blocks_[i].size = 0;  // nothing to keep when the list moves
    resize(i, static_cast<int>(values.size()));
    std::copy(values.begin(), values.end(), list(i).begin());
  }
  void push_back(int i, int v) {
    resize(i, blocks_[i].size + 1);
    list(i).back() = v;
  }

 private:
  struct Block {
    std::size_t begin;
    int size, capacity;
  };
  std::vector<int> items_;
  std::vector<Block> blocks_;
};

// |v| by a square root where the sum of squares is safely in range, else by std::hypot: the
// same value up to the last bit, at a fraction of hypot's cost on the hot path.
double length(Point2 v) {
  const double squared = dot(v, v);
  return squared > 1e-290 && squared < 1e290 ? std::sqrt(squared) : norm(v);
}
Point2 unit(Point2 v) { return (1.0 / length(v)) * v; }

// Closed segments ab and cd meet; parallel (or degenerate) pairs count as meeting, as in the
// authors' corner test (spec 2.6 step 5).
bool segments_meet(Point2 a, Point2 b, Point2 c, Point2 d) {
  const Point2 r = b - a, s = d - c;
  const double rs = cross(r, s);
  if (rs == 0.0) return true;
  const double t = cross(c - a, s) / rs, u = cross(c - a, r) / rs;
  return t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0;
}

// What a visit may have to undo (spec 2.6 steps 2 and 7): the fit before growth. The sides
// are kept in FitConnect::saved_neighborhood_, whose capacity is reused.
// n sites in `state`, nothing fitted, linked or grown.
FittedNeighborhoods unfitted(int n, State state) {
  FittedNeighborhoods fits;
  fits.states.assign(n, state);
  fits.links.assign(n, {kNone, kNone});
  fits.neighborhoods.assign(n, {});
  fits.side0_sizes.assign(n, 0);
  fits.centers.assign(n, {});
  fits.radii.assign(n, 0.0);
  fits.normals.assign(n, {});
  fits.fits_on_a_line.assign(n, 0);
  fits.residuals.assign(n, 0.0);
  return fits;
}

struct SavedFit {
  Point2 center, normal;
  double radius = 0.0;
  int side0_size = 0;
  std::uint8_t on_a_line = 0;
};

class FitConnect {
 public:
  FitConnect(std::span<const Point2> sites, int max_neighbors)
      : p_(sites),
        n_(static_cast<int>(sites.size())),
        max_neighbors_(max_neighbors),
        nn_(sites),
        streams_(std::vector<int>(n_, batch_size(2) - 1)),
        grown_(n_, 0),
        reach_(n_, -1.0),
        sides_(std::vector<int>(n_, batch_size(2) - 1)),
        out_(unfitted(n_, State::Initial)),
        open_(n_),
        side_marks_(n_),
        chain_marks_(n_),
        other_marks_(n_),
        list_position_(n_) {
    for (int i = 0; i < n_; ++i) open_.insert(i);
    // Every stream's first batch up front, in Z order whatever the input order: the queries of
    // the first visits, each near the one before in the tree and without the visits' state
    // between them in the cache. Ref(q) gets a block for every stream whose first batch holds q.
    std::vector<int> first_batch_holders(n_, 0);
    for (int i : z_order(sites)) {
      fetch_stream(i, batch_size(2));
      for (int q : streams_.list(i)) ++first_batch_holders[q];
    }
    refs_ = ListPool(first_batch_holders);
  }

  FittedNeighborhoods run() {
    for (int pass = 0; !open_.empty() && pass < kMaxPasses; ++pass) {
      open_.set_cursor(open_.next_member(0));
      while (open_.cursor() < n_) {
        const int p = open_.cursor();
        open_.set_cursor(open_.next_member(p + 1));
        visit(p);
      }
    }
    collect_edges();
    collect_residuals();
    for (int i = 0; i < n_; ++i) out_.neighborhoods[i].assign(sides_.list(i).begin(), sides_.list(i).end());
    return std::move(out_);
  }

 private:
  static bool is_linked_state(State s) { return s == State::Manifold || s == State::Leaf || s == State::Sharp; }
  bool is(int i, State s) const { return i != kNone && state_[i] == s; }  // state[-1] is no state
  int link_count(int i) const { return (link_[i][0] != kNone) + (link_[i][1] != kNone); }
  // A_i^t as FittedNeighborhoods::side has it.
  std::span<const int> side(int i, int t) const {
    const std::span<const int> all = sides_.list(i);
    const int split = out_.side0_sizes[i];
    return t == 0 ? all.first(split) : all.subspan(split);
  }
  bool in_side(int i, int t, int q) const {
    // A point farther than the farthest of R_i is in neither side: a cheap exact test first.
    if (q < 0 || squared_distance(p_[i], p_[q]) > reach_[i]) return false;
    const auto s = side(i, t);
    return std::find(s.begin(), s.end(), q) != s.end();
  }
  int side_holding(int i, int q) const { return in_side(i, 0, q) ? 0 : 1; }
  int slot_of(int i, int q) const { return link_[i][0] == q ? 0 : 1; }

  // set(p, s) of spec 2.4: MANIFOLD / LEAF / SHARP / ELIMINATED leave U (a LEAF is already
  // out), CONFORM / NONCONFORM enter it.
  void set_state(int i, State s) {
    if (s == State::Manifold || s == State::Eliminated || s == State::Leaf || s == State::Sharp) {
      if (state_[i] != State::Leaf) open_.erase(i);
    } else {
      open_.insert(i);
    }
    state_[i] = s;
  }

  // cut(p, t) of spec 2.4.
  void cut(int i, int t) {
    const int q = link_[i][t];
    if (q == kNone) return;
    link_[i][t] = kNone;
    const int qt = slot_of(q, i);
    link_[q][qt] = kNone;
    if (state_[q] == State::Manifold || state_[q] == State::Leaf) {
      set_state(q, State::Conform);
    } else if (state_[q] == State::Sharp) {
      set_state(q, State::Nonconform);
      const int r = link_[q][1 - qt];
      if (r != kNone) {
        link_[q][1 - qt] = kNone;
        link_[r][slot_of(r, q)] = kNone;
        if (state_[r] == State::Manifold) set_state(r, State::Conform);
      }
    }
  }
  void drop_one(int i, int t) {
    cut(i, t);
    affected_.insert(i);
    if (state_[i] == State::Manifold) set_state(i, State::Conform);
  }
  void drop_all(int i) {
    cut(i, 0);
    cut(i, 1);
    affected_.insert(i);
    if (state_[i] == State::Manifold || state_[i] == State::Leaf) set_state(i, State::Conform);
    else if (state_[i] == State::Sharp) set_state(i, State::Nonconform);
  }

  // chain(p, t) of spec 2.4 into chain_marks_. On consistent (symmetric) links the walk stays
  // inside A_p^t and visits each point once, so |A_p^t| steps bound it; the bound only guards
  // against looping on an inconsistent state.
  void mark_chain(int i, int t) {
    const auto s = side(i, t);
    side_marks_.clear();
    for (int q : s) side_marks_.set(q);
    chain_marks_.clear();
    int previous = i, current = link_[i][t];
    for (std::size_t steps = 0; steps < s.size() && side_marks_.has(current); ++steps) {
      chain_marks_.set(current);
      const int next = link_[current][link_[current][0] == previous ? 1 : 0];
      previous = current;
      current = next;
    }
  }
  bool has_stray(int i, int t) {
    mark_chain(i, t);
    for (int q : side(i, t))
      if (!chain_marks_.has(q) && is_linked_state(state_[q])) return true;
    return false;
  }
  // Spec 2.6 step 3f: drop every linked point of A_p^t off p's chain, in list order.
  void drop_strays(int i, int t) {
    mark_chain(i, t);
    for (int q : side(i, t))
      if (!chain_marks_.has(q) && is_linked_state(state_[q])) drop_all(q);
  }

  // fix(p) of spec 2.4.
  void fix_slots(int i) {
    const int a = link_[i][0], b = link_[i][1];
    if ((a != kNone && !in_side(i, 0, a)) || (b != kNone && !in_side(i, 1, b))) std::swap(link_[i][0], link_[i][1]);
  }

  // target(p, t) of spec 2.4: the farthest point of A_p^t that reciprocates.
  int target(int i, int t) const {
    const auto s = side(i, t);
    for (auto it = s.rbegin(); it != s.rend(); ++it) {
      const int q = *it;
      if (state_[q] != State::Conform && state_[q] != State::Leaf && state_[q] != State::Manifold) continue;
      for (int j = 0; j < 2; ++j) {
        if (!in_side(q, j, i)) continue;
        if (state_[q] == State::Manifold ? (link_[q][0] == i || link_[q][1] == i)
                                         : (link_[q][j] == kNone || link_[q][j] == i))
          return q;
        break;  // i is on one side of q only
      }
    }
    return kNone;
  }

  // One cached stream per point, fetched in doubling batches: the list only ever grows. A
  // batch holds no more than the cap lets a list grow to (INITIAL takes two regardless); the
  // stream's entries do not depend on the batch size. Self comes first, hence the + 1.
  int batch_size(int wanted) const {
    int neighbors = std::max(2 * wanted, 8);
    if (max_neighbors_ > 0) neighbors = std::min(neighbors, std::max(max_neighbors_, wanted));
    return std::min(n_, neighbors + 1);
  }
  void fetch_stream(int i, int k) {
    nn_.k_nearest(p_[i], k, knn_buffer_);
    std::erase(knn_buffer_, i);
    streams_.assign(i, knn_buffer_);
  }

  // Spec 2.3: one growth step and refit; false if the list is exhausted (n - 1 neighbours or
  // the cap, spec 3), in which case nothing changes.
  bool grow(int i) {
    int wanted;
    if (state_[i] == State::Initial) {
      wanted = 2;
    } else {
      if (grown_[i] >= n_ - 1 || (max_neighbors_ > 0 && grown_[i] >= max_neighbors_)) return false;
      wanted = grown_[i] + 1;
    }
    if (streams_.size(i) < wanted) fetch_stream(i, batch_size(wanted));
    // Squared distances that overflow to infinity (coordinates beyond about 1e154) rank no
    // neighbour: the list ends there, as if exhausted.
    const std::span<const int> stream = streams_.list(i);
    if (static_cast<int>(stream.size()) < wanted) return false;
    for (int k = grown_[i]; k < wanted; ++k) refs_.push_back(stream[k], i);
    grown_[i] = wanted;
    // The list is ordered by this same squared distance (nearest_neighbors.h); the margin
    // only guards against a compiler evaluating it differently in the two places.
    reach_[i] = squared_distance(p_[i], p_[stream[wanted - 1]]) * (1 + 1e-9);
    refit(i);
    return true;
  }

  // Spec 2.1-2.2: circle through p and R_p, sides, and CONFORM / NONCONFORM.
  void refit(int i) {
    const int k = grown_[i];
    const std::span<const int> stream = streams_.list(i);
    fit_points_.resize(k + 1);
    fit_points_[0] = p_[i];
    for (int j = 0; j < k; ++j) fit_points_[j + 1] = p_[stream[j]];
    const FittedCircle circle = hyper_circle_fit(fit_points_);
    out_.centers[i] = circle.center;
    out_.radii[i] = circle.radius;
    out_.fits_on_a_line[i] = circle.on_a_line;
    // The normal by std::hypot: StretchDenoise moves vertices along it, bit for bit as before.
    const Point2 radial = p_[i] - circle.center;
    out_.normals[i] = (1.0 / norm(radial)) * radial;

    int& split = out_.side0_sizes[i];
    if (std::isfinite(circle.center.x) && std::isfinite(circle.center.y)) {
      // Stable sort of (p, R_p) by angle about the centre relative to p; p has angle 0 and
      // comes first in the list, so A^0 is exactly the negative angles (reversed) and A^1 the
      // rest. The previous fit's order (A^0 reversed, then A^1) is the guess to start from.
      for (int j = 0; j < k; ++j) list_position_[stream[j]] = j;
      order_.clear();
      const std::span<const int> previous = sides_.list(i);
      for (int j = split - 1; j >= 0; --j) order_.push_back(list_position_[previous[j]]);
      for (std::size_t j = split; j < previous.size(); ++j) order_.push_back(list_position_[previous[j]]);
      const int negative =
          sort_by_angle_about(circle.center, p_[i], std::span<const Point2>(fit_points_).subspan(1), order_);
      sides_.resize(i, k);
      const std::span<int> s = sides_.list(i);
      for (int j = 0; j < negative; ++j) s[negative - 1 - j] = stream[order_[j]];
      for (int j = negative; j < k; ++j) s[j] = stream[order_[j]];
      split = negative;
    } else {
      // A non-finite centre (degenerate branch of the fit with z = 0) gives the authors NaN
      // angles, which their ordered map keeps in list order after p: A^0 empty.
      sides_.assign(i, stream.first(k));
      split = 0;
    }

    bool conform = false;
    if (split > 0 && split < k) {
      auto project = [&](int q) { return circle.center + circle.radius * unit(p_[q] - circle.center); };
      const Point2 own = project(i), end0 = project(side(i, 0).back()), end1 = project(side(i, 1).back());
      // Compared squared: the same order as the distances, without their square roots.
      const double span = squared_distance(end0, end1);
      conform = span > squared_distance(own, end0) && span > squared_distance(own, end1);
    }
    state_[i] = conform ? State::Conform : State::Nonconform;
  }

  SavedFit save_fit(int i) {
    saved_neighborhood_.assign(sides_.list(i).begin(), sides_.list(i).end());
    return {out_.centers[i], out_.normals[i], out_.radii[i], out_.side0_sizes[i], out_.fits_on_a_line[i]};
  }
  void restore_fit(int i, const SavedFit& saved) {
    out_.centers[i] = saved.center;
    out_.normals[i] = saved.normal;
    out_.radii[i] = saved.radius;
    out_.fits_on_a_line[i] = saved.on_a_line;
    sides_.assign(i, saved_neighborhood_);
    out_.side0_sizes[i] = saved.side0_size;
  }

  void visit(int p);
  void exhausted(int p);
  bool inside_edge(int p);
  void corner(int p, State old);
  bool is_sharp(int p, const std::array<std::array<int, 2>, 2>& segments);
  bool consistent(int q);
  void propagate();

  // StretchDenoise's noise estimate (its spec 2.4): the largest radial residual of each stored
  // fit over the points it was fitted to, the site and its sides (they partition R_i as of the
  // stored fit, restored ones included).
  void collect_residuals() {
    for (int i = 0; i < n_; ++i) {
      const Point2 c = out_.centers[i];
      const double r = out_.radii[i];
      // std::max(residual, NaN) keeps residual: a NaN radius (degenerate fit, spec 2.1) gives 0.
      double residual = std::max(0.0, std::fabs(distance(p_[i], c) - r));
      for (int q : sides_.list(i)) residual = std::max(residual, std::fabs(distance(p_[q], c) - r));
      out_.residuals[i] = residual;
    }
  }

  // Spec 2.7: every link between MANIFOLD / LEAF / SHARP points, once.
  void collect_edges() {
    std::vector<Edge>& edges = out_.edges;
    for (int i = 0; i < n_; ++i) {
      if (!is_linked_state(state_[i])) continue;
      for (int q : link_[i])
        if (q != kNone && is_linked_state(state_[q])) edges.push_back(make_edge(i, q));
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  }

  std::span<const Point2> p_;
  int n_;
  int max_neighbors_;
  NearestNeighbors nn_;
  ListPool streams_;           // nearest neighbours of each point, self excluded
  std::vector<int> grown_;     // |R_i|: R_i is the prefix of streams_.list(i)
  std::vector<double> reach_;  // squared distance to the farthest of R_i, a little more
  ListPool sides_;             // A_i^0 then A_i^1, moved to out_.neighborhoods at the end
  ListPool refs_;              // Ref(q) = {i : q in R_i}
  FittedNeighborhoods out_;    // states, links, fits and side sizes as the spec names them
  std::vector<State>& state_ = out_.states;
  std::vector<std::array<int, 2>>& link_ = out_.links;
  OpenSet open_;
  AffectedSet affected_;
  Marks side_marks_, chain_marks_, other_marks_;
  std::vector<int> knn_buffer_, scratch_, saved_neighborhood_;
  std::vector<Point2> fit_points_;
  std::vector<int> list_position_;  // of a neighbour in the list of the site being refitted
  std::vector<int> order_;          // list positions sorted by angle
};

void FitConnect::visit(int p) {
  const State old = state_[p];
  const SavedFit saved = save_fit(p);

  // Step 1, leaf check: a CONFORM point with one link whose chain continues through two more
  // MANIFOLD points of the same side.
  int leaf_side = kNone;
  if (old == State::Conform && link_count(p) == 1) {
    const int t = link_[p][0] != kNone ? 0 : 1;
    bool follows = true;
    int previous = p, current = link_[p][t];
    for (int count = 0; follows && count < 2; ++count) {
      const int next = link_[current][1 - slot_of(current, previous)];
      follows = is(next, State::Manifold) && in_side(p, t, next);
      previous = current;
      current = next;
    }
    if (follows) leaf_side = t;
  }

  // Step 2: grow.
  if (!grow(p)) {
    exhausted(p);
  } else if (leaf_side != kNone && has_stray(p, leaf_side) && side(p, 1 - leaf_side).empty()) {
    restore_fit(p, saved);
    set_state(p, State::Leaf);
    affected_.insert(p);
    fix_slots(p);
  }

  // Step 3: a CONFORM point links to its reciprocating targets and cleans its overlaps. The
  // state is tested once; later sub-steps run even when 3c made p MANIFOLD, as in the code.
  if (state_[p] == State::Conform) {
    const int targets[2] = {target(p, 0), target(p, 1)};
    for (int t = 0; t < 2; ++t) {  // 3b
      const int q = link_[p][t];
      if (q != kNone && q != targets[0] && q != targets[1]) drop_one(p, t);
    }
    for (int q : targets) {  // 3c
      if (q == kNone || q == link_[p][0] || q == link_[p][1]) continue;
      const int t = link_[p][0] == kNone ? 0 : 1;
      link_[p][t] = q;
      const int qt = side_holding(q, p);
      link_[q][qt] = p;
      if (link_[p][1 - t] != kNone) {
        set_state(p, State::Manifold);
        affected_.insert(p);
      }
      if (link_[q][1 - qt] != kNone) {
        set_state(q, State::Manifold);
        affected_.insert(q);
      }
    }
    fix_slots(p);  // 3d

    for (int t = 0; t < 2; ++t) {  // 3e, redundancy
      const int q = link_[p][t];
      if (q == kNone) continue;
      other_marks_.clear();
      for (int x : side(p, t)) {
        if (x == q) break;
        if (open_.contains(x)) other_marks_.set(x);
      }
      scratch_.clear();
      for (int x : side(q, slot_of(q, p))) {
        if (x == p) break;
        if (open_.contains(x) && other_marks_.has(x)) scratch_.push_back(x);
      }
      std::sort(scratch_.begin(), scratch_.end());
      for (int x : scratch_) {
        if (state_[x] == State::Conform || state_[x] == State::Manifold || state_[x] == State::Sharp) drop_all(x);
        set_state(x, State::Eliminated);
      }
    }

    for (int t = 0; t < 2; ++t) {  // 3f, strays on p's side and on its partner's side
      if (link_[p][t] == kNone) continue;
      drop_strays(p, t);
      const int q = link_[p][t];
      if (q != kNone) drop_strays(q, slot_of(q, p));
    }

    if (link_count(p) == 1) {  // 3g, obstacle
      const int t = link_[p][0] != kNone ? 0 : 1;
      const int q = link_[p][t];
      for (int b : side(p, t)) {
        if (b == q) break;
        if (state_[b] != State::Conform) continue;
        if (link_count(b) == 1 && in_side(p, 1 - t, link_[b][link_[b][0] != kNone ? 0 : 1])) {
          drop_one(p, t);
          set_state(p, State::Eliminated);
        }
        break;
      }
    }
  }

  // Step 4: inside an edge.
  if ((state_[p] == State::Conform || state_[p] == State::Nonconform) && inside_edge(p)) {
    if (state_[p] == State::Nonconform && old == State::Conform) state_[p] = State::Conform;
    if (state_[p] == State::Conform) drop_all(p);
    set_state(p, State::Eliminated);
    affected_.insert(p);
  }

  // Step 5: corner.
  if (state_[p] == State::Nonconform) corner(p, old);

  propagate();  // step 6

  // Step 7: a CONFORM point whose growth made it NONCONFORM keeps its old fit and links.
  if (state_[p] == State::Nonconform && old == State::Conform) {
    restore_fit(p, saved);
    state_[p] = State::Conform;
  }
}

// Spec 2.6 step 2 when the list cannot grow.
void FitConnect::exhausted(int p) {
  if (state_[p] == State::Conform && link_count(p) > 0) {
    const int t = link_[p][0] != kNone ? 0 : 1;
    int lone = kNone, count = 0;
    for (int q : side(p, 1 - t))
      if (state_[q] == State::Nonconform) {
        lone = q;
        ++count;
      }
    if (count == 1) {
      link_[p][1 - t] = lone;
      link_[lone][side_holding(lone, p)] = p;
      set_state(lone, State::Leaf);
      affected_.insert(lone);
      set_state(p, State::Manifold);
    } else {
      set_state(p, State::Leaf);
    }
    affected_.insert(p);
    return;
  }
  if (state_[p] == State::Nonconform && (side(p, 0).empty() != side(p, 1).empty())) {
    const int t = side(p, 0).empty() ? 1 : 0;
    for (int q : side(p, t)) {
      if (state_[q] == State::Eliminated) continue;
      if (state_[q] == State::Conform && link_count(q) == 1) {
        link_[q][link_[q][0] == kNone ? 0 : 1] = p;
        link_[p][t] = q;
        set_state(q, State::Manifold);
        affected_.insert(q);
        set_state(p, State::Leaf);
        affected_.insert(p);
        return;
      }
      break;
    }
  }
  set_state(p, State::Eliminated);
}

// Spec 2.6 step 4: p has no link to a MANIFOLD point, and the first handled point on each
// side (handled: anything but ELIMINATED / INITIAL) is a MANIFOLD / SHARP pair linked to each
// other. Only the first handled point of A_p^0 can qualify, since every earlier entry must be
// unhandled; its partner is its slot-0 link if that is a MANIFOLD / SHARP point of A_p^1,
// else its slot-1 link under the same condition.
bool FitConnect::inside_edge(int p) {
  for (int q : link_[p])
    if (is(q, State::Manifold)) return false;
  auto first_handled = [&](int t) {
    for (int q : side(p, t))
      if (state_[q] != State::Eliminated && state_[q] != State::Initial) return q;
    return kNone;
  };
  const int m = first_handled(0);
  if (!is(m, State::Manifold) && !is(m, State::Sharp)) return false;
  other_marks_.clear();
  for (int q : side(p, 1))
    if (state_[q] == State::Manifold || state_[q] == State::Sharp) other_marks_.set(q);
  int partner = link_[m][0];
  if (!other_marks_.has(partner)) partner = other_marks_.has(link_[m][1]) ? link_[m][1] : kNone;
  return partner != kNone && partner == first_handled(1);
}

// Spec 2.6 step 5: trace the chains through MANIFOLD points of W = A_p^0 u A_p^1; with no
// through curve and exactly two open segments, try a SHARP corner at p.
void FitConnect::corner(int p, State old) {
  other_marks_.clear();  // W
  scratch_.clear();      // MANIFOLD points of W, ascending
  std::size_t w_size = 0;
  for (int t = 0; t < 2; ++t)
    for (int q : side(p, t)) {
      other_marks_.set(q);
      ++w_size;
      if (state_[q] == State::Manifold) scratch_.push_back(q);
    }
  std::sort(scratch_.begin(), scratch_.end());
  chain_marks_.clear();  // traced MANIFOLD points
  std::array<std::array<int, 2>, 2> segments{};  // {first point, exiting end}
  int open_segments = 0;
  bool through = false;
  for (int start : scratch_) {
    if (chain_marks_.has(start)) continue;
    chain_marks_.set(start);
    int end[2], exits[2];
    for (int d = 0; d < 2; ++d) {
      int previous = start, current = link_[start][d];
      end[d] = start;
      // Bounded by |W| steps: a walk on consistent links visits each point of W once.
      for (std::size_t steps = 0; current != kNone && current != start && other_marks_.has(current) && steps <= w_size;
           ++steps) {
        if (state_[current] == State::Manifold) chain_marks_.set(current);
        end[d] = current;
        const int next = link_[current][link_[current][0] == previous ? 1 : 0];
        previous = current;
        current = next;
      }
      exits[d] = current != kNone && current != p && current != start && !other_marks_.has(current);
    }
    if (exits[0] && exits[1]) {
      through = true;
    } else if (exits[0] || exits[1]) {
      if (open_segments < 2) segments[open_segments] = exits[0] ? std::array{end[1], end[0]} : std::array{end[0], end[1]};
      ++open_segments;
    }
  }
  if (through || open_segments != 2 || !is_sharp(p, segments)) return;

  if (old == State::Conform) {
    state_[p] = State::Conform;
    drop_all(p);
  }
  set_state(p, State::Sharp);
  affected_.insert(p);
  for (int k = 0; k < 2; ++k) {
    const int f = segments[k][0];
    if (state_[f] != State::Manifold) {
      set_state(f, State::Manifold);
      affected_.insert(f);
      link_[f][link_[f][0] == kNone ? 0 : 1] = p;
    }
    link_[p][k] = f;
  }
}

// The corner test of spec 2.6 step 5 (other_marks_ holds W).
bool FitConnect::is_sharp(int p, const std::array<std::array<int, 2>, 2>& segments) {
  const Point2 c = p_[p];
  double rho = 0.0;
  for (int t = 0; t < 2; ++t)
    for (int q : side(p, t)) rho = std::max(rho, length(p_[q] - c));
  double angle[2];
  for (int k = 0; k < 2; ++k) {
    const int e = segments[k][1];
    int outside = link_[e][0];
    if (outside == p || other_marks_.has(outside)) outside = link_[e][1];
    if (outside == kNone) return false;  // an exiting end always has its outside link
    const Point2 e0 = p_[e], v = p_[outside] - e0, ec = e0 - c;
    const double a = dot(v, v), b = 2 * dot(v, ec), cc = dot(ec, ec) - rho * rho;
    const double root = std::sqrt(b * b - 4 * a * cc);
    double t = (-b - root) / (2 * a);
    if (t < -1e-4 || t > 1 + 1e-4) t = (-b + root) / (2 * a);
    const Point2 hit = e0 + t * v;
    angle[k] = std::atan2(hit.y - c.y, hit.x - c.x) * 180.0 / std::numbers::pi;
  }
  double difference = std::fabs(angle[0] - angle[1]);
  if (difference > 180.0) difference = 360.0 - difference;
  if (difference > 60.0) return false;  // a NaN difference (no hit) passes, as in the code

  auto followable = [&](int q) {
    return state_[q] == State::Manifold || state_[q] == State::Conform || state_[q] == State::Leaf;
  };
  auto crossed = [&](int q) {
    if (!followable(q)) return false;
    for (int r : link_[q]) {
      if (r == kNone || !followable(r)) continue;
      for (const auto& segment : segments) {
        const int f = segment[0];
        if (q != f && r != f && segments_meet(c, p_[f], p_[q], p_[r])) return true;
      }
    }
    return false;
  };
  if (crossed(p)) return false;
  for (int t = 0; t < 2; ++t)
    for (int q : side(p, t))
      if (crossed(q)) return false;
  return true;
}

// Spec 2.6 step 6 for one referencing point q that has a link.
bool FitConnect::consistent(int q) {
  if (state_[q] == State::Sharp) return is(link_[q][0], State::Manifold) && is(link_[q][1], State::Manifold);
  for (int t = 0; t < 2; ++t) {
    const int r = link_[q][t];
    if (r != kNone && state_[r] != State::Sharp && !in_side(q, t, r)) return false;
  }
  for (int t = 0; t < 2; ++t) {
    const int r = link_[q][t];
    if (r != kNone && state_[r] != State::Sharp && has_stray(q, t)) return false;
  }
  return true;
}

void FitConnect::propagate() {
  // The sweep's cursor is the successor the removed point had when it was removed, as an
  // iterator into the authors' ordered set: points inserted between the two are visited by
  // the next sweep, points above the cursor by this one.
  while (!affected_.empty()) {
    for (int q = affected_.first(); q != kNone;) {
      const int next = affected_.erase_and_next(q);
      const std::span<int> refs = refs_.list(q);
      std::sort(refs.begin(), refs.end());  // Ref(q) is visited ascending
      for (int r : refs)
        if (link_count(r) > 0 && !consistent(r)) drop_all(r);
      q = next;
    }
  }
}

}  // namespace

FittedNeighborhoods connect_fitted_neighborhoods(std::span<const Point2> sites, int max_neighbors) {
  // Fewer than three sites: no neighbourhood of two, nothing to fit or link.
  if (sites.size() < 3) return unfitted(static_cast<int>(sites.size()), State::Eliminated);
  return FitConnect(sites, max_neighbors).run();
}

ParameterSpec max_neighbors_parameter() {
  return integer_parameter("max_neighbors", kDefaultMaxNeighbors, 0, 1000000000,
                           "growth cap: a sample with this many neighbours counts as exhausted; 0: unbounded, as the "
                           "authors' code");
}

FittedNeighborhoods connect_fitted_neighborhoods(std::span<const Point2> sites, const ParameterValues& params,
                                                 PhaseTimer& timer) {
  FittedNeighborhoods fits = connect_fitted_neighborhoods(sites, static_cast<int>(params.integer("max_neighbors")));
  timer.lap("connect");
  return fits;
}

}  // namespace curvebench
