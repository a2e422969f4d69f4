// The extension module `curvebench._curvebench`: a thin layer over the library the command
// line uses (the registry and Algorithm::reconstruct, generate, the file formats of harness/io
// and evaluation_to_json). The public API, with its argument checks, is curvebench/__init__.py.
//
// Arrays: points come in as C-contiguous float64 (n, 2) arrays and are read in place, never
// copied; every array a result hands out is a read-only view of the C++ object's own vectors,
// which the view keeps alive. Errors of the library (bad input, bad parameter, a malformed
// file) are ValueError with the library's one-line message.
#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/pair.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "core/registry.h"
#include "generators/generate.h"
#include "io/evaluation_json.h"
#include "io/generated_input_files.h"
#include "io/ground_truth_json.h"
#include "io/parameters_json.h"
#include "io/points_file.h"
#include "io/reconstruction_json.h"

namespace nb = nanobind;

namespace curvebench {
namespace {

// Points are read in place as Point2 records: two doubles, nothing else.
static_assert(sizeof(Point2) == 2 * sizeof(double) && std::is_standard_layout_v<Point2>);
static_assert(sizeof(Edge) == 2 * sizeof(int));

// Points as the library reads them: C-contiguous float64 (n, 2), in place.
using PointsArray = nb::ndarray<const double, nb::shape<-1, 2>, nb::c_contig, nb::device::cpu>;
// A writable numpy array that owns its points (read from a file, generated).
using OwnedPoints = nb::ndarray<nb::numpy, double, nb::shape<-1, 2>, nb::c_contig>;
// Read-only numpy views of vectors that a Python object owns.
using PointsView = nb::ndarray<nb::numpy, const double, nb::shape<-1, 2>, nb::c_contig>;
using EdgesView = nb::ndarray<nb::numpy, const int, nb::shape<-1, 2>, nb::c_contig>;
template <typename T>
using VectorView = nb::ndarray<nb::numpy, const T, nb::shape<-1>, nb::c_contig>;

std::span<const Point2> point_span(const PointsArray& array) {
  return {reinterpret_cast<const Point2*>(array.data()), array.shape(0)};
}

OwnedPoints owned_points_array(std::vector<Point2> points) {
  auto* owned = new std::vector<Point2>(std::move(points));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<Point2>*>(p); });
  return OwnedPoints(reinterpret_cast<double*>(owned->data()), {owned->size(), 2}, owner);
}

PointsView points_view(const std::vector<Point2>& points, nb::handle owner) {
  return PointsView(reinterpret_cast<const double*>(points.data()), {points.size(), 2}, owner);
}
EdgesView edges_view(const std::vector<Edge>& edges, nb::handle owner) {
  return EdgesView(reinterpret_cast<const int*>(edges.data()), {edges.size(), 2}, owner);
}
template <typename T>
VectorView<T> vector_view(const std::vector<T>& values, nb::handle owner) {
  return VectorView<T>(values.data(), {values.size()}, owner);
}

// Runs `body`, turning the library's errors (InputError, PointsFileError, the file readers'
// and the generators' std::runtime_error, the metrics' invalid_argument and out_of_range)
// into ValueError with the same message; an algorithm's logic_error stays a RuntimeError.
template <typename Body>
auto library_call(Body&& body) {
  try {
    return body();
  } catch (const nb::builtin_exception&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw nb::value_error(e.what());
  } catch (const std::invalid_argument& e) {
    throw nb::value_error(e.what());
  } catch (const std::out_of_range& e) {
    throw nb::value_error(e.what());
  }
}

template <typename Json>
Json parse_json_text(const std::string& text, const std::string& what) {
  try {
    return Json::parse(text);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(what + ": not JSON: " + e.what());
  }
}

// A reconstruction with what it was made from: the algorithm, its resolved parameters and
// the input points it indexes (the caller's array itself, or points read from a file).
struct PyReconstruction {
  std::string algorithm;
  ParameterValues parameters;
  PointsArray points;
  std::string input_path;  // the points file it was read with, else empty
  Reconstruction result;
};

PyReconstruction reconstruct(const PointsArray& points, const std::string& algorithm_name, const std::string& parameters_json) {
  return library_call([&] {
    const Algorithm& algorithm = find_algorithm(algorithm_name);
    const ParameterAssignments given =
        parameters_from_json(parse_json_text<nlohmann::json>(parameters_json, "parameters"), algorithm.name());
    const ParameterValues resolved = resolve_parameters(algorithm.name(), algorithm.info().parameters, given);
    Reconstruction result;
    {
      nb::gil_scoped_release no_gil;
      result = algorithm.reconstruct(point_span(points), given);
    }
    return PyReconstruction{algorithm.name(), resolved, points, "", std::move(result)};
  });
}

