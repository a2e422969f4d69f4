// One generated input: a curve family (or an imported outline), a sampler, noise and
// outliers, all from one seed.
//
// In:  the settings (generator_settings.h).
// Out: the points, and their ground truth: the settings record (generator_settings_to_json),
//      the true curves with local feature size, each sample's curve, parameter and lfs
//      (outliers have none), the correct adjacency, the true interior medial axis (exact
//      where the family knows it) and the dominant points.
// Throws std::runtime_error "--option: why" for a setting out of its range or an unknown
// family, sampler or noise scale, and what the family's builder or the outline reader
// throws.
#pragma once

#include <vector>

#include "core/point.h"
#include "generators/generator_settings.h"
#include "generators/ground_truth.h"

namespace curvebench {

struct GeneratedInput {
  std::vector<Point2> points;
  GroundTruth truth;
};

GeneratedInput generate(const GeneratorSettings& settings);

}  // namespace curvebench
