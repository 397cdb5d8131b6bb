#pragma once
// Provenance written into every output: the code version and the git commit of the build.
// Defined in a generated file compiled into its own shared library (cmake/HmfnetVersion.cmake):
// a new commit rebuilds only that library, and the executables, which do not relink on its
// change, keep their timestamps, so `make paper-figures` re-runs only the drivers whose code
// changed, while each run still records the commit it ran at.
namespace hmfnet {

/// The project version (CMake's PROJECT_VERSION), e.g. "0.1.0".
const char* version();

/// `git describe --always --dirty --abbrev=12` of the source tree at the last build ("unknown"
/// outside a git checkout).
const char* git_commit();

}  // namespace hmfnet