std::string reconstruction_json_text(const PyReconstruction& r, const std::string& points_path) {
  return reconstruction_to_json(r.algorithm, r.parameters, {points_path, static_cast<int>(r.points.shape(0))}, r.result)
             .dump(2) +
         "\n";
}

// `points` given: the reconstruction indexes them; else the points file its JSON names.
PyReconstruction read_reconstruction(const std::string& path, std::optional<PointsArray> points) {
  return library_call([&] {
    ReconstructionFile file = read_reconstruction_file(path);
    const std::string algorithm = file.json.value("algorithm", "");
    const Algorithm& found = find_algorithm(algorithm);
    const ParameterValues parameters = resolve_parameters(
        algorithm, found.info().parameters, parameters_from_json(file.json.value("parameters", nlohmann::json::object()), path));
    std::string input_path;
    if (!points) {
      input_path = file.json.contains("input") ? file.json["input"].value("path", "") : "";
      if (input_path.empty()) throw std::runtime_error(path + ": names no input points file; give points");
      points = PointsArray(owned_points_array(read_points_file(input_path)));
    }
    return PyReconstruction{algorithm, parameters, *points, input_path, std::move(file.reconstruction)};
  });
}

nb::dict parameters_dict(const ParameterValues& values) {
  nb::dict dict;
  for (const auto& [name, value] : values.all()) {
    std::visit([&](const auto& v) { dict[name.c_str()] = v; }, value);
  }
  return dict;
}

std::pair<OwnedPoints, GroundTruth> generate_input(const std::string& settings_json) {
  return library_call([&] {
    GeneratedInput input = generate(generator_settings_from_json(parse_json_text<nlohmann::ordered_json>(settings_json, "settings")));
    return std::make_pair(owned_points_array(std::move(input.points)), std::move(input.truth));
  });
}

}  // namespace
}  // namespace curvebench

