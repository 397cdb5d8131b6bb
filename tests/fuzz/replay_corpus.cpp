// Replays the fuzz seed corpus and every kept crashing input through the network readers and the
// CLI grammar (cli_arguments/, cli_target.hpp) in the ordinary build (CTest unit.fuzz_replay), so a
// crash the fuzzer once found stays fixed without clang or libFuzzer.
//
// Usage: hmfnet_fuzz_replay ROOT...   where each ROOT holds one folder per reader
//        (matrix_market/, edge_list/, network_hdf5/; tests/fuzz/corpus and tests/fuzz/crashes).
// Each file must be refused with InputError or accepted as a valid Network (reader_targets.hpp);
// anything else aborts, which fails the test. Files directly in ROOT (README) are not inputs.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "cli_target.hpp"
#include "reader_targets.hpp"

namespace {

using hmfnet::fuzz::Reader;

// Sorted so a failure always names the same first file.
std::vector<std::filesystem::path> files_in(const std::filesystem::path& dir) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.is_regular_file()) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s ROOT...  (folders holding matrix_market/ edge_list/ ...)\n",
                 argv[0]);
    return 2;
  }
  int replayed = 0;
  for (int a = 1; a < argc; ++a) {
    const std::filesystem::path root = argv[a];
    if (!std::filesystem::is_directory(root)) {
      std::fprintf(stderr, "%s: not a directory\n", argv[a]);
      return 2;
    }
    for (const Reader reader : {Reader::matrix_market, Reader::edge_list, Reader::network_hdf5}) {
      const std::filesystem::path dir = root / hmfnet::fuzz::reader_name(reader);
      if (!std::filesystem::is_directory(dir)) continue;
      for (const auto& file : files_in(dir)) {
        const int accepted = hmfnet::fuzz::read_file(reader, file.string());
        std::printf("%-14s %-60s %s\n", hmfnet::fuzz::reader_name(reader), file.c_str(),
                    accepted > 0 ? "accepted" : "refused");
        ++replayed;
      }
    }
  }
  int reached = 0;
  for (int a = 1; a < argc; ++a) {
    const std::filesystem::path dir = std::filesystem::path(argv[a]) / "cli_arguments";
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& file : files_in(dir)) {
      std::ifstream in(file, std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)),
                              std::istreambuf_iterator<char>());
      const bool ok = hmfnet::fuzz::parse_command_line(hmfnet::fuzz::split_arguments(
          reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size()));
      std::printf("%-14s %-60s %s\n", "cli_arguments", file.c_str(),
                  ok ? "reached work" : "refused");
      reached += ok ? 1 : 0;
      ++replayed;
    }
  }
  // An empty corpus would make this test pass while checking nothing.
  if (replayed == 0) {
    std::fprintf(stderr, "no input files found\n");
    return 1;
  }
  std::printf("%d files replayed: every one refused with InputError or accepted as valid\n",
              replayed);
  return 0;
}
