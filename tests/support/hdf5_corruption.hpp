#pragma once
// Corrupting a valid hmfnet HDF5 file after the fact, as a bit flip or a buggy external tool
// would, with the raw C API (no hmfnet code involved), for the readers' refusal tests.
#include <hdf5.h>

#include <catch2/catch.hpp>
#include <string>
#include <vector>

namespace hmfnet::test {

/// Overwrites the whole of an existing 1-D dataset (same length) of the file at `path`.
template <class T>
void overwrite_dataset(const std::string& path, const std::string& name, const std::vector<T>& v,
                       hid_t mem_type) {
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
  REQUIRE(file >= 0);
  const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
  REQUIRE(set >= 0);
  const hid_t space = H5Dget_space(set);
  hsize_t length = 0;
  H5Sget_simple_extent_dims(space, &length, nullptr);
  REQUIRE(length == v.size());
  CHECK(H5Dwrite(set, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, v.data()) >= 0);
  H5Sclose(space);
  H5Dclose(set);
  H5Fclose(file);
}

}  // namespace hmfnet::test
