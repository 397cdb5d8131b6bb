// hmfnet's HDF5 network file: exact round trips, and refusal (an InputError naming the file) of
// files that are not HDF5, not ours, whose CSR arrays were corrupted after writing, or whose
// attributes have the wrong type or contradict the datasets.
#include <hdf5.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>

#include "io/hdf5_file.hpp"
#include "io/network_hdf5.hpp"
#include "network/erdos_renyi.hpp"
#include "support/bit_difference.hpp"
#include "support/hdf5_corruption.hpp"
#include "support/io_helpers.hpp"
#include "support/weighted_networks.hpp"

using namespace hmfnet;
using Catch::Matchers::Contains;
using hmfnet::test::input_error_from;
using hmfnet::test::overwrite_dataset;
using hmfnet::test::require_input_error;
using hmfnet::test::TempDirectory;
using hmfnet::test::weighted_er;

namespace {

void delete_object(const std::string& path, const std::string& name) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(file >= 0);
  CHECK(H5Ldelete(file, name.c_str(), H5P_DEFAULT) >= 0);
  H5Fclose(file);
}

void set_int_attribute(const std::string& path, const std::string& object, const std::string& name,
                       std::int64_t value) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t where = H5Oopen(file, object.c_str(), H5P_DEFAULT);
  REQUIRE(where >= 0);
  const hid_t attr = H5Aopen(where, name.c_str(), H5P_DEFAULT);
  REQUIRE(attr >= 0);
  CHECK(H5Awrite(attr, H5T_NATIVE_INT64, &value) >= 0);
  H5Aclose(attr);
  H5Oclose(where);
  H5Fclose(file);
}

// Replaces the attribute NAME of OBJECT by a floating-point one (a foreign writer's n = 1000.9).
void set_double_attribute(const std::string& path, const std::string& object,
                          const std::string& name, double value) {
  const Hdf5File file(path, Hdf5File::Mode::update);
  const H5Id where(H5Oopen(file.id(), object.c_str(), H5P_DEFAULT), H5Oclose);
  REQUIRE(where.get() >= 0);
  file.set_attribute(where.get(), name, value);
}

// A small valid file of the unweighted test network, for the corruption tests.
std::string valid_file(const TempDirectory& dir) {
  const std::string path = dir.file("net.h5");
  write_network_hdf5(path, test::unweighted_network_with_loops());
  return path;
}

}  // namespace

TEST_CASE("HDF5 network round trip is exact [0/1 with self-loops]", "[io][hdf5]") {
  TempDirectory dir;
  const Network net = test::unweighted_network_with_loops();
  write_network_hdf5(dir.file("u.h5"), net, R"({"generator": "test"})");
  CHECK(dir.listing() == std::vector<std::string>{"u.h5"});
  const ReadResult r = read_network_hdf5(dir.file("u.h5"));
  CHECK(r.warnings.empty());
  test::require_same_network(r.network, net);

  const Hdf5File file(dir.file("u.h5"), Hdf5File::Mode::read);
  CHECK(file.string_attribute(file.id(), "hmfnet_format") == "network");
  CHECK(file.int_attribute(file.id(), "format_version") == 1);
  CHECK(file.string_attribute(file.id(), "provenance") == R"({"generator": "test"})");
  const H5Id group = file.open_group("network");
  CHECK(file.int_attribute(group.get(), "n") == net.size());
  CHECK(file.int_attribute(group.get(), "nnz") == net.nnz());
  CHECK(file.int_attribute(group.get(), "edges") == net.edges());
  CHECK(file.int_attribute(group.get(), "self_loops") == 2);
  CHECK(file.int_attribute(group.get(), "weighted") == 0);
  CHECK_FALSE(file.exists("network/weights"));
}

TEST_CASE("HDF5 network round trip is exact [weighted with self-loops]", "[io][hdf5]") {
  TempDirectory dir;
  const Network net = test::awkward_weighted_network();
  write_network_hdf5(dir.file("w.h5"), net);
  const ReadResult r = read_network_hdf5(dir.file("w.h5"));
  test::require_same_network(r.network, net);
}

