// Provenance (src/core/version.hpp): the generated definitions hold a real version and commit,
// and the files hmfnet writes record exactly them.
#include <catch2/catch.hpp>
#include <regex>
#include <string>

#include "core/version.hpp"
#include "io/hdf5_file.hpp"
#include "io/network_hdf5.hpp"
#include "support/io_helpers.hpp"

using namespace hmfnet;

TEST_CASE("Version: the configure-time substitution happened", "[version]") {
  // A failed substitution leaves "@PROJECT_VERSION@" or an empty string.
  CHECK(std::regex_match(std::string(version()), std::regex(R"(\d+\.\d+\.\d+)")));
  // `git describe --always --dirty --abbrev=12` prints 12+ hex digits, a tag name (at a tagged
  // commit), or tag-N-gHEX, each optionally with "-dirty"; "unknown" outside a git checkout.
  // What must not survive is the placeholder or an empty string, or text with spaces (a
  // captured error message).
  const std::string commit = git_commit();
  CHECK_FALSE(commit.empty());
  CHECK(commit.find('@') == std::string::npos);
  CHECK(std::regex_match(commit, std::regex(R"([0-9A-Za-z._/+-]+)")));
}

TEST_CASE("Version: an HDF5 network records this build's version and commit", "[version][io]") {
  test::TempDirectory dir;
  write_network_hdf5(dir.file("v.h5"), test::unweighted_network_with_loops(), "{}");
  const Hdf5File file(dir.file("v.h5"), Hdf5File::Mode::read);
  CHECK(file.string_attribute(file.id(), "hmfnet_version") == version());
  CHECK(file.string_attribute(file.id(), "git_commit") == git_commit());
}
