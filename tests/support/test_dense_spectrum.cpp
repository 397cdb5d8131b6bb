#include <catch2/catch.hpp>
#include <cmath>

#include "support/dense_spectrum.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

TEST_CASE("Dense spectrum matches closed forms: star / K_ab / complete / regular", "[dense]") {
  using Catch::Matchers::WithinRel;
  REQUIRE_THAT(test::dense_spectrum(test::star(26)).eigenvalues.back(), WithinRel(5.0, 1e-12));
  REQUIRE_THAT(test::dense_spectrum(test::complete_bipartite(4, 9)).eigenvalues.back(),
               WithinRel(6.0, 1e-12));
  REQUIRE_THAT(test::dense_spectrum(test::complete(20)).eigenvalues.back(), WithinRel(19.0, 1e-12));
  REQUIRE_THAT(test::dense_spectrum(test::circulant(40, 3)).eigenvalues.back(),
               WithinRel(6.0, 1e-12));
  const auto bip = test::dense_spectrum(test::star(26)).eigenvalues;
  REQUIRE_THAT(bip.front(), WithinRel(-5.0, 1e-12));  // bipartite: lambda_min = -lambda
}
