#pragma once
// The floating-point precision of the sparse force kernel (network_force.hpp): float64, or
// float32 storage and accumulation of the gathered [cos, sin] table. Chosen per run
// (`simulate --precision`); the work-precision charts (verification/work_precision.cpp) show
// what each costs and where float32 stops being adequate.
#include <string>

#include "core/error.hpp"

namespace hmfnet {

enum class ForcePrecision { float64, float32 };

inline const char* to_string(ForcePrecision p) {
  return p == ForcePrecision::float64 ? "float64" : "float32";
}

/// "float64" or "float32"; anything else is refused with the allowed values.
inline ForcePrecision parse_force_precision(const std::string& name) {
  if (name == "float64") return ForcePrecision::float64;
  if (name == "float32") return ForcePrecision::float32;
  throw ParameterError("force precision", "'" + name + "'", "float64, float32");
}

}  // namespace hmfnet
