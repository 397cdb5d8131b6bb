// CSR segmenting of the sparse force kernel (dynamics/column_segments.hpp): the segmented walk
// equals the unblocked one bit for bit, for forces and for whole trajectories, at segment widths
// from one column to nearly all of them, 1 and 2 threads, float64 and float32, 1 to 4, 8 and
// 13 replicas, 0/1 and weighted rows; on 2 ranks (label mpi) the same with ghost columns. The
// widths are forced small so that networks of a few hundred nodes take many segments.
#include <omp.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "dynamics/column_segments.hpp"
#include "dynamics/integrator.hpp"
#include "dynamics/network_force.hpp"
#include "dynamics/simulation.hpp"
#include "dynamics/team.hpp"
#include "network/erdos_renyi.hpp"
#include "parallel/distributed_network.hpp"
#include "parallel/network_content_hash.hpp"
#include "support/bit_difference.hpp"
#include "support/simulation_runs.hpp"
#include "support/small_networks.hpp"

using namespace hmfnet;

namespace {

struct Evaluation {
  std::vector<double> g, y;
  ForceSums sums;
  int segments = 0;
};

Evaluation evaluate(const DistributedNetwork& d, ForcePrecision p, NodeIndex width,
                    const RotorState& s) {
  NetworkForce force(d, p, width);
  Evaluation e;
  force.prepare(s, e.g, e.sums);
  in_team([&] { force.evaluate(s, e.g, e.sums); });
  e.y = force.local_fields();
  e.segments = force.segments();
  return e;
}

RotorState state(const DistributedNetwork& d, int replicas) {
  std::vector<InitialCondition> ic;
  for (int b = 0; b < replicas; ++b) ic.push_back({6.0, 1.0, static_cast<std::uint64_t>(b + 3)});
  return initial_state(d.first_row(), d.local_size(), ic);
}

// Where any output differs in its bits (g, the local fields y, both sums of every replica),
// named; "" where none does.
std::string bit_difference(const Evaluation& a, const Evaluation& b) {
  std::string out;
  const auto add = [&](const char* name, const std::vector<double>& x,
                       const std::vector<double>& y) {
    const std::string d = test::bit_difference(x, y);
    if (!d.empty()) out += std::string(out.empty() ? "" : "; ") + name + ": " + d;
  };
  add("g", a.g, b.g);
  add("y", a.y, b.y);
  add("order", a.sums.order, b.sums.order);
  add("coupling", a.sums.coupling, b.sums.coupling);
  return out;
}

// Threads for the scope, restored after.
struct Threads {
  explicit Threads(int n) : m_saved(omp_get_max_threads()) { omp_set_num_threads(n); }
  ~Threads() { omp_set_num_threads(m_saved); }
  Threads(const Threads&) = delete;
  Threads& operator=(const Threads&) = delete;
  int m_saved;
};

}  // namespace

TEST_CASE("segmented force equals the unblocked force bit for bit [ER N=603, widths 1 to 577]",
          "[column_segments]") {
  // Degrees around 15, not multiples of 4 (the tail goes to partial 0), so runs start at every
  // place mod 4 and a width of one column leaves most segments of a row empty. 603 rows: panels
  // of 151 rows and a last one of 150.
  const Network plain = erdos_renyi({603, 0.025, 17});
  const Network heavy = test::pair_weighted(plain);
  for (const Network* net : {&plain, &heavy}) {
    const DistributedNetwork d(*net);
    for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
      for (const int replicas : {1, 2, 3, 4, 8, 13}) {
        const RotorState s = state(d, replicas);
        const Evaluation unblocked = evaluate(d, precision, k_unsegmented, s);
        REQUIRE(unblocked.segments == 1);
        for (const int threads : {1, 2}) {
          const Threads scope(threads);
          for (const NodeIndex width : {1, 7, 64, 150, 577}) {
            const Evaluation cut = evaluate(d, precision, width, s);
            INFO((net->weighted() ? "weighted" : "0/1")
                 << ", " << to_string(precision) << ", B = " << replicas << ", " << threads
                 << " thread(s), width " << width << " (" << cut.segments << " segments)");
            CHECK(cut.segments > 1);
            CHECK(bit_difference(cut, unblocked) == "");
          }
        }
      }
    }
  }
}

