#include "app/option_checks.hpp"

#include <charconv>
#include <cmath>

#include "core/error.hpp"

namespace hmfnet::app {

namespace {

// NaN fails every comparison, so each `ok` is written as "inside the range": NaN is refused.
void require_number(bool ok, const char* option, double x, const char* allowed) {
  if (ok) return;
  throw ParameterError(option, "value " + shortest_text(x) + " is not allowed", allowed);
}

}  // namespace

// The fewest digits that read back to x (std::to_chars): in fixed notation for 1e-4 <= |x| < 1e4,
// where printf's %g reads best ("0.0001", "100"; to_chars alone would pick "1e-04"), elsewhere in
// whichever of fixed and scientific is shorter ("120000", "1e+06", "1e-300").
std::string shortest_text(double x) {
  char text[32];
  const double size = std::fabs(x);
  const auto end = size >= 1e-4 && size < 1e4
                       ? std::to_chars(text, text + sizeof text, x, std::chars_format::fixed).ptr
                       : std::to_chars(text, text + sizeof text, x).ptr;
  return {text, end};
}

void require_positive(const char* option, double x) {
  require_number(x > 0.0 && x < HUGE_VAL, option, x, "> 0");
}

void require_non_negative(const char* option, double x) {
  require_number(x >= 0.0 && x < HUGE_VAL, option, x, ">= 0");
}

void require_finite(const char* option, double x) {
  require_number(std::isfinite(x), option, x, "finite");
}

void require_closed_range(const char* option, double x, double lo, double hi) {
  const std::string allowed = shortest_text(lo) + " <= x <= " + shortest_text(hi);
  require_number(x >= lo && x <= hi, option, x, allowed.c_str());
}

void require_greater_than(const char* option, double x, double lo) {
  const std::string allowed = "> " + shortest_text(lo);
  require_number(x > lo && x < HUGE_VAL, option, x, allowed.c_str());
}

void require_probability(const char* option, double x) {
  require_number(x >= 0.0 && x <= 1.0, option, x, "0 <= q <= 1");
}

void require_positive_or_inf(const char* option, double x) {
  require_number(x > 0.0, option, x, "> 0, or inf");
}

void require_in_range(const char* option, std::int64_t x, std::int64_t lo, std::int64_t hi) {
  if (x >= lo && x <= hi) return;
  throw ParameterError(std::string(option) + ": Value " + std::to_string(x) + " not in range " +
                       std::to_string(lo) + " to " + std::to_string(hi));
}

void require_member(const char* option, const std::string& word,
                    std::initializer_list<const char*> allowed) {
  std::string set;
  for (const char* a : allowed) {
    if (word == a) return;
    set += (set.empty() ? "" : ",") + std::string(a);
  }
  throw ParameterError(std::string(option) + ": " + word + " not in {" + set + "}");
}

void require_member(const char* option, int x, std::initializer_list<int> allowed) {
  std::string set;
  for (const int a : allowed) {
    if (x == a) return;
    set += (set.empty() ? "" : ",") + std::to_string(a);
  }
  throw ParameterError(std::string(option) + ": " + std::to_string(x) + " not in {" + set + "}");
}

void require_not_both(const char* option, bool given, const char* other, bool other_given) {
  if (given && other_given) throw ParameterError(std::string(option) + " excludes " + other);
}

}  // namespace hmfnet::app
