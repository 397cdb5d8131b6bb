#include "app/spectrum_request.hpp"

#include "app/option_checks.hpp"

namespace hmfnet::app {

void validate(const SpectrumRequest& r) {
  if (r.sigma0) require_positive("--sigma0", *r.sigma0);
  require_closed_range("--tolerance", r.tolerance, 1e-15, 1e-2);
  require_member("--lambda2", r.lambda2, {"auto", "converged", "bound"});
}

}  // namespace hmfnet::app
