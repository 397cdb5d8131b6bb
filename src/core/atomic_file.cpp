#include "core/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"

namespace hmfnet {

void require_writable_destination(const std::string& path) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError("<output>", 0, "empty output path");
  const fs::path dir =
      fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  if (!fs::is_directory(dir)) {
    throw InputError(path, 0, "cannot write: directory '" + dir.string() + "' does not exist");
  }
  if (::access(dir.c_str(), W_OK) != 0) {
    throw InputError(path, 0, "cannot write: directory '" + dir.string() + "' is not writable");
  }
  if (fs::is_directory(path)) throw InputError(path, 0, "cannot write: is a directory");
}

void require_free_space(const std::string& path, std::uintmax_t bytes) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  std::error_code error;
  const fs::space_info space = fs::space(dir, error);
  if (error) return;  // unknown (e.g. a special file system): the write itself will tell
  if (space.available >= bytes) return;
  const auto megabytes = [](std::uintmax_t b) {
    return std::to_string((b + (1u << 20) - 1) >> 20) + " MB";
  };
  throw InputError(path, 0,
                   "not enough free space: the run's output needs about " + megabytes(bytes) +
                       ", '" + dir.string() + "' has " + megabytes(space.available));
}

AtomicFile::AtomicFile(std::string final_path) : m_final(std::move(final_path)) {
  require_writable_destination(m_final);
  // pid + a per-process counter: distinct temporaries for concurrent writers of one path.
  static std::atomic<unsigned> counter{0};
  m_temp = m_final + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

AtomicFile::~AtomicFile() {
  if (!m_committed) std::remove(m_temp.c_str());
}

void AtomicFile::commit() {
  if (std::rename(m_temp.c_str(), m_final.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(m_temp.c_str());
    throw InputError(m_final, 0, "cannot rename temporary output into place: " + why);
  }
  m_committed = true;
}

}  // namespace hmfnet
