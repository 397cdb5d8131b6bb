#pragma once
// Transparent huge pages for the arrays the force reads at random. The sparse step gathers one
// record per stored entry from anywhere in its [cos, sin] table; in 4 KiB pages a table of
// N = 10^6 (16 MB in float64 with one replica, 128 MB with eight) spans 4,096 to 32,768 pages,
// more than a core's second-level TLB holds (Zen 4: 3,072 entries), so most gathers add a page
// walk to their line's latency. In 2 MiB pages the same table takes 8 to 64 TLB entries.
// Debian's kernels leave huge pages to madvise (/sys/kernel/mm/transparent_hugepage/enabled).
#include <cstddef>

namespace hmfnet {

/// The size of one transparent huge page on x86-64 (and AArch64 with 4 KiB base pages).
inline constexpr std::size_t k_huge_page_bytes = std::size_t{2} << 20;

/// Asks the kernel for huge pages over the whole 2 MiB blocks inside [data, data + bytes)
/// (madvise MADV_HUGEPAGE); best before the pages are first written. A request the kernel refuses
/// (huge pages off, another system) leaves the pages as they were: only their size changes.
void prefer_huge_pages(void* data, std::size_t bytes) noexcept;

/// An array of `bytes` aligned to `alignment`, or, when it is at least `huge_from` bytes, to
/// k_huge_page_bytes with huge pages asked for, so that every one of its 2 MiB blocks can be one.
void* allocate_table(std::size_t bytes, std::size_t alignment, std::size_t huge_from);

/// Releases what allocate_table(bytes, alignment, huge_from) returned.
void deallocate_table(void* p, std::size_t bytes, std::size_t alignment,
                      std::size_t huge_from) noexcept;

}  // namespace hmfnet