NB_MODULE(_curvebench, m) {
  using namespace curvebench;
  m.doc() = "The curvebench C++ library: the registry, reconstruction, generators, file formats and metrics.";

  m.def("catalogue_json", [] { return algorithm_catalogue(all_algorithms()).dump(2); },
        "The catalogue `curvebench list --json` prints, as JSON text.");

  nb::class_<MedialAxis>(m, "MedialAxis", "An interior medial axis: vertices, the radii of their empty disks, edges between vertices.")
      .def_prop_ro("vertices", [](const MedialAxis& a) { return points_view(a.vertices, nb::find(a)); }, "(k, 2) float64")
      .def_prop_ro("radii", [](const MedialAxis& a) { return vector_view(a.radii, nb::find(a)); }, "(k,) float64")
      .def_prop_ro("edges", [](const MedialAxis& a) { return edges_view(a.edges, nb::find(a)); }, "(e, 2) int32, indices into vertices");

  nb::class_<PyReconstruction>(m, "Reconstruction",
                               "What curvebench.reconstruct returns; arrays are read-only views, absent outputs None.")
      .def_ro("algorithm", &PyReconstruction::algorithm)
      .def_prop_ro("parameters", [](const PyReconstruction& r) { return parameters_dict(r.parameters); },
                   "Every parameter, defaults included, in its type.")
      .def_prop_ro("points", [](const PyReconstruction& r) { return PointsView(r.points); }, nb::rv_policy::reference,
              "The (n, 2) float64 input points the indices refer to (the caller's array when it was C-contiguous float64).")
      .def_ro("input_path", &PyReconstruction::input_path, "The points file it was read with, else ''.")
      .def_prop_ro("distinct_points", [](const PyReconstruction& r) { return r.result.distinct_points; })
      .def_prop_ro(
          "edges",
          [](const PyReconstruction& r) -> std::optional<EdgesView> {
            if (r.result.curve_edges) return edges_view(*r.result.curve_edges, nb::find(r));
            if (r.result.new_curve) return edges_view(r.result.new_curve->edges, nb::find(r));
            return std::nullopt;
          },
          "(m, 2) int32 curve edges: input indices, or indices into `vertices` when the method places its own.")
      .def_prop_ro(
          "positions",
          [](const PyReconstruction& r) -> std::optional<PointsView> {
            if (!r.result.moved_points) return std::nullopt;
            return points_view(*r.result.moved_points, nb::find(r));
          },
          "(n, 2) float64: a denoising method's new position of every input point, which the edges join.")
      .def_prop_ro(
          "vertices",
          [](const PyReconstruction& r) -> std::optional<PointsView> {
            if (!r.result.new_curve) return std::nullopt;
            return points_view(r.result.new_curve->vertices, nb::find(r));
          },
          "(k, 2) float64: the vertices of a method that places its own, which the edges index.")
      .def_prop_ro(
          "medial_axis",
          [](const PyReconstruction& r) -> const MedialAxis* { return r.result.medial_axis ? &*r.result.medial_axis : nullptr; },
          nb::rv_policy::reference_internal)
      .def_prop_ro(
          "dominant_points",
          [](const PyReconstruction& r) -> std::optional<VectorView<int>> {
            if (!r.result.dominant_points) return std::nullopt;
            return vector_view(*r.result.dominant_points, nb::find(r));
          }, "(d,) int32 input indices, ascending.")
      .def_prop_ro(
          "timing_ms",
          [](const PyReconstruction& r) {
            nb::dict timing;
            for (const auto& [phase, ms] : r.result.timing_ms) timing[phase.c_str()] = ms;
            return timing;
          }, "Milliseconds per phase, in order, then 'total'.")
      .def(
          "to_json", [](const PyReconstruction& r, const std::string& points_path) { return reconstruction_json_text(r, points_path); },
          nb::arg("points_path") = "", "The reconstruction JSON `curvebench reconstruct` writes; `points_path` is its input path.");

  nb::class_<GroundTruth>(m, "GroundTruth", "The ground truth of a generated input (harness/io/ground_truth_json.h).")
      .def_prop_ro("edges", [](const GroundTruth& t) { return edges_view(t.edges, nb::find(t)); }, "(e, 2) int32: the true adjacency between samples.")
      .def_prop_ro(
          "curves",
          [](const GroundTruth& t) {
            std::vector<PointsView> curves;
            for (const auto& curve : t.curves) curves.push_back(points_view(curve.vertices, nb::find(t)));
            return curves;
          }, "The true curves as dense polylines.")
      .def_prop_ro(
          "closed",
          [](const GroundTruth& t) {
            nb::list closed;
            for (const auto& curve : t.curves) closed.append(curve.closed);
            return closed;
          },
          "For each true curve, whether it is closed.")
      .def("to_json", [](const GroundTruth& t) { return ground_truth_to_json(t).dump() + "\n"; },
           "The ground-truth JSON `curvebench generate --truth` writes.");

  m.def("reconstruct", &reconstruct, nb::arg("points").noconvert(), nb::arg("algorithm"), nb::arg("parameters_json"),
        "Algorithm::reconstruct on the points in place (the GIL is released while it runs).");
  m.def("generate", &generate_input, nb::arg("settings_json"),
        "generate() of the generator library; settings as a sweep configuration's input object.");
  m.def(
      "evaluate",
      [](const GroundTruth& truth, const PyReconstruction& r, const PointsArray& points) {
        return library_call([&] {
          std::string text;
          {
            nb::gil_scoped_release no_gil;
            text = evaluation_to_json(truth, point_span(points), r.result).dump();
          }
          return text;
        });
      },
      nb::arg("truth"), nb::arg("reconstruction"), nb::arg("points").noconvert(),
      "evaluation_to_json: the oracle L2 error and the metrics, as JSON text.");
  m.def("read_points", [](const std::string& path) { return library_call([&] { return owned_points_array(read_points_file(path)); }); },
        nb::arg("path"));
  m.def(
      "write_points",
      [](const std::string& path, const PointsArray& points, const std::string& header) {
        library_call([&] {
          const auto span = point_span(points);
          write_points_file(path, std::vector<Point2>(span.begin(), span.end()), header);
          return 0;
        });
      },
      nb::arg("path"), nb::arg("points").noconvert(), nb::arg("header") = "");
  m.def("read_reconstruction", &read_reconstruction, nb::arg("path"), nb::arg("points").noconvert() = nb::none());
  m.def(
      "write_reconstruction",
      [](const std::string& path, const PyReconstruction& r, const std::string& points_path) {
        library_call([&] {
          write_file_atomically(path, reconstruction_json_text(r, points_path));
          return 0;
        });
      },
      nb::arg("path"), nb::arg("reconstruction"), nb::arg("points_path") = "");
  m.def("read_ground_truth", [](const std::string& path) { return library_call([&] { return read_ground_truth_file(path); }); },
        nb::arg("path"));
  m.def(
      "write_generated",
      [](const PointsArray& points, const GroundTruth& truth, const std::string& points_path, const std::string& truth_path) {
        library_call([&] {
          const auto span = point_span(points);
          write_generated_input_files(GeneratedInput{std::vector<Point2>(span.begin(), span.end()), truth}, points_path, truth_path);
          return 0;
        });
      },
      nb::arg("points").noconvert(), nb::arg("truth"), nb::arg("points_path"), nb::arg("truth_path") = "",
      "The points file (headed by the settings, as `curvebench generate` writes it) and the ground-truth JSON.");
}
