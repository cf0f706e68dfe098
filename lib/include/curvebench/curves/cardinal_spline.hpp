// cardinal_spline: cardinal cubic splines (Catmull-Rom for s = 1/2) with alpha parameterization:
// interpolating C1 cubics whose slope at a point is 2s times the derivative of the parabola
// through its neighbours, on given knots or knots from |P_{i+1} - P_i|^alpha (alpha = 0 uniform,
// 1/2 centripetal, 1 chordal); s = 1/2 is the Barry-Goldman non-uniform Catmull-Rom curve (as
// Boost.Math's catmull_rom). Ends: phantom, one_sided, given_tangents, closed, control_points (the
// textbook form through P_1..P_{n-2}; formulas, and the erratum to seed 000's difference formula,
// above cardinal_end). Evaluated by piecewise_cubic.
// Sources: seeds 000, 001, 002 (cardinal matrix, finite-difference slopes, extrapolated ends);
// Barry & Goldman (1988).
// Cost: O(n) construction, O(1) evaluation; local control (moving P_j changes at most segments
// j-2 .. j+1; with control_points ends, whose segment k starts at P_{k+1}, segments j-3 .. j).
// Accuracy: interpolates the points to rounding; C1 at the knots; reproduces quadratics (s = 1/2,
// one_sided or control_points ends) on any knots.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/curves/detail/cubic_family.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"

#include <cstddef>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace curvebench {

// Knots: given, or from the points by u_0 = 0, u_{i+1} = u_i + |P_{i+1} - P_i|^alpha with alpha = 0
// (uniform), 1/2 (centripetal), 1 (chordal). The slope dP/du at an interior point is 2s times the
// derivative of the parabola through the three neighbouring points,
//     m_i = 2s (h_i D_{i-1} + h_{i-1} D_i) / (h_{i-1} + h_i),   D_i = (P_{i+1} - P_i) / h_i,
// seed 000's "2nd-order finite difference" (DESIGN.md erratum: its `÷` is a product and its `-` a
// `+`). On uniform knots m_i = s (P_{i+1} - P_{i-1}): the cardinal matrix of seed 002 (s = 1/2 is
// Catmull-Rom). With s = 1/2 and any alpha this is the Barry-Goldman non-uniform Catmull-Rom curve
// (the slope above equals D_{i-1} + D_i - (P_{i+1} - P_{i-1})/(h_{i-1} + h_i)), which is what
// Boost.Math's catmull_rom evaluates.
// End conditions (cardinal_end):
//   phantom        extrapolated end points P_{-1} = 2 P_0 - P_1, P_{n+1} = 2 P_n - P_{n-1}, at the
//                  mirrored knots (seed 002: "extrapolate"); gives m_0 = 2s D_0, m_n = 2s D_{n-1}
//   one_sided      2s times the slope of the parabola through the first (last) three points at the
//                  end knot: seed 000's second-order one-sided difference
//   given_tangents the user's dP/du at both ends (not scaled by 2s)
//   closed         a closed loop: the segment P_{n-1} -> P_0 is added and slopes wrap around
//   control_points the first and last points only shape the end segments (seed 001's "all but the
//                  endpoints", the textbook Catmull-Rom): n >= 4 points, knots from all n (or n
//                  given), and the curve runs from P_1 to P_{n-2} on [u_1, u_{n-2}] (n - 3
//                  segments), each P_i with the interior slope above from its real neighbours. For
//                  s = 1/2 each segment is the four-point Barry-Goldman pyramid; on uniform knots it
//                  is given_tangents on P_1..P_{n-2} with s (P_2 - P_0) and s (P_{n-1} - P_{n-3}).
/// How a cardinal spline treats its ends (see the comment above).
enum class cardinal_end { phantom, one_sided, given_tangents, closed, control_points };

[[nodiscard]] inline const char* to_string(cardinal_end e) {
  switch (e) {
    case cardinal_end::phantom: return "phantom";
    case cardinal_end::one_sided: return "one_sided";
    case cardinal_end::given_tangents: return "given_tangents";
    case cardinal_end::closed: return "closed";
    case cardinal_end::control_points: return "control_points";
  }
  return "unknown";
}