TEST_CASE("16-bit and 32-bit segment indices give the unblocked force's bits [ER N=140000]",
          "[column_segments]") {
  // More than 2^16 columns, so that one width keeps 16-bit indices (65,536 columns: 3
  // segments, the last local index 65,535) and the next one 32-bit (65,537: 3 segments).
  const Network net = erdos_renyi({140'000, 3e-5, 31});
  const NodeIndex columns = net.size();
  REQUIRE(ColumnSegments(net.row_ptr(), net.cols(), columns, k_narrow_segment_columns).narrow());
  REQUIRE(
      !ColumnSegments(net.row_ptr(), net.cols(), columns, k_narrow_segment_columns + 1).narrow());
  // The largest local index of the narrow cut, 65,535, is stored (column 65,535 or 131,071).
  const auto stored = [&](NodeIndex c) {
    return std::find(net.cols().begin(), net.cols().end(), c) != net.cols().end();
  };
  REQUIRE((stored(k_narrow_segment_columns - 1) || stored(2 * k_narrow_segment_columns - 1)));
  const DistributedNetwork d(net);
  for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
    for (const int replicas : {1, 2, 3}) {
      const RotorState s = state(d, replicas);
      const Evaluation unblocked = evaluate(d, precision, k_unsegmented, s);
      for (const NodeIndex width : {k_narrow_segment_columns, k_narrow_segment_columns + 1}) {
        const Evaluation cut = evaluate(d, precision, width, s);
        INFO(to_string(precision) << ", B = " << replicas << ", width " << width);
        CHECK(cut.segments == 3);
        CHECK(bit_difference(cut, unblocked) == "");
      }
    }
  }
}

TEST_CASE("segmented force with fewer rows than panels and threads [ER N=5, 4 threads]",
          "[column_segments]") {
  // 5 rows: panels of 2, 2 and 1 rows, each split over 4 threads (most take none).
  const Network net = erdos_renyi({5, 0.9, 3});
  const DistributedNetwork d(net);
  const Threads scope(4);
  for (const int replicas : {1, 3}) {
    const RotorState s = state(d, replicas);
    const Evaluation unblocked = evaluate(d, ForcePrecision::float64, k_unsegmented, s);
    const Evaluation cut = evaluate(d, ForcePrecision::float64, 1, s);
    INFO("B = " << replicas);
    CHECK(cut.segments > 1);
    CHECK(bit_difference(cut, unblocked) == "");
  }
}

TEST_CASE("runs of 255 entries and more (hubs) give the unblocked force's bits [N=1500]",
          "[column_segments]") {
  // ER with five hubs joined to every node: their runs in segments of 400 columns are ~400
  // entries, past the one-byte lengths (run_lengths.hpp), so the walk reads them from the long
  // runs. Hub 900 lies before row 937 in its block of 64 rows, and 937 (a hub too) is where the
  // second of two threads starts the third panel (rows 750-1124): a walk made from inside a
  // block steps over a long run before it and starts on one. Hub 720 does the same for the
  // index copy's walk (ColumnSegments: its second thread starts at row 750, in block 704-767).
  const NodeIndex n = 1500;
  const Network er = erdos_renyi({n, 0.01, 41});
  std::vector<std::pair<NodeIndex, NodeIndex>> edges;
  const std::vector<NodeIndex> hubs{0, 720, 900, 937, 1499};
  const auto is_hub = [&](NodeIndex v) {
    return std::find(hubs.begin(), hubs.end(), v) != hubs.end();
  };
  for (NodeIndex i = 0; i < n; ++i) {
    for (EdgeOffset k = er.row_ptr()[static_cast<std::size_t>(i)];
         k < er.row_ptr()[static_cast<std::size_t>(i) + 1]; ++k) {
      const NodeIndex j = er.cols()[static_cast<std::size_t>(k)];
      if (i < j && !is_hub(i) && !is_hub(j)) edges.emplace_back(i, j);
    }
  }
  for (const NodeIndex h : hubs)
    for (NodeIndex j = 0; j < n; ++j)
      if (j != h && (!is_hub(j) || h < j)) edges.emplace_back(std::min(h, j), std::max(h, j));
  const Network net = Network::from_undirected_edges(n, edges);
  const DistributedNetwork d(net);
  const Threads scope(2);
  int team = 0;
  in_team([&] {
#pragma omp master
    team = omp_get_num_threads();
  });
  REQUIRE(team == 2);  // the walks above start inside blocks only with two threads
  for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
    for (const int replicas : {1, 2, 3}) {
      const RotorState s = state(d, replicas);
      const Evaluation unblocked = evaluate(d, precision, k_unsegmented, s);
      const Evaluation cut = evaluate(d, precision, 400, s);
      INFO(to_string(precision) << ", B = " << replicas);
      CHECK(cut.segments == 4);
      CHECK(bit_difference(cut, unblocked) == "");
    }
  }
}

