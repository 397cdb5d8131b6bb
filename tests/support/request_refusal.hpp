#pragma once
// The message with which a request's check (src/app: validate) refuses `valid` once `change` has
// altered it, or "accepted": the tests of tests/app compare it word for word with the CLI's.
#include <functional>
#include <string>

#include "core/error.hpp"

namespace hmfnet::test {

template <class Request>
std::string refusal(Request request, const std::function<void(Request&)>& change) {
  change(request);
  try {
    validate(request);  // found in the request's namespace
  } catch (const ParameterError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace hmfnet::test
