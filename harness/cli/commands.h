// The subcommands of the `curvebench` executable, one file each; main.cpp wires them up.
// Each callback throws on failure; main prints one line on stderr and exits nonzero.
#pragma once

#include <CLI/CLI.hpp>

namespace curvebench {

void add_list_command(CLI::App& app);
void add_reconstruct_command(CLI::App& app);
void add_generate_command(CLI::App& app);
void add_evaluate_command(CLI::App& app);
void add_sweep_command(CLI::App& app);

}  // namespace curvebench
