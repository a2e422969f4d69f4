// The subcommands of the `curvebench` executable, one file each; main.cpp wires them up.
// Each callback throws on failure; main prints one line on stderr and exits nonzero.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace curvebench {

void add_list_command(CLI::App& app);
void add_reconstruct_command(CLI::App& app);
void add_generate_command(CLI::App& app);
void add_evaluate_command(CLI::App& app);
void add_sweep_command(CLI::App& app);  // sweep, merge and the hidden sweep-run

// --external FILE (repeatable): files declaring external algorithms (README.md, "External
// algorithms"), or sweep configurations that declare some, registered before the command runs
// by register_external_files.
void add_external_option(CLI::App& command, std::vector<std::string>& files);
void register_external_files(const std::vector<std::string>& files);

}  // namespace curvebench
