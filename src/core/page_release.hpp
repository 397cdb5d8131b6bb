#pragma once
// Giving an array's pages back to the system as a copy moves through it, so that a copy made in
// place of the array (the force's narrower or segmented column indices) never holds both whole:
// the peak is the larger of the two, not their sum.
#include <cstdint>

namespace hmfnet {

/// Releases the pages of an array behind a pass that moves forward through it from `begin`:
/// up_to(p) gives back the whole pages between the last release and p (madvise MADV_DONTNEED:
/// the array must not be read there again; they read as zeros if it is), in steps of at least
/// 1 MiB. Whole pages only, so nothing outside [begin, p) is lost.
class PageRelease {
 public:
  explicit PageRelease(const void* begin);
  void up_to(const void* end);

 private:
  std::uintptr_t m_done;
};

}  // namespace hmfnet
