#pragma once
// Everything a run needs to continue bit-identically: where it stands and the rotors
// (RunPosition), every accumulator of the segment (SegmentState), and the results so far. The
// fields are those of segment_state.hpp's lists, captured into a CheckpointRecord (rows gathered
// over ranks) and walked generically by the writer, the reader and the checksum, so no field is
// named here. One HDF5 file written by the root rank through write-then-rename (a checkpoint is
// never half-written); read by every rank. A `fingerprint` of the run's parameters guards against
// resuming another run's checkpoint.
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "dynamics/segment_state.hpp"
#include "dynamics/simulation.hpp"
#include "parallel/distributed_network.hpp"

namespace hmfnet {

/// The stored form of the listed fields: scalars, and arrays of the whole network (rows x
/// columns, row-major). Look-ups by name throw InputError naming `source` and the field.
struct CheckpointRecord {
  struct Array {
    std::string name;
    std::vector<double> values;
    std::size_t columns = 1;
  };
  std::vector<std::pair<std::string, std::int64_t>> counts;
  std::vector<std::pair<std::string, double>> reals;
  std::vector<Array> arrays;
  std::string source;  ///< the file, for messages

  std::int64_t count(const std::string& name) const;
  double real(const std::string& name) const;
  const Array& array(const std::string& name) const;
};

struct Checkpoint {
  std::string fingerprint;
  int replicas = 1;
  CheckpointRecord record;
  std::vector<PointResult> points;
  TimeSeries series;
};

/// FNV-1a (64 bit, as 16 hex digits) over every byte a resume uses: the fingerprint, the record
/// and every field of the results so far (point_result.hpp's lists). A bit flipped on disk
/// changes it, so a damaged checkpoint is refused instead of resumed.
std::string checkpoint_checksum(const Checkpoint& c);

/// How this rank's rows travel to and from whole-network arrays of `width` columns. Both are
/// collective over ranks.
struct RowExchange {
  std::function<std::vector<double>(const std::vector<double>& local, std::size_t width)> gather;
  std::function<std::vector<double>(const std::vector<double>& global, std::size_t width)> scatter;
};

/// Rows of `network` as this rank owns them (one gather per column: checkpoints and results
/// only). scatter throws InputError naming `source` when an array does not fit the network.
RowExchange row_exchange(const DistributedNetwork& network, const std::string& source);

/// Collective: the record of `position` and `segment` (rows gathered, additive node statistics
/// summed over ranks) on every rank.
CheckpointRecord capture(const RunPosition& position, const SegmentState& segment, int replicas,
                         const RowExchange& exchange);

/// Collective: fills `position` and `segment` from `record`. The segment's BatchMeans and
/// NodeStatistics must already have the shapes of the run (sizes are checked against the record).
/// Throws InputError naming the record's source for a missing or misfitting field.
void restore(const CheckpointRecord& record, RunPosition& position, SegmentState& segment,
             int replicas, const RowExchange& exchange);

void write_checkpoint(const std::string& path, const Checkpoint& c);

/// Throws InputError naming the file for anything missing or inconsistent, and for a checkpoint
/// of another format version.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace hmfnet
