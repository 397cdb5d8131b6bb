// libFuzzer harness for the edge-list reader (src/io/edge_list.cpp), with index base 0 and 1.
// Run: build-fuzz/bin/fuzz_edge_list tests/fuzz/corpus/edge_list (ci/fuzz.sh bounds it in time and
// memory).
#include <cstddef>
#include <cstdint>

#include "reader_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hmfnet::fuzz::fuzz_one_input(hmfnet::fuzz::Reader::edge_list, data, size);
}
