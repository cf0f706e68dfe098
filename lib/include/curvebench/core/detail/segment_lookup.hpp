// Private helper shared by every piecewise object (curves, arc-length tables, motion, references,
// the keyframe channel): which segment of a sorted breakpoint list holds a parameter. Not part of
// the public interface.
//
// The rule: breakpoints b_0 <= b_1 <= ... <= b_n (n >= 1, so n segments [b_i, b_{i+1}]); segment_of
// gives the i with b_i <= u < b_{i+1}, so an interior breakpoint belongs to the segment on its
// right (the piece that starts there) and the value there is the limit from the right; u = b_n (the
// domain's right end) belongs to the last segment n - 1. With repeated breakpoints the segment is
// the one after the last copy (b_i <= u is taken for the largest such i: breakpoint_at_or_below,
// which tables answering exactly at their last node use unclamped), so an empty segment is
// never chosen for u < b_n; only a repeated last breakpoint (b_{n-1} = b_n) makes u = b_n fall in the
// empty last segment, which callers that allow it handle themselves (the B-spline's last non-empty
// span). Outside the domain segment_of answers the nearest end segment (0 below b_0, n - 1 above
// b_n and for NaN, which compares false everywhere); checked_segment_of throws std::domain_error
// there instead (check_parameter's message, core/curve.hpp). segment_of_from_left is the mirror rule
// (b_i < u <= b_{i+1}: a breakpoint belongs to the segment on its left, b_0 to the first), for the
// limit from the left. in_segment tells whether u still lies in segment i under the rule (the O(1)
// test of batch evaluations that walk sorted parameters).
// The records' variant of breakpoint_at_or_below serves sorted keys whose time is a member.
// Cost: one binary search, O(log n) comparisons, no allocation (in_segment: two comparisons).
#pragma once

#include "curvebench/core/curve.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

namespace curvebench::detail {

/// The index of the last breakpoint <= u: the i in 0..n with b_i <= u < b_{i+1} (b_{n+1} = +inf),
/// n at u >= b_n (and NaN), 0 below b_0; breakpoints need not be more than one. The node rule of
/// tables that answer exactly at their last node (the arc-length references).
template <class Real>
[[nodiscard]] std::size_t breakpoint_at_or_below(std::type_identity_t<std::span<const Real>> breakpoints,
                                                 const Real& u) {
  // The first breakpoint > u, minus one.
  const auto above =
      static_cast<std::size_t>(std::upper_bound(breakpoints.begin(), breakpoints.end(), u) - breakpoints.begin());
  return above == 0 ? 0 : above - 1;
}

/// breakpoint_at_or_below over records whose breakpoint is a member (keys, points): key(r) is the
/// breakpoint of record r; the records are sorted by it.
template <class Record, class Real, class Key>
[[nodiscard]] std::size_t breakpoint_at_or_below(std::span<const Record> records, const Real& u, Key key) {
  const auto above = static_cast<std::size_t>(
      std::upper_bound(records.begin(), records.end(), u, [&](const Real& v, const Record& r) { return v < key(r); }) -
      records.begin());
  return above == 0 ? 0 : above - 1;
}

/// The segment i in 0..n-1 of breakpoints b_0 <= ... <= b_n (n >= 1) with b_i <= u < b_{i+1}; n - 1
/// at u >= b_n (and NaN), 0 below b_0 (see the header): breakpoint_at_or_below clamped to the
/// segments.
template <class Real>
[[nodiscard]] std::size_t segment_of(std::type_identity_t<std::span<const Real>> breakpoints, const Real& u) {
  return std::min(breakpoint_at_or_below<Real>(breakpoints, u), breakpoints.size() - 2);
}

/// segment_of for u in the domain [b_0, b_n]; std::domain_error otherwise (NaN included):
/// "u = 2 is outside the domain [0, 1]", the name and index as check_parameter writes them.
template <class Real>
[[nodiscard]] std::size_t checked_segment_of(std::type_identity_t<std::span<const Real>> breakpoints, const Real& u,
                                             std::string_view name = "u", std::size_t index = std::string::npos) {
  check_parameter(u, interval<Real>{breakpoints.front(), breakpoints.back()}, name, index);
  return segment_of<Real>(breakpoints, u);
}

/// The mirror rule: the segment i with b_i < u <= b_{i+1} (a breakpoint belongs to the segment on
/// its left; 0 at u <= b_0, n - 1 above b_n).
template <class Real>
[[nodiscard]] std::size_t segment_of_from_left(std::type_identity_t<std::span<const Real>> breakpoints, const Real& u) {
  // The first breakpoint >= u, minus one, clamped to the segments.
  const auto at_or_above =
      static_cast<std::size_t>(std::lower_bound(breakpoints.begin(), breakpoints.end(), u) - breakpoints.begin());
  const std::size_t last = breakpoints.size() - 2;
  return at_or_above == 0 ? 0 : std::min(at_or_above - 1, last);
}

/// Whether segment_of(breakpoints, u) == i for u in the domain: b_i <= u < b_{i+1}, or i is the last
/// segment and b_i <= u <= b_n. False for NaN.
template <class Real>
[[nodiscard]] bool in_segment(std::type_identity_t<std::span<const Real>> breakpoints, std::size_t i, const Real& u) {
  const Real& right = breakpoints[i + 1];
  return breakpoints[i] <= u && (u < right || (i + 2 == breakpoints.size() && u <= right));
}

}  // namespace curvebench::detail
