#include <algorithm>
#include <iostream>

#include "cli/commands.h"
#include "core/registry.h"
#include "io/parameters_json.h"

namespace curvebench {

void add_list_command(CLI::App& app) {
  auto* list = app.add_subcommand("list", "Name every algorithm, what it produces and its parameters");
  auto json = std::make_shared<bool>(false);
  auto external = std::make_shared<std::vector<std::string>>();
  list->add_flag("--json", *json, "Print the machine-readable catalogue (names, citations, outputs, typed parameters)");
  add_external_option(*list, *external);
  list->callback([json, external] {
    register_external_files(*external);
    const auto algorithms = all_algorithms();
    if (*json) {
      std::cout << algorithm_catalogue(algorithms).dump(2) << "\n";
      return;
    }
    for (const Algorithm* algorithm : algorithms) {
      const AlgorithmInfo& info = algorithm->info();
      std::string produces;
      for (std::string output : output_names(info.outputs)) {
        std::replace(output.begin(), output.end(), '_', ' ');
        produces += (produces.empty() ? "" : ", ") + output;
      }
      std::cout << info.name << "\n  " << info.citation << "\n  produces: " << produces << "\n";
      if (info.collinear == CollinearInput::kReconstructed) std::cout << "  takes collinear input\n";
      for (const auto& p : info.parameters) {
        std::cout << "  --param " << p.name << "=" << value_text(p.default_value) << "  (" << type_name(p.type) << ": "
                  << allowed_values(p) << ") " << p.description << "\n";
      }
    }
  });
}

}  // namespace curvebench
