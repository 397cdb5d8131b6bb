// The device's measured ceilings (device_bounds.hpp).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "dynamics/cuda/device_bounds.hpp"
#include "dynamics/cuda/device_buffer.cuh"
#include "dynamics/kernel_arithmetic.hpp"

namespace hmfnet::cuda {

namespace {

constexpr int k_repeats = 7;

// A CUDA event, destroyed on every way out.
class Event {
 public:
  Event() { check(cudaEventCreate(&m_event), "cudaEventCreate"); }
  Event(const Event&) = delete;
  Event& operator=(const Event&) = delete;
  ~Event() { cudaEventDestroy(m_event); }
  cudaEvent_t get() const { return m_event; }

 private:
  cudaEvent_t m_event = nullptr;
};

// Seconds of the fastest of k_repeats runs of `run` (one warm-up first).
template <typename Run>
double best_seconds(Run&& run) {
  const Event start, stop;
  run();
  check(cudaDeviceSynchronize(), "warm-up");
  float best = 1e30F;
  for (int i = 0; i < k_repeats; ++i) {
    check(cudaEventRecord(start.get()), "cudaEventRecord");
    run();
    check(cudaEventRecord(stop.get()), "cudaEventRecord");
    check(cudaEventSynchronize(stop.get()), "cudaEventSynchronize");
    float ms = 0.0F;
    check(cudaEventElapsedTime(&ms, start.get(), stop.get()), "cudaEventElapsedTime");
    best = std::min(best, ms);
  }
  return static_cast<double>(best) * 1e-3;
}

__device__ std::uint64_t scramble(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// Random record indices, drawn once outside the timing (the step reads its columns too).
__global__ void index_kernel(std::uint32_t* index, std::int64_t count, std::int64_t records) {
  const std::int64_t i = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i >= count) return;
  index[i] = static_cast<std::uint32_t>(scramble(static_cast<std::uint64_t>(i)) %
                                        static_cast<std::uint64_t>(records));
}

// Groups of `words` neighbouring threads gather `per_thread` records whose indices they read
// from `index` (consecutive groups, consecutive indices: as the step reads its sorted columns),
// each thread one 16-byte word of the record: the sparse force's access, whose B replica lanes
// are B neighbouring threads reading one record of the [cos, sin] table.
__global__ void gather_kernel(const double2* table, const std::uint32_t* index, std::int64_t mask,
                              int words, int per_thread, double* out) {
  const std::uint64_t t = static_cast<std::uint64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  const std::uint64_t groups =
      static_cast<std::uint64_t>(gridDim.x) * blockDim.x / static_cast<std::uint64_t>(words);
  const std::uint64_t group = t / static_cast<std::uint64_t>(words);
  const std::uint64_t word = t % static_cast<std::uint64_t>(words);
  double sum = 0.0;
  for (int i = 0; i < per_thread; ++i) {
    const std::uint64_t r =
        index[(static_cast<std::uint64_t>(i) * groups + group) & static_cast<std::uint64_t>(mask)];
    const double2 v = table[r * static_cast<std::uint64_t>(words) + word];
    sum += v.x + v.y;
  }
  out[t] = sum;
}

// 8-byte records: a table of doubles, one thread a record.
__global__ void gather8_kernel(const double* table, const std::uint32_t* index, std::int64_t mask,
                               int per_thread, double* out) {
  const std::uint64_t t = static_cast<std::uint64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  const std::uint64_t threads = static_cast<std::uint64_t>(gridDim.x) * blockDim.x;
  double sum = 0.0;
  for (int i = 0; i < per_thread; ++i) {
    sum += table[index[(static_cast<std::uint64_t>(i) * threads + t) &
                       static_cast<std::uint64_t>(mask)]];
  }
  out[t] = sum;
}

__global__ void empty_kernel() {}

__global__ void sincos_rate_kernel(int per_thread, double* out) {
  const std::uint64_t t = static_cast<std::uint64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  double sum = 0.0;
  for (int i = 0; i < per_thread; ++i) {
    const double x =
        static_cast<double>((t * 7919 + static_cast<std::uint64_t>(i) * 104729) % 2000001) * 1e-4 -
        100.0;
    double c = 0.0, s = 0.0;
    sincos_one(x, c, s);
    sum += c + s;
  }
  out[t] = sum;
}

}  // namespace

int multiprocessors() {
  int device = 0, sms = 0;
  check(cudaGetDevice(&device), "cudaGetDevice");
  check(cudaDeviceGetAttribute(&sms, cudaDevAttrMultiProcessorCount, device),
        "cudaDeviceGetAttribute");
  return sms;
}

double copy_bandwidth(std::size_t bytes) {
  require_device();
  DeviceBuffer<unsigned char> from(bytes), to(bytes);
  check(cudaMemset(from.data(), 1, bytes), "cudaMemset");
  const double s = best_seconds([&] {
    check(cudaMemcpy(to.data(), from.data(), bytes, cudaMemcpyDeviceToDevice), "cudaMemcpy");
  });
  return 2.0 * static_cast<double>(bytes) / s;
}

double gather_rate(std::int64_t records, int record_bytes) {
  require_device();
  if (record_bytes != 8 && (record_bytes % 16 != 0 || record_bytes > 128)) {
    throw DeviceError("gather_rate: records of 8 or a multiple of 16 bytes up to 128");
  }
  if (records < 1 || records > INT64_C(0xffffffff)) {
    throw DeviceError("gather_rate: 1 to 2^32 - 1 records (32-bit indices)");
  }
  const auto table_bytes =
      static_cast<std::size_t>(records) * static_cast<std::size_t>(record_bytes);
  DeviceBuffer<double> table((table_bytes + 7) / 8);
  check(cudaMemset(table.data(), 0, table_bytes), "cudaMemset");
  constexpr int k_threads = 256;
  constexpr int k_per_thread = 64;
  const auto blocks = static_cast<unsigned>(multiprocessors() * 64);
  const auto threads = static_cast<std::size_t>(blocks) * k_threads;
  DeviceBuffer<double> out(threads);
  // 2^24 indices (64 MB), read cyclically.
  constexpr std::int64_t k_indices = std::int64_t{1} << 24;
  DeviceBuffer<std::uint32_t> index(static_cast<std::size_t>(k_indices));
  index_kernel<<<blocks_for(static_cast<std::size_t>(k_indices), 256), 256>>>(index.data(),
                                                                              k_indices, records);
  check_launch("index kernel");
  const double s = best_seconds([&] {
    if (record_bytes == 8) {
      gather8_kernel<<<blocks, k_threads>>>(table.data(), index.data(), k_indices - 1, k_per_thread,
                                            out.data());
    } else {
      gather_kernel<<<blocks, k_threads>>>(reinterpret_cast<const double2*>(table.data()),
                                           index.data(), k_indices - 1, record_bytes / 16,
                                           k_per_thread, out.data());
    }
    check_launch("gather kernel");
  });
  const double words = record_bytes == 8 ? 1.0 : record_bytes / 16.0;
  return static_cast<double>(threads) / words * k_per_thread / s;
}

double launch_seconds() {
  require_device();
  constexpr int k_launches = 1000;
  const double s = best_seconds([&] {
    for (int i = 0; i < k_launches; ++i) empty_kernel<<<1, 32>>>();
    check_launch("empty kernel");
  });
  return s / k_launches;
}

double sincos_rate() {
  require_device();
  constexpr int k_threads = 256;
  constexpr int k_per_thread = 256;
  const auto blocks = static_cast<unsigned>(multiprocessors() * 32);
  const auto threads = static_cast<std::size_t>(blocks) * k_threads;
  DeviceBuffer<double> out(threads);
  const double s = best_seconds([&] {
    sincos_rate_kernel<<<blocks, k_threads>>>(k_per_thread, out.data());
    check_launch("sincos rate kernel");
  });
  return static_cast<double>(threads) * k_per_thread / s;
}

}  // namespace hmfnet::cuda
