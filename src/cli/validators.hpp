#pragma once
// Range checks for CLI options with messages a person reads: CLI11 2.1's PositiveNumber prints
// the whole range up to the largest double.
#include <CLI/CLI.hpp>
#include <string>

namespace hmfnet::cli {

inline CLI::Validator number_check(bool (*ok)(double), const std::string& allowed,
                                   const std::string& name) {
  return CLI::Validator(
      [ok, allowed](std::string& text) -> std::string {
        try {
          std::size_t used = 0;
          const double v = std::stod(text, &used);
          if (used == text.size() && ok(v)) return {};
        } catch (const std::exception&) {
        }
        return "value " + text + " is not allowed (allowed: " + allowed + ")";
      },
      name);
}

inline const CLI::Validator k_positive =
    number_check([](double v) { return v > 0.0 && v < HUGE_VAL; }, "> 0", "POSITIVE");
inline const CLI::Validator k_non_negative =
    number_check([](double v) { return v >= 0.0 && v < HUGE_VAL; }, ">= 0", "NON-NEGATIVE");

}  // namespace hmfnet::cli
