#pragma once
// The network a Python user holds (`hmfnet.Network`): stored rows or the complete graph kept
// implicitly, as a network file holds them (io/network_file.hpp: NetworkInput), with the name
// of where it came from for messages and provenance.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "io/network_file.hpp"
#include "parallel/distributed_read.hpp"

namespace hmfnet::python {

struct PythonNetwork {
  NetworkInput input;
  std::string source;  ///< a file name, "generate er", "scipy matrix", ...

  /// The same network as the CLI's read gives it to the commands (one rank holds all rows).
  DistributedInput distributed() const;
};

void bind_network(pybind11::module_& m);

}  // namespace hmfnet::python
