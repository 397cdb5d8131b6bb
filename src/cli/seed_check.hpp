#pragma once
// The seed's text, which every command checks before CLI11 reads it into a uint64 (the ranges of
// the other values are the typed requests' own checks, app/option_checks.hpp).
#include <CLI/CLI.hpp>
#include <string>

namespace hmfnet::cli {

// A random seed: a non-negative integer below 2^64. CLI11 reads "-1" into a uint64 as 2^64 - 1
// (strtoull wraps), so a negative seed would silently become a different, valid one.
inline const CLI::Validator k_seed = CLI::Validator(
    [](std::string& text) -> std::string {
      const bool digits = !text.empty() && text.size() <= 20 &&
                          text.find_first_not_of("0123456789") == std::string::npos;
      if (digits && (text.size() < 20 || text <= "18446744073709551615")) return {};
      return "value " + text + " is not allowed (allowed: an integer 0 <= seed < 2^64)";
    },
    "SEED");

}  // namespace hmfnet::cli
