#include "generators/samplers.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/nearest_neighbors.h"
#include "generators/random.h"

namespace curvebench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Arc-length access to one dense curve. Positions u are arc lengths from vertex 0; on a
// closed curve they may run past one full turn (up to two), so that a walk starting
// anywhere never wraps; on an open one they lie in [0, total], vertex n-1 at total.
class ArcLength {
 public:
  explicit ArcLength(const DenseCurve& curve) : curve_(curve), start_(curve.points.size() + 1, 0.0) {
    const size_t n = curve.points.size();
    for (size_t i = 0; i < n; ++i) {
      const Point2 d = curve.points[(i + 1) % n] - curve.points[i];
      start_[i + 1] = start_[i] + std::sqrt(dot(d, d));
    }
    if (!curve.closed) start_.pop_back();  // no closing edge
  }

  bool closed() const { return curve_.closed; }
  double total() const { return start_.back(); }
  int vertex_count() const { return static_cast<int>(curve_.points.size()); }
  // Unrolled vertex j (vertex j mod n, in turn j / n) and its position.
  Point2 vertex(int j) const { return curve_.points[j % vertex_count()]; }
  double vertex_lfs(int j) const { return curve_.lfs[j % vertex_count()]; }
  double vertex_position(int j) const { return start_[j % vertex_count()] + (j / vertex_count()) * total(); }
  // The first unrolled vertex strictly after position u.
  int vertex_after(double u) const {
    const double turns = std::floor(u / total());
    const int j = static_cast<int>(std::upper_bound(start_.begin(), start_.end() - 1, u - turns * total()) - start_.begin());
    return j + static_cast<int>(turns) * vertex_count();
  }

  Point2 point_at(double u) const {
    const auto [i, f] = locate(u);
    return curve_.points[i] + f * (curve_.points[(i + 1) % vertex_count()] - curve_.points[i]);
  }
  double lfs_at(double u) const {
    const auto [i, f] = locate(u);
    return curve_.lfs[i] + f * (curve_.lfs[(i + 1) % vertex_count()] - curve_.lfs[i]);
  }
  // Outward unit normal of the polyline edge at u (the curve is counter-clockwise).
  Point2 normal_at(double u) const {
    const int i = locate(u).first;
    const Point2 d = curve_.points[(i + 1) % vertex_count()] - curve_.points[i];
    return (1.0 / norm(d)) * Point2{d.y, -d.x};
  }
  // Closed: the fraction of a turn in [0, 1); open: of the way from the first end, in [0, 1].
  double fraction_of_turn(double u) const {
    if (!closed()) return u / total();
    const double f = std::fmod(u, total()) / total();
    return f < 1.0 ? f : 0.0;
  }

 private:
  // The edge holding position u (of an open curve: the last edge holds its end) and how far along it.
  std::pair<int, double> locate(double u) const {
    if (closed()) u = std::fmod(u, total());
    const int i = std::clamp(static_cast<int>(std::upper_bound(start_.begin(), start_.end(), u) - start_.begin()) - 1, 0,
                             vertex_count() - (closed() ? 1 : 2));
    const double length = start_[i + 1] - start_[i];
    return {i, length > 0 ? std::clamp((u - start_[i]) / length, 0.0, 1.0) : 0.0};
  }

  const DenseCurve& curve_;
  std::vector<double> start_;  // arc length at each vertex; closed: start_[n] is the total length
};

// Epsilon-sampling of one curve by a forward walk; returns the sample positions in order.
class EpsilonWalk {
 public:
  EpsilonWalk(const ArcLength& arc, double epsilon) : arc_(arc), epsilon_(epsilon) {}

  // True if every vertex strictly between positions a < b is within epsilon*lfs of the
  // samples at a or b.
  bool covered_between(double a, double b) const {
    const Point2 pa = arc_.point_at(a), pb = arc_.point_at(b);
    for (int j = arc_.vertex_after(a); arc_.vertex_position(j) < b; ++j) {
      if (!covers(pa, j) && !covers(pb, j)) return false;
    }
    return true;
  }

