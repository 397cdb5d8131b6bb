// Reading and writing by file name: the extension picks the format, an unknown one is an
// InputError naming the file, and every format round-trips through read_network/write_network.
#include <catch2/catch.hpp>

#include "io/network_file.hpp"
#include "support/io_helpers.hpp"

using namespace hmfnet;
using hmfnet::test::input_error_from;
using hmfnet::test::require_input_error;
using hmfnet::test::TempDirectory;

TEST_CASE("Network file format follows the extension in any letter case [extensions]",
          "[io][network_file]") {
  const auto [name, format] = GENERATE(table<std::string, NetworkFormat>({
      {"a.mtx", NetworkFormat::matrix_market},
      {"dir.v2/a.MM", NetworkFormat::matrix_market},
      {"a.h5", NetworkFormat::hdf5},
      {"a.HDF5", NetworkFormat::hdf5},
      {"a.txt", NetworkFormat::edge_list},
      {"a.edges", NetworkFormat::edge_list},
      {"a.el", NetworkFormat::edge_list},
      {"a.tsv", NetworkFormat::edge_list},
  }));
  INFO(name);
  CHECK(format_from_extension(name) == format);
}

TEST_CASE("Network file refuses an unknown or missing extension naming the file [extensions]",
          "[io][network_file]") {
  const std::string name = GENERATE(as<std::string>{}, "net.csv", "net", "net.mtx.gz");
  const auto e = input_error_from([&] { format_from_extension(name); });
  require_input_error(e, name, 0, "unknown network file extension");
}

TEST_CASE("An HDF5 output named like a text network is refused naming the option [extensions]",
          "[io][network_file]") {
  for (const std::string name : {"run.h5", "run.HDF5", "run.ck", "run", "dir.mtx/run"}) {
    INFO(name);
    CHECK_NOTHROW(require_not_a_text_network_name("--output", name));
  }
  const auto row = GENERATE(table<std::string, std::string>({
      {"run.mtx", "a Matrix Market"},
      {"run.MM", "a Matrix Market"},
      {"run.txt", "an edge-list"},
      {"dir.h5/run.tsv", "an edge-list"},
  }));
  const std::string name = std::get<0>(row);
  const std::string kind = std::get<1>(row);
  const auto e = input_error_from([&] { require_not_a_text_network_name("--checkpoint", name); });
  require_input_error(e, name, 0,
                      "--checkpoint is written in HDF5, but its extension names " + kind +
                          " network file; choose a name ending in .h5");
}

TEST_CASE("Network file round trip is exact in every format [weighted and 0/1 with self-loops]",
          "[io][network_file]") {
  const std::string name = GENERATE(as<std::string>{}, "n.mtx", "n.h5", "n.edges");
  const bool weighted = GENERATE(true, false);
  INFO(name << (weighted ? " weighted" : " 0/1"));
  TempDirectory dir;
  const Network net =
      weighted ? test::awkward_weighted_network() : test::unweighted_network_with_loops();
  write_network(dir.file(name), net, R"({"seed": 1})");
  ReadOptions options;
  options.edge_list_nodes = net.size();
  const ReadResult r = read_network(dir.file(name), options);
  CHECK(r.warnings.empty());
  test::require_same_network(r.network, net);
  CHECK(dir.listing() == std::vector<std::string>{name});
}

TEST_CASE(
    "Network file writer refuses an unknown extension before creating anything "
    "[extensions]",
    "[io][network_file]") {
  TempDirectory dir;
  const auto e = input_error_from(
      [&] { write_network(dir.file("n.csv"), test::unweighted_network_with_loops()); });
  require_input_error(e, dir.file("n.csv"), 0, "unknown network file extension");
  CHECK(dir.listing().empty());
}

TEST_CASE("Network file reader passes the asymmetry policy to Matrix Market [symmetrize]",
          "[io][network_file]") {
  TempDirectory dir;
  test::write_text(dir.file("g.mtx"),
                   "%%MatrixMarket matrix coordinate pattern general\n2 2 1\n1 2\n");
  require_input_error(input_error_from([&] { read_network(dir.file("g.mtx")); }), dir.file("g.mtx"),
                      3, "matrix is not symmetric");
  ReadOptions options;
  options.asymmetry = AsymmetryPolicy::symmetrize;
  const ReadResult r = read_network(dir.file("g.mtx"), options);
  CHECK(r.warnings.size() == 1);
  CHECK(r.network.weights() == std::vector<double>{0.5, 0.5});
}
