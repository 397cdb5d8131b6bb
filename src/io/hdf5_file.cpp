#include "io/hdf5_file.hpp"

#include <algorithm>
#include <limits>

#include "core/error.hpp"

namespace hmfnet {

namespace {

// HDF5 prints its error stack to stderr by default; our errors say it in one line instead.
struct SilenceHdf5 {
  SilenceHdf5() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }
};

void silence() { static const SilenceHdf5 once; }

hsize_t length_of(std::size_t n) { return static_cast<hsize_t>(n); }

// Deflate, the usual HDF5 filter, expands data at most 1032-fold (zlib technical details).
constexpr hsize_t k_max_compression_ratio = 1032;

// The readers allocate the length a dataspace declares before H5Dread, and a corrupted dataspace
// (or one never written) can declare 10^18 values in a 5 KiB file (found by tests/fuzz). The
// values must be stored: the declared bytes may exceed the stored bytes only by what compression
// explains. A corrupted layout message can overstate the storage too, so the file size caps it.
void require_stored(const Hdf5File& f, hid_t set, hid_t type, const std::string& name,
                    hsize_t count) {
  hsize_t file_size = 0;
  if (H5Fget_filesize(f.id(), &file_size) < 0) f.fail("cannot get the file size");
  const hsize_t stored = std::min(H5Dget_storage_size(set), file_size);
  const std::size_t value_size = H5Tget_size(type);
  if (count > 0 && (value_size == 0 || count > stored * k_max_compression_ratio / value_size)) {
    f.fail("dataset " + name + " declares " + std::to_string(count) + " values but stores only " +
           std::to_string(stored) + " bytes");
  }
}

}  // namespace

H5Id& H5Id::operator=(H5Id&& other) noexcept {
  if (this != &other) {
    if (m_id >= 0 && m_close != nullptr) m_close(m_id);
    m_id = other.m_id;
    m_close = other.m_close;
    other.m_id = -1;
  }
  return *this;
}

H5Id::~H5Id() {
  if (m_id >= 0 && m_close != nullptr) m_close(m_id);
}

