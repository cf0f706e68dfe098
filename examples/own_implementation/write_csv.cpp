// The engine team's export: its Catmull-Rom (centripetal, keys.hpp) at 101 frames and its chord
// table's lengths and inverse, as CSV files that `curvebench check` reads (curvebench_add_check in
// CMakeLists.txt runs this program, then the check on spec.json).
//   own_write_csv VALUES.csv LENGTHS.csv INVERSE.csv
#include "catmull_rom.hpp"
#include "chord_table.hpp"
#include "keys.hpp"

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: own_write_csv VALUES.csv LENGTHS.csv INVERSE.csv\n");
    return 2;
  }
  const own::catmull_rom c(own::keys(), 0.5);
  const own::chord_table t(c, c.start(), c.end(), own::table_steps);
  std::FILE* values = std::fopen(argv[1], "w");
  std::FILE* lengths = std::fopen(argv[2], "w");
  std::FILE* inverse = std::fopen(argv[3], "w");
  if (!values || !lengths || !inverse) {
    std::fprintf(stderr, "own_write_csv: cannot write the CSV files\n");
    return 1;
  }
  constexpr int frames = 100;
  std::fprintf(values, "u,x,y\n");
  std::fprintf(lengths, "u0,u1,length\n");
  std::fprintf(inverse, "s,u\n");
  for (int f = 0; f <= frames; ++f) {
    const double u = f == frames ? c.end() : c.start() + (c.end() - c.start()) * f / frames;
    const own::vec2 p = c(u);
    std::fprintf(values, "%.17g,%.17g,%.17g\n", u, p.x, p.y);
    std::fprintf(lengths, "%.17g,%.17g,%.17g\n", c.start(), u, t.length(c.start(), u));
    const double s = f == frames ? t.total() : t.total() * f / frames;
    std::fprintf(inverse, "%.17g,%.17g\n", s, t.u(s));
  }
  std::fclose(values);
  std::fclose(lengths);
  std::fclose(inverse);
  return 0;
}
