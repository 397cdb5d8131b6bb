// libFuzzer harness for the Matrix Market reader (src/io/matrix_market.cpp), under both asymmetry
// policies. Run: build-fuzz/bin/fuzz_matrix_market tests/fuzz/corpus/matrix_market (ci/fuzz.sh
// bounds it in time and memory).
#include <cstddef>
#include <cstdint>

#include "reader_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hmfnet::fuzz::fuzz_one_input(hmfnet::fuzz::Reader::matrix_market, data, size);
}
