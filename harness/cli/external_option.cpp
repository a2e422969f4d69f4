#include "cli/commands.h"
#include "external/register_external_algorithms.h"

namespace curvebench {

void add_external_option(CLI::App& command, std::vector<std::string>& files) {
  command.add_option("--external", files,
                     "JSON file declaring external algorithms (any program as an algorithm: README.md, \"External algorithms\"), "
                     "or a sweep configuration whose external_algorithms to declare; repeatable")
      ->allow_extra_args(false);  // one file per --external, so that positionals after it stay positionals
}

void register_external_files(const std::vector<std::string>& files) {
  for (const std::string& file : files) read_external_algorithms_file(file);
}

}  // namespace curvebench
