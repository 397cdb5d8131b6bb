// The QSS campaign's resume file (qss_resume_file.hpp).
#include "qss_resume_file.hpp"

#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace hmfnet::verification {

namespace {

constexpr std::array<char, 16> k_magic = {'h', 'm', 'f', 'n', 'e', 't', '-', 'q',
                                          's', 's', '-', 'r', 'e', 's', '-', '1'};
// Guards the products of the header's counts against overflow; the bytes left in the file bound
// every array before it is allocated.
constexpr std::int64_t k_largest_count = std::int64_t{1} << 40;

std::runtime_error bad(const std::string& path, const std::string& why) {
  return std::runtime_error("QSS resume file " + path + ": " + why);
}

void put(std::ofstream& out, std::int64_t v) {
  out.write(reinterpret_cast<const char*>(&v), sizeof v);
}

void put(std::ofstream& out, const std::vector<double>& v) {
  out.write(reinterpret_cast<const char*>(v.data()),
            static_cast<std::streamsize>(v.size() * sizeof(double)));
}

std::int64_t take(std::ifstream& in, const std::string& path) {
  std::int64_t v = 0;
  if (!in.read(reinterpret_cast<char*>(&v), sizeof v)) throw bad(path, "truncated");
  return v;
}

std::vector<double> take(std::ifstream& in, std::int64_t count, const std::string& path) {
  const std::streamoff here = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff left = in.tellg() - here;
  in.seekg(here);
  if (count > left / static_cast<std::streamoff>(sizeof(double))) throw bad(path, "truncated");
  std::vector<double> v(static_cast<std::size_t>(count));
  if (!in.read(reinterpret_cast<char*>(v.data()),
               static_cast<std::streamsize>(v.size() * sizeof(double)))) {
    throw bad(path, "truncated");
  }
  return v;
}

// The arrays' lengths from the header, each checked before anything is allocated.
void check_header(const QssResumeSize& s, const std::string& path) {
  const bool ok = s.n >= 1 && s.replicas >= 1 && s.record_every >= 1 && s.records >= 0 &&
                  s.steps_done >= 0 && s.steps_done <= s.steps_planned &&
                  s.steps_done % s.record_every == 0 && s.n <= k_largest_count / s.replicas &&
                  s.records <= k_largest_count / s.replicas;
  if (!ok) {
    throw bad(path, "size N = " + std::to_string(s.n) + " has an impossible header (replicas " +
                        std::to_string(s.replicas) + ", records " + std::to_string(s.records) +
                        " every " + std::to_string(s.record_every) + ", steps " +
                        std::to_string(s.steps_done) + " of " + std::to_string(s.steps_planned) +
                        ")");
  }
}

// The file's bytes to `tmp` (errors name `path`, the file the caller asked for).
void write_sizes(const std::string& tmp, const std::string& path,
                 const std::vector<QssResumeSize>& sizes) {
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  if (!out) throw bad(path, "cannot be written");
  out.write(k_magic.data(), k_magic.size());
  put(out, static_cast<std::int64_t>(sizes.size()));
  for (const QssResumeSize& s : sizes) {
    const auto records = static_cast<std::size_t>(s.replicas * s.records);
    const auto cells = static_cast<std::size_t>(s.n * s.replicas);
    if (s.R_mean.size() != records || s.energy.size() != records || s.theta.size() != cells ||
        s.p.size() != cells) {
      throw bad(path, "size N = " + std::to_string(s.n) + ": arrays of the wrong length");
    }
    for (const std::int64_t v :
         {s.n, s.replicas, s.record_every, s.records, s.steps_planned, s.steps_done}) {
      put(out, v);
    }
    put(out, s.R_mean);
    put(out, s.energy);
    put(out, s.theta);
    put(out, s.p);
  }
  out.flush();
  if (!out) throw bad(path, "writing failed");
}

}  // namespace

void write_qss_resume(const std::string& path, const std::vector<QssResumeSize>& sizes) {
  const std::string tmp = path + ".tmp";
  try {
    write_sizes(tmp, path, sizes);
  } catch (...) {
    std::remove(tmp.c_str());
    throw;
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    std::remove(tmp.c_str());
    throw bad(path, "cannot be renamed into place");
  }
}

std::vector<QssResumeSize> read_qss_resume(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw bad(path, "cannot be opened");
  std::array<char, 16> magic{};
  if (!in.read(magic.data(), magic.size()) || magic != k_magic) {
    throw bad(path, "not a resume file of hmfnet_gpu_qss_lifetime");
  }
  const std::int64_t count = take(in, path);
  if (count < 0 || count > 1024) throw bad(path, "an impossible size count");
  std::vector<QssResumeSize> sizes(static_cast<std::size_t>(count));
  for (QssResumeSize& s : sizes) {
    for (std::int64_t* v :
         {&s.n, &s.replicas, &s.record_every, &s.records, &s.steps_planned, &s.steps_done}) {
      *v = take(in, path);
    }
    check_header(s, path);
    s.R_mean = take(in, s.replicas * s.records, path);
    s.energy = take(in, s.replicas * s.records, path);
    s.theta = take(in, s.n * s.replicas, path);
    s.p = take(in, s.n * s.replicas, path);
  }
  if (in.peek() != std::ifstream::traits_type::eof()) throw bad(path, "bytes after the last size");
  return sizes;
}

}  // namespace hmfnet::verification
