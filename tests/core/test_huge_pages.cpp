#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>

#include "core/cache_aligned.hpp"
#include "core/huge_pages.hpp"

using hmfnet::allocate_table;
using hmfnet::deallocate_table;
using hmfnet::k_huge_page_bytes;

namespace {

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

}  // namespace

// Whether the kernel backs a block with huge pages depends on its settings (never, madvise,
// always), so what is asserted is what the allocator controls: where a block starts, and that
// the advice leaves its contents as written.
TEST_CASE("allocate_table aligns large blocks on a huge page and small ones on the asked line",
          "[huge_pages]") {
  constexpr std::size_t line = 64, from = 2 * k_huge_page_bytes;
  for (const std::size_t bytes : {std::size_t{8}, std::size_t{4096}, from - 8, from,
                                  from + 4096 + 24, 5 * k_huge_page_bytes + 1}) {
    void* p = allocate_table(bytes, line, from);
    REQUIRE(p != nullptr);
    const std::size_t expected = bytes >= from ? k_huge_page_bytes : line;
    CHECK(address(p) % expected == 0);
    std::memset(p, 0x5a, bytes);
    const auto* c = static_cast<const unsigned char*>(p);
    CHECK(c[0] == 0x5a);
    CHECK(c[bytes - 1] == 0x5a);
    deallocate_table(p, bytes, line, from);
  }
}

TEST_CASE("prefer_huge_pages takes any range, whole blocks or none", "[huge_pages]") {
  // No whole 2 MiB block inside: nothing asked; a block inside: asked; neither fails or writes.
  hmfnet::CacheAlignedVector<char> v(3 * k_huge_page_bytes, 'x');
  hmfnet::prefer_huge_pages(v.data() + 1, 100);
  hmfnet::prefer_huge_pages(v.data() + 1, v.size() - 1);
  hmfnet::prefer_huge_pages(nullptr, 0);
  CHECK(v.front() == 'x');
  CHECK(v.back() == 'x');
  CHECK(address(v.data()) % k_huge_page_bytes == 0);  // >= k_huge_table_bytes: a huge page's start
}