  // The largest b in (a, limit] such that the samples at a and b cover every vertex between
  // them: candidates advance vertex by vertex, keeping the vertices that a does not cover,
  // and the first failing candidate is bisected against the last good one (both on the edge
  // into that vertex). A step always reaches at least the next vertex (nothing lies between).
  double largest_step_end(double a, double limit) {
    const Point2 pa = arc_.point_at(a);
    not_covered_by_a_.clear();
    double good = a;
    for (int j = arc_.vertex_after(a);; ++j) {
      const double candidate = std::min(arc_.vertex_position(j), limit);
      const double edge_start = arc_.vertex_position(j - 1), edge_length = arc_.vertex_position(j) - edge_start;
      const Point2 from = arc_.vertex(j - 1 + arc_.vertex_count()), edge = arc_.vertex(j) - from;
      auto on_edge = [&](double u) { return from + ((u - edge_start) / edge_length) * edge; };
      if (!covers_rest(on_edge(candidate))) {
        double bad = candidate;
        for (int iteration = 0; iteration < 24; ++iteration) {  // to 1e-7 of the edge
          const double middle = 0.5 * (good + bad);
          (covers_rest(on_edge(middle)) ? good : bad) = middle;
        }
        return good;
      }
      if (candidate >= limit) return limit;
      good = candidate;
      if (!covers(pa, j)) not_covered_by_a_.push_back(j);
    }
  }

 private:
  // Squared distances: cheaper than hypot and correctly rounded everywhere.
  bool covers(Point2 sample, int j) const {
    const Point2 d = arc_.vertex(j) - sample;
    const double reach = epsilon_ * arc_.vertex_lfs(j);
    return dot(d, d) <= reach * reach;
  }
  bool covers_rest(Point2 b) const {
    return std::all_of(not_covered_by_a_.begin(), not_covered_by_a_.end(), [&](int j) { return covers(b, j); });
  }

  const ArcLength& arc_;
  double epsilon_;
  std::vector<int> not_covered_by_a_;
};

// Appends samples of curve c at arc positions in walking order, and the cycle (closed
// curve) or path (open curve) through them.
void append_curve_samples(SampledScene& out, const ArcLength& arc, int c, const std::vector<double>& positions) {
  const int first = static_cast<int>(out.points.size());
  const int count = static_cast<int>(positions.size());
  for (const double u : positions) {
    out.points.push_back(arc.point_at(u));
    out.curve.push_back(c);
    out.parameter.push_back(arc.fraction_of_turn(u));
    out.lfs.push_back(arc.lfs_at(u));
  }
  for (int i = 0; i + (arc.closed() ? 0 : 1) < count; ++i) out.true_edges.push_back(make_edge(first + i, first + (i + 1) % count));
}

struct Box {
  Point2 low{HUGE_VAL, HUGE_VAL}, high{-HUGE_VAL, -HUGE_VAL};
};

Box bounding_box(const Scene& scene) {
  Box box;
  for (const auto& curve : scene.curves) {
    for (const Point2 p : curve.points) {
      box.low = {std::min(box.low.x, p.x), std::min(box.low.y, p.y)};
      box.high = {std::max(box.high.x, p.x), std::max(box.high.y, p.y)};
    }
  }
  return box;
}

}  // namespace

SampledScene epsilon_sample(const Scene& scene, double epsilon, std::uint64_t seed, double min_step_fraction) {
  if (!(epsilon > 0) || !std::isfinite(epsilon)) throw std::invalid_argument("epsilon must be a positive number");
  if (!(min_step_fraction > 0 && min_step_fraction <= 1)) throw std::invalid_argument("min_step_fraction must be in (0, 1]");
  Random random(seed);
  SampledScene out;
  for (int c = 0; c < static_cast<int>(scene.curves.size()); ++c) {
    const ArcLength arc(scene.curves[c]);
    EpsilonWalk walk(arc, epsilon);
    // A closed curve from a random start round to it; an open one from end to end, both ends sampled.
    const double start = arc.closed() ? arc.total() * random.uniform() : 0.0;
    const double end = start + arc.total();
    std::vector<double> positions{start};
    // Steps are capped at a third of a closed curve, half of an open one, so that every curve
    // gets at least three samples (a closed curve or a path with a middle to reconstruct),
    // however large epsilon is.
    const double longest_step = arc.total() / (arc.closed() ? 3 : 2);
    for (double a = start;;) {
      const double largest = walk.largest_step_end(a, std::min(a + longest_step, end));
      if (largest >= end) {
        if (!arc.closed()) positions.push_back(end);
        break;
      }
      double b = a + random.uniform(min_step_fraction, 1.0) * (largest - a);
      // Coverage is not monotone in b on a curved arc; fall back to the largest step.
      if (!walk.covered_between(a, b)) b = largest;
      positions.push_back(b);
      a = b;
    }
    append_curve_samples(out, arc, c, positions);
  }
  std::sort(out.true_edges.begin(), out.true_edges.end());
  return out;
}

