#include "core/nearest_neighbors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <nanoflann.hpp>

namespace curvebench {
namespace {

struct PointCloud {
  std::span<const Point2> points;
  std::size_t kdtree_get_point_count() const { return points.size(); }
  double kdtree_get_pt(std::size_t i, std::size_t dim) const { return dim == 0 ? points[i].x : points[i].y; }
  template <class BoundingBox>
  bool kdtree_get_bbox(BoundingBox&) const {
    return false;
  }
};

using KdTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud>, PointCloud, 2,
                                                   unsigned>;

}  // namespace

struct NearestNeighbors::Tree {
  explicit Tree(std::span<const Point2> points) : cloud{points}, index(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)) {}
  PointCloud cloud;
  KdTree index;
};

NearestNeighbors::NearestNeighbors(std::span<const Point2> points)
    : points_(points), tree_(std::make_unique<Tree>(points)) {}

NearestNeighbors::~NearestNeighbors() = default;

void NearestNeighbors::sort_by_distance(Point2 query, std::vector<int>& indices) const {
  const auto nearer = [&](int a, int b) {
    const double da = squared_distance(query, points_[a]), db = squared_distance(query, points_[b]);
    return da < db || (da == db && a < b);
  };
  // The tree's k nearest come ordered by distance, so often already in this order; the order
  // is strict, so sorting could only return the same.
  if (!std::is_sorted(indices.begin(), indices.end(), nearer)) std::sort(indices.begin(), indices.end(), nearer);
}

void NearestNeighbors::k_nearest(Point2 query, int k, std::vector<int>& out) const {
  out.clear();
  const int wanted = std::min(k, size());
  if (wanted <= 0) return;
  // One more than asked: if the last two tie, the tree's choice among equally distant points
  // at the boundary is arbitrary, so every point at that distance is gathered and ordered.
  const int asked = std::min(wanted + 1, size());
  // Scratch kept per thread: the queries of an algorithm's inner loop allocate nothing.
  thread_local std::vector<unsigned> found;
  thread_local std::vector<double> squared;
  found.resize(asked);
  squared.resize(asked);
  const double q[2] = {query.x, query.y};
  const std::size_t count = tree_->index.knnSearch(q, asked, found.data(), squared.data());
  out.assign(found.begin(), found.begin() + count);
  sort_by_distance(query, out);
  if (static_cast<int>(out.size()) > wanted &&
      squared_distance(query, points_[out[wanted]]) == squared_distance(query, points_[out[wanted - 1]])) {
    within_squared_distance(query, squared_distance(query, points_[out[wanted - 1]]), out);
  }
  // Fewer than `wanted` when the rest lie at a squared distance that overflows to infinity
  // (coordinates beyond about 1e154): the tree never ranks those.
  if (static_cast<int>(out.size()) > wanted) out.resize(wanted);
}

void NearestNeighbors::within_radius(Point2 query, double radius, std::vector<int>& out) const {
  out.clear();
  if (!(radius >= 0.0)) return;
  within_squared_distance(query, radius * radius, out);
}

void NearestNeighbors::within_squared_distance(Point2 query, double bound, std::vector<int>& out) const {
  out.clear();
  if (size() == 0) return;
  // nanoflann keeps squared distances strictly below its bound: widen it a little, then keep
  // exactly those within `bound` by our own comparison.
  std::vector<std::pair<unsigned, double>> matches;
  const double q[2] = {query.x, query.y};
  nanoflann::SearchParams params;
  params.sorted = false;
  tree_->index.radiusSearch(q, std::nextafter(bound * (1.0 + 1e-12), std::numeric_limits<double>::infinity()), matches, params);
  for (const auto& [index, squared] : matches) {
    if (squared_distance(query, points_[index]) <= bound) out.push_back(static_cast<int>(index));
  }
  sort_by_distance(query, out);
}

int NearestNeighbors::nearest(Point2 query) const {
  std::vector<int> out;
  k_nearest(query, 1, out);
  return out.empty() ? -1 : out[0];
}

}  // namespace curvebench
