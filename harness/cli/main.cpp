// curvebench: a thin command line over the curvebench library.
#include <exception>
#include <iostream>

#include "cli/commands.h"

int main(int argc, char** argv) {
  CLI::App app{"curvebench: reconstruct closed curves, medial axes and dominant points from planar points, "
               "and compare reconstruction algorithms"};
  app.require_subcommand(1);
  curvebench::add_list_command(app);
  curvebench::add_reconstruct_command(app);
  curvebench::add_generate_command(app);
  curvebench::add_evaluate_command(app);
  curvebench::add_sweep_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {
    std::cerr << "curvebench: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
