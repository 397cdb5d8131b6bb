#include "core/huge_pages.hpp"

#include <sys/mman.h>

#include <cstdint>
#include <new>

namespace hmfnet {

namespace {

std::size_t table_alignment(std::size_t bytes, std::size_t alignment, std::size_t huge_from) {
  return bytes >= huge_from && alignment < k_huge_page_bytes ? k_huge_page_bytes : alignment;
}

}  // namespace

void prefer_huge_pages(void* data, std::size_t bytes) noexcept {
  const auto first = reinterpret_cast<std::uintptr_t>(data);
  const auto begin = (first + k_huge_page_bytes - 1) / k_huge_page_bytes * k_huge_page_bytes;
  const auto end = (first + bytes) / k_huge_page_bytes * k_huge_page_bytes;
  if (end <= begin) return;
  // NOLINTNEXTLINE(performance-no-int-to-ptr): the pages of an array this process owns
  static_cast<void>(madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE));
}

void* allocate_table(std::size_t bytes, std::size_t alignment, std::size_t huge_from) {
  const std::size_t align = table_alignment(bytes, alignment, huge_from);
  void* p = ::operator new (bytes, std::align_val_t{align});
  if (align == k_huge_page_bytes) prefer_huge_pages(p, bytes);
  return p;
}

void deallocate_table(void* p, std::size_t bytes, std::size_t alignment,
                      std::size_t huge_from) noexcept {
  ::operator delete (p, std::align_val_t{table_alignment(bytes, alignment, huge_from)});
}

}  // namespace hmfnet
