// The write-over-input rule (core/distinct_files.hpp): a written path is refused when it is a read
// file by any spelling, link or hard link, another written path, or the temporary of one; paths
// that differ, and read labels that name no file, pass.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>

#include "core/distinct_files.hpp"
#include "support/io_helpers.hpp"

using namespace hmfnet;
using hmfnet::test::input_error_from;
using hmfnet::test::require_input_error;
using hmfnet::test::TempDirectory;
using hmfnet::test::write_text;
namespace fs = std::filesystem;

TEST_CASE("A written path that is the input by any name is refused [spelling, links]",
          "[distinct_files]") {
  TempDirectory dir;
  const std::string input = dir.file("net.mtx");
  write_text(input, "content\n");
  fs::create_symlink(input, dir.file("link.mtx"));
  fs::create_hard_link(input, dir.file("hard.mtx"));
  const std::string dotted = (fs::path(dir.path()) / "." / "net.mtx").string();
  for (const std::string& written : {input, dotted, dir.file("link.mtx"), dir.file("hard.mtx")}) {
    INFO("written " << written);
    require_input_error(input_error_from([&] {
                          require_distinct_files({{"input", input}}, {{"--output", written}});
                        }),
                        written, 0, "--output names the same file as the input file " + input);
  }
}

TEST_CASE("Two outputs of one name, and an input an output's temporary would replace, are refused",
          "[distinct_files]") {
  TempDirectory dir;
  const std::string out = dir.file("out.h5");
  require_input_error(input_error_from([&] {
                        require_distinct_files({}, {{"--output", out}, {"--checkpoint", out}});
                      }),
                      out, 0, "--checkpoint names the same file as --output " + out);
  // AtomicFile writes OUT.tmp.PID.COUNTER before its rename.
  const std::string temporary_like = out + ".tmp.1.0";
  write_text(temporary_like, "content\n");
  require_input_error(input_error_from([&] {
                        require_distinct_files({{"input", temporary_like}}, {{"--output", out}});
                      }),
                      out, 0, "names the same file as the input file");
}

TEST_CASE("Distinct files, empty paths and labels that name no file pass", "[distinct_files]") {
  TempDirectory dir;
  const std::string input = dir.file("net.mtx");
  write_text(input, "content\n");
  REQUIRE_NOTHROW(require_distinct_files({{"input", input}}, {{"--output", dir.file("out.h5")},
                                                              {"--checkpoint", dir.file("ckpt.h5")},
                                                              {"--checkpoint", ""}}));
  REQUIRE_NOTHROW(
      require_distinct_files({{"input", "networkx graph"}}, {{"--output", "networkx graph"}}));
}
