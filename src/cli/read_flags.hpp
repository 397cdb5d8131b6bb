#pragma once
// Options every command that reads a network file shares (the typed request,
// app/read_request.hpp, which Python's read_network sets too), and the read itself (warnings go
// to stderr on the root rank).
#include <string>

#include "app/read_request.hpp"
#include "cli/cli_app_fwd.hpp"
#include "io/network_file.hpp"
#include "io/read_options.hpp"
#include "parallel/distributed_read.hpp"

namespace hmfnet::cli {

struct ReadFlags : app::ReadRequest {
  void add_to(CLI::App* command);
  /// The stored rows (an implicit structure is refused, naming the file).
  Network read(const std::string& path) const;
  /// Stored rows or the complete graph held implicitly (spectrum, theory, simulate).
  NetworkInput read_input(const std::string& path) const;
  /// This rank's rows only where the format allows it (parallel/distributed_read.hpp).
  /// Collective.
  DistributedInput read_distributed(const std::string& path) const;
  /// The same rows before a DistributedNetwork takes them (`convert`). Collective.
  DistributedRows read_distributed_rows(const std::string& path) const;
};

}  // namespace hmfnet::cli
