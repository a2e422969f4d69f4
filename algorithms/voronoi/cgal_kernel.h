// CGAL types of the Voronoi layer, and its spatially sorted insertion. Included only by the
// .cpp files of algorithms/voronoi and of crust/, which triangulates the sites with their
// Voronoi vertices: the triangulation headers cost seconds and about a gigabyte to compile.
#pragma once

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <utility>
#include <vector>

namespace curvebench::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
using Point = Kernel::Point_2;
using IndexedPoints = std::vector<std::pair<Point, int>>;

// Inserts (point, index) pairs into `dt` in CGAL's spatial order, each from the face of the
// one before, sorting the pairs themselves (see the definition). A point equal to an earlier
// one keeps the earlier vertex, whose index it replaces unless its own is negative.
void insert_in_spatial_order(Delaunay& dt, IndexedPoints& indexed);

}  // namespace curvebench::cgal
