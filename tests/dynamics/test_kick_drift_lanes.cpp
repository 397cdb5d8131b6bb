// The kick and drift in vector lanes (dynamics/kick_drift_lanes.hpp): every instruction set this
// CPU runs, every replica count (one flat run; widths that fill the lanes, leave a remainder, or
// are narrower than them) and every row range give kernel_arithmetic.hpp's kicked_momentum and
// drifted_angle, cell by cell, bit for bit.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "dynamics/kernel_arithmetic.hpp"
#include "dynamics/kick_drift_lanes.hpp"
#include "dynamics/sincos.hpp"
#include "support/bit_difference.hpp"

using namespace hmfnet;

namespace {

// Values of mixed magnitude, so that forming c (K g) instead of (c K) g, or dropping the drift's
// use of the new p, changes bits; and the values where only the exact operations give the same
// bits: p = -0.0 (which a kick of -0.0 keeps and one of +0.0 turns into +0.0), g infinite or NaN,
// and, with `zero_couplings`, K_b = +-0.0 (so that c K_b is -0.0 for one sign of c).
struct Cells {
  std::vector<double> p, theta, g, K;
  Cells(std::size_t rows, std::size_t w, bool zero_couplings)
      : p(rows * w), theta(rows * w), g(rows * w), K(w) {
    for (std::size_t k = 0; k < p.size(); ++k) {
      const auto x = static_cast<double>(k);
      theta[k] = 0.1 + 1e-3 * static_cast<double>(k % 97);
      p[k] = k % 11 == 5 ? -0.0 : 6.0 + std::sin(x);
      g[k] = std::cos(0.7 * x) * std::pow(10.0, static_cast<double>(k % 9) - 4);
      if (k % 29 == 3) g[k] = std::numeric_limits<double>::infinity();
      if (k % 31 == 7) g[k] = std::numeric_limits<double>::quiet_NaN();
    }
    for (std::size_t b = 0; b < w; ++b) {
      K[b] =
          zero_couplings ? (b % 2 == 0 ? -0.0 : 0.0) : (1.3 + 0.1 * static_cast<double>(b)) / 3.0;
    }
  }
  KickDriftCells view(std::size_t w, bool drift) {
    return {p.data(), drift ? theta.data() : nullptr, g.data(), K.data(), w};
  }
};

}  // namespace

TEST_CASE("the kick and drift lanes give the scalar cell's bits in every instruction set",
          "[kick_drift_lanes]") {
  // A closing kick of either sign, the opening one positive.
  const double c_open = 0.07 / 3.0, c_drift = 0.1 / 7.0;
  const std::size_t rows = 37;
  for (const std::size_t w : {1U, 2U, 3U, 4U, 7U, 8U, 12U, 16U, 17U, 24U}) {
    for (const bool zero_couplings : {false, true}) {
      for (const double c_close : {0.05 / 3.0, -0.05 / 3.0}) {
        for (const bool drift : {false, true}) {
          for (const int kicks : {1, 2}) {
            // One kick by c_close, or a step's closing kick (c_close) then the next one's.
            const KickDriftCoefficients c =
                kicks == 2 ? KickDriftCoefficients{{c_close, c_open}, 2, c_drift}
                           : KickDriftCoefficients{{c_close, 0.0}, 1, c_drift};
            // Rows [r0, r1) changed, the others left as they were.
            for (const auto& range :
                 {std::pair<std::size_t, std::size_t>{0, rows}, {3, 4}, {5, 30}, {10, 10}}) {
              Cells expected(rows, w, zero_couplings);
              for (std::size_t r = range.first; r < range.second; ++r) {
                for (std::size_t b = 0; b < w; ++b) {
                  const std::size_t k = r * w + b;
                  for (int i = 0; i < kicks; ++i) {
                    expected.p[k] = kicked_momentum(expected.p[k], i == 0 ? c_close : c_open,
                                                    expected.K[b], expected.g[k]);
                  }
                  if (drift) {
                    expected.theta[k] = drifted_angle(expected.theta[k], c_drift, expected.p[k]);
                  }
                }
              }
              for (const SincosIsa isa :
                   {SincosIsa::baseline, SincosIsa::avx2, SincosIsa::avx512}) {
                if (!sincos_isa_available(isa)) {
                  WARN(sincos_isa_name(isa) << " not on this CPU: not compared");
                  continue;
                }
                INFO(sincos_isa_name(isa)
                     << ", " << w << " replicas, zero couplings " << zero_couplings
                     << ", closing kick " << c_close << ", drift " << drift << ", " << kicks
                     << " kicks, rows " << range.first << ".." << range.second);
                Cells cells(rows, w, zero_couplings);
                kick_drift_rows_isa(isa, cells.view(w, drift), c, range.first, range.second);
                CHECK(test::bit_difference(cells.p, expected.p) == "");
                CHECK(test::bit_difference(cells.theta, expected.theta) == "");
              }
              // The default set is one of them.
              Cells cells(rows, w, zero_couplings);
              kick_drift_rows(cells.view(w, drift), c, range.first, range.second);
              CHECK(test::bit_difference(cells.p, expected.p) == "");
              CHECK(test::bit_difference(cells.theta, expected.theta) == "");
            }
          }
        }
      }
    }
  }
}
