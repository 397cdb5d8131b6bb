// ns per angle of hmfnet's sincos (src/dynamics/sincos.hpp) in every instruction set this CPU
// runs, of an earlier commit's sincos_interleaved (linked under the namespace hmfnet_before by
// bench/sincos_table.sh) and of SLEEF's 8-lane AVX-512 sincos (Sleef_sincosd8_u10avx512f, 1 ulp,
// and _u35, 3.5 ulp; Debian's libsleef-dev, when the script finds it), all on the same 4096
// angles uniform in +-100 (one thread, in L1), timed alternately in this one process: each round
// times every version once, and the table gives the median of the rounds per version and its
// ratio to the earlier commit's. Also checks that every hmfnet version gives the earlier commit's
// bits. Not a test: bench/sincos_table.sh builds and runs it.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "dynamics/sincos.hpp"

namespace hmfnet_before {
void sincos_interleaved(const double* x, std::size_t n, double* cs);
}

// SLEEF's declarations of its AVX-512 functions need __AVX512F__: bench/sincos_table.sh compiles
// this file a second time with -mavx512f and HMFNET_BENCH_SLEEF_WRAPPERS for these two only.
namespace bench_sleef {
void sleef_u10(const double* x, std::size_t n, double* cs);
void sleef_u35(const double* x, std::size_t n, double* cs);
}  // namespace bench_sleef

#ifdef HMFNET_BENCH_SLEEF_WRAPPERS
#include <immintrin.h>
#include <sleef.h>
namespace bench_sleef {
namespace {
// SLEEF returns (sin, cos) in two vectors; interleaved as hmfnet writes them.
void store_interleaved(Sleef___m512d_2 r, double* cs) {
  const __m512i lo_index = _mm512_set_epi64(11, 3, 10, 2, 9, 1, 8, 0);
  const __m512i hi_index = _mm512_set_epi64(15, 7, 14, 6, 13, 5, 12, 4);
  _mm512_storeu_pd(cs, _mm512_permutex2var_pd(r.y, lo_index, r.x));
  _mm512_storeu_pd(cs + 8, _mm512_permutex2var_pd(r.y, hi_index, r.x));
}
}  // namespace
void sleef_u10(const double* x, std::size_t n, double* cs) {
  for (std::size_t k = 0; k + 8 <= n; k += 8)
    store_interleaved(Sleef_sincosd8_u10avx512f(_mm512_loadu_pd(x + k)), cs + 2 * k);
}
void sleef_u35(const double* x, std::size_t n, double* cs) {
  for (std::size_t k = 0; k + 8 <= n; k += 8)
    store_interleaved(Sleef_sincosd8_u35avx512f(_mm512_loadu_pd(x + k)), cs + 2 * k);
}
}  // namespace bench_sleef
#else

namespace {

using Sincos = void (*)(const double*, std::size_t, double*);

struct Version {
  std::string name;
  Sincos run;
  std::vector<double> ns;
};

template <hmfnet::SincosIsa Isa>
void hmfnet_isa(const double* x, std::size_t n, double* cs) {
  hmfnet::sincos_interleaved_isa(Isa, x, n, cs);
}

double time_ns_per_angle(Sincos f, const std::vector<double>& x, std::vector<double>& cs) {
  constexpr int calls = 2000;
  const auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < calls; ++i) {
    f(x.data(), x.size(), cs.data());
    asm volatile("" : : "r"(cs.data()) : "memory");
  }
  const std::chrono::duration<double, std::nano> t = std::chrono::steady_clock::now() - t0;
  return t.count() / (calls * static_cast<double>(x.size()));
}

}  // namespace

int main() {
  using hmfnet::SincosIsa;
  std::vector<double> x(4096);
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-100.0, 100.0);
  for (double& v : x) v = u(rng);
  std::vector<double> cs(2 * x.size()), before(2 * x.size());
  std::vector<Version> versions = {{"before (chosen)", hmfnet_before::sincos_interleaved, {}}};
  const std::pair<SincosIsa, Sincos> isas[] = {
      {SincosIsa::baseline, hmfnet_isa<SincosIsa::baseline>},
      {SincosIsa::avx2, hmfnet_isa<SincosIsa::avx2>},
      {SincosIsa::avx512, hmfnet_isa<SincosIsa::avx512>}};
  hmfnet_before::sincos_interleaved(x.data(), x.size(), before.data());
  for (const auto& [isa, f] : isas) {
    if (!hmfnet::sincos_isa_available(isa)) continue;
    f(x.data(), x.size(), cs.data());
    const bool same = std::memcmp(cs.data(), before.data(), cs.size() * sizeof(double)) == 0;
    std::printf("hmfnet %s: %s bits as before\n", hmfnet::sincos_isa_name(isa),
                same ? "the same" : "NOT the same");
    versions.push_back({std::string("hmfnet ") + hmfnet::sincos_isa_name(isa), f, {}});
  }
#ifdef HMFNET_BENCH_SLEEF
  if (__builtin_cpu_supports("avx512f")) {
    versions.push_back({"SLEEF 3.5 u10 avx512f", bench_sleef::sleef_u10, {}});
    versions.push_back({"SLEEF 3.5 u35 avx512f", bench_sleef::sleef_u35, {}});
  }
#endif
  constexpr int rounds = 7;
  for (int r = 0; r < rounds; ++r)
    for (Version& v : versions) v.ns.push_back(time_ns_per_angle(v.run, x, cs));
  const auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  };
  const double reference = median(versions.front().ns);
  std::printf("%-24s %12s %12s %16s\n", "version", "ns/angle", "min", "before / this");
  for (const Version& v : versions) {
    const double m = median(v.ns);
    std::printf("%-24s %12.3f %12.3f %16.2f\n", v.name.c_str(), m,
                *std::min_element(v.ns.begin(), v.ns.end()), reference / m);
  }
  return 0;
}
#endif
