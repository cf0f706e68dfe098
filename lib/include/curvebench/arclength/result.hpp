// Results of the arc-length methods: every value comes with what it cost and how sure it is.
//
// DESIGN.md: "Results of numerical methods carry what they cost and how sure they are: the value,
// an error estimate, and the number of curve/derivative evaluations." Iterative methods have caps
// and say when they hit them. The status vocabulary (converged, cap_hit, rounding_limited,
// not_guaranteed) is curvebench's one result_status (core/result_status.hpp, shared with the time
// solvers of channel/time_solver.hpp); arclength::result_status, arclength::to_string and
// arclength::worst name the same type and functions, so code written against this header compiles
// unchanged. For quadrature, lengths and inversion:
//   converged       the error estimate is <= the requested tolerance (and, for the adaptive
//                   methods, the estimate is an upper bound on every test curve of the suite);
//   cap_hit         an iteration / interval / depth / table-size cap stopped the method first;
//                   the estimate is still reported and still meant as a bound;
//   rounding_limited the estimate is dominated by the rounding floor of Real: the tolerance asked
//                   for is below what Real resolves; the estimate includes that floor;
//   not_guaranteed  the method has no error bound for this result (a fixed rule asked for no
//                   comparison, a table without a coarser table, a step that could not be checked);
//                   the error estimate is then +infinity, never a made-up number.
// Cost: O(1); these are plain aggregates.
#pragma once

#include "curvebench/core/result_status.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string_view>

namespace curvebench::arclength {

/// The status vocabulary of core/result_status.hpp under its arc-length name (the same type).
using result_status = ::curvebench::result_status;
using ::curvebench::result_status_from_string;
using ::curvebench::to_string;
using ::curvebench::worst;

/// An integral or a length: value, error estimate (an intended upper bound on |value - exact|),
/// curve-derivative (or position) evaluations, status.
template <class Real>
struct quadrature_result {
  Real value{0};
  Real error_estimate{0};
  std::size_t evaluations{0};
  result_status status{result_status::converged};

  [[nodiscard]] bool converged() const { return status == result_status::converged; }

  /// Sum of two pieces (e.g. the segments of a curve): values and estimates add, costs add, the
  /// status is the worse of the two.
  quadrature_result& operator+=(const quadrature_result& o) {
    value += o.value;
    error_estimate += o.error_estimate;
    evaluations += o.evaluations;
    status = worst(status, o.status);
    return *this;
  }
};

/// u with s(u) = s_target: the parameter found, the residual s(u) - s_target as computed (after a
/// Newton step bounded without integrating over it, the step's linear model s(u0) - s_target +
/// |P'(u0)| (u - u0)), an error estimate in arc length (|s_exact(u) - s_target| <= s_error_estimate
/// is intended), iterations, curve-derivative evaluations, status.
template <class Real>
struct inversion_result {
  Real u{0};
  Real residual{0};
  Real s_error_estimate{0};
  int iterations{0};
  std::size_t evaluations{0};
  result_status status{result_status::converged};

  [[nodiscard]] bool converged() const { return status == result_status::converged; }
};

/// +infinity of Real: the error estimate of a result that has no bound.
template <class Real>
[[nodiscard]] Real no_bound() {
  return std::numeric_limits<Real>::infinity();
}

}  // namespace curvebench::arclength
