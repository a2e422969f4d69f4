// Samplers: point sets drawn from a Scene, with the ground truth of where each came from.
#pragma once

#include <cstdint>
#include <vector>

#include "core/point.h"
#include "generators/closed_curves.h"

namespace curvebench {

struct SampledScene {
  std::vector<Point2> points;
  std::vector<int> curve;          // curve index of each point, -1 for an outlier
  std::vector<double> parameter;   // arc-length fraction in [0, 1) along its curve, NaN for an outlier
  std::vector<double> lfs;         // local feature size of the curve where the sample was drawn, NaN for an outlier
  std::vector<Edge> true_edges;    // consecutive samples along each curve (the correct reconstruction)
};

// An epsilon-sample in the sense of Definition 4 (every curve point x within epsilon*lfs(x)
// of a sample), placed at random so that density varies: each step along the curve is a
// random fraction in [min_step_fraction, 1] of the largest step that keeps the condition.
SampledScene epsilon_sample(const Scene& scene, double epsilon, std::uint64_t seed, double min_step_fraction = 0.5);

// The smallest epsilon for which `samples` epsilon-samples `scene`, measured over the dense
// vertices (the certificate the tests check).
double achieved_epsilon(const Scene& scene, const SampledScene& samples);

// `count` samples along arc length, shared among the curves in proportion to their length
// (at least 3 each): equally spaced from a random start on each curve, or, with
// `random_positions`, at independent uniform positions (then sorted along the curve).
SampledScene arc_length_sample(const Scene& scene, int count, bool random_positions, std::uint64_t seed);

enum class NoiseScale { local_feature_size, bounding_box_diagonal };
enum class NoiseModel { gaussian, uniform };

// Moves every curve sample along the curve normal at its parameter by a random amount whose
// size w is `level` times the local feature size there, or times the diagonal of the
// scene's bounding box: Gaussian of standard deviation w, or uniform in [-w, w] (a band of
// half-width w, the noise model of denoising guarantees such as StretchDenoise's). The truth
// (curve, parameter, lfs, edges) stays as drawn. Throws std::invalid_argument unless level
// is a finite number >= 0.
void add_normal_noise(const Scene& scene, SampledScene& samples, double level, NoiseScale scale, std::uint64_t seed,
                      NoiseModel model = NoiseModel::gaussian);

// Appends round(fraction * number of curve samples) outliers, uniform in the scene's
// bounding box grown by 10% on every side (curve -1, parameter and lfs NaN, no edges).
// Throws std::invalid_argument unless fraction is a finite number >= 0.
void add_outliers(const Scene& scene, SampledScene& samples, double fraction, std::uint64_t seed);

}  // namespace curvebench
