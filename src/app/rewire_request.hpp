#pragma once
// What `rewire` is asked (the CLI's options), checked by one function in the CLI's words. Plain
// data: the CLI grammar binds to it in the fuzz build too.
#include <cstdint>
#include <string>

namespace hmfnet::app {

struct RewireRequest {
  std::string input;
  double target_rho = 0.0;  ///< eq:rhodef
  std::uint64_t seed = 0;
  std::int64_t max_attempts = 0;  ///< 0: 200 x edges
  std::string output;
};

/// Throws ParameterError naming the first value out of range (app/option_checks.hpp).
void validate(const RewireRequest& r);

}  // namespace hmfnet::app
