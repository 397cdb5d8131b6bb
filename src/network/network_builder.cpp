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

// General input: the transpose of every entry must be present with the same weight. Counts
// the entries of rows [first, last) that have none. When the policy allows it, forms
// (A + A^T)/2 whatever the count: exact where the transpose matches (w/2 + w/2 = w for normal
// w), and right for a part of the rows whose own entries all match while an entry of another
// part, in one of these columns, has no transpose here.
std::vector<MatrixEntry> resolve_general(const std::string& source,
                                         std::vector<MatrixEntry> entries,
                                         const BuildOptions& options, NodeIndex first,
                                         NodeIndex last, RowsBuild& build) {
  std::sort(entries.begin(), entries.end(), by_position);
  reject_duplicates(source, entries, options.index_base, "entry");
  for (const auto& e : entries) {
    if (e.row == e.col || e.row < first || e.row >= last) continue;
    const MatrixEntry key{e.col, e.row, 0.0, 0};
    const auto it = std::lower_bound(entries.begin(), entries.end(), key, by_position);
    const bool matched =
        it != entries.end() && it->row == e.col && it->col == e.row && it->weight == e.weight;
    if (!matched) {
      if (build.unmatched++ == 0) {
        build.first_unmatched_line = e.line;
        build.first_unmatched = pair_name(e, options.index_base);
      }
    }
  }
  if (options.asymmetry == AsymmetryPolicy::reject) return entries;
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

// The rows [first, last) of the entries as a block, sized exactly; weights only when some
// differ from 1 (all_ones says which).
void assemble(NodeIndex n, NodeIndex first, NodeIndex last, std::vector<MatrixEntry>& entries,
              RowsBuild& build) {
  std::sort(entries.begin(), entries.end(), by_position);
  const auto begin =
      std::lower_bound(entries.begin(), entries.end(), MatrixEntry{first, 0, 0, 0}, by_position);
  const auto end =
      std::lower_bound(entries.begin(), entries.end(), MatrixEntry{last, 0, 0, 0}, by_position);
  build.all_ones = std::all_of(begin, end, [](const MatrixEntry& e) { return e.weight == 1.0; });
  RowBlock& block = build.block;
  block.n = n;
  block.first_row = first;
  block.row_ptr.assign(static_cast<std::size_t>(last - first) + 1, 0);
  block.cols.assign(static_cast<std::size_t>(end - begin), 0);
  block.weights.assign(build.all_ones ? 0 : block.cols.size(), 0.0);
  std::size_t k = 0;
  for (auto e = begin; e != end; ++e, ++k) {
    ++block.row_ptr[static_cast<std::size_t>(e->row - first) + 1];
    block.cols[k] = e->col;
    if (!build.all_ones) block.weights[k] = e->weight;
  }
  for (std::size_t r = 0; r + 1 < block.row_ptr.size(); ++r)
    block.row_ptr[r + 1] += block.row_ptr[r];
}

}  // namespace

std::string asymmetry_message(const RowsBuild& first_part, std::int64_t unmatched) {
  return "matrix is not symmetric: entry " + first_part.first_unmatched +
         " has no transpose of equal weight (" + std::to_string(unmatched) +
         " such entries); use --symmetrize to take (A+A^T)/2";
}

std::string asymmetry_warning(const std::string& source, std::int64_t unmatched) {
  return source + ": warning: matrix is not symmetric (" + std::to_string(unmatched) +
         " entries without an equal transpose); using (A+A^T)/2";
}

std::string zeros_warning(const std::string& source, std::int64_t zeros) {
  return source + ": warning: " + std::to_string(zeros) +
         " explicit zero entries dropped (a zero weight is no edge)";
}

RowsBuild build_rows(const std::string& source, NodeIndex n, NodeIndex first, NodeIndex last,
                     std::vector<MatrixEntry> entries, const BuildOptions& options) {
  RowsBuild build;
  check_weights(source, entries);
  const auto is_zero = [](const MatrixEntry& e) { return e.weight == 0.0; };
  if (std::any_of(entries.begin(), entries.end(), is_zero)) {
    reject_duplicates_among_all(source, entries, options);
    build.zeros = std::count_if(entries.begin(), entries.end(), [&](const MatrixEntry& e) {
      return is_zero(e) && e.row >= first && e.row < last;
    });
    entries.erase(std::remove_if(entries.begin(), entries.end(), is_zero), entries.end());
  }
  entries = options.symmetry == EntrySymmetry::symmetric
                ? expand_symmetric(source, std::move(entries), options.index_base)
                : resolve_general(source, std::move(entries), options, first, last, build);
  assemble(n, first, last, entries, build);
  return build;
}

BuildResult build_network(const std::string& source, NodeIndex n, std::vector<MatrixEntry> entries,
                          const BuildOptions& options) {
  BuildResult result;
  // An empty network is refused before its n + 1 row pointers are allocated: with no entries the
  // node count is not bounded by io/node_count_limit.hpp ("# nodes 1999999999" alone asked for
  // 16 GB; found by tests/fuzz). Bad weights and repeated zeros are still named first.
  if (n <= 0 || std::all_of(entries.begin(), entries.end(),
                            [](const MatrixEntry& e) { return e.weight == 0.0; })) {
    build_rows(source, 0, 0, 0, std::move(entries), options);
    throw InputError(source, 0, "empty network: " + std::to_string(n) + " nodes and no edges");
  }
  RowsBuild build = build_rows(source, n, 0, n, std::move(entries), options);
  if (build.zeros > 0) result.warnings.push_back(zeros_warning(source, build.zeros));
  if (build.unmatched > 0) {
    if (options.asymmetry == AsymmetryPolicy::reject) {
      throw InputError(source, build.first_unmatched_line,
                       asymmetry_message(build, build.unmatched));
    }
    result.warnings.push_back(asymmetry_warning(source, build.unmatched));
  }
  RowBlock& b = build.block;
  result.network =
      Network::from_csr(n, std::move(b.row_ptr), std::move(b.cols), std::move(b.weights));
  return result;
}

}  // namespace hmfnet
