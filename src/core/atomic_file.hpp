#pragma once
// Write-then-rename: an output appears under its final name only when complete, so an interrupted
// or failed run never leaves a partial file there. The temporary sits in the same directory (same
// file system, so rename(2) is atomic) and is removed if commit() is never reached.
#include <cstdint>
#include <string>

namespace hmfnet {

/// Throws InputError naming `path` unless its directory exists and is writable: called by
/// commands before their work, so a bad output location fails at start-up, not after hours.
void require_writable_destination(const std::string& path);

/// Throws InputError naming `path` unless the file system of its directory has at least `bytes`
/// available: a run whose results cannot fit fails at start-up, not when it writes them.
void require_free_space(const std::string& path, std::uintmax_t bytes);

class AtomicFile {
 public:
  /// Checks at once that the destination directory is writable, so a run fails before its work.
  explicit AtomicFile(std::string final_path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  /// Where to write the content.
  const std::string& temp_path() const { return m_temp; }
  const std::string& final_path() const { return m_final; }
  /// Renames the temporary to the final name; throws InputError naming the path on failure.
  void commit();

 private:
  std::string m_final;
  std::string m_temp;
  bool m_committed = false;
};

}  // namespace hmfnet
