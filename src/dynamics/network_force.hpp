#pragma once
// The general coupling force on a sparse network, one fused pass per evaluation
// (eq:dMomentum_dT_orderParam): sin and cos once per rotor, the ghost values of remote
// neighbours through one Tpetra Import, then per row the sum over neighbours of the interleaved
// [cos, sin] pairs of every replica, then g and the observable terms. OpenMP over rows with a
// static schedule: each row is summed by one thread in CSR order, so results are bit-identical
// for any thread count; 1 and 2 ranks agree to round-off (the remote columns are the same
// numbers, sums over rows are split differently).
// Precision (ForcePrecision): float64, or float32 storage of the gathered [cos, sin] table and
// the weights with float32 accumulation per row (the owned rows' cos, sin and the outputs stay
// double). Error per row: |dy_n| <= (d_n + 3) u sum_m |A_nm| with u = 2^-24 (rounding of each
// stored value and of each addition, Higham's gamma_n bound for the four-way split sum); the
// gain is half the bytes per neighbour in the gather that bounds the kernel.
// Where the gathered table outgrows the L2 cache the rows are walked segment by segment
// (column_segments.hpp: CSR segmenting), with the same additions in the same order: the same
// bits as the unblocked walk, for any segment width; wherever the rows are walked unblocked and
// every column index fits in 16 bits (at most 65,536 columns on the rank), the walk reads them in
// 16 bits (narrow_columns.hpp).
#include <cstdint>
#include <optional>
#include <vector>

#include "core/cache_aligned.hpp"
#include "dynamics/column_segments.hpp"
#include "dynamics/coupling_force.hpp"
#include "dynamics/force_precision.hpp"
#include "dynamics/narrow_columns.hpp"
#include "dynamics/ordered_sum.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

class NetworkForce : public CouplingForce {
 public:
  /// Keeps a reference to `network`, which must outlive this object. `segment_width`: columns
  /// per segment, k_automatic_segments (automatic_segment_width against this CPU's caches for
  /// the replica count of prepare and the team that evaluates), k_unsegmented, or a width >= 1
  /// (tests, benchmarks). `allow_narrow` false keeps the unblocked walk on the network's 32-bit
  /// column indices where 16 bits would hold them (the tests compare both).
  explicit NetworkForce(const DistributedNetwork& network,
                        ForcePrecision precision = ForcePrecision::float64,
                        NodeIndex segment_width = k_automatic_segments, bool allow_narrow = true);

  /// Lets the force take `network`'s column indices (the network it was made with) when it cuts
  /// them into segments or narrows them to 16 bits: the copy then replaces them
  /// (DistributedNetwork:: release_columns; peak RSS at ER N = 10^6, degree 100:
  /// docs/performance.md, "The segments in place of the network's indices"). For a run that reads
  /// the network only through this force (the CLI's simulate); the same bits either way.
  void take_columns(DistributedNetwork& network);

  void prepare(const RotorState& state, std::vector<double>& g, ForceSums& sums) override;
  EdgeOffset work_per_evaluation() const override { return m_nnz; }
  double lane_gather_cost(int lanes) const override;
  const char* name() const override {
    return m_precision == ForcePrecision::float64 ? "sparse" : "sparse-float32";
  }
  ForcePrecision precision() const { return m_precision; }
  /// {1, the trial width's segments} where the rule left the rows unblocked for the carry alone
  /// (trial_segment_width), at the last prepare's shape; empty otherwise, and for a given width.
  std::vector<int> segment_candidates() const override;
  void use_segments(int count) override;
  /// The caches the segment rules read from the next prepare on, instead of this CPU's
  /// (this_cpu_caches), with the team's size as l3_threads: another machine's, for tests and
  /// benchmarks.
  void read_caches_as(CacheSizes caches) {
    m_caches = caches;
    m_segmented_rows = -1;
  }
  /// Column segments of the last prepare (1: unblocked).
  int segments() const { return m_segments.count(); }
  /// Whether the unblocked walk of the last prepare reads 16-bit column indices.
  bool narrow_columns() const { return !m_narrow_cols.empty(); }
  /// Bytes the walk holds besides the network's column indices (or in place of them where
  /// take_columns let the force take them): the segments or the 16-bit indices, and the carried
  /// sums.
  std::size_t segment_bytes() const {
    return m_segments.bytes() + m_narrow_cols.bytes() + m_carry.size() * sizeof(double) +
           m_carry_f32.size() * sizeof(float) + m_cursor.size() * sizeof(std::uint32_t);
  }
  const std::vector<double>& local_fields() const override { return m_y; }

