#pragma once
// The checks a request makes of its values, in the words the CLI grammar has always used, so a
// value refused from the command line and the same value refused from Python read alike:
//   "--h: value 0 is not allowed (allowed: > 0)"         (a number outside its range)
//   "--replicas: Value 0 not in range 1 to 64"            (an integer outside its range)
//   "--force: dense not in {auto,sparse,rank-one}"        (a word outside its set)
// Each throws ParameterError. A value is shown as the shortest text that reads back to it.
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <string>

namespace hmfnet::app {

/// The shortest decimal text that reads back to x ("0.1", "100", "1e-300", "nan").
std::string shortest_text(double x);

/// x > 0 and finite.
void require_positive(const char* option, double x);
/// x >= 0 and finite.
void require_non_negative(const char* option, double x);
/// x finite.
void require_finite(const char* option, double x);
/// lo <= x <= hi for a real option with two finite ends (tolerances).
void require_closed_range(const char* option, double x, double lo, double hi);
/// x > lo and finite (the power-law exponent alpha > 2).
void require_greater_than(const char* option, double x, double lo);
/// 0 <= x <= 1.
void require_probability(const char* option, double x);
/// x > 0; infinity allowed (a bound that may be absent).
void require_positive_or_inf(const char* option, double x);
/// lo <= x <= hi for an integer option.
void require_in_range(const char* option, std::int64_t x, std::int64_t lo, std::int64_t hi);
/// `word` one of `allowed`.
void require_member(const char* option, const std::string& word,
                    std::initializer_list<const char*> allowed);
/// `x` one of `allowed`, for an integer option ("--index-base: 2 not in {0,1}").
void require_member(const char* option, int x, std::initializer_list<int> allowed);
/// At most one of options that exclude each other given ("--q excludes --mean-degree").
void require_not_both(const char* option, bool given, const char* other, bool other_given);

}  // namespace hmfnet::app
