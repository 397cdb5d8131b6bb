#include "parallel/network_content_hash.hpp"

#include <cstdio>
#include <cstring>
#include <vector>

#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30U)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27U)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31U);
}

// Row and column go through separate rounds, so (i, j) and (j, i) mix differently.
std::uint64_t entry_hash(std::int64_t row, std::int64_t column, double weight) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &weight, sizeof bits);
  std::uint64_t h = mix(static_cast<std::uint64_t>(row));
  h = mix(h ^ static_cast<std::uint64_t>(column));
  return mix(h ^ bits);
}

}  // namespace

std::uint64_t network_content_hash(const DistributedNetwork& network) {
  std::vector<std::uint64_t> sum{0};
  if (!network.stores_rows()) {
    sum[0] = mix(static_cast<std::uint64_t>(network.global_size())) +
             static_cast<std::uint64_t>(network.global_self_loops());
  } else {
    const auto& a = network.local_adjacency();
    const std::vector<NodeIndex> globals = network.column_globals();
    const NodeIndex first = network.first_row();
    for (NodeIndex r = 0; r < network.local_size(); ++r) {
      const auto row = static_cast<std::size_t>(r);
      for (EdgeOffset k = a.row_ptr[row]; k < a.row_ptr[row + 1]; ++k) {
        const auto entry = static_cast<std::size_t>(k);
        const double w = a.weights.empty() ? 1.0 : a.weights[entry];
        sum[0] += entry_hash(first + r, globals[static_cast<std::size_t>(a.cols[entry])], w);
      }
    }
  }
  ParallelSession::sum_in_place(sum);  // addition modulo 2^64: any rank split gives the same
  return sum[0];
}

std::string hash_hex(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace hmfnet
