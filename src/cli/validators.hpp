#pragma once
// Range checks for CLI options with messages a person reads: CLI11 2.1's PositiveNumber prints
// the whole range up to the largest double.
#include <CLI/CLI.hpp>
#include <cmath>
#include <functional>
#include <string>
#include <utility>

namespace hmfnet::cli {

// A number check that names the allowed range. NaN fails every comparison, so each `ok` below
// is written as "v inside the range" (never "v outside"): NaN is then refused like any other
// bad value, which CLI::Range(lo, hi) does not do for doubles ("--q nan" passed it).
inline CLI::Validator number_check(std::function<bool(double)> ok, const std::string& allowed,
                                   const std::string& name) {
  return CLI::Validator(
      [ok = std::move(ok), allowed](std::string& text) -> std::string {
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
inline const CLI::Validator k_finite =
    number_check([](double v) { return std::isfinite(v); }, "finite", "FINITE");
inline const CLI::Validator k_probability =
    number_check([](double v) { return v >= 0.0 && v <= 1.0; }, "0 <= q <= 1", "PROBABILITY");
// A positive bound that may be infinite ("inf": no bound).
inline const CLI::Validator k_positive_or_inf =
    number_check([](double v) { return v > 0.0; }, "> 0, or inf", "POSITIVE");

// lo <= v <= hi, for tolerances and other doubles with two finite ends.
inline CLI::Validator closed_range(double lo, double hi) {
  return number_check([lo, hi](double v) { return v >= lo && v <= hi; },
                      CLI::detail::to_string(lo) + " <= x <= " + CLI::detail::to_string(hi),
                      "RANGE");
}

// v > lo and finite, e.g. the power-law exponent alpha > 2 (finite mean degree).
inline CLI::Validator greater_than(double lo) {
  return number_check([lo](double v) { return v > lo && v < HUGE_VAL; },
                      "> " + CLI::detail::to_string(lo), "GREATER");
}

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