/// Knots u_0 = 0, u_{i+1} = u_i + |P_{i+1} - P_i|^alpha (alpha in [0, 1]); `closed` appends the knot
/// of the closing chord P_{n-1} -> P_0. Repeated consecutive points with alpha > 0 -> invalid_input.
template <class Real, int Dim>
[[nodiscard]] std::vector<Real> alpha_knots(std::span<const point<Real, Dim>> points, const Real& alpha,
                                            bool closed = false) {
  validate::in_range("alpha", alpha, Real(0), Real(1));
  validate::count_at_least("points", points.size(), 2, "a segment needs two points");
  validate::finite_points<Real, Dim>("points", points);
  const std::size_t n = points.size();
  const std::size_t chords = closed ? n : n - 1;
  std::vector<Real> k(chords + 1);
  k[0] = Real(0);
  using std::pow;
  for (std::size_t i = 0; i < chords; ++i) {
    const std::size_t j = (i + 1) % n;
    Real step(1);
    if (alpha != Real(0)) {
      // safe_norm: the plain norm squares the components, which overflow from coordinates near
      // 1e154 and underflow below 1e-154, where the chord itself is representable.
      const Real d = safe_norm(point<Real, Dim>(points[j] - points[i]));
      if (!(d > Real(0)))
        validate::fail(validate::indexed("points", j) + " repeats " + validate::indexed("points", i) +
                       ": a zero chord gives a zero knot interval |dP|^alpha with alpha = " + to_text(alpha) +
                       " > 0 (remove the repeated point or use alpha = 0)");
      step = pow(d, alpha);
    }
    k[i + 1] = k[i] + step;
  }
  return k;
}

template <class Real, int Dim>
struct cardinal_options {
  /// Tangent scale s (s = 1/2 Catmull-Rom; s = (1 - tension)/2).
  Real s = Real(1) / Real(2);
  /// Parameterization exponent, used when the knots are not given: 0 uniform, 1/2 centripetal, 1 chordal.
  Real alpha = Real(0);
  cardinal_end end = cardinal_end::phantom;
  /// dP/du at the first and last point, for cardinal_end::given_tangents only.
  point<Real, Dim> start_tangent = point<Real, Dim>::Zero();
  point<Real, Dim> end_tangent = point<Real, Dim>::Zero();
};

template <class Real, int Dim>
class cardinal_spline : public detail::cubic_family<Real, Dim> {
  using base = detail::cubic_family<Real, Dim>;

 public:
  using typename base::point_type;
  using options = cardinal_options<Real, Dim>;

  /// Knots from the points by options.alpha (closed: one more knot for the closing chord).
  explicit cardinal_spline(const point_list<Real, Dim>& points, const options& opt = {})
      : cardinal_spline(build(checked_alpha_knots(points, opt), points, opt), points, opt) {}

  /// Given knots (e.g. key times): points.size() knots, or points.size() + 1 for a closed loop
  /// (the last knot is the return to points[0]); with control_points ends the curve's domain is
  /// [knots[1], knots[n-2]]. options.alpha must be 0 (the knots ARE the parameterization).
  cardinal_spline(const std::vector<Real>& knots, const point_list<Real, Dim>& points, const options& opt)
      : cardinal_spline(build(knots, points, check_given_knots(opt)), points, opt) {}

  [[nodiscard]] const point_list<Real, Dim>& points() const { return points_; }
  /// The slopes dP/du at the knots (closed: n + 1 entries, the last equal to the first;
  /// control_points: n - 2 entries, at P_1..P_{n-2}, the curve's breakpoints).
  [[nodiscard]] const point_list<Real, Dim>& slopes() const { return slopes_; }
  [[nodiscard]] const options& settings() const { return options_; }

 private:
  struct built {
    typename base::engine_type engine;
    point_list<Real, Dim> slopes;
  };

  cardinal_spline(built b, const point_list<Real, Dim>& points, const options& opt)
      : base(std::move(b.engine)), points_(points), options_(opt), slopes_(std::move(b.slopes)) {}

  static std::vector<Real> checked_alpha_knots(const point_list<Real, Dim>& points, const options& opt) {
    check_options(points, opt);
    return alpha_knots<Real, Dim>(points, opt.alpha, opt.end == cardinal_end::closed);
  }

  static const options& check_given_knots(const options& opt) {
    if (opt.alpha != Real(0))
      validate::fail("alpha = " + to_text(opt.alpha) +
                     ": must be 0 when knots are given (the knots are the parameterization)");
    return opt;
  }

