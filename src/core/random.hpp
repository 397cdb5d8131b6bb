#pragma once
// Reproducible random numbers. std:: distributions are implementation-defined (libstdc++ and
// libc++ give different normals from the same engine), so every distribution used for results is
// written here: xoshiro256** (Blackman & Vigna 2018) seeded through splitmix64, uniform doubles
// from the top 53 bits, normals by the Marsaglia polar method.
//
// Streams: Rng(seed, stream) gives statistically independent sequences for different stream ids,
// so a generator can draw row i of a network from stream i. That makes results independent of
// the order rows are visited in, hence of thread and rank counts.
#include <array>
#include <cmath>
#include <cstdint>

namespace hmfnet {

/// splitmix64 finaliser (Steele, Lea & Flood 2014): a bijective mix of 64 bits.
constexpr std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

class Rng {
 public:
  /// Stream `stream` of the generator family selected by `seed`.
  explicit Rng(std::uint64_t seed, std::uint64_t stream = 0) {
    std::uint64_t sm = seed;
    const std::uint64_t mixed_seed = splitmix64(sm);
    std::uint64_t st = mixed_seed ^ (stream * 0xd1342543de82ef95ULL + 0x2545f4914f6cdd1dULL);
    for (auto& word : m_s) word = splitmix64(st);
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(m_s[1] * 5, 7) * 9;
    const std::uint64_t t = m_s[1] << 17;
    m_s[2] ^= m_s[0];
    m_s[3] ^= m_s[1];
    m_s[1] ^= m_s[2];
    m_s[0] ^= m_s[3];
    m_s[2] ^= t;
    m_s[3] = rotl(m_s[3], 45);
    return result;
  }

  /// Uniform in [0, 1): 53 random bits.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// Uniform in (0, 1]: safe as the argument of log.
  double uniform_open_zero() { return static_cast<double>((next() >> 11) + 1) * 0x1.0p-53; }

  /// Uniform integer in [0, bound), bound > 0 (Lemire's multiply-shift, rejection for exactness).
  std::uint64_t below(std::uint64_t bound) {
    for (;;) {
      const std::uint64_t x = next();
      const unsigned __int128 m = static_cast<unsigned __int128>(x) * bound;
      const auto low = static_cast<std::uint64_t>(m);
      if (low >= bound || low >= (0 - bound) % bound) return static_cast<std::uint64_t>(m >> 64);
    }
  }

  /// Standard normal, Marsaglia polar method (two uniforms, rejection; one value cached).
  double normal() {
    if (m_has_spare) {
      m_has_spare = false;
      return m_spare;
    }
    double u = 0.0, v = 0.0, s = 0.0;
    do {
      u = 2.0 * uniform() - 1.0;
      v = 2.0 * uniform() - 1.0;
      s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    const double factor = std::sqrt(-2.0 * std::log(s) / s);
    m_spare = v * factor;
    m_has_spare = true;
    return u * factor;
  }

  /// The full state, for checkpoints.
  std::array<std::uint64_t, 4> state() const { return m_s; }

 private:
  static constexpr std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::array<std::uint64_t, 4> m_s{};
  double m_spare = 0.0;
  bool m_has_spare = false;
};

}  // namespace hmfnet
