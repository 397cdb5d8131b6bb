#include "parallel/entry_exchange.hpp"

#include <Tpetra_Core.hpp>
#include <Tpetra_Distributor.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <type_traits>

#include "parallel/parallel_session.hpp"

namespace hmfnet {

namespace {

std::size_t at(std::int64_t k) { return static_cast<std::size_t>(k); }

// One round: this rank's entries [first, last) sent, what it receives appended to `mine`.
void exchange_round(const std::vector<MatrixEntry>& entries, std::size_t first, std::size_t last,
                    const std::vector<NodeIndex>& row_starts, Destinations destinations,
                    std::vector<MatrixEntry>& mine) {
  constexpr std::size_t bytes = sizeof(MatrixEntry);
  const auto owner_of = [&](NodeIndex row) {
    return static_cast<int>(std::upper_bound(row_starts.begin(), row_starts.end(), row) -
                            row_starts.begin()) -
           1;
  };
  const std::size_t ranks = row_starts.size() - 1;
  std::vector<int> owner;
  std::vector<char> packets;
  ParallelSession::agree([&] {
    // The packets grouped by destination (what createFromSends wants).
    std::vector<std::size_t> next(ranks + 1, 0);
    const auto for_each_send = [&](const auto& send) {
      for (std::size_t k = first; k < last; ++k) {
        const MatrixEntry& e = entries[k];
        const int p = owner_of(e.row);
        send(p, e);
        if (destinations == Destinations::row_and_column_owner) {
          const int q = owner_of(e.col);
          if (q != p) send(q, e);
        }
      }
    };
    for_each_send([&](int p, const MatrixEntry&) { ++next[at(p) + 1]; });
    for (std::size_t p = 0; p < ranks; ++p) next[p + 1] += next[p];
    owner.resize(next[ranks]);
    packets.resize(next[ranks] * bytes);
    for_each_send([&](int p, const MatrixEntry& e) {
      const std::size_t slot = next[at(p)]++;
      owner[slot] = p;
      std::memcpy(&packets[slot * bytes], &e, bytes);
    });
  });
  Tpetra::Distributor distributor(Tpetra::getDefaultComm());
  const std::size_t imports = distributor.createFromSends(Teuchos::ArrayView<const int>(owner));
  const std::size_t before = mine.size();
  ParallelSession::agree([&] { mine.resize(before + imports); });
  // Received in place, as bytes (MatrixEntry is trivially copyable).
  distributor.doPostsAndWaits<char>(
      Teuchos::ArrayView<const char>(packets), bytes,
      Teuchos::ArrayView<char>(reinterpret_cast<char*>(mine.data() + before),
                               static_cast<Teuchos::ArrayView<char>::size_type>(imports * bytes)));
}

}  // namespace

std::vector<MatrixEntry> send_to_owners(const std::vector<MatrixEntry>& entries,
                                        const std::vector<NodeIndex>& row_starts,
                                        Destinations destinations, std::size_t round_entries) {
  static_assert(std::is_trivially_copyable_v<MatrixEntry>);
  // Rounds bound the packets and keep each message below MPI's 2^31 bytes (Tpetra passes its
  // length as an int): at most 2 round_entries entries of 24 bytes to one rank per round.
  const std::size_t chunk = std::max<std::size_t>(round_entries, 1);
  const auto rounds = static_cast<std::size_t>(ParallelSession::max(
      std::ceil(static_cast<double>(entries.size()) / static_cast<double>(chunk))));
  std::vector<MatrixEntry> mine;
  for (std::size_t round = 0; round < rounds; ++round) {
    const std::size_t first = std::min(entries.size(), round * chunk);
    const std::size_t last = std::min(entries.size(), first + chunk);
    exchange_round(entries, first, last, row_starts, destinations, mine);
  }
  return mine;
}

}  // namespace hmfnet
