#pragma once
// What `convert` is asked (the CLI's options), checked by one function in the CLI's words. Plain
// data: the CLI grammar binds to it in the fuzz build too.
#include <cstdint>
#include <string>

namespace hmfnet::app {

struct ConvertRequest {
  std::string input;
  std::string output;              ///< hmfnet HDF5 (.h5/.hdf5)
  int partition = 0;               ///< P > 0: the P parts of a Zoltan2 partition made contiguous
  std::uint64_t seed = 1;          ///< the partitioner's random choices
  std::string order = "original";  ///< or rcm, degree (network/node_ordering.hpp)
};

/// Throws ParameterError naming the first value out of range (app/option_checks.hpp).
void validate(const ConvertRequest& r);

}  // namespace hmfnet::app
