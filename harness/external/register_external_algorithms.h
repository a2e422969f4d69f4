// Declaring external algorithms (external_algorithm.h) from a sweep configuration's
// "external_algorithms" or from a file given with --external.
//
// In:  `entries`: a list whose items are declarations (objects) or paths of declaration files
//      (strings, relative to `directory`); a declaration file holds one declaration or a list of
//      them, and its own directory is the {dir} of its declarations. `where` names the source
//      in messages. read_external_algorithms_file: the same for one file, which may also be a
//      sweep configuration (an object with neither "name" nor "command"): then its
//      "external_algorithms", if any.
// Out: each algorithm registered (core/registry.h), so that every command finds it by name
//      like a built-in one, and `"algorithms": "all"` includes it; the registered algorithms,
//      in the order declared. Throws std::runtime_error naming the file and the declaration
//      for a malformed one or a name already taken.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "external/external_algorithm.h"

namespace curvebench {

std::vector<const ExternalAlgorithm*> register_external_algorithms(const nlohmann::ordered_json& entries,
                                                                   const std::filesystem::path& directory,
                                                                   const std::string& where);

std::vector<const ExternalAlgorithm*> read_external_algorithms_file(const std::filesystem::path& path);

}  // namespace curvebench
