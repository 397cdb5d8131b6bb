#pragma once
// What `spectrum` is asked (the CLI's options, Python's keywords), checked by one function in the
// CLI's words. Plain data: the CLI grammar binds to it in the fuzz build too.
#include <optional>
#include <string>

namespace hmfnet::app {

struct SpectrumRequest {
  std::string input;             ///< the network's file, for messages (empty in memory)
  std::optional<double> sigma0;  ///< also K_c = 2 sigma0^2 N / lambda when given
  double tolerance = 1e-10;      ///< relative eigen-residual
  std::string lambda2 = "auto";  ///< converged, bound or auto (spectrum_service.hpp)
};

/// Throws ParameterError naming the first value out of range (app/option_checks.hpp).
void validate(const SpectrumRequest& r);

}  // namespace hmfnet::app
