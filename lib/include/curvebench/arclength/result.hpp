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
// Every status but converged names why: `reason`, a status_reason, says which bound failed
// or which cap stopped the method (a static text), on which segment [breakpoint i, breakpoint i+1]
// and parameter interval where the method knows it, and the quantity against the bound it failed.
// It holds a string_view and numbers only, no allocation (gauss_length without an estimate is
// benchmarked per evaluation); to_text(reason) words it as one line when it is printed. A sum of
// results keeps the reason of the worse status (the first on a tie).
// Cost: O(1); these are plain aggregates.
#pragma once

#include "curvebench/core/result_status.hpp"

#include "curvebench/core/error.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <string_view>

namespace curvebench::arclength {

/// The status vocabulary of core/result_status.hpp under its arc-length name (the same type).
using result_status = ::curvebench::result_status;
using ::curvebench::result_status_from_string;
using ::curvebench::to_string;
using ::curvebench::to_text;  // numbers' text beside the reasons' (to_text(status_reason) below)
using ::curvebench::worst;

/// Why a result is not converged: `what` names the failed bound or the cap (static text; empty when
/// there is no reason, as for a converged result), `segment` the segment [breakpoint i, i+1] it
/// concerns (npos when the reason is not per segment), [a, b] the parameter interval concerned
/// (a == b: none), `measured` the quantity and `limit` the bound it failed (both 0 when the reason
/// is not numeric). No allocation: built on the hot path, worded only when printed (to_text).
template <class Real>
struct status_reason {
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);
  std::string_view what{};
  std::size_t segment = npos;
  Real a{0}, b{0};
  Real measured{0}, limit{0};

  [[nodiscard]] bool empty() const { return what.empty(); }
};

/// The reasons' texts, one per bound or cap of the length methods (the methods' headers say when
/// each applies). Tests compare a result's reason.what with them.
namespace reasons {
inline constexpr std::string_view no_estimate = "fixed rule without an estimate (estimate:none)";
inline constexpr std::string_view composite_no_estimate = "composite rule without an estimate";
inline constexpr std::string_view order_test = "order test failed: |Q1 - Q2| < 16 |Q2 - Q4|";
inline constexpr std::string_view near_cusp = "near-cusp branch point within 1/8 of the piece";
inline constexpr std::string_view shallow_near =
    "shallow speed minimum inside the piece with branch points within 1/8 of its width";
inline constexpr std::string_view no_rounding_bound = "the curve knows no rounding bound";
inline constexpr std::string_view rounding_over_tolerance = "the curve's rounding bound exceeds the tolerance";
inline constexpr std::string_view budget = "evaluation budget reached";
inline constexpr std::string_view budget_unmeasured = "evaluation budget reached before this segment was measured";
inline constexpr std::string_view interval_cap = "panel cap reached (max_intervals)";
inline constexpr std::string_view max_depth = "max depth reached";
inline constexpr std::string_view panels_at_floor = "panels at their rounding floor";
inline constexpr std::string_view halves_no_better = "halves do not improve on their panel (the integrand's rounding)";
inline constexpr std::string_view pieces_at_floor = "pieces at their rounding floor";
inline constexpr std::string_view bracket_not_finite = "a piece's bracket is not finite (overflow or NaN)";
inline constexpr std::string_view estimate_not_finite = "the summed bound is not finite";
inline constexpr std::string_view table_steps = "steps per segment not a multiple of 4 of at least 16: no coarser sums";
inline constexpr std::string_view table_turn =
    "4h chords turn by more than 60 degrees (cosine of the turn below 1/2): the table does not resolve the curve";
inline constexpr std::string_view table_ratio = "chord sums' ratio (L_2h - L_4h) / (L_h - L_2h) outside [3, 6]";
inline constexpr std::string_view noise_length = "length within rounding noise of the curve's size (may be 0)";
// u(s) and s(u) (newton_inversion.hpp, parameterization.hpp).
inline constexpr std::string_view bracket_end_bound =
    "the answer is the bracket's end, whose bound exceeds the tolerance";
inline constexpr std::string_view newton_cap = "Newton's iteration or evaluation cap reached before the tolerance";
inline constexpr std::string_view bracket_at_rounding = "the bracket cannot shrink further in Real";
inline constexpr std::string_view chord_table_no_estimate = "chord table without an estimate (linear interpolation)";
inline constexpr std::string_view table_residual = "the table value's residual bound exceeds the tolerance";
inline constexpr std::string_view table_size_given = "table size given: not measured";
inline constexpr std::string_view table_unmeasured =
    "the cap on cells or the budget left a segment unhalved: its table is not measured";
inline constexpr std::string_view table_cap = "the cap on cells or the evaluation budget stopped the table";
inline constexpr std::string_view table_node_cap = "a table node's Newton solve ran out of its share of the budget";
inline constexpr std::string_view table_at_resolution =
    "the table is at the resolution of u in Real (8 eps max|u| max|P'|)";
}  // namespace reasons

