// Every metric (README.md, "Metrics") of one reconstruction against its ground truth.
//
// In:  the ground truth, the input points it describes (file order, one per truth sample)
//      and a reconstruction of those points.
// Out: the metrics of each output the reconstruction has; those of an output it lacks stay
//      absent. (The oracle L2 error, which needs no reconstruction, is in oracle_l2_error.h.)
//   curve          l2_error        even-odd region of the edges vs the true region (l2_error.h);
//                                  NaN (written as null) when a true curve is open
//                  hausdorff       Hausdorff distance between the true dense curves and the
//                                  edges, over the true curves' bounding-box diagonal, exact to
//                                  10^-4 of the diagonal (hausdorff_distance.h); infinite when
//                                  the reconstruction has no edge
//                  curve_recall    share of the true curves' length within a tolerance of the
//                                  edges (curve_recall.h; the tolerance below), and that
//                                  tolerance over the diagonal
//                  topology        manifold, components, closed components (curve_topology.h),
//                                  compared with true_curves
//                  vertex_distance mean and largest distance from the curve's vertices (the
//                                  ends of its edges, where a denoising method moved them) to
//                                  the true curves, over the diagonal (distance_to_curve.h)
//                  edges           precision, recall, F1, exactness against the true adjacency
//                                  (edge_agreement.h); only when the edges join input points
//                                  (interpolating and denoising methods), absent for a curve
//                                  on vertices of its own (metrics_json writes null then)
//   medial axis    medial_axis_hausdorff  Hausdorff distance between the true and the
//                                  reconstructed interior medial axes (isolated vertices count
//                                  as points), over the same diagonal; infinite if either is
//                                  empty; absent when a true curve is open (it has no interior)
//   dominant points  count, CR, ISE, FOM over the samples (dominant_point_quality.h)
// Throws std::invalid_argument if the point count differs from the truth's sample count or a
// reconstructed coordinate is not finite (NaN, infinite), and
// std::out_of_range if an edge of the reconstruction names a vertex it does not have.
#pragma once

#include <optional>
#include <span>

#include "core/reconstruction.h"
#include "io/ground_truth_json.h"
#include "metrics/curve_topology.h"
#include "metrics/distance_to_curve.h"
#include "metrics/dominant_point_quality.h"
#include "metrics/edge_agreement.h"

namespace curvebench {

// curve_recall's tolerance: the larger of this fraction of the diagonal of the true curves'
// bounding box (the scale of hausdorff, defined on every input: local feature size vanishes
// at the corners of polygons and outlines) and the Hausdorff distance between the true
// curves and the samples joined in true order (what the sampling itself forces on any
// interpolating reconstruction: the sagitta of the chords of a sparse sample, the noise of a
// noisy one; plus the 10^-4 of the diagonal it may fall short by), so that the true
// adjacency always scores 1.
inline constexpr double kCurveRecallToleranceOverDiagonal = 0.01;

struct ReconstructionMetrics {
  int true_curves = 0;
  std::optional<double> l2_error;  // NaN when a true curve is open
  std::optional<double> hausdorff;  // over the diagonal; may be infinite
  std::optional<double> curve_recall;  // share of the true length within the tolerance below
  std::optional<double> curve_recall_tolerance;  // over the diagonal
  std::optional<DistanceToCurve> vertex_distance;  // over the diagonal
  std::optional<CurveTopology> topology;
  std::optional<EdgeAgreement> edges;
  std::optional<double> medial_axis_hausdorff;  // over the diagonal; may be infinite
  std::optional<DominantPointQuality> dominant_points;
};

ReconstructionMetrics evaluate_reconstruction(const GroundTruth& truth, std::span<const Point2> points,
                                              const Reconstruction& reconstruction);

}  // namespace curvebench