TEST_CASE("HDF5 network writer replaces an existing file [overwrite]", "[io][hdf5]") {
  TempDirectory dir;
  write_network_hdf5(dir.file("o.h5"), test::awkward_weighted_network());
  const Network net = test::unweighted_network_with_loops();
  write_network_hdf5(dir.file("o.h5"), net);
  test::require_same_network(read_network_hdf5(dir.file("o.h5")).network, net);
  CHECK(dir.listing() == std::vector<std::string>{"o.h5"});
}

TEST_CASE("HDF5 network reader refuses a file that is not HDF5 [text file]", "[io][hdf5]") {
  TempDirectory dir;
  test::write_text(dir.file("text.h5"), "%%MatrixMarket matrix coordinate pattern symmetric\n");
  const auto e = input_error_from([&] { read_network_hdf5(dir.file("text.h5")); });
  require_input_error(e, dir.file("text.h5"), 0, "not an HDF5 file");
}

TEST_CASE("HDF5 network reader refuses a missing file [no file]", "[io][hdf5]") {
  TempDirectory dir;
  const auto e = input_error_from([&] { read_network_hdf5(dir.file("absent.h5")); });
  require_input_error(e, dir.file("absent.h5"), 0, "not an HDF5 file (or cannot be read)");
}

TEST_CASE(
    "HDF5 network reader refuses an HDF5 file without the hmfnet_format attribute "
    "[foreign HDF5]",
    "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = dir.file("foreign.h5");
  const hid_t file = H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(file >= 0);
  H5Gclose(H5Gcreate2(file, "network", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT));
  H5Fclose(file);
  const auto e = input_error_from([&] { read_network_hdf5(path); });
  require_input_error(e, path, 0, "not an hmfnet network file");
}

TEST_CASE(
    "HDF5 network reader refuses another hmfnet file kind and an unknown format version "
    "[format]",
    "[io][hdf5]") {
  TempDirectory dir;
  SECTION("hmfnet_format is not 'network'") {
    const std::string path = dir.file("run.h5");
    {
      const Hdf5File file(path, Hdf5File::Mode::create);
      file.set_attribute(file.id(), "hmfnet_format", std::string("trajectory"));
    }
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "not an hmfnet network file");
  }
  SECTION("format version 7") {
    const std::string path = valid_file(dir);
    set_int_attribute(path, "/", "format_version", 7);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "network format version 7 is not supported (1 or 2)");
  }
  SECTION("a CSR file marked as format 2 (implicit) without a structure") {
    const std::string path = valid_file(dir);
    set_int_attribute(path, "/", "format_version", 2);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    REQUIRE(e.has_value());
    CHECK_THAT(e->cause(), Contains("structure"));
  }
}

TEST_CASE(
    "HDF5 network reader refuses a column index out of range written after the fact "
    "[corrupted col]",
    "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = valid_file(dir);
  std::vector<std::int32_t> cols = read_network_hdf5(path).network.cols();
  cols.back() = 6;  // n = 6: one past the last node
  overwrite_dataset(path, "/network/col", cols, H5T_NATIVE_INT32);
  const auto e = input_error_from([&] { read_network_hdf5(path); });
  require_input_error(e, path, 0, "/network: column index 6 in row 5 out of range [0,6)");
}

TEST_CASE("HDF5 network reader refuses a stored matrix that is not symmetric [corrupted col]",
          "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = valid_file(dir);
  // Row 5 is {1, 4}; {2, 4} keeps it sorted and in range, but now (1,5) has no transpose.
  std::vector<std::int32_t> cols = read_network_hdf5(path).network.cols();
  REQUIRE(cols[cols.size() - 2] == 1);
  cols[cols.size() - 2] = 2;
  overwrite_dataset(path, "/network/col", cols, H5T_NATIVE_INT32);
  const auto e = input_error_from([&] { read_network_hdf5(path); });
  require_input_error(e, path, 0, "/network: entry (1,5) has no transpose (5,1)");
}

