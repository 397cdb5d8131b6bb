#pragma once
// What the device can do at most, measured on it: the rates a step's cost is bounded by
// (bench/gpu/ensemble_rates.cpp divides each configuration's rate by them). Each is the best of
// several timed repetitions after a warm-up, with device events.
#include <cstddef>
#include <cstdint>

namespace hmfnet::cuda {

/// Device-to-device copy of `bytes`: bytes read plus bytes written per second.
double copy_bandwidth(std::size_t bytes);

/// Random gathers of `record_bytes`-byte records (8, or a multiple of 16 up to 128) from a table
/// of `records` records (< 2^32), at indices read from a precomputed random array as the step
/// reads its columns, each record read by neighbouring threads one 16-byte word each, summed
/// so that none is optimised away: records gathered per second. The access of the sparse
/// force's [cos, sin] table (one record of 2 B sizeof(T) per stored entry, its B lanes read by B
/// neighbouring threads).
double gather_rate(std::int64_t records, int record_bytes);

/// Seconds per launch of an empty kernel, launched back to back (the floor of a step made of
/// launches).
double launch_seconds();

/// The current device's multiprocessor count (cuda::use_device).
int multiprocessors();

/// sincos_one (kernel_arithmetic.hpp) of distinct angles in +-100: angles per second.
double sincos_rate();

}  // namespace hmfnet::cuda
