// libFuzzer harness for the HDF5 network reader (src/io/network_hdf5.cpp): the bytes are written to
// a file because HDF5 opens files by name (the reader has no in-memory entry point); the HDF5
// library itself is Debian's uninstrumented build, so only hmfnet's code gets coverage feedback.
// Run: build-fuzz/bin/fuzz_network_hdf5 tests/fuzz/corpus/network_hdf5 (ci/fuzz.sh bounds it in
// time and memory).
#include <cstddef>
#include <cstdint>

#include "reader_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hmfnet::fuzz::fuzz_one_input(hmfnet::fuzz::Reader::network_hdf5, data, size);
}
