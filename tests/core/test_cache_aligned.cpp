#include <catch2/catch.hpp>
#include <cstdint>

#include "core/cache_aligned.hpp"

using hmfnet::CacheAlignedVector;
using hmfnet::k_cache_line_bytes;

namespace {

template <typename T>
bool on_a_line(const CacheAlignedVector<T>& v) {
  return reinterpret_cast<std::uintptr_t>(v.data()) % k_cache_line_bytes == 0;
}

}  // namespace

// Small blocks come from malloc's heap, large ones (the tables of N = 10^4 and more: 160 KB and
// up) from their own pages, 16 bytes past the page with std::allocator.
TEST_CASE("CacheAlignedVector starts on a cache line at every size, and grows as a vector",
          "[cache_aligned]") {
  for (const std::size_t n : {1UL, 3UL, 1000UL, 20000UL, 1UL << 20}) {
    CacheAlignedVector<double> d(n, 1.5);
    CacheAlignedVector<float> f(n, 2.5F);
    CHECK(on_a_line(d));
    CHECK(on_a_line(f));
    d.resize(2 * n + 1, -1.0);
    CHECK(on_a_line(d));
    CHECK(d[n - 1] == 1.5);
    CHECK(d[2 * n] == -1.0);
  }
}
