#pragma once
// A list of numbers on the command line (`--K 0.5,1,2`, also `--K 0.5 1 2` or `--K 0.5 --K 1`),
// read item by item so that a typo is refused instead of changing the run: CLI11's own delimiter
// drops the empty items between commas (`1,,2` ran K = 1, 2) and names no item it cannot read.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace hmfnet::cli {

/// The numbers of `values` (each a comma-separated list, items trimmed of spaces) in order; an
/// empty item or one that is not a whole number gives CLI::ValidationError naming `option`, the
/// item's place and the text it came from.
std::vector<double> parse_number_list(const std::string& option,
                                      const std::vector<std::string>& values);

/// Adds `name` to `command` as such a list, read into `target` when the option is given.
CLI::Option* add_number_list(CLI::App* command, const std::string& name,
                             std::vector<double>& target, const std::string& description);

}  // namespace hmfnet::cli