TEST_CASE("segments that take the CSR's column indices: the same cut, the indices put back",
          "[column_segments]") {
  const Network net = erdos_renyi({603, 0.025, 17});
  for (const NodeIndex width : {1, 64, 577}) {
    std::vector<NodeIndex> taken = net.cols();
    const ColumnSegments copy(net.row_ptr(), net.cols(), net.size(), width);
    const ColumnSegments cut = ColumnSegments::taking(net.row_ptr(), taken, net.size(), width);
    INFO("width " << width << ", " << cut.count() << " segments");
    CHECK(cut.count() > 1);
    CHECK(taken.empty());
    CHECK(cut.bytes() == copy.bytes());
    CHECK(copy.csr_columns() == net.cols());
    CHECK(cut.csr_columns() == net.cols());
  }
  // Nothing to cut (one segment, or rows not sorted): the indices stay where they were.
  std::vector<NodeIndex> whole = net.cols();
  CHECK(ColumnSegments::taking(net.row_ptr(), whole, net.size(), net.size()).count() == 1);
  CHECK(whole == net.cols());
  std::vector<NodeIndex> unsorted = net.cols();
  std::swap(unsorted[0], unsorted[1]);
  const std::vector<NodeIndex> before = unsorted;
  CHECK(ColumnSegments::taking(net.row_ptr(), unsorted, net.size(), 64).count() == 1);
  CHECK(unsorted == before);
}

