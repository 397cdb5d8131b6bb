#include "app/convert_request.hpp"

#include "app/option_checks.hpp"

namespace hmfnet::app {

void validate(const ConvertRequest& r) {
  require_in_range("--partition", r.partition, 0, 65536);
  require_member("--order", r.order, {"original", "rcm", "degree"});
  require_not_both("--partition", r.partition > 0, "--order", r.order != "original");
}

}  // namespace hmfnet::app
