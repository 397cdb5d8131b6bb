#pragma once
// The subcommands of the `hmfnet` CLI. Each add_* registers its options and a callback on the
// app; errors are thrown (InputError, ParameterError, ConvergenceError) and reported by main().
#include <string>

#include "cli/cli_app_fwd.hpp"

namespace hmfnet::cli {

void add_generate_command(CLI::App& app);
void add_rewire_command(CLI::App& app);
void add_convert_command(CLI::App& app);
void add_spectrum_command(CLI::App& app);
void add_theory_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_simulate_command(CLI::App& app);

/// True on the rank that prints and writes (rank 0).
bool is_root();

}  // namespace hmfnet::cli
