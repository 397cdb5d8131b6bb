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
  // `git describe --always --dirty --abbrev=12`: a tag-based description or 12+ hex digits,
  // optionally "-dirty"; "unknown" outside a git checkout.
  const std::string commit = git_commit();
  CHECK(std::regex_match(commit,
                         std::regex(R"(unknown|([0-9A-Za-z._-]*-g)?[0-9a-f]{12,}(-dirty)?)")));
}

TEST_CASE("Version: an HDF5 network records this build's version and commit", "[version][io]") {
  test::TempDirectory dir;
  write_network_hdf5(dir.file("v.h5"), test::unweighted_network_with_loops(), "{}");
  const Hdf5File file(dir.file("v.h5"), Hdf5File::Mode::read);
  CHECK(file.string_attribute(file.id(), "hmfnet_version") == version());
  CHECK(file.string_attribute(file.id(), "git_commit") == git_commit());
}