TEST_CASE(
    "HDF5 network reader refuses row pointers that run past the column array "
    "[corrupted row_ptr]",
    "[io][hdf5]") {
  TempDirectory dir;
  SECTION("pointer one past the end in the middle, columns ascending to the end") {
    // Two self-loops: col = {0, 1}, row_ptr = {0, 1, 2}. With row_ptr[1] = 3 row 0 claims
    // col[0..3), whose entries ascend up to the end of the array: only a check of the pointers
    // themselves stops a read of col[2], one past the end (found by valgrind before the fix).
    const std::string path = dir.file("loops.h5");
    write_network_hdf5(path, Network::from_undirected_edges(2, {{0, 0}, {1, 1}}));
    overwrite_dataset<std::int64_t>(path, "/network/row_ptr", {0, 3, 2}, H5T_NATIVE_INT64);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "/network: row_ptr[1] = 3");
  }
  SECTION("huge pointer in the middle") {
    const std::string path = valid_file(dir);
    std::vector<std::int64_t> row_ptr = read_network_hdf5(path).network.row_ptr();
    row_ptr[1] = std::numeric_limits<std::int64_t>::max() / 2;
    overwrite_dataset(path, "/network/row_ptr", row_ptr, H5T_NATIVE_INT64);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "/network: row_ptr[1] = " + std::to_string(row_ptr[1]));
  }
  SECTION("decreasing pointers") {
    const std::string path = valid_file(dir);
    std::vector<std::int64_t> row_ptr = read_network_hdf5(path).network.row_ptr();
    row_ptr[2] = row_ptr[1] - 1;
    overwrite_dataset(path, "/network/row_ptr", row_ptr, H5T_NATIVE_INT64);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "/network: row_ptr");
  }
  SECTION("last pointer disagrees with the column count") {
    const std::string path = valid_file(dir);
    std::vector<std::int64_t> row_ptr = read_network_hdf5(path).network.row_ptr();
    const auto nnz = row_ptr.back();
    row_ptr.back() = nnz - 1;
    overwrite_dataset(path, "/network/row_ptr", row_ptr, H5T_NATIVE_INT64);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "/network: row_ptr");
  }
}

TEST_CASE(
    "HDF5 network reader refuses a non-positive weight and a missing weights dataset "
    "[corrupted weights]",
    "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = dir.file("w.h5");
  write_network_hdf5(path, test::awkward_weighted_network());
  SECTION("negative weight") {
    std::vector<double> weights = read_network_hdf5(path).network.weights();
    weights.front() = -1.0;
    overwrite_dataset(path, "/network/weights", weights, H5T_NATIVE_DOUBLE);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "/network: entry (0,0) has weight -1.000000");
  }
  SECTION("NaN weight") {
    std::vector<double> weights = read_network_hdf5(path).network.weights();
    weights.front() = std::numeric_limits<double>::quiet_NaN();
    overwrite_dataset(path, "/network/weights", weights, H5T_NATIVE_DOUBLE);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "(weights must be finite and > 0)");
  }
  SECTION("weights dataset deleted") {
    delete_object(path, "/network/weights");
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "missing dataset weights");
  }
}

TEST_CASE(
    "HDF5 network reader refuses a missing group or dataset and a wrong node count "
    "[incomplete]",
    "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = valid_file(dir);
  SECTION("no /network") {
    delete_object(path, "/network");
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "missing group network");
  }
  SECTION("no /network/col") {
    delete_object(path, "/network/col");
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "missing dataset col");
  }
  SECTION("node count disagrees with row_ptr") {
    set_int_attribute(path, "/network", "n", 7);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "/network: row_ptr has 7 entries, expected n+1 = 8");
  }
  SECTION("negative node count") {
    set_int_attribute(path, "/network", "n", -3);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "/network: node count -3 out of range");
  }
}

TEST_CASE("HDF5 network reader refuses a file holding a network with no edges [empty]",
          "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = dir.file("empty.h5");
  write_network_hdf5(path, Network::from_undirected_edges(3, {}));
  const auto e = input_error_from([&] { read_network_hdf5(path); });
  require_input_error(e, path, 0, "empty network: 3 nodes and no edges");
}