 private:
  void compute(const RotorState& state, std::vector<double>& g, ForceSums& sums,
               ForceOutputs outputs) override;
  /// The row kernel in precision T over the weights (nullptr: 0/1) and gathered table in T;
  /// the rows' terms only where `outputs` reads the sums (row_kernel_args.hpp); the column
  /// indices in 16 bits where m_narrow_cols holds them.
  template <typename T>
  void run_rows(const T* weights, const T* column_cs, NodeIndex rows, int replicas,
                std::vector<double>& g, ForceOutputs outputs);
  /// Cuts the columns for `replicas` (rebuilt only when the width changes) and sizes the carry;
  /// nothing when rows and replicas are those of the last call.
  void prepare_segments(NodeIndex rows, int replicas);
  /// m_segments at `width`, from the network's column indices or, once taken, from this force's;
  /// for one segment, m_narrow_cols where the columns fit in 16 bits.
  void cut(NodeIndex width);
  /// Whether a 16-bit copy of the indices beside the network's fits (half the memory left).
  bool narrow_copy_fits() const;
  /// The CSR's column indices, where the unblocked kernel reads them.
  const std::vector<NodeIndex>& csr_cols() const {
    return m_took_columns ? m_own_cols : m_adjacency.cols;
  }

  const DistributedNetwork& m_network;
  const DistributedNetwork::LocalAdjacency& m_adjacency;  ///< the network's own rows
  EdgeOffset m_nnz;                                       // stored entries of this rank's rows
  double m_inverse_n;
  bool m_identity_import;  // one rank: the column space is the owned block
  // The gathered tables start on a cache line: a record of 2B values in as few lines as it can.
  CacheAlignedVector<double> m_owned_cs;   // rows x replicas x [cos, sin]
  CacheAlignedVector<double> m_column_cs;  // columns x replicas x [cos, sin]
  std::vector<double> m_y;                 // rows x replicas x [Re y, Im y]
  std::vector<double> m_terms;             // rows x replicas x [|y_n|, Re(e^{-i theta_n} y_n)]
  std::vector<double> m_term_sums;         // replicas x [sum |y_n|, sum Re(e^{-i theta_n} y_n)]
  OrderedColumnSums m_sums;
  ForcePrecision m_precision;
  std::vector<float> m_weights_f32;        // float32: the stored weights (empty for 0/1)
  CacheAlignedVector<float> m_column_f32;  // float32: the gathered table
  NodeIndex m_segment_request;
  bool m_allow_narrow;
  NodeIndex m_segment_width = -1;           // the width m_segments was cut with (-1: not yet)
  std::optional<CacheSizes> m_caches;       // read_caches_as, else this CPU's
  NodeIndex m_trial_width = k_unsegmented;  // trial_segment_width at the last decided shape
  bool m_use_trial_width = false;           // use_segments: cut at m_trial_width
  NodeIndex m_segmented_rows = -1;          // the shape prepare_segments last decided for
  int m_segmented_replicas = -1;
  int m_segmented_threads = -1;
  ColumnSegments m_segments;
  DistributedNetwork* m_column_owner = nullptr;  // take_columns: the network to take them from
  bool m_took_columns = false;
  std::vector<NodeIndex> m_own_cols;  // taken, where no segments hold them (one segment)
  NarrowColumns m_narrow_cols;        // one segment: the indices in 16 bits, where they fit
  // Segmented walk, one panel of carried_rows(rows) rows at a time: 4 partials x replicas x
  // [cos, sin] a row in the table's type, and where each row's run stopped.
  std::vector<double> m_carry;
  std::vector<float> m_carry_f32;
  std::vector<std::uint32_t> m_cursor;
};

}  // namespace hmfnet
