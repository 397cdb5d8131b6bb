#include "core/distinct_files.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <system_error>

#include "core/error.hpp"

namespace hmfnet {

namespace {

struct FileIdentity {
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  std::string canonical;  ///< absolute, links of the existing prefix resolved
};

FileIdentity identity_of(const std::string& path) {
  namespace fs = std::filesystem;
  FileIdentity id;
  struct stat status {};
  // stat follows symbolic links: a link to the input has the input's identity.
  if (::stat(path.c_str(), &status) == 0) {
    id.exists = true;
    id.device = status.st_dev;
    id.inode = status.st_ino;
  }
  std::error_code error;
  const fs::path absolute = fs::absolute(path, error);
  const fs::path canonical = fs::weakly_canonical(absolute, error);
  id.canonical = (error ? absolute.lexically_normal() : canonical).string();
  return id;
}

bool same_file(const FileIdentity& a, const FileIdentity& b) {
  if (a.exists && b.exists) return a.device == b.device && a.inode == b.inode;
  return a.canonical == b.canonical;
}

// AtomicFile writes FINAL.tmp.PID.COUNTER next to FINAL before the rename.
bool is_temporary_of(const FileIdentity& written, const FileIdentity& other) {
  const std::string prefix = written.canonical + ".tmp.";
  return other.canonical.compare(0, prefix.size(), prefix) == 0;
}

[[noreturn]] void refuse(const FileRole& written, const FileRole& other, bool other_is_read) {
  const std::string other_name =
      (other.role == "input" ? "the input file" : other.role) + " " + other.path;
  throw InputError(written.path, 0,
                   written.role + " names the same file as " + other_name + ": " +
                       (other_is_read ? "writing it would destroy what the command reads"
                                      : "one output would overwrite the other") +
                       "; choose another path");
}

}  // namespace

void require_distinct_files(const std::vector<FileRole>& reads,
                            const std::vector<FileRole>& writes) {
  std::vector<FileIdentity> written;
  written.reserve(writes.size());
  for (const FileRole& w : writes) written.push_back(identity_of(w.path));
  for (std::size_t i = 0; i < writes.size(); ++i) {
    if (writes[i].path.empty()) continue;
    for (const FileRole& r : reads) {
      if (r.path.empty()) continue;
      const FileIdentity read = identity_of(r.path);
      if (!read.exists) continue;
      if (same_file(written[i], read) || is_temporary_of(written[i], read)) {
        refuse(writes[i], r, true);
      }
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (writes[j].path.empty()) continue;
      if (same_file(written[i], written[j])) refuse(writes[i], writes[j], false);
    }
  }
}

}  // namespace hmfnet
