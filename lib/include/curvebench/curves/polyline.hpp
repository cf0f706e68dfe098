// Polyline: the piecewise linear curve through vertices P_0 .. P_{n-1} at parameters u_0 < ... < u_{n-1}.
//
// Source: seed 000 ("piecewise linear spline": a_i = (y_{i+1} - y_i) / (t_{i+1} - t_i), C0 but not
// C1), seed 001 ("polyline: connect each pair of consecutive vertices with a line segment").
//
// Parameters: given per vertex (finite, strictly increasing), or by default uniform u_i = i, so the
// domain is [0, n - 1]. `chord_length_parameters(vertices)` gives u_0 = 0, u_i = u_{i-1} + |P_i - P_{i-1}|,
// with which the polyline has unit speed and u is arc length.
// On segment i, u in [u_i, u_{i+1}], with h = u_{i+1} - u_i:
//     P(u) = ((u_{i+1} - u) / h) P_i + ((u - u_i) / h) P_{i+1},
// a form that returns the vertices exactly at both ends of the segment and is within a few ulps of
// the vertex scale inside (each weight has <= 2 roundings). Cost: the segment is found by binary
// search over the parameters, O(log n); evaluation O(Dim); nothing is allocated.
// Derivatives are exact: order 1 is the segment's constant slope (P_{i+1} - P_i) / h; order >= 2
// is zero. The first derivative is discontinuous at interior vertices: at u = u_i the right-hand
// segment [u_i, u_{i+1}] is used, except at the last vertex, where the last segment is used (the
// left-hand one). Breakpoints are the vertex parameters.
// Errors: fewer than 2 vertices, non-finite coordinates, a parameter count that does not match the
// vertex count, non-finite or non-increasing parameters -> invalid_input at construction;
// u outside [u_0, u_{n-1}] -> std::domain_error; negative derivative order -> invalid_input.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace curvebench {

/// Chord-length parameters: u_0 = 0, u_i = u_{i-1} + |P_i - P_{i-1}| (Euclidean norm). Throws
/// invalid_input for fewer than 2 vertices, non-finite coordinates, or two equal consecutive
/// vertices (a zero chord: the parameters would not increase).
template <class Real, int Dim>
[[nodiscard]] std::vector<Real> chord_length_parameters(std::span<const point<Real, Dim>> vertices) {
  validate::count_at_least("vertices", vertices.size(), 2, "a polyline has at least one segment");
  validate::finite_points<Real, Dim>("vertices", vertices);
  std::vector<Real> u(vertices.size(), Real(0));
  for (std::size_t i = 1; i < vertices.size(); ++i) {
    const Real chord = point<Real, Dim>(vertices[i] - vertices[i - 1]).norm();
    if (!(chord > Real(0)))
      validate::fail(validate::indexed("vertices", i) + " equals " + validate::indexed("vertices", i - 1) +
                     ": zero chord, chord-length parameters must increase");
    u[i] = u[i - 1] + chord;
  }
  return u;
}

template <class Real, int Dim>
class polyline {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;

  /// Vertices at the uniform parameters 0, 1, ..., n - 1.
  explicit polyline(std::span<const point_type> vertices) : vertices_(vertices.begin(), vertices.end()) {
    check_vertices();
    params_.reserve(vertices_.size());
    for (std::size_t i = 0; i < vertices_.size(); ++i) params_.push_back(from_int<Real>(static_cast<long long>(i)));
  }

  /// Vertices at the given parameters (one per vertex, finite, strictly increasing).
  polyline(std::span<const point_type> vertices, std::span<const Real> parameters)
      : vertices_(vertices.begin(), vertices.end()), params_(parameters.begin(), parameters.end()) {
    check_vertices();
    validate::same_count("parameters", params_.size(), "vertices", vertices_.size());
    validate::increasing<Real>("parameters", params_);
  }

  [[nodiscard]] interval<Real> domain() const { return {params_.front(), params_.back()}; }
  /// The vertex parameters: every segment boundary.
  [[nodiscard]] std::span<const Real> breakpoints() const { return params_; }
  [[nodiscard]] std::span<const point_type> vertices() const { return vertices_; }
  [[nodiscard]] std::span<const Real> parameters() const { return params_; }
  /// Number of segments (vertices - 1).
  [[nodiscard]] std::size_t segment_count() const { return vertices_.size() - 1; }

  /// The segment i with u_i <= u < u_{i+1}, or the last segment for u = u_{n-1} (binary search).
  [[nodiscard]] std::size_t segment(const Real& u) const {
    check_parameter(u, domain());
    const auto it = std::upper_bound(params_.begin(), params_.end(), u);
    const auto i = static_cast<std::size_t>(it - params_.begin());  // first parameter > u, in 1..n
    return std::min(i, params_.size() - 1) - 1;
  }

  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }

  /// d^order P / du^order: the value (order 0), the segment slope (order 1), zero (order >= 2).
  [[nodiscard]] point_type derivative(const Real& u, int order) const {
    validate::derivative_order(order);
    const std::size_t i = segment(u);  // checks the domain
    const Real h = params_[i + 1] - params_[i];
    if (order == 0) {
      const Real a = (params_[i + 1] - u) / h;
      const Real b = (u - params_[i]) / h;
      return point_type(a * vertices_[i] + b * vertices_[i + 1]);
    }
    if (order == 1) return point_type((vertices_[i + 1] - vertices_[i]) / h);
    return zero_point<Real, Dim>();
  }

 private:
  void check_vertices() const {
    validate::count_at_least("vertices", vertices_.size(), 2, "a polyline has at least one segment");
    validate::finite_points<Real, Dim>("vertices", vertices_);
  }

  point_list<Real, Dim> vertices_;
  std::vector<Real> params_;
};

}  // namespace curvebench
