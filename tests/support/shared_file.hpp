#pragma once
// Test support for the ranks of one MPI run: a file all of them name alike, and the message of
// the CollectiveError a step ends with.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "io/network_hdf5.hpp"
#include "parallel/parallel_session.hpp"

namespace hmfnet::test {

// One file name for all ranks of this run (their parent, mpirun, is shared), another for a
// concurrent run at another rank count; rank 0 writes it and removes it.
class SharedFile {
 public:
  explicit SharedFile(const std::string& stem, const std::string& extension = ".h5")
      : m_path((std::filesystem::temp_directory_path() /
                (stem + "_" + std::to_string(::getppid()) + "_" +
                 std::to_string(ParallelSession::ranks()) + extension))
                   .string()) {}
  ~SharedFile() {
    ParallelSession::sum(0.0);  // every rank is done with it
    if (ParallelSession::rank() == 0) std::filesystem::remove(m_path);
  }
  SharedFile(const SharedFile&) = delete;
  SharedFile& operator=(const SharedFile&) = delete;
  const std::string& path() const { return m_path; }
  /// Rank 0 writes (then `corrupt` runs on it); the others wait for it.
  template <class Corrupt>
  void write(const Network& net, Corrupt corrupt) const {
    ParallelSession::agree([&] {
      if (ParallelSession::rank() == 0) {
        write_network_hdf5(m_path, net);
        corrupt();
      }
    });
  }
  /// Rank 0 writes `text` as the file's bytes; the others wait for it.
  void write_text(const std::string& text) const {
    ParallelSession::agree([&] {
      if (ParallelSession::rank() != 0) return;
      std::ofstream out(m_path, std::ios::binary);
      out << text;
      if (!out.flush()) throw std::runtime_error("cannot write " + m_path);
    });
  }

 private:
  std::string m_path;
};

inline std::string collective_message(const std::function<void()>& step) {
  try {
    step();
  } catch (const CollectiveError& e) {
    return e.what();
  }
  return "(no CollectiveError)";
}

}  // namespace hmfnet::test
