#include "app/rewire_request.hpp"

#include "app/option_checks.hpp"

namespace hmfnet::app {

void validate(const RewireRequest& r) {
  require_positive("--target-rho", r.target_rho);
  require_non_negative("--max-attempts", static_cast<double>(r.max_attempts));
}

}  // namespace hmfnet::app
