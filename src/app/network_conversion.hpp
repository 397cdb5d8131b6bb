#pragma once
// `convert`'s work: a network file to hmfnet HDF5, the format every rank reads by row blocks, so a
// large text network is parsed once (docs/scaling.md). The text is parsed in parallel
// (parallel/distributed_text_read.hpp) and the rows written without gathering them
// (parallel/distributed_network_file.hpp): the file is the same for any rank count and equals
// what `write_network` writes for the serial read. `partition = P` renumbers the nodes so that
// the P parts of a Zoltan2 partition (PHG) are contiguous row blocks
// (parallel/graph_partition.hpp), recording the old indices in /network/original_index; `order`
// renumbers them for the force kernel's cache (network/node_ordering.hpp).
#include <string>
#include <vector>

#include "app/convert_request.hpp"
#include "parallel/distributed_read.hpp"

namespace hmfnet::app {

struct ConvertedFile {
  NodeIndex n = 0;
  EdgeOffset nnz = 0;
  /// What the renumbering did, one line each ("partition into 4 parts: ...", "order rcm:
  /// bandwidth ..."), for the CLI's stderr.
  std::vector<std::string> notes;
  double seconds = 0.0;
  int ranks = 1;
  std::vector<double> peak_rss_mb_per_rank;
};

/// The request's check and its output's (an HDF5 name, a writable place, not the input file):
/// made before the input is read, so a bad output costs no parse.
void check_convert(const ConvertRequest& r);

/// Checks (check_convert), renumbers `rows` as asked and writes r.output (a temporary file, then
/// renamed). Collective over the MPI ranks.
ConvertedFile convert(const ConvertRequest& r, DistributedRows rows);

}  // namespace hmfnet::app
