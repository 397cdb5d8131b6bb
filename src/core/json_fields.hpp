#pragma once
// A visitor that writes each field it is given into a JSON object under the field's name: the
// CLI's `--json` outputs walk their results' field lists (visit_*_fields) with it, as Python's
// dicts walk the same lists (src/python). A non-finite number becomes null (nlohmann's dump).
#include <nlohmann/json.hpp>

namespace hmfnet {

struct JsonFields {
  nlohmann::json& out;
  template <class T>
  void field(const char* name, const T& value) {
    out[name] = value;
  }
};

}  // namespace hmfnet
