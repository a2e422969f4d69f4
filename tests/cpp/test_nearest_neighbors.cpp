// core/nearest_neighbors.h and core/z_order.h: the ranking every kNN-based method relies on.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <vector>

#include "core/nearest_neighbors.h"
#include "core/z_order.h"

namespace curvebench {
namespace {

TEST(NearestNeighbors, RanksByDistanceThenByIndex) {
  // Four points at distance 1 from the query and one at distance 2.
  const std::vector<Point2> points = {{2, 0}, {0, 1}, {1, 0}, {0, -1}, {-1, 0}};
  const NearestNeighbors index(points);
  std::vector<int> out;
  index.k_nearest({0, 0}, 3, out);
  EXPECT_EQ(out, (std::vector<int>{1, 2, 3}));
  index.k_nearest({0, 0}, 10, out);
  EXPECT_EQ(out, (std::vector<int>{1, 2, 3, 4, 0}));
}

TEST(NearestNeighbors, PointsBeyondAnOverflowingDistanceAreNotReturned) {
  // From (1e200, 0) the squared distance to the origin overflows to infinity: the query gets
  // the two points it can rank, and no made-up third.
  const std::vector<Point2> points = {{0, 0}, {1e200, 0}, {1e200, 1e150}};
  const NearestNeighbors index(points);
  std::vector<int> out;
  index.k_nearest(points[1], 3, out);
  EXPECT_EQ(out, (std::vector<int>{1, 2}));
}

TEST(ZOrder, IsAPermutationThatKeepsNearbySitesTogether) {
  std::vector<Point2> points;
  for (int i = 0; i < 1000; ++i) points.push_back({(i * 7919) % 1000 / 1000.0, (i * 104729) % 997 / 997.0});
  std::vector<int> order = z_order(points);
  std::vector<int> sorted_order = order;
  std::sort(sorted_order.begin(), sorted_order.end());
  std::vector<int> identity(points.size());
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_EQ(sorted_order, identity);
  // Consecutive sites in Z order are near: their mean step is far below the mean step of the
  // input order, which jumps across the square.
  auto mean_step = [&](const std::vector<int>& sequence) {
    double total = 0;
    for (std::size_t i = 1; i < sequence.size(); ++i) total += distance(points[sequence[i - 1]], points[sequence[i]]);
    return total / (sequence.size() - 1);
  };
  EXPECT_LT(mean_step(order), 0.25 * mean_step(identity));
  EXPECT_TRUE(z_order(std::vector<Point2>{}).empty());
  EXPECT_EQ(z_order(std::vector<Point2>(3, Point2{1, 1})), (std::vector<int>{0, 1, 2}));
}

}  // namespace
}  // namespace curvebench