TEST_CASE("segments that take the indices give their pages back as they go [ER N=30000, 2 threads]",
          "[column_segments]") {
  // ~1.2 M entries (4.8 MB of indices): each of two threads passes the 1 MiB step of the page
  // release twice, from a start that is not on a page boundary.
  const Network net = erdos_renyi({30'000, 0.0013, 5});
  REQUIRE(net.cols().size() > 1'000'000);
  const Threads scope(2);
  std::vector<NodeIndex> taken = net.cols();
  const ColumnSegments cut = ColumnSegments::taking(net.row_ptr(), taken, net.size(), 2000);
  CHECK(cut.count() == 15);
  CHECK(taken.empty());
  const bool put_back = cut.csr_columns() == net.cols();  // (a failure prints no 10^6 values)
  CHECK(put_back);
  const DistributedNetwork d(net);
  DistributedNetwork taker(net);
  NetworkForce force(taker, ForcePrecision::float64, 2000);
  force.take_columns(taker);
  for (const int replicas : {1, 3}) {
    const RotorState s = state(d, replicas);
    const Evaluation unblocked = evaluate(d, ForcePrecision::float64, k_unsegmented, s);
    Evaluation e;
    force.prepare(s, e.g, e.sums);
    in_team([&] { force.evaluate(s, e.g, e.sums); });
    e.y = force.local_fields();
    INFO("B = " << replicas);
    CHECK(bit_difference(e, unblocked) == "");
  }
}

TEST_CASE("a force that takes the network's column indices: the same run, resumed in a new one",
          "[column_segments]") {
  // As the CLI runs: each process reads the network, and its force takes the column indices
  // when it cuts them (width 29: 11 segments on one rank). Stopped after 170 steps with a
  // checkpoint, then resumed by a second network and force: the results equal an uninterrupted
  // unblocked run's bit for bit (the checkpoint's content hash taken before the indices went).
  const Network net = erdos_renyi({300, 0.05, 6});
  SimulationParameters p = test::short_run();
  p.node_data = true;
  DistributedNetwork reference(net);
  NetworkForce unblocked(reference, ForcePrecision::float64, k_unsegmented);
  const SimulationResult whole = simulate(reference, net.degrees(), unblocked, p);

  p.checkpoint_path = test::temp_path("hmfnet_test_taken_columns");
  test::remove_on_root(p.checkpoint_path);
  p.checkpoint_seconds = 0.0;
  p.resume = true;
  SimulationResult last;
  for (const std::int64_t stop : {170, 0}) {
    DistributedNetwork d(net);
    NetworkForce force(d, ForcePrecision::float64, 29);
    NetworkForce other(d, ForcePrecision::float64, k_unsegmented);  // made before the take
    force.take_columns(d);
    p.stop_after_steps = stop;
    last = simulate(d, net.degrees(), force, p);
    CHECK(force.segments() > 1);
    Evaluation e;
    CHECK_THROWS_WITH(other.prepare(state(d, 1), e.g, e.sums), Catch::Contains("given to another"));
    // What needs the indices now says where they went.
    CHECK_THROWS_WITH(d.local_adjacency(), Catch::Contains("given to the sparse force"));
    CHECK_THROWS_WITH(network_content_hash(d), Catch::Contains("given to the sparse force"));
    std::vector<double> y;
    CHECK_THROWS_WITH(
        d.apply(std::vector<double>(static_cast<std::size_t>(d.local_size()), 1.0), y),
        Catch::Contains("given to the sparse force"));
    CHECK_THROWS_AS(force.take_columns(reference), ParameterError);
  }
  REQUIRE(last.resumed);
  REQUIRE(last.points.size() == whole.points.size());
  for (std::size_t k = 0; k < whole.points.size(); ++k) {
    CHECK(last.points[k].R_mean == whole.points[k].R_mean);
    CHECK(last.points[k].energy_rel_error_max == whole.points[k].energy_rel_error_max);
    CHECK(last.points[k].R_node == whole.points[k].R_node);
    CHECK(test::bit_difference(last.points[k].rotor_theta_bar, whole.points[k].rotor_theta_bar) ==
          "");
  }
  CHECK(last.series.energy == whole.series.energy);
  test::remove_on_root(p.checkpoint_path);
}

TEST_CASE("segmented leap-frog trajectories equal unblocked ones bit for bit [ER N=400, 40 steps]",
          "[column_segments]") {
  const Network plain = erdos_renyi({400, 0.04, 23});
  const Network heavy = test::pair_weighted(plain);
  for (const Network* net : {&plain, &heavy}) {
    const DistributedNetwork d(*net);
    for (const ForcePrecision precision : {ForcePrecision::float64, ForcePrecision::float32}) {
      for (const int replicas : {1, 2, 8}) {
        for (const int threads : {1, 2}) {
          const Threads scope(threads);
          const auto run = [&](NodeIndex width) {
            NetworkForce force(d, precision, width);
            RotorState s = state(d, replicas);
            ForceEvaluation f(force);
            f.update(s);
            const std::vector<double> K(static_cast<std::size_t>(replicas), 40.0);
            for (int step = 0; step < 40; ++step) LeapFrog().step(s, 0.05, K, f);
            return s;
          };
          const RotorState unblocked = run(k_unsegmented), cut = run(29);
          INFO((net->weighted() ? "weighted" : "0/1")
               << ", " << to_string(precision) << ", B = " << replicas << ", " << threads
               << " thread(s)");
          CHECK(test::bit_difference(cut.theta, unblocked.theta) == "");
          CHECK(test::bit_difference(cut.p, unblocked.p) == "");
        }
      }
    }
  }
}

TEST_CASE("segment runs put every row back together in CSR order, and unsorted rows stay whole",
          "[column_segments]") {
  // Rows {0, 2, 5, 9}, {}, {1, 3, 4, 8, 9}, {7}; 10 columns in segments of 3.
  const std::vector<EdgeOffset> row_ptr{0, 4, 4, 9, 10};
  const std::vector<NodeIndex> cols{0, 2, 5, 9, 1, 3, 4, 8, 9, 7};
  for (const bool allow_narrow : {true, false}) {
    const ColumnSegments cut(row_ptr, cols, 10, 3, allow_narrow);
    REQUIRE(cut.count() == 4);
    CHECK(cut.narrow() == allow_narrow);
    for (NodeIndex r = 0; r < 4; ++r) {
      std::vector<NodeIndex> joined;
      for (int s = 0; s < cut.count(); ++s) {
        const RunSpan run = cut.runs().walk(s, r).next(r);
        for (std::uint32_t k = run.begin; k < run.begin + run.n; ++k) {
          const NodeIndex local =
              allow_narrow ? NodeIndex{cut.cols<std::uint16_t>(s)[k]} : cut.cols<NodeIndex>(s)[k];
          CHECK(local < 3);  // the run lies in its segment's columns
          joined.push_back(cut.first_column(s) + local);
        }
      }
      INFO("row " << r << (allow_narrow ? ", 16-bit" : ", 32-bit"));
      CHECK(joined ==
            std::vector<NodeIndex>(cols.begin() + row_ptr[static_cast<std::size_t>(r)],
                                   cols.begin() + row_ptr[static_cast<std::size_t>(r) + 1]));
    }
  }
  const std::vector<NodeIndex> unsorted{0, 5, 2, 9, 1, 3, 4, 8, 9, 7};
  CHECK(ColumnSegments(row_ptr, unsorted, 10, 3).count() == 1);
  CHECK(ColumnSegments(row_ptr, cols, 10, 10).count() == 1);
}

TEST_CASE("automatic segment width: unblocked while the table fits in L2, half an L2 per segment",
          "[column_segments]") {
  // The Intel Xeon's caches: 2 MiB L2, a socket's 260 MiB L3, whose slices live in L2.
  const CacheSizes l2{std::size_t{2} << 20, std::size_t{260} << 20};
  CHECK_FALSE(slices_in_l3(l2));
  CHECK_FALSE(slices_in_l3(CacheSizes{std::size_t{2} << 20, 0}));
  const std::size_t plenty = std::size_t{64} << 30;
  // ER N = 10^4, degree 100, 8 float64 replicas: 1.28 MB table, fits.
  CHECK(automatic_segment_width(10'000, 1'000'000, 10'000, 128, l2, plenty) == k_unsegmented);
  // N = 10^6, degree 100, float64, one replica: 16 MB table, 16 slices of 1 MiB (62,500 columns).
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16, l2, plenty) == 62'500);
  // 8 replicas: 128 MB would take 123 slices, but 100 / 6 entries allow 16 segments.
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 128, l2, plenty) == 62'500);
  // 16 float64 replicas (256-byte records), 32 float32 ones: unblocked at any size.
  CHECK(automatic_segment_width(10'000, 1'000'000, 10'000, 256, l2, plenty) == k_unsegmented);
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 256, l2, plenty) ==
        k_unsegmented);
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 129, l2, plenty) ==
        k_unsegmented);
  // Unless the unblocked rows would run the baseline loop (no AVX2): the rule's 16 segments.
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 256, l2, plenty, false) ==
        62'500);
  // Degree 10: fewer than two segments of 6 entries: unblocked.
  CHECK(automatic_segment_width(1'000'000, 10'000'000, 1'000'000, 16, l2, plenty) == k_unsegmented);
  // The segments' memory at N = 10^6, degree 100, float64, one replica: 200 MB of 16-bit
  // column indices (62,500 columns a segment), 17 MB of run lengths (a byte a run of 16
  // segments, a 4-byte start every 64 rows, 17 offsets into the long runs), 16 MB carried and
  // 1 MB of cursors (a quarter of the rows); segments wider than 2^16 columns keep 32-bit
  // indices.
  const std::size_t extra = segmented_bytes(100'000'000, 1'000'000, 16, 62'500, 16);
  CHECK(extra == 200'000'000 + (16'000'000 + 16 * 15'626 * 4 + 17 * 8) + 16'000'000 + 1'000'000);
  CHECK(carried_rows(1'000'000) == 250'000);
  CHECK(carried_rows(1'000'001) == 250'001);
  CHECK(segmented_bytes(100'000'000, 1'000'000, 16, 65'537, 16) == extra + 200'000'000);
  CHECK(segment_index_bytes(65'536) == 2);
  CHECK(segment_index_bytes(65'537) == 4);
  // Segmented only while that leaves half the available memory.
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16, l2, 2 * extra) == 62'500);
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16, l2, 2 * extra - 1) ==
        k_unsegmented);
  CHECK(available_memory_bytes() > 0);
}

TEST_CASE("automatic segment width: slices of half a core complex's L3, where the carry pays",
          "[column_segments]") {
  // The AMD EPYC's caches: 512 KiB L2, 8 MiB L3, a core complex's.
  const CacheSizes near{std::size_t{512} << 10, std::size_t{8} << 20, 1, true};
  REQUIRE(slices_in_l3(near));
  const std::size_t plenty = std::size_t{64} << 30;
  // ER N = 10^4, degree 100: tables of 0.64 MB (float64, 4 replicas) and 1.28 MB (8) beyond the
  // L2 but within half the L3: unblocked.
  CHECK(automatic_segment_width(10'000, 1'000'000, 10'000, 64, near, plenty) == k_unsegmented);
  CHECK(automatic_segment_width(10'000, 1'000'000, 10'000, 128, near, plenty) == k_unsegmented);
  // N = 10^6, float64, one replica: 16 MB in 4 slices of at most 4 MiB; the carry (4 segments x
  // 2 x 4 x 16 B a row) well under the row's 100 lines.
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16, near, plenty) == 250'000);
  // float32, one replica: 8 MB in 2; 4 replicas (32 B): 32 MB in 8, carry 2 KB against 6.4 KB.
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 8, near, plenty) == 500'000);
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 32, near, plenty) == 125'000);
  // Records of 64 B and 128 B fill their lines: 16 segments' carry (8 KB, 16 KB a row) would move
  // more than the 6.4 KB and 12.8 KB of lines they save: unblocked.
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 64, near, plenty) ==
        k_unsegmented);
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 128, near, plenty) ==
        k_unsegmented);
  // An L3 no larger than twice the L2 holds no slice the L2 would not: slices in L2.
  CHECK_FALSE(slices_in_l3(CacheSizes{std::size_t{1} << 20, std::size_t{2} << 20, 1, true}));
  // Two threads share the L3: slices of 2 MiB, 8 segments of 125,000 columns for float64 with one
  // replica.
  const CacheSizes shared{near.l2, near.l3, 2, true};
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16, shared, plenty) == 125'000);
  // glibc's socket-wide 64 MiB, where sysfs does not answer, is not a core complex's L3.
  CHECK_FALSE(slices_in_l3(CacheSizes{std::size_t{512} << 10, std::size_t{64} << 20, 1, true}));
}

