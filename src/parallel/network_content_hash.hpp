#pragma once
// A 64-bit hash of a network's stored entries, for checkpoints: a run resumes only on the network
// that started it, and two networks of the same size and entry count (random regular graphs of
// two seeds) must not pass for one another. Each stored entry (row, column, weight) is mixed into
// 64 bits (the splitmix64 finaliser, Steele, Lea & Flood, OOPSLA 2014) and the mixes are added
// modulo 2^64: the sum does not depend on the order of the entries, so it is the same whatever
// the rank count, the row blocks and each rank's column order. Not cryptographic: it guards
// against accidents, one changed entry or weight changes it with probability 1 - 2^-64.
#include <cstdint>
#include <string>

#include "parallel/distributed_network.hpp"

namespace hmfnet {

/// Collective. The complete graph held without rows hashes its size and self-loops.
std::uint64_t network_content_hash(const DistributedNetwork& network);

/// The hash as 16 hexadecimal digits.
std::string hash_hex(std::uint64_t hash);

}  // namespace hmfnet
