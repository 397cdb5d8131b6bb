#pragma once
// A thin RAII layer over the HDF5 C API (Debian ships no HighFive). Every failure becomes an
// InputError naming the file and the object, instead of HDF5's error-stack dump on stderr.
#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace hmfnet {

/// Owns one hid_t and closes it with the matching H5*close.
class H5Id {
 public:
  H5Id() = default;
  H5Id(hid_t id, herr_t (*closer)(hid_t)) : m_id(id), m_close(closer) {}
  H5Id(H5Id&& other) noexcept : m_id(other.m_id), m_close(other.m_close) { other.m_id = -1; }
  H5Id& operator=(H5Id&& other) noexcept;
  H5Id(const H5Id&) = delete;
  H5Id& operator=(const H5Id&) = delete;
  ~H5Id();
  hid_t get() const { return m_id; }

 private:
  hid_t m_id = -1;
  herr_t (*m_close)(hid_t) = nullptr;
};

class Hdf5File {
 public:
  enum class Mode { read, create, update };
  /// `create` truncates; callers write to an AtomicFile's temporary path. `update` opens an
  /// existing file for writing (the ranks that fill a file created by one of them, in turn).
  Hdf5File(const std::string& path, Mode mode);
  const std::string& path() const { return m_path; }
  hid_t id() const { return m_file.get(); }

  H5Id create_group(const std::string& name) const;
  H5Id open_group(const std::string& name) const;
  bool exists(const std::string& name) const;

  // Datasets: 1-D, contiguous. Readers check type class and rank.
  void write(hid_t where, const std::string& name, const std::vector<std::int64_t>& v) const;
  void write(hid_t where, const std::string& name, const std::vector<std::int32_t>& v) const;
  void write(hid_t where, const std::string& name, const std::vector<double>& v) const;
  /// A 1-D dataset of `length` values of `file_type` (H5T_STD_I64LE, H5T_STD_I32LE,
  /// H5T_IEEE_F64LE), filled later by write_range.
  void create_dataset(hid_t where, const std::string& name, hid_t file_type,
                      std::size_t length) const;
  /// Writes v into elements [first, first + v.size()) of an existing 1-D dataset (a hyperslab).
  void write_range(hid_t where, const std::string& name, std::size_t first,
                   const std::vector<std::int64_t>& v) const;
  void write_range(hid_t where, const std::string& name, std::size_t first,
                   const std::vector<std::int32_t>& v) const;
  void write_range(hid_t where, const std::string& name, std::size_t first,
                   const std::vector<double>& v) const;
  std::vector<std::int64_t> read_int64(hid_t where, const std::string& name) const;
  std::vector<std::int32_t> read_int32(hid_t where, const std::string& name) const;
  std::vector<double> read_double(hid_t where, const std::string& name) const;
  /// Elements [first, first + count) of a 1-D dataset (one hyperslab: only those are read).
  std::vector<std::int32_t> read_int32(hid_t where, const std::string& name, std::size_t first,
                                       std::size_t count) const;
  std::vector<double> read_double(hid_t where, const std::string& name, std::size_t first,
                                  std::size_t count) const;
  /// Length of a 1-D dataset of the given class (checked as the readers check it).
  std::size_t dataset_size(hid_t where, const std::string& name, H5T_class_t expected) const;
  /// 1-D dataset of fixed-length strings (as long as the longest; h5py reads bytes).
  void write_strings(hid_t where, const std::string& name, const std::vector<std::string>& v) const;
  std::vector<std::string> read_strings(hid_t where, const std::string& name) const;

  /// 2-D row-major dataset rows x cols (HDF5 keeps C order, so h5py reads it as [rows, cols]).
  void write_matrix(hid_t where, const std::string& name, const std::vector<double>& v,
                    std::size_t rows, std::size_t cols) const;
  /// Reads a 2-D double dataset; rows and cols are set from its shape.
  std::vector<double> read_matrix(hid_t where, const std::string& name, std::size_t& rows,
                                  std::size_t& cols) const;

  // Scalar attributes. The readers refuse a stored type class that would convert silently:
  // int_attribute takes only integers (not a float 1000.9), double_attribute integers or floats.
  void set_attribute(hid_t where, const std::string& name, const std::string& value) const;
  void set_attribute(hid_t where, const std::string& name, std::int64_t value) const;
  void set_attribute(hid_t where, const std::string& name, double value) const;
  std::string string_attribute(hid_t where, const std::string& name) const;
  std::int64_t int_attribute(hid_t where, const std::string& name) const;
  double double_attribute(hid_t where, const std::string& name) const;
  bool has_attribute(hid_t where, const std::string& name) const;

  /// Flushes to disk; throws if HDF5 reports a failure (e.g. disk full).
  void flush() const;

  [[noreturn]] void fail(const std::string& cause) const;

 private:
  std::size_t dataset_length(hid_t set, const std::string& name, H5T_class_t expected) const;
  std::size_t checked_length(hid_t where, const std::string& name, H5T_class_t expected) const;
  std::string m_path;
  H5Id m_file;
};

}  // namespace hmfnet