/// A reason naming a segment and its parameter interval.
template <class Real>
[[nodiscard]] status_reason<Real> segment_reason(std::string_view what, std::size_t segment, const Real& a,
                                                 const Real& b, const Real& measured = Real(0),
                                                 const Real& limit = Real(0)) {
  return status_reason<Real>{what, segment, a, b, measured, limit};
}

/// A reason of the whole result (no segment, no interval): e.g. a global cap, with the estimate
/// reached and the target it did not meet.
template <class Real>
[[nodiscard]] status_reason<Real> global_reason(std::string_view what, const Real& measured = Real(0),
                                                const Real& limit = Real(0)) {
  return status_reason<Real>{what, status_reason<Real>::npos, Real(0), Real(0), measured, limit};
}

namespace detail {
/// A number of a reason as text: 5 significant digits (a reason is read, not parsed back; a
/// multiprecision value is shown through double).
template <class Real>
[[nodiscard]] std::string reason_number(const Real& x) {
  std::ostringstream os;
  os.precision(5);
  os << static_cast<double>(x);
  return os.str();
}
}  // namespace detail

/// The reason as one line: "segment 8 (u 10.124 to 11.649): order test failed: |Q1 - Q2| < 16 |Q2 -
/// Q4| (measured 3.0245e-07, bound 6.2e-07)"; "" for an empty reason. Parts the reason does not
/// have are left out ("u 0 to 1: ...", "...: evaluation budget reached (measured 1e-09, bound 1e-12)").
template <class Real>
[[nodiscard]] std::string to_text(const status_reason<Real>& r) {
  if (r.empty()) return {};
  std::string out;
  if (r.segment != status_reason<Real>::npos) out = "segment " + std::to_string(r.segment);
  if (r.a != r.b) {
    const std::string range = "u " + detail::reason_number(r.a) + " to " + detail::reason_number(r.b);
    out = out.empty() ? range : out + " (" + range + ")";
  }
  if (!out.empty()) out += ": ";
  out += r.what;
  if (r.measured != Real(0) || r.limit != Real(0))
    out += " (measured " + detail::reason_number(r.measured) + ", bound " + detail::reason_number(r.limit) + ")";
  return out;
}

/// An integral or a length: value, error estimate (an intended upper bound on |value - exact|),
/// curve-derivative (or position) evaluations, status, and why when it is not converged.
template <class Real>
struct quadrature_result {
  Real value{0};
  Real error_estimate{0};
  std::size_t evaluations{0};
  result_status status{result_status::converged};
  status_reason<Real> reason{};  ///< why the status is not converged (empty when converged)

  [[nodiscard]] bool converged() const { return status == result_status::converged; }

  /// Sum of two pieces (e.g. the segments of a curve): values and estimates add, costs add, the
  /// status is the worse of the two, and the reason that of the worse (the first on a tie, unless
  /// the first has none).
  quadrature_result& operator+=(const quadrature_result& o) {
    value += o.value;
    error_estimate += o.error_estimate;
    evaluations += o.evaluations;
    const result_status w = worst(status, o.status);
    if (w != status || (reason.empty() && o.status == status)) reason = o.reason;
    status = w;
    return *this;
  }

  /// Sets the status to s with its reason when s is worse than the status held (a status no worse
  /// keeps the status and the reason held).
  void degrade(result_status s, const status_reason<Real>& why) {
    if (worst(status, s) == status && !(reason.empty() && s == status)) return;
    status = worst(status, s);
    reason = why;
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
  status_reason<Real> reason{};  ///< why the status is not converged (empty when converged)

  [[nodiscard]] bool converged() const { return status == result_status::converged; }
};

/// +infinity of Real: the error estimate of a result that has no bound.
template <class Real>
[[nodiscard]] Real no_bound() {
  return std::numeric_limits<Real>::infinity();
}

}  // namespace curvebench::arclength