// Found by an adversarial probe: H5Aread converted a float n = 1000.9 to the integer 1000 and the
// file was read as if it held 1000 nodes, while a float col dataset was refused.
TEST_CASE(
    "HDF5 network readers refuse an integer attribute stored as a float, naming it "
    "[float n, nnz, weighted, format_version]",
    "[io][hdf5]") {
  TempDirectory dir;
  const std::string cause = " has the wrong type class (floating point; an integer is expected)";
  SECTION("a CSR file's n, nnz and weighted, read whole and by rows") {
    for (const char* name : {"n", "nnz", "weighted"}) {
      const std::string path = valid_file(dir);
      set_double_attribute(path, "/network", name, 1000.9);
      INFO("attribute " << name);
      require_input_error(input_error_from([&] { read_network_hdf5(path); }), path, 0,
                          "attribute " + std::string(name) + cause);
      require_input_error(input_error_from([&] { read_network_hdf5_rows(path, 0, 2); }), path, 0,
                          "attribute " + std::string(name) + cause);
    }
  }
  SECTION("format_version 1.0: equal to an allowed value, still the wrong class") {
    const std::string path = valid_file(dir);
    set_double_attribute(path, "/", "format_version", 1.0);
    require_input_error(input_error_from([&] { read_network_hdf5(path); }), path, 0,
                        "attribute format_version" + cause);
  }
  SECTION("the complete graph's n and nnz") {
    const std::string path = dir.file("k.h5");
    for (const char* name : {"n", "nnz", "self_loops_all"}) {
      write_complete_graph_hdf5(path, CompleteGraph::make(50, false));
      set_double_attribute(path, "/network", name, 50.0);
      INFO("attribute " << name);
      require_input_error(input_error_from([&] { read_implicit_network_hdf5(path); }), path, 0,
                          "attribute " + std::string(name) + cause);
    }
  }
}

TEST_CASE("HDF5 real attributes accept integers and refuse strings [double_attribute]",
          "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = dir.file("a.h5");
  {
    const Hdf5File file(path, Hdf5File::Mode::create);
    file.set_attribute(file.id(), "count", std::int64_t{7});
    file.set_attribute(file.id(), "text", std::string("7.5"));
  }
  const Hdf5File file(path, Hdf5File::Mode::read);
  CHECK(file.double_attribute(file.id(), "count") == 7.0);
  require_input_error(input_error_from([&] { file.double_attribute(file.id(), "text"); }), path, 0,
                      "attribute text has the wrong type class (string; a number is expected)");
  require_input_error(input_error_from([&] { file.int_attribute(file.id(), "text"); }), path, 0,
                      "attribute text has the wrong type class (string; an integer is expected)");
}

// Found by an adversarial probe: a weights dataset in a file whose attribute says weighted = 0
// was silently ignored, so the network was read as 0/1 whatever the weights held.
TEST_CASE(
    "HDF5 network readers refuse weights that the weighted attribute contradicts "
    "[weights with weighted = 0, weighted = 2]",
    "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = valid_file(dir);
  SECTION("a weights dataset while weighted = 0") {
    {
      const Hdf5File file(path, Hdf5File::Mode::update);
      const H5Id group = file.open_group("network");
      const auto nnz = static_cast<std::size_t>(file.int_attribute(group.get(), "nnz"));
      file.write(group.get(), "weights", std::vector<double>(nnz, 2.5));
    }
    const std::string cause = "/network: dataset weights is present but attribute weighted = 0";
    require_input_error(input_error_from([&] { read_network_hdf5(path); }), path, 0, cause);
    for (int part = 0; part < 2; ++part) {
      require_input_error(input_error_from([&] { read_network_hdf5_rows(path, part, 2); }), path, 0,
                          cause);
    }
  }
  SECTION("weighted = 2") {
    set_int_attribute(path, "/network", "weighted", 2);
    require_input_error(input_error_from([&] { read_network_hdf5(path); }), path, 0,
                        "/network: weighted = 2 (allowed: 0 or 1)");
    require_input_error(input_error_from([&] { read_network_hdf5_rows(path, 0, 1); }), path, 0,
                        "/network: weighted = 2 (allowed: 0 or 1)");
  }
}

