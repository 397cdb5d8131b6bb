// The QSS campaign's resume file (verification/gpu/qss_resume_file.hpp): a round trip keeps
// every value's bits; a damaged file is refused naming the file and the fault, before any array
// its header describes is allocated; a writer leaves no temporary file.
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "qss_resume_file.hpp"
#include "support/bit_difference.hpp"

using hmfnet::test::bit_difference;
using hmfnet::verification::QssResumeSize;
using hmfnet::verification::read_qss_resume;
using hmfnet::verification::write_qss_resume;
namespace fs = std::filesystem;

namespace {

QssResumeSize filled(std::int64_t n, std::int64_t replicas, std::int64_t records,
                     std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> value;
  QssResumeSize s;
  s.n = n;
  s.replicas = replicas;
  s.record_every = 7;
  s.records = records;
  s.steps_planned = 7 * records;
  s.steps_done = 7 * (records / 2);
  for (auto* v : {&s.R_mean, &s.energy}) {
    v->resize(static_cast<std::size_t>(replicas * records));
    for (double& x : *v) x = value(rng);
  }
  for (auto* v : {&s.theta, &s.p}) {
    v->resize(static_cast<std::size_t>(n * replicas));
    for (double& x : *v) x = value(rng);
  }
  s.R_mean.back() = std::numeric_limits<double>::quiet_NaN();  // a record not yet written
  return s;
}

std::string error_of(const std::string& path) {
  try {
    read_qss_resume(path);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

struct Folder {
  fs::path dir =
      fs::temp_directory_path() / ("hmfnet-qss-resume-" + std::to_string(std::random_device{}()));
  Folder() { fs::create_directories(dir); }
  ~Folder() { fs::remove_all(dir); }
};

}  // namespace

TEST_CASE("the QSS resume file keeps every value's bits", "[qss_resume_file]") {
  Folder f;
  const std::string path = (f.dir / "r.bin").string();
  const std::vector<QssResumeSize> sizes = {filled(300, 3, 40, 1), filled(17, 5, 8, 2)};
  write_qss_resume(path, sizes);
  CHECK(fs::directory_iterator(f.dir)->path().filename() == "r.bin");
  const std::vector<QssResumeSize> back = read_qss_resume(path);
  REQUIRE(back.size() == 2);
  for (std::size_t i = 0; i < 2; ++i) {
    CHECK(back[i].n == sizes[i].n);
    CHECK(back[i].replicas == sizes[i].replicas);
    CHECK(back[i].record_every == sizes[i].record_every);
    CHECK(back[i].records == sizes[i].records);
    CHECK(back[i].steps_planned == sizes[i].steps_planned);
    CHECK(back[i].steps_done == sizes[i].steps_done);
    CHECK(bit_difference(back[i].R_mean, sizes[i].R_mean) == "");
    CHECK(bit_difference(back[i].energy, sizes[i].energy) == "");
    CHECK(bit_difference(back[i].theta, sizes[i].theta) == "");
    CHECK(bit_difference(back[i].p, sizes[i].p) == "");
  }
  write_qss_resume(path, {});
  CHECK(read_qss_resume(path).empty());
  // Arrays that contradict their header: refused, the old file whole, no temporary left.
  QssResumeSize bad = filled(20, 2, 4, 5);
  bad.theta.pop_back();
  CHECK_THROWS_WITH(write_qss_resume(path, {bad}), Catch::Contains("arrays of the wrong length"));
  CHECK(read_qss_resume(path).empty());
  CHECK(std::distance(fs::directory_iterator(f.dir), fs::directory_iterator()) == 1);
}

TEST_CASE("a damaged QSS resume file is refused naming the file and the fault",
          "[qss_resume_file]") {
  Folder f;
  const std::string path = (f.dir / "r.bin").string();
  write_qss_resume(path, {filled(50, 2, 10, 3)});
  const auto bytes = static_cast<std::size_t>(fs::file_size(path));
  std::vector<char> good(bytes);
  std::ifstream(path, std::ios::binary).read(good.data(), static_cast<std::streamsize>(bytes));
  const auto write_bytes = [&](const std::vector<char>& b) {
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(b.data(), static_cast<std::streamsize>(b.size()));
  };

  CHECK_THAT(error_of((f.dir / "absent.bin").string()),
             Catch::Contains("absent.bin") && Catch::Contains("cannot be opened"));
  std::vector<char> b = good;
  b[0] = 'X';
  write_bytes(b);
  CHECK_THAT(error_of(path), Catch::Contains(path) && Catch::Contains("not a resume file"));
  b = good;
  b.resize(bytes - 8);
  write_bytes(b);
  CHECK_THAT(error_of(path), Catch::Contains("truncated"));
  b = good;
  b.push_back(0);
  write_bytes(b);
  CHECK_THAT(error_of(path), Catch::Contains("bytes after the last size"));
  // N = 2^40 in the header: refused by the bytes left, not by an allocation of 2^43 bytes.
  // The header of the first size starts after the 16-byte magic and the 8-byte count: N, then
  // replicas, record_every, records, steps planned, steps done.
  constexpr std::ptrdiff_t n_at = 24, steps_done_at = n_at + 40;
  b = good;
  const std::int64_t huge = std::int64_t{1} << 40;
  std::memcpy(b.data() + n_at, &huge, sizeof huge);
  write_bytes(b);
  CHECK_THAT(error_of(path), Catch::Contains("impossible header") || Catch::Contains("truncated"));
  // steps done not at a record's end (7 steps a record).
  b = good;
  const std::int64_t off_record = 36;
  std::memcpy(b.data() + steps_done_at, &off_record, sizeof off_record);
  write_bytes(b);
  CHECK_THAT(error_of(path), Catch::Contains("impossible header"));
}
