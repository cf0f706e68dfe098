// The engine team's easing export: CSS `ease` (cubic-bezier(0.25, 0.1, 0.25, 1), easing.hpp) in
// float at 121 times, as the CSV `curvebench check` reads for a channel spec (t,value; easing.json).
//   own_write_easing EASING.csv
#include "easing.hpp"

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: own_write_easing EASING.csv\n");
    return 2;
  }
  std::FILE* out = std::fopen(argv[1], "w");
  if (!out) {
    std::fprintf(stderr, "own_write_easing: cannot write %s\n", argv[1]);
    return 1;
  }
  const own::css_easing ease{0.25f, 0.1f, 0.25f, 1.0f};
  constexpr int steps = 120;
  std::fprintf(out, "t,value\n");
  for (int i = 0; i <= steps; ++i) {
    const float t = static_cast<float>(i) / steps;  // the engine's own time, a float
    std::fprintf(out, "%.9g,%.9g\n", static_cast<double>(t), static_cast<double>(ease(t)));
  }
  return std::fclose(out) == 0 ? 0 : 1;
}
