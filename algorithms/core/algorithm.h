// The one interface every reconstruction algorithm implements, and the skeleton around it.
//
// An algorithm declares what it is (AlgorithmInfo: name, citation, outputs, typed
// parameters, the input it works on) and implements run(): distinct sites in, results over
// those sites out. Algorithm::reconstruct is the skeleton every call goes through: it
// checks the parameters, refuses input without a curve to find (no points, fewer than three
// distinct points, all collinear, a coordinate that is not finite), merges duplicates,
// builds the Delaunay/Voronoi layer when the algorithm asks for it, times the phases, checks
// the output and maps it back to input indices. An algorithm whose specification defines its
// output on collinear sites (an open curve along the line, or nothing) declares so and is
// given them.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/parameters.h"
#include "core/phase_timer.h"
#include "core/point.h"
#include "core/reconstruction.h"

namespace curvebench {

struct DelaunayVoronoi;

// Input an algorithm cannot reconstruct from (too few points, all collinear, bad parameter).
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum Output : unsigned {
  kCurve = 1u << 0,           // edges between input points
  kMedialAxis = 1u << 1,
  kDominantPoints = 1u << 2,
  kMovedPoints = 1u << 3,     // a new position for every input point (denoising methods)
  kNewCurve = 1u << 4,        // a curve on vertices of its own (approximating methods)
};

// What run() is given the sites as.
enum class SiteInput {
  kDistinctPoints,  // the distinct points, in order of first occurrence
  kDelaunay,        // the shared Delaunay/Voronoi layer of the distinct points (its numbering)
};

// What the skeleton does with sites that all lie on one line.
enum class CollinearInput {
  kRefused,        // InputError: they bound no closed curve
  kReconstructed,  // run() is given them (the Delaunay layer then has dimension 1, no triangle)
};

struct AlgorithmInfo {
  std::string name;       // lower case, words joined by '-': the folder's name
  std::string citation;   // one line: the method and where it was published
  unsigned outputs = 0;   // a bitwise or of Output values
  std::vector<ParameterSpec> parameters;
  SiteInput input = SiteInput::kDelaunay;
  CollinearInput collinear = CollinearInput::kRefused;
};

// The sites run() works on: distinct, at least three, finite, not all collinear unless the
// algorithm declares CollinearInput::kReconstructed.
struct Sites {
  std::span<const Point2> points;
  const DelaunayVoronoi* delaunay = nullptr;  // set when the algorithm asked for SiteInput::kDelaunay
};

// What run() produces, over site indices; the skeleton maps it to input indices.
struct SiteResult {
  std::optional<std::vector<Edge>> curve_edges;  // kCurve
  std::optional<std::vector<Point2>> moved_points;  // kMovedPoints: one per site
  std::optional<PolylineGraph> new_curve;          // kNewCurve
  std::optional<MedialAxis> medial_axis;           // kMedialAxis
  std::optional<std::vector<int>> dominant_points;  // kDominantPoints
};

class Algorithm {
 public:
  virtual ~Algorithm() = default;
  virtual const AlgorithmInfo& info() const = 0;
  // The algorithm's own work. `timer` has lapped "delaunay" already when the input is
  // SiteInput::kDelaunay; run() laps its own phases by name.
  virtual SiteResult run(const Sites& sites, const ParameterValues& parameters, PhaseTimer& timer) const = 0;

  const std::string& name() const { return info().name; }
  // The skeleton: `given` holds parameter names from info().parameters (missing ones take
  // their defaults). Throws InputError with a one-line message on bad input or parameters.
  Reconstruction reconstruct(std::span<const Point2> points, const ParameterAssignments& given) const;
};

}  // namespace curvebench
