#include "external/register_external_algorithms.h"

#include <fstream>
#include <stdexcept>

#include "core/registry.h"

namespace curvebench {

std::vector<const ExternalAlgorithm*> register_external_algorithms(const nlohmann::ordered_json& entries,
                                                                   const std::filesystem::path& directory,
                                                                   const std::string& where) {
  if (!entries.is_array()) throw std::runtime_error(where + " must be a list of declarations and declaration files");
  std::vector<const ExternalAlgorithm*> registered;
  for (size_t i = 0; i < entries.size(); ++i) {
    const nlohmann::ordered_json& entry = entries[i];
    if (entry.is_string()) {
      const auto from_file = read_external_algorithms_file(directory / entry.get<std::string>());
      registered.insert(registered.end(), from_file.begin(), from_file.end());
      continue;
    }
    const std::string at = where + "[" + std::to_string(i) + "]";
    std::unique_ptr<ExternalAlgorithm> algorithm = external_algorithm_from_json(entry, directory, at);
    registered.push_back(algorithm.get());
    try {
      register_algorithm(std::move(algorithm));
    } catch (const std::logic_error& e) {
      throw std::runtime_error(at + ": " + e.what());
    }
  }
  return registered;
}

std::vector<const ExternalAlgorithm*> read_external_algorithms_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open for reading");
  nlohmann::ordered_json declarations;
  try {
    declarations = nlohmann::ordered_json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(path.string() + ": not JSON: " + e.what());
  }
  std::string where = path.string();
  if (declarations.is_object() && (declarations.contains("name") || declarations.contains("command"))) {
    declarations = nlohmann::ordered_json::array({declarations});
  } else if (declarations.is_object()) {  // a sweep configuration
    declarations = declarations.value("external_algorithms", nlohmann::ordered_json::array());
    where += ": external_algorithms";
  }
  return register_external_algorithms(declarations, std::filesystem::absolute(path).parent_path(), where);
}

}  // namespace curvebench
