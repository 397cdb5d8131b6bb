#pragma once
// Node indices (NodeIndex, 32-bit) and edge offsets (EdgeOffset, 64-bit) are signed, as Tpetra's
// ordinals are; idx() makes one a position in a std::vector, where the caller knows it is
// non-negative. One overload per width, so a narrowing never happens on the way.
#include <cstddef>
#include <cstdint>

namespace hmfnet {

constexpr std::size_t idx(std::int32_t i) { return static_cast<std::size_t>(i); }
constexpr std::size_t idx(std::int64_t k) { return static_cast<std::size_t>(k); }
/// Any other type (an unsigned size, a long long, a short) is a compile error, not a conversion.
template <class T>
constexpr std::size_t idx(T) = delete;

}  // namespace hmfnet
