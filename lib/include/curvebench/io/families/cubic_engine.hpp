// What the registry entries of the piecewise-cubic families (hermite, cardinal, catmull_rom,
// kochanek_bartels, natural_cubic) share: their evaluation algorithms, those of the
// piecewise_cubic engine each of them evaluates with.
#pragma once

#include "curvebench/curves/piecewise_cubic.hpp"
#include "curvebench/io/family.hpp"

namespace curvebench::io::detail {

inline constexpr std::array<std::string_view, 3> cubic_engine_algorithms{"power", "matrix", "bezier"};

/// u -> c's engine evaluated with `algorithm`, for c wrapping a C (a family with engine()).
template <class C, int Dim>
evaluator_fn<Dim> cubic_engine_evaluator(const any_curve<double, Dim>& c, std::string_view type,
                                         std::string_view algorithm) {
  const cubic_algorithm a =
      named(type, algorithm, {cubic_algorithm::power, cubic_algorithm::matrix, cubic_algorithm::bezier});
  return on_target<C>(c, type, [a](const C& f, double u) { return f.engine().evaluate(u, 0, a); });
}

}  // namespace curvebench::io::detail
