// Polyline: the piecewise linear curve through vertices P_0 .. P_{n-1} at parameters
// u_0 < ... < u_{n-1} (default u_i = i; chord_length_parameters gives unit speed).
// On segment i: P(u) = ((u_{i+1} - u) / h) P_i + ((u - u_i) / h) P_{i+1}, exact at both vertices.
// Derivative of order 1 is the segment's slope (discontinuous at interior vertices: the right-hand
// segment is used, the left-hand one at the last vertex); orders >= 2 are zero. Breakpoints are the
// vertex parameters. Bad data (fewer than 2 vertices, non-finite values, non-increasing
// parameters) throw invalid_input; u outside the domain std::domain_error.
// Sources: seed 000 (piecewise linear spline), seed 001 (polyline).
// Cost: O(log n) lookup, O(Dim) evaluation, no allocation. Accuracy: a few ulps of the vertex
// scale (each weight has <= 2 roundings). rounding_bound(order) (core/curve.hpp), the largest over
// the segments: order 0, each weight within 3 roundings (two differences, a division) and the
// combination 2 more, 5 u < 3 eps of |P_i| + |P_{i+1}|; order 1, a difference and a division by a
// rounded h, 3 u < 2 eps of |P_{i+1} - P_i| / h.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
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
    build_rounding_bounds();
  }

  /// Vertices at the given parameters (one per vertex, finite, strictly increasing).
  polyline(std::span<const point_type> vertices, std::span<const Real> parameters)
      : vertices_(vertices.begin(), vertices.end()), params_(parameters.begin(), parameters.end()) {
    check_vertices();
    validate::same_count("parameters", params_.size(), "vertices", vertices_.size());
    validate::increasing<Real>("parameters", params_);
    build_rounding_bounds();
  }

  [[nodiscard]] interval<Real> domain() const { return {params_.front(), params_.back()}; }
  /// The vertex parameters: every segment boundary.
  [[nodiscard]] std::span<const Real> breakpoints() const { return params_; }
  [[nodiscard]] std::span<const point_type> vertices() const { return vertices_; }
  [[nodiscard]] std::span<const Real> parameters() const { return params_; }
  /// Number of segments (vertices - 1).
  [[nodiscard]] std::size_t segment_count() const { return vertices_.size() - 1; }

  /// The segment i with u_i <= u < u_{i+1}, or the last segment for u = u_{n-1} (binary search).
  [[nodiscard]] std::size_t segment(const Real& u) const { return detail::checked_segment_of<Real>(params_, u); }

  [[nodiscard]] point_type operator()(const Real& u) const { return derivative(u, 0); }

  /// Upper bound on the rounding of P (order 0) or P' (order 1) over the domain (see the header),
  /// computed at construction; 0 for higher orders (exact zeros).
  [[nodiscard]] Real rounding_bound(int order) const {
    if (order < 0) return std::numeric_limits<Real>::infinity();
    return order <= 1 ? rounding_bound_[static_cast<std::size_t>(order)] : Real(0);
  }

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
  void build_rounding_bounds() {
    Real b0(0), b1(0);
    for (std::size_t i = 0; i + 1 < vertices_.size(); ++i) {
      b0 = std::max(b0, Real(3) * epsilon<Real>() * (safe_norm(vertices_[i]) + safe_norm(vertices_[i + 1])));
      b1 = std::max(b1, Real(2) * epsilon<Real>() * safe_norm(point_type(vertices_[i + 1] - vertices_[i])) /
                            (params_[i + 1] - params_[i]));
    }
    const Real margin = Real(101) / Real(100);
    rounding_bound_ = {b0 * margin, b1 * margin};
  }

  void check_vertices() const {
    validate::count_at_least("vertices", vertices_.size(), 2, "a polyline has at least one segment");
    validate::finite_points<Real, Dim>("vertices", vertices_);
  }

  point_list<Real, Dim> vertices_;
  std::vector<Real> params_;
  std::array<Real, 2> rounding_bound_{};
};

}  // namespace curvebench