TEST_CASE("HDF5 network readers refuse an nnz attribute that disagrees with col [summary nnz]",
          "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = valid_file(dir);
  const auto nnz = static_cast<std::int64_t>(read_network_hdf5(path).network.nnz());
  set_int_attribute(path, "/network", "nnz", nnz + 1);
  const std::string cause = "/network: attribute nnz = " + std::to_string(nnz + 1) +
                            " but dataset col holds " + std::to_string(nnz) + " entries";
  require_input_error(input_error_from([&] { read_network_hdf5(path); }), path, 0, cause);
  require_input_error(input_error_from([&] { read_network_hdf5_rows(path, 1, 2); }), path, 0,
                      cause);
}

TEST_CASE("HDF5 network writer to a missing directory throws and creates nothing [no dir]",
          "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = dir.file("missing/net.h5");
  const auto e =
      input_error_from([&] { write_network_hdf5(path, test::unweighted_network_with_loops()); });
  require_input_error(e, path, 0, "does not exist");
  CHECK(dir.listing().empty());
}

namespace {

// Replaces the attribute NAME of OBJECT by an array of `count` copies of `value`: the same name
// and type class, but not one value.
void make_array_attribute(const std::string& path, const std::string& object,
                          const std::string& name, hid_t file_type, const void* values,
                          hsize_t count) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t where = H5Oopen(file, object.c_str(), H5P_DEFAULT);
  REQUIRE(H5Adelete(where, name.c_str()) >= 0);
  const hid_t space = H5Screate_simple(1, &count, nullptr);
  const hid_t attr = H5Acreate2(where, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT);
  REQUIRE(attr >= 0);
  CHECK(H5Awrite(attr, file_type, values) >= 0);
  H5Aclose(attr);
  H5Sclose(space);
  H5Oclose(where);
  H5Fclose(file);
}

}  // namespace

// Found while writing tests/fuzz, reproduced by crashes/network_hdf5/*_attribute_array.h5: H5Aread
// fills every value of the attribute's dataspace into a buffer for one (an AddressSanitizer
// stack-buffer-overflow in the fuzz build).
TEST_CASE("HDF5 network reader refuses an attribute stored as an array [fuzz: attribute shape]",
          "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = valid_file(dir);
  SECTION("integer attribute format_version") {
    const std::vector<std::int64_t> versions(64, 1);
    make_array_attribute(path, "/", "format_version", H5T_NATIVE_INT64, versions.data(), 64);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "attribute format_version is not a single value");
  }
  SECTION("string attribute hmfnet_format") {
    const hid_t type = H5Tcopy(H5T_C_S1);
    H5Tset_size(type, 7);
    std::string values;
    for (int k = 0; k < 64; ++k) values += "network";
    make_array_attribute(path, "/", "hmfnet_format", type, values.data(), 64);
    H5Tclose(type);
    const auto e = input_error_from([&] { read_network_hdf5(path); });
    require_input_error(e, path, 0, "attribute hmfnet_format is not a single value");
  }
}

// Found by tests/fuzz (crashes/network_hdf5/crash-2aa902...): a corrupted dataspace declared far
// more values than the file holds, and the reader allocated them before H5Dread failed.
TEST_CASE(
    "HDF5 network reader refuses a dataset that declares more values than it stores "
    "[fuzz: dataset length]",
    "[io][hdf5]") {
  TempDirectory dir;
  const std::string path = valid_file(dir);
  {
    // 2^40 column indices declared and never written: HDF5 allocates no storage for them.
    delete_object(path, "/network/col");
    const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    REQUIRE(file >= 0);
    const hsize_t length = hsize_t{1} << 40;
    const hid_t space = H5Screate_simple(1, &length, nullptr);
    const hid_t set = H5Dcreate2(file, "/network/col", H5T_STD_I32LE, space, H5P_DEFAULT,
                                 H5P_DEFAULT, H5P_DEFAULT);
    REQUIRE(set >= 0);
    H5Dclose(set);
    H5Sclose(space);
    H5Fclose(file);
  }
  const auto e = input_error_from([&] { read_network_hdf5(path); });
  require_input_error(e, path, 0,
                      "dataset col declares 1099511627776 values but stores only 0 bytes");
}