Hdf5File::Hdf5File(const std::string& path, Mode mode) : m_path(path) {
  silence();
  if (mode == Mode::read) {
    if (H5Fis_hdf5(path.c_str()) <= 0) fail("not an HDF5 file (or cannot be read)");
    m_file = H5Id(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  } else if (mode == Mode::update) {
    m_file = H5Id(H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
  } else {
    m_file = H5Id(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
  }
  if (m_file.get() < 0) fail(mode == Mode::create ? "cannot create" : "cannot open");
}

void Hdf5File::fail(const std::string& cause) const { throw InputError(m_path, 0, cause); }

H5Id Hdf5File::create_group(const std::string& name) const {
  H5Id g(H5Gcreate2(id(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
  if (g.get() < 0) fail("cannot create group " + name);
  return g;
}

H5Id Hdf5File::open_group(const std::string& name) const {
  if (!exists(name)) fail("missing group " + name);
  H5Id g(H5Gopen2(id(), name.c_str(), H5P_DEFAULT), H5Gclose);
  if (g.get() < 0) fail("cannot open group " + name);
  return g;
}

bool Hdf5File::exists(const std::string& name) const {
  return H5Lexists(id(), name.c_str(), H5P_DEFAULT) > 0;
}

namespace {
template <class T>
void write_vector(const Hdf5File& f, hid_t where, const std::string& name, const std::vector<T>& v,
                  hid_t file_type, hid_t mem_type) {
  const hsize_t dims[1] = {length_of(v.size())};
  H5Id space(H5Screate_simple(1, dims, nullptr), H5Sclose);
  H5Id set(H5Dcreate2(where, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Dclose);
  if (set.get() < 0) f.fail("cannot create dataset " + name);
  if (!v.empty() && H5Dwrite(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0) {
    f.fail("cannot write dataset " + name);
  }
}
}  // namespace

void Hdf5File::write(hid_t where, const std::string& name,
                     const std::vector<std::int64_t>& v) const {
  write_vector(*this, where, name, v, H5T_STD_I64LE, H5T_NATIVE_INT64);
}
void Hdf5File::write(hid_t where, const std::string& name,
                     const std::vector<std::int32_t>& v) const {
  write_vector(*this, where, name, v, H5T_STD_I32LE, H5T_NATIVE_INT32);
}
void Hdf5File::write(hid_t where, const std::string& name, const std::vector<double>& v) const {
  write_vector(*this, where, name, v, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE);
}

void Hdf5File::write_strings(hid_t where, const std::string& name,
                             const std::vector<std::string>& v) const {
  std::size_t width = 1;
  for (const auto& x : v) width = std::max(width, x.size());
  std::vector<char> buffer(v.size() * width, '\0');
  for (std::size_t k = 0; k < v.size(); ++k) v[k].copy(buffer.data() + k * width, v[k].size());
  H5Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), width);
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  const hsize_t dims[1] = {length_of(v.size())};
  H5Id space(H5Screate_simple(1, dims, nullptr), H5Sclose);
  H5Id set(H5Dcreate2(where, name.c_str(), type.get(), space.get(), H5P_DEFAULT, H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Dclose);
  if (set.get() < 0) fail("cannot create dataset " + name);
  if (!v.empty() &&
      H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0) {
    fail("cannot write dataset " + name);
  }
}

void Hdf5File::create_dataset(hid_t where, const std::string& name, hid_t file_type,
                              std::size_t length) const {
  const hsize_t dims[1] = {length_of(length)};
  H5Id space(H5Screate_simple(1, dims, nullptr), H5Sclose);
  H5Id set(H5Dcreate2(where, name.c_str(), file_type, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Dclose);
  if (set.get() < 0) fail("cannot create dataset " + name);
}

namespace {
template <class T>
void write_range_of(const Hdf5File& f, hid_t where, const std::string& name, std::size_t first,
                    const std::vector<T>& v, hid_t mem_type) {
  if (v.empty()) return;
  H5Id set(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (set.get() < 0) f.fail("cannot open dataset " + name);
  H5Id file_space(H5Dget_space(set.get()), H5Sclose);
  const hsize_t start[1] = {static_cast<hsize_t>(first)};
  const hsize_t length[1] = {length_of(v.size())};
  H5Id memory_space(H5Screate_simple(1, length, nullptr), H5Sclose);
  if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, length, nullptr) < 0 ||
      H5Dwrite(set.get(), mem_type, memory_space.get(), file_space.get(), H5P_DEFAULT, v.data()) <
          0) {
    f.fail("cannot write elements [" + std::to_string(first) + ", " +
           std::to_string(first + v.size()) + ") of dataset " + name);
  }
}
}  // namespace

void Hdf5File::write_range(hid_t where, const std::string& name, std::size_t first,
                           const std::vector<std::int64_t>& v) const {
  write_range_of(*this, where, name, first, v, H5T_NATIVE_INT64);
}
void Hdf5File::write_range(hid_t where, const std::string& name, std::size_t first,
                           const std::vector<std::int32_t>& v) const {
  write_range_of(*this, where, name, first, v, H5T_NATIVE_INT32);
}
void Hdf5File::write_range(hid_t where, const std::string& name, std::size_t first,
                           const std::vector<double>& v) const {
  write_range_of(*this, where, name, first, v, H5T_NATIVE_DOUBLE);
}

std::vector<std::string> Hdf5File::read_strings(hid_t where, const std::string& name) const {
  const std::size_t n = checked_length(where, name, H5T_STRING);
  H5Id set(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose);
  H5Id type(H5Dget_type(set.get()), H5Tclose);
  if (H5Tis_variable_str(type.get()) > 0) fail("dataset " + name + " is not fixed-length strings");
  const std::size_t width = H5Tget_size(type.get());
  std::vector<char> buffer(n * width);
  if (!buffer.empty() &&
      H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, buffer.data()) < 0) {
    fail("cannot read dataset " + name);
  }
  std::vector<std::string> v(n);
  for (std::size_t k = 0; k < n; ++k) {
    const char* first = buffer.data() + k * width;
    v[k].assign(first, std::find(first, first + width, '\0'));
  }
  return v;
}

std::size_t Hdf5File::dataset_length(hid_t set, const std::string& name,
                                     H5T_class_t expected) const {
  H5Id type(H5Dget_type(set), H5Tclose);
  if (H5Tget_class(type.get()) != expected) fail("dataset " + name + " has the wrong type class");
  H5Id space(H5Dget_space(set), H5Sclose);
  if (H5Sget_simple_extent_ndims(space.get()) != 1) fail("dataset " + name + " is not 1-D");
  hsize_t dims[1] = {0};
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  require_stored(*this, set, type.get(), name, dims[0]);
  return static_cast<std::size_t>(dims[0]);
}

namespace {
template <class T>
std::vector<T> read_vector(const Hdf5File& f, hid_t where, const std::string& name,
                           std::size_t length, hid_t mem_type) {
  H5Id set(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose);
  std::vector<T> v(length);
  if (!v.empty() && H5Dread(set.get(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0) {
    f.fail("cannot read dataset " + name + " (values out of range for its type?)");
  }
  return v;
}

template <class T>
std::vector<T> read_range(const Hdf5File& f, hid_t where, const std::string& name,
                          std::size_t first, std::size_t count, hid_t mem_type) {
  std::vector<T> v(count);
  if (count == 0) return v;
  H5Id set(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose);
  H5Id file_space(H5Dget_space(set.get()), H5Sclose);
  const hsize_t start[1] = {static_cast<hsize_t>(first)};
  const hsize_t length[1] = {static_cast<hsize_t>(count)};
  H5Id memory_space(H5Screate_simple(1, length, nullptr), H5Sclose);
  if (H5Sselect_hyperslab(file_space.get(), H5S_SELECT_SET, start, nullptr, length, nullptr) < 0 ||
      H5Dread(set.get(), mem_type, memory_space.get(), file_space.get(), H5P_DEFAULT, v.data()) <
          0) {
    f.fail("cannot read elements [" + std::to_string(first) + ", " + std::to_string(first + count) +
           ") of dataset " + name);
  }
  return v;
}
}  // namespace

std::size_t Hdf5File::dataset_size(hid_t where, const std::string& name,
                                   H5T_class_t expected) const {
  return checked_length(where, name, expected);
}

std::vector<std::int32_t> Hdf5File::read_int32(hid_t where, const std::string& name,
                                               std::size_t first, std::size_t count) const {
  if (first + count > checked_length(where, name, H5T_INTEGER)) {
    fail("dataset " + name + " is shorter than element " + std::to_string(first + count));
  }
  return read_range<std::int32_t>(*this, where, name, first, count, H5T_NATIVE_INT32);
}

std::vector<double> Hdf5File::read_double(hid_t where, const std::string& name, std::size_t first,
                                          std::size_t count) const {
  if (first + count > checked_length(where, name, H5T_FLOAT)) {
    fail("dataset " + name + " is shorter than element " + std::to_string(first + count));
  }
  return read_range<double>(*this, where, name, first, count, H5T_NATIVE_DOUBLE);
}

std::size_t Hdf5File::checked_length(hid_t where, const std::string& name,
                                     H5T_class_t expected) const {
  if (H5Lexists(where, name.c_str(), H5P_DEFAULT) <= 0) fail("missing dataset " + name);
  H5Id set(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose);
  if (set.get() < 0) fail("cannot open dataset " + name);
  return dataset_length(set.get(), name, expected);
}

std::vector<std::int64_t> Hdf5File::read_int64(hid_t where, const std::string& name) const {
  const std::size_t n = checked_length(where, name, H5T_INTEGER);
  return read_vector<std::int64_t>(*this, where, name, n, H5T_NATIVE_INT64);
}

std::vector<std::int32_t> Hdf5File::read_int32(hid_t where, const std::string& name) const {
  const std::size_t n = checked_length(where, name, H5T_INTEGER);
  return read_vector<std::int32_t>(*this, where, name, n, H5T_NATIVE_INT32);
}

std::vector<double> Hdf5File::read_double(hid_t where, const std::string& name) const {
  const std::size_t n = checked_length(where, name, H5T_FLOAT);
  return read_vector<double>(*this, where, name, n, H5T_NATIVE_DOUBLE);
}

void Hdf5File::write_matrix(hid_t where, const std::string& name, const std::vector<double>& v,
                            std::size_t rows, std::size_t cols) const {
  if (v.size() != rows * cols) fail("dataset " + name + ": size does not match its shape");
  const hsize_t dims[2] = {length_of(rows), length_of(cols)};
  H5Id space(H5Screate_simple(2, dims, nullptr), H5Sclose);
  H5Id set(H5Dcreate2(where, name.c_str(), H5T_IEEE_F64LE, space.get(), H5P_DEFAULT, H5P_DEFAULT,
                      H5P_DEFAULT),
           H5Dclose);
  if (set.get() < 0) fail("cannot create dataset " + name);
  if (!v.empty() &&
      H5Dwrite(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0) {
    fail("cannot write dataset " + name);
  }
}

std::vector<double> Hdf5File::read_matrix(hid_t where, const std::string& name, std::size_t& rows,
                                          std::size_t& cols) const {
  if (H5Lexists(where, name.c_str(), H5P_DEFAULT) <= 0) fail("missing dataset " + name);
  H5Id set(H5Dopen2(where, name.c_str(), H5P_DEFAULT), H5Dclose);
  H5Id type(H5Dget_type(set.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_FLOAT) fail("dataset " + name + " is not floating point");
  H5Id space(H5Dget_space(set.get()), H5Sclose);
  if (H5Sget_simple_extent_ndims(space.get()) != 2) fail("dataset " + name + " is not 2-D");
  hsize_t dims[2] = {0, 0};
  H5Sget_simple_extent_dims(space.get(), dims, nullptr);
  if (dims[1] > 0 && dims[0] > std::numeric_limits<hsize_t>::max() / dims[1]) {
    fail("dataset " + name + " has an impossible shape");
  }
  require_stored(*this, set.get(), type.get(), name, dims[0] * dims[1]);
  rows = static_cast<std::size_t>(dims[0]);
  cols = static_cast<std::size_t>(dims[1]);
  std::vector<double> v(rows * cols);
  if (!v.empty() &&
      H5Dread(set.get(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) < 0) {
    fail("cannot read dataset " + name);
  }
  return v;
}

namespace {
void write_scalar_attribute(const Hdf5File& f, hid_t where, const std::string& name, hid_t type,
                            const void* value) {
  H5Id space(H5Screate(H5S_SCALAR), H5Sclose);
  if (H5Aexists(where, name.c_str()) > 0) H5Adelete(where, name.c_str());
  H5Id attr(H5Acreate2(where, name.c_str(), type, space.get(), H5P_DEFAULT, H5P_DEFAULT), H5Aclose);
  if (attr.get() < 0 || H5Awrite(attr.get(), type, value) < 0) {
    f.fail("cannot write attribute " + name);
  }
}
}  // namespace

void Hdf5File::set_attribute(hid_t where, const std::string& name, const std::string& value) const {
  H5Id type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), value.empty() ? 1 : value.size());
  H5Tset_strpad(type.get(), H5T_STR_NULLPAD);
  H5Tset_cset(type.get(), H5T_CSET_UTF8);
  const std::string padded = value.empty() ? std::string(1, '\0') : value;
  write_scalar_attribute(*this, where, name, type.get(), padded.data());
}

void Hdf5File::set_attribute(hid_t where, const std::string& name, std::int64_t value) const {
  write_scalar_attribute(*this, where, name, H5T_NATIVE_INT64, &value);
}

void Hdf5File::set_attribute(hid_t where, const std::string& name, double value) const {
  write_scalar_attribute(*this, where, name, H5T_NATIVE_DOUBLE, &value);
}

bool Hdf5File::has_attribute(hid_t where, const std::string& name) const {
  return H5Aexists(where, name.c_str()) > 0;
}

namespace {
// H5Aread fills as many values as the attribute's dataspace holds, and the readers below pass a
// buffer for one: an attribute stored as an array (a corrupted or foreign file; tests/fuzz)
// would overflow it, so anything but exactly one value is refused first.
H5Id open_scalar_attribute(const Hdf5File& f, hid_t where, const std::string& name) {
  if (!f.has_attribute(where, name)) f.fail("missing attribute " + name);
  H5Id attr(H5Aopen(where, name.c_str(), H5P_DEFAULT), H5Aclose);
  if (attr.get() < 0) f.fail("cannot open attribute " + name);
  H5Id space(H5Aget_space(attr.get()), H5Sclose);
  if (space.get() < 0 || H5Sget_simple_extent_npoints(space.get()) != 1) {
    f.fail("attribute " + name + " is not a single value");
  }
  return attr;
}
}  // namespace

std::string Hdf5File::string_attribute(hid_t where, const std::string& name) const {
  const H5Id attr = open_scalar_attribute(*this, where, name);
  H5Id type(H5Aget_type(attr.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING || H5Tis_variable_str(type.get()) > 0) {
    fail("attribute " + name + " is not a fixed-length string");
  }
  std::string value(H5Tget_size(type.get()), '\0');
  if (H5Aread(attr.get(), type.get(), value.data()) < 0) fail("cannot read attribute " + name);
  value.resize(value.find('\0') == std::string::npos ? value.size() : value.find('\0'));
  return value;
}

namespace {
std::string class_name(H5T_class_t type_class) {
  switch (type_class) {
    case H5T_INTEGER:
      return "integer";
    case H5T_FLOAT:
      return "floating point";
    case H5T_STRING:
      return "string";
    default:
      return "neither integer nor floating point";
  }
}

// H5Aread converts between type classes without a word: a float 1000.9 read into an int64 is
// 1000. So the stored class is checked first, as dataset_length checks a dataset's.
void require_attribute_class(const Hdf5File& f, hid_t attr, const std::string& name,
                             bool float_allowed) {
  H5Id type(H5Aget_type(attr), H5Tclose);
  const H5T_class_t stored = H5Tget_class(type.get());
  if (stored == H5T_INTEGER || (float_allowed && stored == H5T_FLOAT)) return;
  f.fail("attribute " + name + " has the wrong type class (" + class_name(stored) + "; " +
         (float_allowed ? "a number" : "an integer") + " is expected)");
}
}  // namespace

std::int64_t Hdf5File::int_attribute(hid_t where, const std::string& name) const {
  const H5Id attr = open_scalar_attribute(*this, where, name);
  require_attribute_class(*this, attr.get(), name, false);
  std::int64_t value = 0;
  if (H5Aread(attr.get(), H5T_NATIVE_INT64, &value) < 0) fail("cannot read attribute " + name);
  return value;
}

double Hdf5File::double_attribute(hid_t where, const std::string& name) const {
  const H5Id attr = open_scalar_attribute(*this, where, name);
  // An integer converts exactly up to 2^53, so an integer attribute is a valid real.
  require_attribute_class(*this, attr.get(), name, true);
  double value = 0.0;
  if (H5Aread(attr.get(), H5T_NATIVE_DOUBLE, &value) < 0) fail("cannot read attribute " + name);
  return value;
}

void Hdf5File::flush() const {
  if (H5Fflush(id(), H5F_SCOPE_GLOBAL) < 0) fail("flush failed (disk full?)");
}

}  // namespace hmfnet
