#pragma once
// What `theory` is asked (the CLI's options, Python's keywords), checked by one function in the
// CLI's words. Plain data: the CLI grammar binds to it in the fuzz build too.
#include <string>
#include <vector>

namespace hmfnet::app {

struct TheoryRequest {
  std::string input;  ///< the network's file, for messages (empty in memory)
  double sigma0 = 0.0;
  std::string momenta = "gaussian";  ///< gaussian or waterbag: whose K_c and gamma
  std::vector<double> K, K_over_Kc;  ///< one of the two, not both
  double tolerance = 1e-10;          ///< relative residual of the self-consistent solves
};

/// Throws ParameterError naming the first value out of range (app/option_checks.hpp).
void validate(const TheoryRequest& r);

}  // namespace hmfnet::app
