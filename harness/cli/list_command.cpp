#include <iostream>

#include "cli/commands.h"
#include "core/registry.h"

namespace curvebench {

void add_list_command(CLI::App& app) {
  auto* list = app.add_subcommand("list", "Name every algorithm, what it produces and its parameters");
  list->callback([] {
    for (const auto& algorithm : all_algorithms()) {
      std::string produces;
      const unsigned outputs = algorithm->outputs();
      if (outputs & kCurve) produces += "curve";
      if (outputs & kMedialAxis) produces += std::string(produces.empty() ? "" : ", ") + "medial axis";
      if (outputs & kDominantPoints) produces += std::string(produces.empty() ? "" : ", ") + "dominant points";
      std::cout << algorithm->name() << "\n  " << algorithm->description() << "\n  produces: " << produces << "\n";
      for (const auto& p : algorithm->parameters()) {
        std::cout << "  --param " << p.name << "=" << p.default_value << "  " << p.description << "\n";
      }
    }
  });
}

}  // namespace curvebench
