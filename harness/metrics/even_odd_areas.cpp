// The only file of harness/ that includes CGAL's arrangement headers (slow to compile).
#include "metrics/even_odd_areas.h"

#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <array>
#include <numeric>
#include <vector>

namespace curvebench {
namespace {

// How many segments of each input set cover an arrangement edge.
using Coverage = std::array<int, 2>;

struct AddCoverage {
  Coverage operator()(const Coverage& a, const Coverage& b) const { return {a[0] + b[0], a[1] + b[1]}; }
};

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SegmentTraits = CGAL::Arr_segment_traits_2<Kernel>;
using Traits = CGAL::Arr_curve_data_traits_2<SegmentTraits, Coverage, AddCoverage>;
using FaceIndexDcel = CGAL::Arr_face_extended_dcel<Traits, int>;
using Arrangement = CGAL::Arrangement_2<Traits, FaceIndexDcel>;

class DisjointSets {
 public:
  explicit DisjointSets(int size) : parent_(size) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(int a, int b) { parent_[find(a)] = find(b); }

 private:
  std::vector<int> parent_;
};

// Steps 2 and 3 of the header for input set `set`: whether each arrangement face lies in
// its even-odd region.
std::vector<bool> faces_inside(const Arrangement& arrangement, int set, int face_count) {
  auto covered_oddly = [set](const Arrangement::Edge_const_iterator& e) { return e->curve().data()[set] % 2 == 1; };
  DisjointSets faces_of_set(face_count);  // arrangement faces merged into the faces of `set` alone
  for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    if (!covered_oddly(e)) faces_of_set.unite(e->face()->data(), e->twin()->face()->data());
  }
  std::vector<std::vector<int>> neighbours(face_count);
  for (auto e = arrangement.edges_begin(); e != arrangement.edges_end(); ++e) {
    if (!covered_oddly(e)) continue;
    const int a = faces_of_set.find(e->face()->data());
    const int b = faces_of_set.find(e->twin()->face()->data());
    if (a == b) continue;  // bounds nothing
    neighbours[a].push_back(b);
    neighbours[b].push_back(a);
  }
  std::vector<int> depth(face_count, -1);
  const int outside = faces_of_set.find(arrangement.unbounded_face()->data());
  std::vector<int> frontier{outside};
  depth[outside] = 0;
  for (size_t next = 0; next < frontier.size(); ++next) {
    const int face = frontier[next];
    for (int neighbour : neighbours[face]) {
      if (depth[neighbour] < 0) {
        depth[neighbour] = depth[face] + 1;
        frontier.push_back(neighbour);
      }
    }
  }
  std::vector<bool> inside(face_count);
  for (int f = 0; f < face_count; ++f) inside[f] = depth[faces_of_set.find(f)] % 2 == 1;
  return inside;
}

// Twice the signed area enclosed by one connected boundary component of a face.
double twice_signed_area(Arrangement::Ccb_halfedge_const_circulator first) {
  double sum = 0.0;
  auto he = first;
  do {
    const auto& p = he->source()->point();
    const auto& q = he->target()->point();
    sum += CGAL::to_double(p.x()) * CGAL::to_double(q.y()) - CGAL::to_double(q.x()) * CGAL::to_double(p.y());
  } while (++he != first);
  return sum;
}

// A bounded face's outer boundary runs counter-clockwise and its holes clockwise, so the
// signed sum over all of them is the face's area; an antenna inside it cancels out.
double face_area(const Arrangement::Face_const_handle& face) {
  double twice_area = twice_signed_area(face->outer_ccb());
  for (auto hole = face->inner_ccbs_begin(); hole != face->inner_ccbs_end(); ++hole) twice_area += twice_signed_area(*hole);
  return 0.5 * twice_area;
}

}  // namespace

EvenOddAreas even_odd_areas(std::span<const Segment2> first, std::span<const Segment2> second) {
  require_finite(first, "even-odd areas: the first segment set");
  require_finite(second, "even-odd areas: the second segment set");
  std::vector<Traits::Curve_2> curves;
  curves.reserve(first.size() + second.size());
  auto add = [&curves](std::span<const Segment2> segments, Coverage coverage) {
    for (const Segment2& s : segments) {
      if (s.source == s.target) continue;  // a point bounds no area
      curves.emplace_back(SegmentTraits::Curve_2(Kernel::Point_2(s.source.x, s.source.y),
                                                 Kernel::Point_2(s.target.x, s.target.y)),
                          coverage);
    }
  };
  add(first, {1, 0});
  add(second, {0, 1});

  Arrangement arrangement;
  CGAL::insert(arrangement, curves.begin(), curves.end());
  int face_count = 0;
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) f->set_data(face_count++);

  const std::vector<bool> in_first = faces_inside(arrangement, 0, face_count);
  const std::vector<bool> in_second = faces_inside(arrangement, 1, face_count);
  EvenOddAreas areas;
  for (auto f = arrangement.faces_begin(); f != arrangement.faces_end(); ++f) {
    if (f->is_unbounded()) continue;
    const int index = f->data();
    if (!in_first[index] && !in_second[index]) continue;
    const double area = face_area(f);
    if (in_first[index]) areas.first += area;
    if (in_second[index]) areas.second += area;
    if (in_first[index] != in_second[index]) areas.symmetric_difference += area;
  }
  return areas;
}

}  // namespace curvebench
