#pragma once
// A list of numbers on the command line (`--K 0.5,1,2`, also `--K 0.5 --K 1,2`),
// read item by item so that a typo is refused instead of changing the run: CLI11's own delimiter
// drops the empty items between commas (`1,,2` ran K = 1, 2) and names no item it cannot read.
#include <string>
#include <vector>

namespace hmfnet::cli {

/// The numbers of `values` (each a comma-separated list, items trimmed of spaces) in order; an
/// empty item, one that strtod does not read whole or one that overflows a double throws
/// ParameterError naming `option`, the item's place and the text it came from. Free of CLI11, whose
/// header alone takes ~8 s to compile: command_options.cpp registers the option and turns the error
/// into CLI11's.
std::vector<double> parse_number_list(const std::string& option,
                                      const std::vector<std::string>& values);

}  // namespace hmfnet::cli
