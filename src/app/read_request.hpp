#pragma once
// How a network file is read (the CLI's --symmetrize, --index-base, --nodes; Python's
// read_network keywords): one request shared by every command that reads a network, checked by
// one function in the CLI's words.
#include "io/read_options.hpp"

namespace hmfnet::app {

struct ReadRequest {
  bool symmetrize = false;  ///< Matrix Market 'general' not symmetric: (A + A^T) / 2, warned
  int index_base = 0;       ///< edge lists: the first node's index, 0 or 1
  int nodes = 0;            ///< edge lists: the node count; 0: the largest index + 1
};

/// Throws ParameterError naming the first value out of range (app/option_checks.hpp).
void validate(const ReadRequest& r);

/// What the readers (io/network_file.hpp) take from the request.
ReadOptions read_options(const ReadRequest& r);

}  // namespace hmfnet::app
