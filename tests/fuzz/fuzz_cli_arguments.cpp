// libFuzzer harness for the CLI grammar (src/cli/command_options.cpp): every subcommand's options,
// ranges and cross-option checks, without the work (cli_target.hpp). Run:
// build-fuzz/bin/fuzz_cli_arguments -dict=tests/fuzz/cli_arguments.dict
// tests/fuzz/corpus/cli_arguments
#include <cstddef>
#include <cstdint>

#include "cli_target.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hmfnet::fuzz::parse_command_line(hmfnet::fuzz::split_arguments(data, size));
  return 0;
}