  static void check_options(const point_list<Real, Dim>& points, const options& opt) {
    validate::finite("s", opt.s);
    if (opt.end == cardinal_end::control_points)
      validate::count_at_least("points", points.size(), 4,
                               "end = control_points: the first and last points only shape the end segments, so "
                               "one segment needs four points");
    const bool needs3 = opt.end == cardinal_end::one_sided || opt.end == cardinal_end::closed;
    validate::count_at_least("points", points.size(), needs3 ? 3 : 2,
                             needs3 ? "one-sided ends and closed loops need three points" : "a segment needs two");
    validate::finite_points<Real, Dim>("points", points);
    validate::finite_point<Real, Dim>("start_tangent", 0, opt.start_tangent);
    validate::finite_point<Real, Dim>("end_tangent", 0, opt.end_tangent);
  }

  static built build(const std::vector<Real>& knots, const point_list<Real, Dim>& pts, const options& opt) {
    check_options(pts, opt);
    const bool closed = opt.end == cardinal_end::closed;
    const std::size_t np = pts.size();
    validate::same_count("knots", knots.size(), closed ? "points + 1 (closed loop)" : "points", closed ? np + 1 : np);
    validate::increasing<Real>("knots", knots);
    const Real two_s = Real(2) * opt.s;
    // Values at the knots: closed loops repeat the first point at the end.
    point_list<Real, Dim> v(pts.begin(), pts.end());
    if (closed) v.push_back(pts.front());
    const std::size_t n = v.size() - 1;  // segments
    auto h = [&](std::size_t i) { return knots[i + 1] - knots[i]; };
    point_list<Real, Dim> slopes(n + 1, point_type::Zero());
    std::vector<Real> err(n + 1, Real(0));  // bounds on the slopes' rounding (detail/cubic_family.hpp)
    for (std::size_t i = 1; i < n; ++i) {
      slopes[i] = two_s * detail::parabola_slope_mid<Real, Dim>(h(i - 1), h(i), v[i - 1], v[i], v[i + 1]);
      err[i] = detail::parabola_slope_mid_error<Real, Dim>(h(i - 1), h(i), v[i - 1], v[i], v[i + 1], two_s);
    }
    switch (opt.end) {
      case cardinal_end::phantom:
        slopes[0] = two_s * point_type((v[1] - v[0]) / h(0));
        slopes[n] = two_s * point_type((v[n] - v[n - 1]) / h(n - 1));
        // A difference of data, h, a division and the scale: 4 u of the slope, 3 eps with margin.
        err[0] = Real(3) * epsilon<Real>() * safe_norm(slopes[0]);
        err[n] = Real(3) * epsilon<Real>() * safe_norm(slopes[n]);
        break;
      case cardinal_end::one_sided:
        slopes[0] = two_s * detail::parabola_slope_start<Real, Dim>(h(0), h(1), v[0], v[1], v[2]);
        slopes[n] = two_s * detail::parabola_slope_end<Real, Dim>(h(n - 2), h(n - 1), v[n - 2], v[n - 1], v[n]);
        err[0] = detail::parabola_slope_end_error<Real, Dim>(h(0), h(1), v[0], v[1], v[2], two_s);
        err[n] = detail::parabola_slope_end_error<Real, Dim>(h(n - 1), h(n - 2), v[n], v[n - 1], v[n - 2], two_s);
        break;
      case cardinal_end::given_tangents:
        slopes[0] = opt.start_tangent;
        slopes[n] = opt.end_tangent;
        break;
      case cardinal_end::closed:
        slopes[0] = two_s * detail::parabola_slope_mid<Real, Dim>(h(n - 1), h(0), v[n - 1], v[0], v[1]);
        slopes[n] = slopes[0];
        err[0] = detail::parabola_slope_mid_error<Real, Dim>(h(n - 1), h(0), v[n - 1], v[0], v[1], two_s);
        err[n] = err[0];
        break;
      case cardinal_end::control_points: {
        // P_0 and P_n only entered the slopes at P_1 and P_{n-1}: the curve is the interior part.
        std::vector<Real> inner_knots(knots.begin() + 1, knots.end() - 1);
        point_list<Real, Dim> inner_values(v.begin() + 1, v.end() - 1);
        point_list<Real, Dim> inner_slopes(slopes.begin() + 1, slopes.end() - 1);
        const std::vector<Real> inner_err(err.begin() + 1, err.end() - 1);
        auto engine = base::engine_type::from_hermite(std::move(inner_knots), inner_values, inner_slopes, inner_slopes,
                                                      inner_err, inner_err);
        return built{std::move(engine), std::move(inner_slopes)};
      }
    }
    auto engine = base::engine_type::from_hermite(knots, v, slopes, slopes, err, err);
    return built{std::move(engine), std::move(slopes)};
  }

  point_list<Real, Dim> points_;
  options options_;
  point_list<Real, Dim> slopes_;
};

}  // namespace curvebench
