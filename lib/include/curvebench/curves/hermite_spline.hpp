// hermite_spline: piecewise cubic Hermite interpolation on non-uniform knots.
//
// The user gives, at knots u_0 < ... < u_n, the values P_i and the slopes dP/du, either one slope
// per knot (C1) or separate incoming and outgoing slopes ("breaking" the spline, seed 000: C0 with
// an abrupt change of velocity, e.g. collisions). Slopes are per unit of the GLOBAL parameter u;
// on segment i the Hermite geometry is [P_i, P_{i+1}, h_i m_i^out, h_i m_{i+1}^in] (local tangents
// dP/dt = h dP/du), which reproduces seed 000's coefficient formulas on [t_i, t_{i+1}]
// (a = -2ΔY/h^3 + (s_i + s_{i+1})/h^2, b = 3ΔY/h^2 - (2 s_i + s_{i+1})/h, c = s_i, d = y_i;
// DESIGN.md erratum: the y_{i+1} blending term is -2(..)^3/h^3 + 3(..)^2/h^2).
// `hermite_spline::chain` builds seed 001's "Hermite cubic chain" from alternating points and
// tangents P_0, T_0, P_1, T_1, ... (2k items, k - 1 segments, knots 0..k-1 unless given).
// Evaluation by the piecewise_cubic engine: O(1) per point (O(log n) lookup on non-uniform
// knots); interpolates values and slopes exactly (to rounding); cubic precision: Hermite data of
// a cubic reproduce it.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/curves/detail/cubic_family.hpp"
#include "curvebench/curves/piecewise_cubic.hpp"

#include <span>
#include <string>
#include <utility>
#include <vector>

namespace curvebench {

template <class Real, int Dim>
class hermite_spline : public detail::cubic_family<Real, Dim> {
  using base = detail::cubic_family<Real, Dim>;

 public:
  using typename base::point_type;

  /// One slope (dP/du) per knot: a C1 spline. knots, values, slopes: n + 1 >= 2 each.
  hermite_spline(std::vector<Real> knots, point_list<Real, Dim> values, point_list<Real, Dim> slopes)
      : base(base::engine_type::from_hermite(knots, values, slopes, slopes)),
        values_(std::move(values)),
        incoming_(slopes),
        outgoing_(std::move(slopes)) {}

  /// Broken tangents: dP/du arriving at knot i is incoming[i], leaving it is outgoing[i].
  /// incoming[0] and outgoing[n] do not enter the curve (they must still be finite).
  hermite_spline(std::vector<Real> knots, point_list<Real, Dim> values, point_list<Real, Dim> incoming,
                 point_list<Real, Dim> outgoing)
      : base(base::engine_type::from_hermite(knots, values, incoming, outgoing)),
        values_(std::move(values)),
        incoming_(std::move(incoming)),
        outgoing_(std::move(outgoing)) {}

  /// Seed 001's Hermite chain: items = P_0, T_0, P_1, T_1, ..., P_{k-1}, T_{k-1} (2k items, k >= 2),
  /// tangents dP/du; knots 0, 1, ..., k-1 (so dP/du = dP/dt, as in the seed).
  [[nodiscard]] static hermite_spline chain(std::span<const point_type> items) {
    check_chain(items);
    return chain(items, uniform_knots<Real>(items.size() / 2 - 1));
  }

  /// The chain on given knots (k of them, strictly increasing); tangents are dP/du.
  [[nodiscard]] static hermite_spline chain(std::span<const point_type> items, std::vector<Real> knots) {
    check_chain(items);
    validate::same_count("knots", knots.size(), "chain points (items / 2)", items.size() / 2);
    point_list<Real, Dim> p, t;
    for (std::size_t i = 0; i < items.size(); i += 2) {
      p.push_back(items[i]);
      t.push_back(items[i + 1]);
    }
    return hermite_spline(std::move(knots), std::move(p), std::move(t));
  }

  [[nodiscard]] const point_list<Real, Dim>& values() const { return values_; }
  [[nodiscard]] const point_list<Real, Dim>& incoming_slopes() const { return incoming_; }
  [[nodiscard]] const point_list<Real, Dim>& outgoing_slopes() const { return outgoing_; }

 private:
  static void check_chain(std::span<const point_type> items) {
    validate::count_at_least("chain items", items.size(), 4, "two points and their tangents");
    if (items.size() % 2 != 0)
      validate::fail("chain items: " + std::to_string(items.size()) +
                     " given, must be even (alternating points and tangents)");
  }

  point_list<Real, Dim> values_;
  point_list<Real, Dim> incoming_;
  point_list<Real, Dim> outgoing_;
};

}  // namespace curvebench
