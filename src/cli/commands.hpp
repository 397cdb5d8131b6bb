#pragma once
// The subcommands of the `hmfnet` CLI. Each add_* registers its options and a callback on the
// app; errors are thrown (InputError, ParameterError, ConvergenceError) and reported by main().
#include <CLI/CLI.hpp>
#include <string>

namespace hmfnet::cli {

void add_generate_command(CLI::App& app);
void add_rewire_command(CLI::App& app);
void add_convert_command(CLI::App& app);
void add_spectrum_command(CLI::App& app);
void add_theory_command(CLI::App& app);
void add_demo_command(CLI::App& app);
void add_simulate_command(CLI::App& app);

/// The command line as typed, for provenance records.
const std::string& command_line();
void set_command_line(int argc, char** argv);
/// For an embedding (the Python module): what the provenance records as the command line.
void set_command_line(const std::string& text);

/// True on the rank that prints and writes (rank 0).
bool is_root();

}  // namespace hmfnet::cli