TEST_CASE("HDF5 complete graph round trip holds N and the loops in O(1) [N = 10^6]",
          "[io][hdf5][complete]") {
  TempDirectory dir;
  for (const bool loops : {false, true}) {
    const CompleteGraph graph = CompleteGraph::make(1000000, loops);
    write_complete_graph_hdf5(dir.file("k.h5"), graph, R"({"generator": "test"})");
    const auto back = read_implicit_network_hdf5(dir.file("k.h5"));
    REQUIRE(back.has_value());
    CHECK(back->n == graph.n);
    CHECK(back->self_loops == loops);
    const Hdf5File file(dir.file("k.h5"), Hdf5File::Mode::read);
    CHECK(file.int_attribute(file.id(), "format_version") == 2);
    const H5Id group = file.open_group("network");
    CHECK(file.int_attribute(group.get(), "nnz") == graph.nnz());
    CHECK(file.int_attribute(group.get(), "edges") == graph.edges());
    CHECK_FALSE(file.exists("network/col"));
  }
  CHECK(dir.listing() == std::vector<std::string>{"k.h5"});
  // A CSR file is not implicit: the caller reads its rows.
  CHECK_FALSE(read_implicit_network_hdf5(valid_file(dir)).has_value());
}

TEST_CASE("HDF5 reader of rows refuses the complete graph stored implicitly, naming it",
          "[io][hdf5][complete]") {
  TempDirectory dir;
  write_complete_graph_hdf5(dir.file("k.h5"), CompleteGraph::make(50, false));
  const auto e = input_error_from([&] { read_network_hdf5(dir.file("k.h5")); });
  require_input_error(e, dir.file("k.h5"), 0,
                      "the complete graph of 50 nodes is stored implicitly, not as rows");
}

TEST_CASE(
    "HDF5 complete graph reader refuses N, loops and summaries that disagree [corrupted "
    "attributes]",
    "[io][hdf5][complete]") {
  TempDirectory dir;
  const std::string path = dir.file("k.h5");
  const std::vector<std::pair<std::string, std::int64_t>> corruptions = {
      {"n", 1},          {"n", -5},    {"n", std::int64_t{1} << 31}, {"self_loops_all", 2},
      {"nnz", 2450 + 1}, {"edges", 7}, {"self_loops", 50},           {"weighted", 1}};
  const std::vector<std::string> causes = {
      "/network: n = 1 (allowed: 2 <= n <= 2147483647)",
      "/network: n = -5 (allowed: 2 <= n <= 2147483647)",
      "/network: n = 2147483648 (allowed: 2 <= n <= 2147483647)",
      "/network: self_loops_all = 2 (allowed: 0 or 1)",
      "/network: nnz = 2451 disagrees with the complete graph of n = 50 without self-loops (2450)",
      "/network: edges = 7 disagrees with the complete graph of n = 50 without self-loops (1225)",
      "/network: self_loops = 50 disagrees with the complete graph of n = 50 without self-loops "
      "(0)",
      "/network: weighted = 1 disagrees with the complete graph of n = 50 without self-loops (0)"};
  for (std::size_t k = 0; k < corruptions.size(); ++k) {
    write_complete_graph_hdf5(path, CompleteGraph::make(50, false));
    set_int_attribute(path, "network", corruptions[k].first, corruptions[k].second);
    INFO(corruptions[k].first << " = " << corruptions[k].second);
    require_input_error(input_error_from([&] { read_implicit_network_hdf5(path); }), path, 0,
                        causes[k]);
  }
}

