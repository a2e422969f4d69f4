// What external algorithms write and declare: the edges file (harness/io/edges_file.h), whose
// errors name the file and the line, and parameters in the catalogue's form
// (io/parameters_json.h), which read back as the specs that wrote them.
#include <gtest/gtest.h>

#include <cmath>

#include "core/registry.h"
#include "io/edges_file.h"
#include "io/parameters_json.h"

namespace curvebench {
namespace {

std::string error_of(const std::string& text, std::size_t vertices) {
  try {
    parse_edges(text, "{output}", vertices);
  } catch (const EdgesFileError& e) {
    return e.what();
  }
  return "";
}

TEST(EdgesFile, ReadsEdgesWithThePointsFilesSeparatorsCommentsAndLineEnds) {
  const auto edges = parse_edges("# chain\n0 1\r\n2,1\r3\t2 extra\n\n", "f", 4);
  EXPECT_EQ(edges, (std::vector<Edge>{{0, 1}, {1, 2}, {2, 3}}));
  EXPECT_TRUE(parse_edges("# no edges\n", "f", 4).empty());
}

TEST(EdgesFile, ABadLineNamesTheFileAndTheLine) {
  EXPECT_EQ(error_of("0 1\n1 4\n", 4), "{output}:2: vertex index 4 is out of range: there are 4 vertices, numbered from 0");
  EXPECT_EQ(error_of("0 1\n\n-1 2\n", 4), "{output}:3: vertex index -1 is out of range: there are 4 vertices, numbered from 0");
  EXPECT_EQ(error_of("0 x\n", 4), "{output}:1: 'x' is not a vertex index");
  EXPECT_EQ(error_of("1.5 2\n", 4), "{output}:1: '1.5' is not a vertex index");
  EXPECT_EQ(error_of("0 1\n3\n", 4), "{output}:2: expected an edge 'i j', found one index");
  EXPECT_EQ(error_of("2 2\n", 4), "{output}:1: edge 2 2 joins a vertex to itself");
  EXPECT_EQ(error_of("0 99999999999999999999\n", 4), "{output}:1: '99999999999999999999' is not a vertex index");
}

bool same_spec(const ParameterSpec& a, const ParameterSpec& b) {
  auto same_bound = [](double x, double y) { return x == y || (std::isinf(x) && std::isinf(y) && (x > 0) == (y > 0)); };
  return a.name == b.name && a.type == b.type && a.default_value == b.default_value && same_bound(a.minimum, b.minimum) &&
         same_bound(a.maximum, b.maximum) && a.minimum_exclusive == b.minimum_exclusive && a.choices == b.choices &&
         a.description == b.description;
}

TEST(ParameterSpecJson, EveryBuiltInParameterReadsBackFromTheCatalogue) {
  const auto algorithms = all_algorithms();
  const auto catalogue = algorithm_catalogue(algorithms);
  int parameters = 0;
  for (size_t a = 0; a < algorithms.size(); ++a) {
    const auto& specs = algorithms[a]->info().parameters;
    for (size_t p = 0; p < specs.size(); ++p, ++parameters) {
      const ParameterSpec read = parameter_spec_from_json(catalogue[a]["parameters"][p], "catalogue");
      EXPECT_TRUE(same_spec(read, specs[p])) << algorithms[a]->name() << "." << specs[p].name;
    }
    EXPECT_EQ(outputs_from_names(catalogue[a]["outputs"], "outputs"), algorithms[a]->info().outputs);
  }
  EXPECT_GT(parameters, 10);
}

TEST(ParameterSpecJson, MissingBoundsAreNoneAndAMalformedSpecIsNamed) {
  const ParameterSpec spec = parameter_spec_from_json(
      nlohmann::json{{"name", "k"}, {"type", "integer"}, {"default", 3}, {"description", "neighbours"}}, "p");
  EXPECT_TRUE(std::isinf(spec.minimum) && spec.minimum < 0 && std::isinf(spec.maximum));
  auto error_of_spec = [](const nlohmann::json& json) {
    try {
      parameter_spec_from_json(json, "x.parameters[0]");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error_of_spec({{"name", "k"}, {"type", "integer"}, {"default", 1.5}, {"description", "d"}}),
            "x.parameters[0] (k).default must be a whole number");
  EXPECT_EQ(error_of_spec({{"name", "k"}, {"type", "text"}, {"default", 1}, {"description", "d"}}),
            "x.parameters[0] (k).type 'text' is not real, integer, boolean or choice");
  EXPECT_EQ(error_of_spec({{"name", "k"}, {"type", "choice"}, {"default", "c"}, {"choices", {"a", "b"}}, {"description", "d"}}),
            "x.parameters[0] (k): the default c is not one of: a, b");
  EXPECT_EQ(error_of_spec({{"type", "real"}}), "x.parameters[0].name must be a non-empty string");
}

}  // namespace
}  // namespace curvebench
