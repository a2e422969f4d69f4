// A labeling algorithm behind the interface: the Delaunay layer's Voronoi vertices labelled
// inner or outer by `label`, then the curve, the dominant points and the interior medial axis
// read off the labels (extract_shapes.h), timed as the phases "labeling" and "extract". The
// paper's algorithm (labeling.cpp) and its extensions register themselves through it.
#pragma once

#include <memory>
#include <string>

#include "core/algorithm.h"
#include "labeling/label_voronoi_vertices.h"

namespace curvebench {

using LabelFunction = VoronoiLabels (*)(const DelaunayVoronoi&);

std::unique_ptr<Algorithm> make_labeling_algorithm(std::string name, std::string citation, LabelFunction label);

}  // namespace curvebench
