#pragma once
// Reading and writing networks by file name: `.mtx`/`.mm` Matrix Market, `.h5`/`.hdf5` hmfnet
// HDF5, `.txt`/`.edges`/`.el`/`.tsv` whitespace edge list. Unknown extensions are an error.
#include <string>

#include "io/read_options.hpp"

namespace hmfnet {

enum class NetworkFormat { matrix_market, hdf5, edge_list };

/// Throws InputError naming the file if the extension is not one of the above.
NetworkFormat format_from_extension(const std::string& path);

ReadResult read_network(const std::string& path, const ReadOptions& options = {});

/// `provenance`: JSON text, stored as an attribute (HDF5) or as comment lines (text formats).
void write_network(const std::string& path, const Network& network,
                   const std::string& provenance = "{}");

}  // namespace hmfnet
