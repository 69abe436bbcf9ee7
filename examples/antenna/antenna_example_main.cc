// The antenna example as a program: prints, per frame, what the robot believed and whether it touched.
#include <cstdio>
#include <exception>

#include "examples/antenna/antenna_example.h"

int main() {
  try {
    const cairn::examples::AntennaRun run = cairn::examples::RunAntennaExample({});
    for (const auto& f : run.frames) {
      std::printf("%-20s truth %-15s memory says %-15s confidence %.2f  touched %d points\n", f.object.c_str(),
                  f.traversable ? "traversable" : "non-traversable",
                  f.classified_traversable ? "traversable" : "non-traversable", f.confidence, f.touched_points);
    }
    std::printf("%d interactions, %d memories\n", run.interactions, run.memory_size);
  } catch (const std::exception& error) {
    std::fprintf(stderr, "antenna_example: %s\n", error.what());
    return 1;
  }
  return 0;
}