TEST_CASE(
    "automatic segment width: a thread's slices take at most its share of a core complex's L3 "
    "[AMD EPYC family 25 model 1 guest]",
    "[column_segments]") {
  // The guest's caches as sysfs reports them: 512 KiB L2, a 32 MiB L3 of a core complex; a
  // thread's re-reads ran at L3 speed only up to 8 MiB there (k_l3_thread_share_bytes).
  const CacheSizes guest{std::size_t{512} << 10, std::size_t{32} << 20, 1, true};
  REQUIRE(slices_in_l3(guest));
  const std::size_t plenty = std::size_t{64} << 30;
  // ER N = 10^6, degree 100. float64, one replica: 16 MB in slices of 4 MiB (half of 8 MiB, not
  // of 32), 4 segments of 250,000 columns; float32: 8 MB in 2.
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16, guest, plenty) == 250'000);
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 8, guest, plenty) == 500'000);
  // float32, 4 replicas (32 B): 32 MB in 8 (carry 2 KB a row against 6.4 KB of lines).
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 32, guest, plenty) == 125'000);
  // 64- and 128-byte records: 16 segments (64 MB in 4 MiB slices; 128 MB capped at d / 6), whose
  // carry (8 KB, 16 KB a row) moves more than the lines it saves: unblocked (float32 and float64
  // with 8 replicas measured 2.1x and 1.6x faster there than in the 4 and 8 slices of the
  // uncapped L3).
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 64, guest, plenty) ==
        k_unsegmented);
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 128, guest, plenty) ==
        k_unsegmented);
  // Two threads: 16 MiB of the 32 for the team, 4 MiB slices again.
  const CacheSizes team{guest.l2, guest.l3, 2, true};
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16, team, plenty) == 250'000);
  // An L3 within the share (the 8 MiB core complex) is read as reported: 4 MiB slices at 1 thread,
  // 2 MiB at 2 (the test above).
  const CacheSizes within{guest.l2, k_l3_thread_share_bytes, 1, true};
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16, within, plenty) == 250'000);
}

