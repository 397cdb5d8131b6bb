// The device each MPI rank of a machine steps on (dynamics/device_assignment.hpp): the devices
// taken in turn, sharing said exactly when the ranks outnumber the devices, bad counts refused.
#include <catch2/catch.hpp>
#include <string>

#include "core/error.hpp"
#include "dynamics/device_assignment.hpp"

using namespace hmfnet;

TEST_CASE("ranks take a machine's devices in turn, one a device where there are as many",
          "[device_assignment]") {
  for (int r = 0; r < 4; ++r) {
    const DeviceAssignment a = assign_device(r, 4, 4);
    CHECK(a.device == r);
    CHECK_FALSE(a.shared);
    CHECK(a.note.empty());
  }
  const DeviceAssignment single = assign_device(0, 1, 8);
  CHECK(single.device == 0);
  CHECK_FALSE(single.shared);
}

TEST_CASE("more ranks than devices share them, and the note says how", "[device_assignment]") {
  CHECK(assign_device(0, 2, 1).device == 0);
  CHECK(assign_device(1, 2, 1).device == 0);
  CHECK(assign_device(4, 5, 2).device == 0);
  CHECK(assign_device(3, 5, 2).device == 1);
  const DeviceAssignment a = assign_device(1, 2, 1);
  CHECK(a.shared);
  CHECK(a.note == "2 MPI ranks share 1 CUDA device on this machine (its rank i on device i mod 1)");
  CHECK(assign_device(2, 3, 2).note ==
        "3 MPI ranks share 2 CUDA devices on this machine (its rank i on device i mod 2)");
}

TEST_CASE("an assignment without a device or outside the machine's ranks is refused",
          "[device_assignment]") {
  CHECK_THROWS_AS(assign_device(0, 1, 0), ParameterError);
  CHECK_THROWS_AS(assign_device(2, 2, 1), ParameterError);
  CHECK_THROWS_AS(assign_device(-1, 2, 1), ParameterError);
  CHECK_THROWS_AS(assign_device(0, 0, 1), ParameterError);
}
