#include "app/theory_request.hpp"

#include "app/option_checks.hpp"
#include "core/error.hpp"

namespace hmfnet::app {

void validate(const TheoryRequest& r) {
  require_positive("--sigma0", r.sigma0);
  require_member("--momenta", r.momenta, {"gaussian", "waterbag"});
  for (const double k : r.K) require_positive("--K", k);
  for (const double k : r.K_over_Kc) require_positive("--K-over-Kc", k);
  require_not_both("--K", !r.K.empty(), "--K-over-Kc", !r.K_over_Kc.empty());
  if (r.K.empty() && r.K_over_Kc.empty()) {
    throw ParameterError("--K / --K-over-Kc", "neither given", "one of them, a list of values");
  }
  require_closed_range("--tolerance", r.tolerance, 1e-14, 1e-2);
}

}  // namespace hmfnet::app
