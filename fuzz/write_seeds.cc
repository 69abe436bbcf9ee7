// cairn_fuzz_write_seeds OUTPUT_FOLDER [TARGET...]: writes each target's seeds (fuzz_harnesses.h: FuzzTarget::seeds,
// the repository's own files and the generated ones) into OUTPUT_FOLDER/<target>/; all targets when none is named.
// scripts/fuzz.sh runs it before the fuzzers, so that the seeds are always the current files.

#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "cairn/common/atomic_file.h"
#include "fuzz_harnesses.h"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s OUTPUT_FOLDER [TARGET...]\n", argv[0]);
    return 2;
  }
  try {
    for (const cairn::fuzz::FuzzTarget& target : cairn::fuzz::FuzzTargets()) {
      bool wanted = argc == 2;
      for (int i = 2; i < argc; ++i) wanted = wanted || target.name == argv[i];
      if (!wanted) continue;
      const std::filesystem::path folder = std::filesystem::path(argv[1]) / target.name;
      std::filesystem::create_directories(folder);
      for (const cairn::fuzz::FuzzSeed& seed : target.seeds()) {
        cairn::WriteFileAtomically((folder / seed.name).string(), seed.contents);
      }
    }
    for (int i = 2; i < argc; ++i) {
      bool known = false;
      for (const cairn::fuzz::FuzzTarget& target : cairn::fuzz::FuzzTargets()) known = known || target.name == argv[i];
      if (!known) {
        std::fprintf(stderr, "%s: unknown target '%s'\n", argv[0], argv[i]);
        return 2;
      }
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: %s\n", argv[0], error.what());
    return 1;
  }
  return 0;
}
