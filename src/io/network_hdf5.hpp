#pragma once
// hmfnet's own network file (HDF5), documented in docs/file_formats.md:
//   /                attributes  hmfnet_format = "network", format_version = 1,
//                                hmfnet_version, git_commit, provenance (JSON text)
//   /network         attributes  n, nnz, edges, self_loops, weighted (0/1)
//   /network/row_ptr int64[n+1]  CSR row pointers
//   /network/col     int32[nnz]  column indices, sorted within each row, full symmetric matrix
//   /network/weights float64[nnz] only when weighted
// The reader checks every invariant of Network (so a corrupted file is refused, naming the
// dataset and the violation).
#include <string>

#include "io/read_options.hpp"

namespace hmfnet {

ReadResult read_network_hdf5(const std::string& path);

/// `provenance` is JSON text (generator, parameters, seed, command line).
void write_network_hdf5(const std::string& path, const Network& network,
                        const std::string& provenance = "{}");

}  // namespace hmfnet