SampledScene arc_length_sample(const Scene& scene, int count, bool random_positions, std::uint64_t seed) {
  const int curves = static_cast<int>(scene.curves.size());
  if (count < 3 * curves) throw std::invalid_argument("need at least 3 samples per curve (" + std::to_string(3 * curves) + ")");
  std::vector<ArcLength> arcs;
  double total = 0.0;
  for (const auto& curve : scene.curves) total += arcs.emplace_back(curve).total();
  // Largest-remainder shares of `count` in proportion to length, at least 3 each.
  std::vector<int> share(curves);
  int given = 0;
  for (int c = 0; c < curves; ++c) given += share[c] = std::max(3, static_cast<int>(count * arcs[c].total() / total));
  for (int c = 0; given < count; c = (c + 1) % curves) ++share[c], ++given;
  for (int c = curves - 1; given > count; c = (c + curves - 1) % curves) {
    if (share[c] > 3) --share[c], --given;
  }
  Random random(seed);
  SampledScene out;
  for (int c = 0; c < curves; ++c) {
    const double length = arcs[c].total();
    std::vector<double> positions(share[c]);
    if (!arcs[c].closed()) {
      // Both ends, and the others between them: at independent uniform positions or equally spaced.
      positions.front() = 0.0, positions.back() = length;
      for (int i = 1; i + 1 < share[c]; ++i) positions[i] = random_positions ? length * random.uniform() : length * i / (share[c] - 1);
      std::sort(positions.begin(), positions.end());
    } else if (random_positions) {
      for (double& u : positions) u = length * random.uniform();
      std::sort(positions.begin(), positions.end());
    } else {
      const double start = length * random.uniform();
      for (int i = 0; i < share[c]; ++i) positions[i] = start + length * i / share[c];
    }
    append_curve_samples(out, arcs[c], c, positions);
  }
  std::sort(out.true_edges.begin(), out.true_edges.end());
  return out;
}

void add_normal_noise(const Scene& scene, SampledScene& samples, double level, NoiseScale scale, std::uint64_t seed,
                      NoiseModel model) {
  if (!(level >= 0) || !std::isfinite(level)) throw std::invalid_argument("noise level must be a number >= 0");
  const Box box = bounding_box(scene);
  const double diagonal = distance(box.low, box.high);
  std::vector<ArcLength> arcs(scene.curves.begin(), scene.curves.end());
  Random random(seed);
  for (size_t i = 0; i < samples.points.size(); ++i) {
    const int c = samples.curve[i];
    if (c < 0) continue;
    const ArcLength& arc = arcs[c];
    const double size = level * (scale == NoiseScale::local_feature_size ? samples.lfs[i] : diagonal);
    const double u = samples.parameter[i] * arc.total();
    const double offset = model == NoiseModel::gaussian ? size * random.gaussian() : random.uniform(-size, size);
    samples.points[i] = samples.points[i] + offset * arc.normal_at(u);
  }
}

void add_outliers(const Scene& scene, SampledScene& samples, double fraction, std::uint64_t seed) {
  if (!(fraction >= 0) || !std::isfinite(fraction)) throw std::invalid_argument("outlier fraction must be a number >= 0");
  const long curve_samples = std::count_if(samples.curve.begin(), samples.curve.end(), [](int c) { return c >= 0; });
  const long count = std::lround(fraction * static_cast<double>(curve_samples));
  Box box = bounding_box(scene);
  const Point2 margin = 0.1 * (box.high - box.low);
  box.low = box.low - margin, box.high = box.high + margin;
  Random random(seed);
  for (long i = 0; i < count; ++i) {
    const double x = random.uniform(box.low.x, box.high.x);
    const double y = random.uniform(box.low.y, box.high.y);
    samples.points.push_back({x, y});
    samples.curve.push_back(-1);
    samples.parameter.push_back(kNaN);
    samples.lfs.push_back(kNaN);
  }
}

double achieved_epsilon(const Scene& scene, const SampledScene& samples) {
  std::vector<Point2> on_curves;
  for (size_t i = 0; i < samples.points.size(); ++i) {
    if (samples.curve[i] >= 0) on_curves.push_back(samples.points[i]);
  }
  if (on_curves.empty()) return std::numeric_limits<double>::infinity();
  const NearestNeighbors nearest(on_curves);
  double worst = 0.0;
  for (const auto& curve : scene.curves) {
    for (size_t i = 0; i < curve.points.size(); ++i) {
      const Point2 x = curve.points[i];
      worst = std::max(worst, distance(x, on_curves[nearest.nearest(x)]) / curve.lfs[i]);
    }
  }
  return worst;
}

}  // namespace curvebench
