#pragma once
// The angles where a sincos is hardest to get right: the doubles nearest k pi/2, where one of cos
// and sin is tiny and the whole reduction error shows in its relative error. Every k up to 2000,
// then k growing by 1% up to 6.3 10^6 (|x| ~ 10^7), each with both neighbours and both signs,
// and the angles a review found 20-3900 ulp off before the reduction carried its rounding.
// Used by tests/dynamics/test_sincos.cpp (accuracy) and test_kernel_arithmetic.cpp (bit identity).
#include <cmath>
#include <vector>

namespace hmfnet::test {

inline std::vector<double> sincos_hard_angles() {
  const long double half_pi = 1.5707963267948966192313216916397514L;
  std::vector<double> x = {45.553093477052, 5830.795965062656, 8166.5701030066675,
                           9436423.844736237};
  for (double k = 1.0; k < 6.3e6; k = k < 2000.0 ? k + 1.0 : std::ceil(k * 1.01)) {
    const auto nearest = static_cast<double>(static_cast<long double>(k) * half_pi);
    for (const double v : {nearest, std::nextafter(nearest, 0.0), std::nextafter(nearest, 1e9)}) {
      x.push_back(v);
      x.push_back(-v);
    }
  }
  return x;
}

}  // namespace hmfnet::test
