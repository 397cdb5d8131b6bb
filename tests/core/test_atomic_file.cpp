// AtomicFile: an output appears under its final name only on commit(), never partially, and a
// destination that cannot be written is reported before any work is done.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "core/atomic_file.hpp"
#include "support/io_helpers.hpp"

using namespace hmfnet;
using hmfnet::test::input_error_from;
using hmfnet::test::read_text;
using hmfnet::test::require_input_error;
using hmfnet::test::TempDirectory;
using hmfnet::test::write_text;
namespace fs = std::filesystem;

TEST_CASE("AtomicFile shows nothing under the final name before commit [commit]", "[atomic_file]") {
  TempDirectory dir;
  const std::string path = dir.file("out.txt");
  AtomicFile file(path);
  CHECK(file.final_path() == path);
  INFO("temporary " << file.temp_path());
  CHECK(file.temp_path() != path);
  CHECK(fs::path(file.temp_path()).parent_path() == dir.path());
  write_text(file.temp_path(), "complete content\n");
  CHECK_FALSE(fs::exists(path));
  file.commit();
  CHECK(read_text(path) == "complete content\n");
  CHECK_FALSE(fs::exists(file.temp_path()));
  CHECK(dir.listing() == std::vector<std::string>{"out.txt"});
}

TEST_CASE("AtomicFile keeps an existing file intact until commit replaces it [overwrite]",
          "[atomic_file]") {
  TempDirectory dir;
  const std::string path = dir.file("out.txt");
  write_text(path, "old\n");
  {
    AtomicFile file(path);
    write_text(file.temp_path(), "new\n");
    CHECK(read_text(path) == "old\n");
    file.commit();
  }
  CHECK(read_text(path) == "new\n");
  CHECK(dir.listing() == std::vector<std::string>{"out.txt"});
}

TEST_CASE("AtomicFile removes its temporary when commit is never called [abandoned]",
          "[atomic_file]") {
  TempDirectory dir;
  const std::string path = dir.file("out.txt");
  std::string temp;
  {
    AtomicFile file(path);
    temp = file.temp_path();
    write_text(temp, "partial");
    REQUIRE(fs::exists(temp));
  }
  CHECK_FALSE(fs::exists(temp));
  CHECK_FALSE(fs::exists(path));
  CHECK(dir.listing().empty());
}

TEST_CASE("AtomicFile removes its temporary when the writer throws [exception]", "[atomic_file]") {
  TempDirectory dir;
  const std::string path = dir.file("out.txt");
  std::string temp;
  try {
    AtomicFile file(path);
    temp = file.temp_path();
    write_text(temp, "partial");
    throw std::runtime_error("writer failed half way");
  } catch (const std::runtime_error&) {
  }
  CHECK_FALSE(temp.empty());
  CHECK(dir.listing().empty());
}

TEST_CASE("AtomicFile throws at construction for a missing directory [no dir]", "[atomic_file]") {
  TempDirectory dir;
  const std::string path = dir.file("no/such/dir/out.txt");
  const auto e = input_error_from([&] { AtomicFile file(path); });
  require_input_error(e, path, 0,
                      "cannot write: directory '" + dir.file("no/such/dir") + "' does not exist");
  CHECK(dir.listing().empty());
}

TEST_CASE("AtomicFile throws at construction when the parent is a regular file [not a dir]",
          "[atomic_file]") {
  TempDirectory dir;
  write_text(dir.file("plain"), "x");
  const std::string path = dir.file("plain/out.txt");
  const auto e = input_error_from([&] { AtomicFile file(path); });
  require_input_error(e, path, 0, "does not exist");
}

TEST_CASE("AtomicFile throws at construction for an unwritable directory [chmod 0555]",
          "[atomic_file]") {
  if (::geteuid() == 0) {
    WARN("running as root: permission bits do not stop root, unwritable-directory case skipped");
    return;
  }
  TempDirectory dir;
  const fs::path locked = dir.path() / "locked";
  fs::create_directory(locked);
  fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
  const std::string path = (locked / "out.txt").string();
  const auto e = input_error_from([&] { AtomicFile file(path); });
  fs::permissions(locked, fs::perms::owner_all);
  require_input_error(e, path, 0, "is not writable");
}

TEST_CASE("AtomicFile rejects an empty path [empty]", "[atomic_file]") {
  const auto e = input_error_from([] { AtomicFile file(""); });
  require_input_error(e, "<output>", 0, "empty output path");
}

TEST_CASE(
    "AtomicFile commit without a written temporary throws naming the final path "
    "[nothing written]",
    "[atomic_file]") {
  TempDirectory dir;
  const std::string path = dir.file("out.txt");
  AtomicFile file(path);
  const auto e = input_error_from([&] { file.commit(); });
  require_input_error(e, path, 0, "cannot rename temporary output into place");
  CHECK_FALSE(fs::exists(path));
}

TEST_CASE("AtomicFile writes a bare file name into the current directory [relative path]",
          "[atomic_file]") {
  TempDirectory dir;
  struct RestoreDirectory {
    fs::path previous = fs::current_path();
    ~RestoreDirectory() { fs::current_path(previous); }
  } restore;
  fs::current_path(dir.path());
  {
    AtomicFile file("out.txt");
    CHECK(fs::path(file.temp_path()).parent_path().empty());
    write_text(file.temp_path(), "here");
    file.commit();
  }
  CHECK(read_text(dir.file("out.txt")) == "here");
  CHECK(dir.listing() == std::vector<std::string>{"out.txt"});
}

TEST_CASE("A destination without room for the output is refused at start-up [free space]",
          "[atomic_file]") {
  TempDirectory dir;
  const std::string path = dir.file("results.h5");
  REQUIRE_NOTHROW(require_free_space(path, 1));
  const auto available = fs::space(dir.path()).available;
  const auto e = input_error_from([&] { require_free_space(path, available + (1u << 30)); });
  REQUIRE(e.has_value());
  CHECK(e->file() == path);
  CHECK_THAT(e->cause(), Catch::Contains("not enough free space") && Catch::Contains("MB"));
}
