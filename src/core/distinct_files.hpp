#pragma once
// The rule that keeps a command from destroying what it reads: before any work, every file it
// will write (results, checkpoint, network) is compared with every file it reads and with the
// other files it writes, by the file's identity, not its spelling: `net.h5`, `./net.h5`, a
// symbolic link to it and a hard link all name one file (same device and inode). A file that does
// not exist yet is compared by its canonical path (symbolic links of its directories resolved).
// The temporaries of AtomicFile (`FINAL.tmp.*`) count as the final path's: a read file with that
// prefix would be overwritten by them too.
#include <string>
#include <vector>

namespace hmfnet {

/// A file a command touches, named as the user named it: `role` is the option or argument
/// ("input", "--output", "--checkpoint"), `path` its value.
struct FileRole {
  std::string role;
  std::string path;
};

/// Throws InputError naming the written path, both roles and the cause when a written file is a
/// read file (or another written file). Read paths that name no existing file are skipped (an
/// in-memory network's label, say): nothing can overwrite them. Empty paths are skipped.
void require_distinct_files(const std::vector<FileRole>& reads,
                            const std::vector<FileRole>& writes);

}  // namespace hmfnet
