#include "core/page_release.hpp"

#include <sys/mman.h>
#include <unistd.h>

namespace hmfnet {

namespace {

// In steps of 1 MiB: ~2,600 rows of degree 100 a madvise call.
constexpr std::uintptr_t k_step = std::uintptr_t{1} << 20;

std::uintptr_t page() {
  static const auto bytes = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  return bytes;
}

std::uintptr_t address(const void* p) { return reinterpret_cast<std::uintptr_t>(p); }

std::uintptr_t round_up(std::uintptr_t a) { return (a + page() - 1) / page() * page(); }

}  // namespace

PageRelease::PageRelease(const void* begin) : m_done(round_up(address(begin))) {}

void PageRelease::up_to(const void* end) {
  const std::uintptr_t to = address(end) / page() * page();
  if (to < m_done + k_step) return;
  // NOLINTNEXTLINE(performance-no-int-to-ptr): the pages of an array this process owns
  madvise(reinterpret_cast<void*>(m_done), to - m_done, MADV_DONTNEED);
  m_done = to;
}

}  // namespace hmfnet
