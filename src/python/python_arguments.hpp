#pragma once
// The Python functions take keyword arguments; hmfnet/__init__.py turns them into the CLI's
// tokens ("--sigma0", "0.35", ...) and these parse them with the CLI's own grammar
// (cli/command_options.hpp), so a Python call accepts exactly what the command line accepts and
// refuses the rest with the same message: a ValueError naming the option and its range.
#include <string>
#include <vector>

#include "cli/command_options.hpp"

namespace hmfnet::python {

/// `tokens` are what follows the subcommand's name; `input` is its positional network argument
/// (for messages and provenance). Throw pybind11::value_error with CLI11's message.
void parse_arguments(cli::SpectrumFlags& f, const std::string& input,
                     const std::vector<std::string>& tokens);
void parse_arguments(cli::TheoryFlags& f, const std::string& input,
                     const std::vector<std::string>& tokens);
/// `generate er|sf|sbm|regular` (the grammar's required --output is given a placeholder: nothing is
/// written).
void parse_generate_arguments(cli::ErFlags& f, const std::vector<std::string>& tokens);
void parse_generate_arguments(cli::SfFlags& f, const std::vector<std::string>& tokens);
void parse_generate_arguments(cli::SbmFlags& f, const std::vector<std::string>& tokens);
void parse_generate_arguments(cli::RegularFlags& f, const std::vector<std::string>& tokens);
/// The read options every network-reading command shares (--symmetrize, --index-base, --nodes).
void parse_read_arguments(cli::ReadFlags& f, const std::vector<std::string>& tokens);

}  // namespace hmfnet::python