TEST_CASE("the trial's slices: only where the rule left the rows unblocked for the carry alone",
          "[column_segments]") {
  // The caches both AMD EPYC guests report (512 KiB or 1 MiB L2, a 32 MiB L3 of a core complex).
  const CacheSizes guest{std::size_t{512} << 10, std::size_t{32} << 20, 1, true};
  const std::size_t plenty = std::size_t{64} << 30;
  // ER N = 10^6, degree 100: 64- and 128-byte records, which the rule leaves unblocked, are tried
  // in its 16 slices (64 MB in 4 MiB slices; 128 MB capped at d / 6) of 62,500 columns.
  CHECK(trial_segment_width(1'000'000, 100'000'000, 1'000'000, 64, guest, plenty) == 62'500);
  CHECK(trial_segment_width(1'000'000, 100'000'000, 1'000'000, 128, guest, plenty) == 62'500);
  // Two threads: 4 MiB slices a thread again (16 MiB of the 32 for the team).
  CHECK(trial_segment_width(1'000'000, 100'000'000, 1'000'000, 64,
                            CacheSizes{guest.l2, guest.l3, 2, true}, plenty) == 62'500);
  // Where the rule segments (16- and 32-byte records) or the table fits in L2, nothing to try.
  CHECK(trial_segment_width(1'000'000, 100'000'000, 1'000'000, 16, guest, plenty) == k_unsegmented);
  CHECK(trial_segment_width(1'000'000, 100'000'000, 1'000'000, 32, guest, plenty) == k_unsegmented);
  CHECK(trial_segment_width(4'000, 400'000, 4'000, 64, guest, plenty) == k_unsegmented);
  // Records beyond k_max_segmented_record_bytes run in registers unblocked, slices in L2 never
  // weigh the carry, and memory that would not hold the segments refuses them.
  CHECK(trial_segment_width(1'000'000, 100'000'000, 1'000'000, 256, guest, plenty) ==
        k_unsegmented);
  const CacheSizes socket{std::size_t{1280} << 10, std::size_t{48} << 20, 1, false};
  CHECK(trial_segment_width(1'000'000, 100'000'000, 1'000'000, 64, socket, plenty) ==
        k_unsegmented);
  const std::size_t needed = segmented_bytes(100'000'000, 1'000'000, 16, 62'500, 64);
  CHECK(trial_segment_width(1'000'000, 100'000'000, 1'000'000, 64, guest, 2 * needed) == 62'500);
  CHECK(trial_segment_width(1'000'000, 100'000'000, 1'000'000, 64, guest, 2 * needed - 1) ==
        k_unsegmented);
  // The rule and the trial never both cut: one of them is unblocked for every record.
  for (const std::size_t record :
       std::initializer_list<std::size_t>{8U, 16U, 32U, 64U, 128U, 256U}) {
    CHECK((automatic_segment_width(1'000'000, 100'000'000, 1'000'000, record, guest, plenty) ==
               k_unsegmented ||
           trial_segment_width(1'000'000, 100'000'000, 1'000'000, record, guest, plenty) ==
               k_unsegmented));
  }
}

TEST_CASE(
    "automatic segment width: an L3 that is no core complex's holds no slice, whatever its "
    "size",
    "[column_segments]") {
  // The Intel Xeon's caches with a 48 MiB L3 (1.25 MiB L2): as large as a core complex's could
  // be, but a whole socket's; its slices live in L2.
  const CacheSizes socket{std::size_t{1280} << 10, std::size_t{48} << 20, 1, false};
  CHECK_FALSE(slices_in_l3(socket));
  CHECK(slices_in_l3(CacheSizes{socket.l2, socket.l3, 1, true}));
  const std::size_t plenty = std::size_t{64} << 30;
  // N = 10^6, degree 100, float64, one replica: a 16 MB table, which half that L3 would hold
  // whole, in slices of 640 KiB of the L2, capped at 100 / 6 = 16 segments of 62,500 columns.
  // Were the L3 a core complex's, its slices would be half a thread's share of it, not half of
  // it (k_l3_thread_share_bytes: 4 MiB, 4 segments).
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16, socket, plenty) == 62'500);
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16,
                                CacheSizes{socket.l2, socket.l3, 1, true}, plenty) == 250'000);
  // Two threads: the same slices (each core has its L2).
  CHECK(automatic_segment_width(1'000'000, 100'000'000, 1'000'000, 16,
                                CacheSizes{socket.l2, socket.l3, 2, false}, plenty) == 62'500);
}
