#include "network/network_builder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

#include "core/error.hpp"

namespace hmfnet {

namespace {

std::string pair_name(const MatrixEntry& e, int base) {
  return "(" + std::to_string(static_cast<std::int64_t>(e.row) + base) + "," +
         std::to_string(static_cast<std::int64_t>(e.col) + base) + ")";
}

bool by_position(const MatrixEntry& a, const MatrixEntry& b) {
  return std::tie(a.row, a.col, a.line) < std::tie(b.row, b.col, b.line);
}

void check_weights(const std::string& source, const std::vector<MatrixEntry>& entries) {
  for (const auto& e : entries) {
    if (std::isnan(e.weight)) throw InputError(source, e.line, "weight is NaN");
    if (std::isinf(e.weight)) throw InputError(source, e.line, "weight is infinite");
    if (e.weight < 0.0) {
      throw InputError(source, e.line,
                       "negative weight " + std::to_string(e.weight) +
                           " (the theory assumes A_nm >= 0: Perron-Frobenius)");
    }
    // A subnormal weight has lost precision already and vanishes when (A+A^T)/2 halves it
    // (found by fuzzing: 4.9e-324 became a zero-weight edge).
    if (e.weight > 0.0 && e.weight < std::numeric_limits<double>::min()) {
      char value[32];
      std::snprintf(value, sizeof value, "%.3g", e.weight);
      throw InputError(
          source, e.line,
          std::string("weight ") + value +
              " is subnormal (below 2.2e-308): use a scale in which weights are normal "
              "numbers");
    }
  }
}

// Sorted entries: two at the same position are a duplicate, reported at the later line.
void reject_duplicates(const std::string& source, const std::vector<MatrixEntry>& sorted, int base,
                       const char* what) {
  for (std::size_t k = 1; k < sorted.size(); ++k) {
    const auto& a = sorted[k - 1];
    const auto& b = sorted[k];
    if (a.row == b.row && a.col == b.col) {
      throw InputError(source, b.line,
                       std::string("duplicate ") + what + " " + pair_name(b, base) +
                           " (first given at line " + std::to_string(a.line) + ")");
    }
  }
}

// A position given twice is a duplicate even when one copy is an explicit zero; zeros are dropped
// before the symmetric/general passes, so this looks for repeats while they are still there.
void reject_duplicates_among_all(const std::string& source, std::vector<MatrixEntry> entries,
                                 const BuildOptions& options) {
  const bool symmetric = options.symmetry == EntrySymmetry::symmetric;
  if (symmetric) {
    for (auto& e : entries) {
      if (e.row > e.col) std::swap(e.row, e.col);
    }
  }
  std::sort(entries.begin(), entries.end(), by_position);
  reject_duplicates(source, entries, options.index_base, symmetric ? "edge" : "entry");
}

// Symmetric input: canonicalise to row <= col, reject repeats, then mirror.
std::vector<MatrixEntry> expand_symmetric(const std::string& source,
                                          std::vector<MatrixEntry> entries, int base) {
  for (auto& e : entries) {
    if (e.row > e.col) std::swap(e.row, e.col);
  }
  std::sort(entries.begin(), entries.end(), by_position);
  reject_duplicates(source, entries, base, "edge");
  const std::size_t count = entries.size();
  for (std::size_t k = 0; k < count; ++k) {
    const MatrixEntry e = entries[k];
    if (e.row != e.col) entries.push_back({e.col, e.row, e.weight, e.line});
  }
  return entries;
}

// General input: the transpose of every entry must be present with the same weight; otherwise
// reject, or form (A + A^T)/2 and say how many entries were unmatched.
std::vector<MatrixEntry> resolve_general(const std::string& source,
                                         std::vector<MatrixEntry> entries,
                                         const BuildOptions& options,
                                         std::vector<std::string>& warnings) {
  std::sort(entries.begin(), entries.end(), by_position);
  reject_duplicates(source, entries, options.index_base, "entry");
  std::int64_t unmatched = 0;
  const MatrixEntry* first_unmatched = nullptr;
  for (const auto& e : entries) {
    if (e.row == e.col) continue;
    const MatrixEntry key{e.col, e.row, 0.0, 0};
    const auto it = std::lower_bound(entries.begin(), entries.end(), key, by_position);
    const bool matched =
        it != entries.end() && it->row == e.col && it->col == e.row && it->weight == e.weight;
    if (!matched) {
      ++unmatched;
      if (first_unmatched == nullptr) first_unmatched = &e;
    }
  }
  if (unmatched == 0) return entries;
  if (options.asymmetry == AsymmetryPolicy::reject) {
    throw InputError(source, first_unmatched->line,
                     "matrix is not symmetric: entry " +
                         pair_name(*first_unmatched, options.index_base) +
                         " has no transpose of equal weight (" + std::to_string(unmatched) +
                         " such entries); use --symmetrize to take (A+A^T)/2");
  }
  warnings.push_back(source + ": warning: matrix is not symmetric (" + std::to_string(unmatched) +
                     " entries without an equal transpose); using (A+A^T)/2");
  std::vector<MatrixEntry> both;
  both.reserve(2 * entries.size());
  for (const auto& e : entries) {
    if (e.row == e.col) {
      both.push_back(e);
      continue;
    }
    both.push_back({e.row, e.col, 0.5 * e.weight, e.line});
    both.push_back({e.col, e.row, 0.5 * e.weight, e.line});
  }
  std::sort(both.begin(), both.end(), by_position);
  std::vector<MatrixEntry> merged;
  for (const auto& e : both) {
    if (!merged.empty() && merged.back().row == e.row && merged.back().col == e.col) {
      merged.back().weight += e.weight;
    } else {
      merged.push_back(e);
    }
  }
  return merged;
}

Network assemble(NodeIndex n, std::vector<MatrixEntry>& entries) {
  std::sort(entries.begin(), entries.end(), by_position);
  const bool all_ones = std::all_of(entries.begin(), entries.end(),
                                    [](const MatrixEntry& e) { return e.weight == 1.0; });
  std::vector<EdgeOffset> row_ptr(static_cast<std::size_t>(n) + 1, 0);
  std::vector<NodeIndex> cols(entries.size());
  std::vector<double> weights(all_ones ? 0 : entries.size());
  for (std::size_t k = 0; k < entries.size(); ++k) {
    ++row_ptr[static_cast<std::size_t>(entries[k].row) + 1];
    cols[k] = entries[k].col;
    if (!all_ones) weights[k] = entries[k].weight;
  }
  for (std::size_t i = 0; i < static_cast<std::size_t>(n); ++i) row_ptr[i + 1] += row_ptr[i];
  return Network::from_csr(n, std::move(row_ptr), std::move(cols), std::move(weights));
}

}  // namespace

BuildResult build_network(const std::string& source, NodeIndex n, std::vector<MatrixEntry> entries,
                          const BuildOptions& options) {
  BuildResult result;
  check_weights(source, entries);
  const auto zeros = std::count_if(entries.begin(), entries.end(),
                                   [](const MatrixEntry& e) { return e.weight == 0.0; });
  if (zeros > 0) {
    reject_duplicates_among_all(source, entries, options);
    entries.erase(std::remove_if(entries.begin(), entries.end(),
                                 [](const MatrixEntry& e) { return e.weight == 0.0; }),
                  entries.end());
    result.warnings.push_back(source + ": warning: " + std::to_string(zeros) +
                              " explicit zero entries dropped (a zero weight is no edge)");
  }
  if (n <= 0 || entries.empty()) {
    throw InputError(source, 0, "empty network: " + std::to_string(n) + " nodes and no edges");
  }
  entries = options.symmetry == EntrySymmetry::symmetric
                ? expand_symmetric(source, std::move(entries), options.index_base)
                : resolve_general(source, std::move(entries), options, result.warnings);
  result.network = assemble(n, entries);
  return result;
}

}  // namespace hmfnet
