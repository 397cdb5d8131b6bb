#pragma once
// What one fuzz input means for each network reader, shared by the libFuzzer harnesses
// (fuzz_<reader>.cpp) and the CTest that replays the corpus and the kept crashes
// (replay_corpus.cpp), so a crash found by the fuzzer reproduces in the ordinary gcc build.
//
// Contract under test (src/io): on any bytes a reader either throws hmfnet::InputError or returns
// a Network that satisfies every invariant of network.hpp. Anything else -- another exception,
// a sanitizer report, a hang, an absurd allocation -- is a bug. Violated invariants abort with a
// message, so libFuzzer and CTest both see a crash.
#include <hdf5.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "io/edge_list.hpp"
#include "io/matrix_market.hpp"
#include "io/network_hdf5.hpp"

namespace hmfnet::fuzz {

enum class Reader { matrix_market, edge_list, network_hdf5 };

inline const char* reader_name(Reader reader) {
  switch (reader) {
    case Reader::matrix_market:
      return "matrix_market";
    case Reader::edge_list:
      return "edge_list";
    case Reader::network_hdf5:
      return "network_hdf5";
  }
  return "unknown";
}

[[noreturn]] inline void invariant_failed(const std::string& path, const std::string& why) {
  std::fprintf(stderr, "reader contract violated: %s: %s\n", path.c_str(), why.c_str());
  std::abort();
}

// Wrong-but-accepted input: the readers build through from_csr, so these should hold by
// construction; checking them here catches a reader that bypasses or weakens the checks.
inline void check_accepted(const std::string& path, const ReadResult& r) {
  const Network& net = r.network;
  const std::string why = Network::check_csr(net.size(), net.row_ptr(), net.cols(), net.weights());
  if (!why.empty()) invariant_failed(path, why);
  // Every reader refuses a network without edges.
  if (net.size() < 1 || net.nnz() < 1) invariant_failed(path, "empty network accepted");
  if (net.nnz() != 2 * (net.edges() - net.self_loops()) + net.self_loops()) {
    invariant_failed(path, "nnz != 2 (edges - self_loops) + self_loops");
  }
  for (const std::string& w : r.warnings) {
    if (w.rfind(path, 0) != 0) invariant_failed(path, "warning does not name the file: " + w);
  }
}

/// Reads the file at `path` with `reader` under every option value that changes parsing
/// (asymmetry policy, index base). Returns how many of the reads were accepted.
inline int read_file(Reader reader, const std::string& path) {
  int accepted = 0;
  const auto attempt = [&](auto&& read) {
    try {
      check_accepted(path, read());
      ++accepted;
    } catch (const InputError&) {
      // The expected refusal of malformed input.
    }
  };
  switch (reader) {
    case Reader::matrix_market:
      for (const auto policy : {AsymmetryPolicy::reject, AsymmetryPolicy::symmetrize}) {
        ReadOptions options;
        options.asymmetry = policy;
        attempt([&] { return read_matrix_market(path, options); });
      }
      break;
    case Reader::edge_list:
      for (const int base : {0, 1}) {
        ReadOptions options;
        options.edge_list_base = base;
        attempt([&] { return read_edge_list(path, options); });
      }
      break;
    case Reader::network_hdf5:
      attempt([&] { return read_network_hdf5(path); });
      // The implicit structure (format 2): a file is rows or a complete graph, never both.
      try {
        if (read_implicit_network_hdf5(path)) {
          bool also_rows = true;
          try {
            read_network_hdf5(path);
          } catch (const InputError&) {
            also_rows = false;
          }
          if (also_rows) invariant_failed(path, "read both as a complete graph and as rows");
          ++accepted;
        }
      } catch (const InputError&) {
        // The expected refusal of malformed input.
      }
      // A handle left open on any path (error or not) keeps the file open inside HDF5, which
      // would hand the next open of the same name the stale file.
      if (H5Fget_obj_count(static_cast<hid_t>(H5F_OBJ_ALL), H5F_OBJ_ALL) != 0) {
        invariant_failed(path, "HDF5 objects left open after the read");
      }
      break;
  }
  return accepted;
}

/// The readers take a path (and HDF5 must open a real file), so fuzz bytes go through one scratch
/// file per process, in /dev/shm when it exists to keep the fuzzer off the disk.
class ScratchFile {
 public:
  explicit ScratchFile(Reader reader) {
    std::error_code ec;
    std::filesystem::path dir = "/dev/shm";
    if (!std::filesystem::is_directory(dir, ec)) dir = std::filesystem::temp_directory_path();
    m_path =
        (dir / ("hmfnet_fuzz_" + std::to_string(::getpid()) + "_" + reader_name(reader))).string();
  }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;
  ~ScratchFile() {
    std::error_code ec;
    std::filesystem::remove(m_path, ec);
  }
  const std::string& write(const std::uint8_t* data, std::size_t size) const {
    std::ofstream out(m_path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) {
      std::fprintf(stderr, "cannot write fuzz scratch file %s\n", m_path.c_str());
      std::abort();
    }
    return m_path;
  }

 private:
  std::string m_path;
};

/// The body of LLVMFuzzerTestOneInput for `reader`.
inline int fuzz_one_input(Reader reader, const std::uint8_t* data, std::size_t size) {
  static const ScratchFile scratch(reader);
  read_file(reader, scratch.write(data, size));
  return 0;
}

}  // namespace hmfnet::fuzz
