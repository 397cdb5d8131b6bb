#pragma once
// Helpers for the reader/writer tests: a scratch directory removed at scope exit, small text
// files written into it, and checks that an InputError names the file, the line and the cause.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "core/error.hpp"
#include "network/network.hpp"

namespace hmfnet::test {

/// A fresh directory under the system temporary directory, unique per process and instance;
/// it and everything in it is removed on destruction.
class TempDirectory {
 public:
  TempDirectory() {
    static std::atomic<int> counter{0};
    const std::string name =
        "hmfnet_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
    m_path = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(m_path);
    std::filesystem::create_directories(m_path);
  }
  ~TempDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(m_path, ignored);
  }
  TempDirectory(const TempDirectory&) = delete;
  TempDirectory& operator=(const TempDirectory&) = delete;

  const std::filesystem::path& path() const { return m_path; }
  /// Full path of `name` inside the directory, as a string (the readers take strings).
  std::string file(const std::string& name) const { return (m_path / name).string(); }
  /// Names of everything in the directory (to check that no temporary was left behind).
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(m_path)) {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }

 private:
  std::filesystem::path m_path;
};

inline void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  REQUIRE(out.good());
}

inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

/// The InputError `action` throws, or nothing if it returns normally. Other exceptions propagate
/// (Catch reports them as failures).
template <class Action>
std::optional<InputError> input_error_from(Action&& action) {
  try {
    action();
  } catch (const InputError& e) {
    return e;
  }
  return std::nullopt;
}

/// Checks that `error` was thrown, names `file` and `line`, has a cause containing `cause`, and
/// that what() is "FILE:LINE: cause" ("FILE: cause" for line 0).
inline void require_input_error(const std::optional<InputError>& error, const std::string& file,
                                std::int64_t line, const std::string& cause) {
  REQUIRE(error.has_value());
  INFO("what(): " << error->what());
  CHECK(error->file() == file);
  CHECK(error->line() == line);
  CHECK_THAT(error->cause(), Catch::Matchers::Contains(cause));
  const std::string place = line > 0 ? file + ":" + std::to_string(line) : file;
  CHECK(std::string(error->what()) == place + ": " + error->cause());
}

using WeightedEdge = std::tuple<NodeIndex, NodeIndex, double>;

/// A weighted network from unordered pairs {i, j, w} (each once; i == j is a self-loop), built
/// directly as CSR so that the writers are tested against input not made by the readers.
inline Network weighted_network(NodeIndex n, const std::vector<WeightedEdge>& edges) {
  std::vector<std::vector<std::pair<NodeIndex, double>>> rows(static_cast<std::size_t>(n));
  for (const auto& [i, j, w] : edges) {
    rows[static_cast<std::size_t>(i)].emplace_back(j, w);
    if (i != j) rows[static_cast<std::size_t>(j)].emplace_back(i, w);
  }
  std::vector<EdgeOffset> row_ptr{0};
  std::vector<NodeIndex> cols;
  std::vector<double> weights;
  for (auto& row : rows) {
    std::sort(row.begin(), row.end());
    for (const auto& [j, w] : row) {
      cols.push_back(j);
      weights.push_back(w);
    }
    row_ptr.push_back(static_cast<EdgeOffset>(cols.size()));
  }
  return Network::from_csr(n, std::move(row_ptr), std::move(cols), std::move(weights));
}

/// Weights that a decimal writer with fewer than 17 significant digits would not round-trip,
/// extremes of the double range included, and self-loops on nodes 0 and 3.
inline Network awkward_weighted_network() {
  return weighted_network(6, {{0, 0, 0.1},
                              {0, 1, 1.0 / 3.0},
                              {1, 2, 2.5},
                              {1, 5, 1.0},
                              {2, 4, 12345.678901234567},
                              {3, 3, 1e-300},
                              {3, 4, 1.7976931348623157e308},
                              {4, 5, 0.30000000000000004}});
}

/// A 0/1 network with self-loops (nodes 0 and 4) and an isolated node in the middle (node 2).
inline Network unweighted_network_with_loops() {
  return Network::from_undirected_edges(6,
                                        {{0, 0}, {0, 1}, {1, 3}, {3, 4}, {4, 4}, {4, 5}, {1, 5}});
}

/// Exact equality of the CSR arrays (HighFive's round-trip style: no tolerance, a written and
/// re-read network must be bit-identical).
inline void require_same_network(const Network& read, const Network& written) {
  REQUIRE(read.size() == written.size());
  CHECK(read.row_ptr() == written.row_ptr());
  CHECK(read.cols() == written.cols());
  CHECK(read.weighted() == written.weighted());
  CHECK(read.weights() == written.weights());
}

}  // namespace hmfnet::test
