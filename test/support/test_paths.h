#pragma once

/// Where a test finds the repository, the shared data, the build tree and the `cairn` program. The paths are
/// defined in one source that cairn_add_test generates per test program, not passed as compile definitions: a
/// definition naming an absolute path would put the clone's folder on every test file's command line, and a
/// second clone (CI's fresh one) would then miss ccache for every test object.
namespace cairn::test {
extern const char* const kSourceDir;  ///< the repository (CAIRN_SOURCE_DIR)
extern const char* const kSharedDir;  ///< ../shared beside it (CAIRN_SHARED_DIR)
extern const char* const kBinaryDir;  ///< the build folder (CAIRN_BINARY_DIR)
extern const char* const kCliPath;    ///< the built `cairn` (CAIRN_CLI_PATH; only in programs added with CLI)
}  // namespace cairn::test

#define CAIRN_SOURCE_DIR (::cairn::test::kSourceDir)
#define CAIRN_SHARED_DIR (::cairn::test::kSharedDir)
#define CAIRN_BINARY_DIR (::cairn::test::kBinaryDir)
#define CAIRN_CLI_PATH (::cairn::test::kCliPath)
