// The "labeling-holes" algorithm: the paper's incremental Voronoi-vertex labeling
// (Peethambaran et al. 2019) extended to holes and nested curves, with its bridges between
// curves repaired and, as a last resort, shape-hull's curve (label_voronoi_vertices_with_holes.h);
// the rest is the paper's (labeling_algorithm.h).
#include "core/registry.h"
#include "labeling-holes/label_voronoi_vertices_with_holes.h"
#include "labeling/labeling_algorithm.h"

namespace curvebench {
namespace {

[[maybe_unused]] const bool registered = register_algorithm(make_labeling_algorithm(
    "labeling-holes",
    "Incremental Voronoi-vertex labeling (Peethambaran, Parakkat, Tagliasacchi, Wang, Muthuganapathy; CGF 2019), "
    "with walks inside the regions it cannot reach (holes and nested curves), its bridges between curves relabelled, "
    "and shape-hull's curve where it passes through every sample and the labels leave samples off one connected curve, "
    "or repaired them into a longer one",
    label_voronoi_vertices_with_holes));

}  // namespace
}  // namespace curvebench
