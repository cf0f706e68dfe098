// The example's keys and the subjects built from them: the points of curvebench's cases
// catmull_rom_uniform_2d and catmull_rom_centripetal_2d (and of spec.json), as the engine team's
// own data.
#pragma once

#include "catmull_rom.hpp"
#include "chord_table.hpp"

#include <harness/subject.hpp>

#include <memory>
#include <string>
#include <vector>

namespace own {

inline std::vector<vec2> keys() { return {{0, 0}, {1, 2}, {3, 3}, {4, 0}, {6, 1}, {7, 4}}; }

/// Chord-table steps over the domain: 64 per key interval, a typical engine setting.
inline constexpr std::size_t table_steps = 64 * 5;

/// The hand-written Catmull-Rom as a curvebench subject (eval only).
inline curvebench::harness::subject<2> spline_subject(double alpha) {
  auto c = std::make_shared<const catmull_rom>(keys(), alpha);
  curvebench::harness::subject<2> s;
  s.name = "own_catmull_rom";
  s.eval = [c](double u) {
    const vec2 p = (*c)(u);
    return curvebench::point<double, 2>(p.x, p.y);
  };
  return s;
}

/// The hand-written chord table on that spline as a subject (length and inverse).
inline curvebench::harness::subject<2> table_subject(double alpha) {
  const catmull_rom c(keys(), alpha);
  auto t = std::make_shared<const chord_table>(c, c.start(), c.end(), table_steps);
  curvebench::harness::subject<2> s;
  s.name = "own_chord_table";
  s.length = [t](double u0, double u1) { return t->length(u0, u1); };
  s.inverse = [t](double s_) { return t->u(s_); };
  return s;
}

}  // namespace own