TEST_CASE("HDF5 network reader refuses an unknown implicit structure and format version",
          "[io][hdf5][complete]") {
  TempDirectory dir;
  const std::string path = dir.file("ring.h5");
  {
    const Hdf5File file(path, Hdf5File::Mode::create);
    file.set_attribute(file.id(), "hmfnet_format", std::string("network"));
    file.set_attribute(file.id(), "format_version", std::int64_t{2});
    const H5Id group = file.create_group("network");
    file.set_attribute(group.get(), "structure", std::string("ring"));
    file.set_attribute(group.get(), "n", std::int64_t{10});
  }
  require_input_error(input_error_from([&] { read_implicit_network_hdf5(path); }), path, 0,
                      "/network: structure \"ring\" is not known (complete)");
  write_complete_graph_hdf5(path, CompleteGraph::make(50, false));
  set_int_attribute(path, "/", "format_version", 3);
  require_input_error(input_error_from([&] { read_implicit_network_hdf5(path); }), path, 0,
                      "network format version 3 is not supported (1 or 2)");
}

TEST_CASE("HDF5 row blocks read by hyperslabs are the rows of the whole network [ER, 1-5 parts]",
          "[io][hdf5][row_block]") {
  TempDirectory dir;
  for (const bool weighted : {false, true}) {
    const Network net = weighted ? weighted_er(700, 0.03, 4) : erdos_renyi({700, 0.03, 4});
    const std::string path = dir.file(weighted ? "w.h5" : "u.h5");
    write_network_hdf5(path, net);
    for (int parts = 1; parts <= 5; ++parts) {
      const auto starts = balanced_row_starts(net.row_ptr(), parts);
      for (int p = 0; p < parts; ++p) {
        const RowBlock block = read_network_hdf5_rows(path, p, parts);
        const RowBlock expected = slice_rows(net, starts[std::size_t(p)],
                                             starts[std::size_t(p) + 1] - starts[std::size_t(p)]);
        INFO("weighted " << weighted << ", part " << p << " of " << parts);
        CHECK(block.n == net.size());
        CHECK(block.first_row == expected.first_row);
        CHECK(test::bit_difference(block.row_ptr, expected.row_ptr) == "");
        CHECK(test::bit_difference(block.cols, expected.cols) == "");
        CHECK(test::bit_difference(block.weights, expected.weights) == "");
      }
    }
  }
}

TEST_CASE("HDF5 row blocks refuse a corrupted entry in the second block only, naming its row",
          "[io][hdf5][row_block]") {
  TempDirectory dir;
  const std::string path = dir.file("net.h5");
  const Network net = erdos_renyi({400, 0.05, 9});
  write_network_hdf5(path, net);
  std::vector<std::int32_t> cols = net.cols();
  cols.back() = 400;  // the last row's last column: one past the last node
  overwrite_dataset(path, "/network/col", cols, H5T_NATIVE_INT32);
  CHECK_NOTHROW(read_network_hdf5_rows(path, 0, 2));
  const auto e = input_error_from([&] { read_network_hdf5_rows(path, 1, 2); });
  require_input_error(e, path, 0, "/network: column index 400 in row 399 out of range [0,400)");
}

TEST_CASE("HDF5 row blocks refuse a part outside 0 .. parts - 1", "[io][hdf5][row_block]") {
  TempDirectory dir;
  const std::string path = valid_file(dir);
  CHECK_THROWS_AS(read_network_hdf5_rows(path, 2, 2), ParameterError);
  CHECK_THROWS_AS(read_network_hdf5_rows(path, -1, 2), ParameterError);
  CHECK_THROWS_AS(read_network_hdf5_rows(path, 0, 0), ParameterError);
}

TEST_CASE("HDF5 row blocks refuse row pointers that do not start at 0 [shifted row_ptr]",
          "[io][hdf5][row_block]") {
  TempDirectory dir;
  const std::string path = valid_file(dir);
  std::vector<std::int64_t> row_ptr = read_network_hdf5(path).network.row_ptr();
  REQUIRE(row_ptr[1] >= 1);
  row_ptr[0] = 1;  // row 0 loses its first entry: the blocks read relative to it would not see it
  overwrite_dataset(path, "/network/row_ptr", row_ptr, H5T_NATIVE_INT64);
  const auto e = input_error_from([&] { read_network_hdf5_rows(path, 0, 1); });
  require_input_error(e, path, 0, "/network: row_ptr[0] = 1, not 0");
}
