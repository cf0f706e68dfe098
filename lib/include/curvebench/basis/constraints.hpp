// Basis matrices from value / derivative constraints: basis_from_constraints.
//
// A polynomial of degree n is P(t) = T(t) · M · G with T(t) = [1 t ... t^n] and G the (n + 1) x Dim
// geometry (cubic_matrices.hpp). Constraint j says "the order_j-th derivative at t_j equals G_j", so
// the power coefficients a solve C a = G with C(j, k) = k!/(k - order_j)! t_j^(k - order_j), and
// M = C^{-1}; column j of T · M is the blending function of constraint j. C is inverted by Eigen's
// fully pivoted LU (any Real, real50 included); rcond = 1 / (||C||_1 ||M||_1) is reported.
// Errors (invalid_input, naming the constraints): none given, non-finite t, negative order,
// order > degree, a repeated (t, order), a numerically singular C (the dependent rows are listed) or
// rcond below eps. Sources: seed 000 (curves from geometric constraints), seed 001 (constraint
// matrix C, basis matrix B = C^-1); Foley et al. (1990), 11.2.
// Cost: O(n^3) once. Accuracy: M within about cond(C) · n · eps of the exact inverse (relative).
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/real.hpp"

#include <Eigen/Core>
#include <Eigen/LU>

#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace curvebench::basis {

template <class Real>
using matrix_x = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;

// API
//   constraint<Real>{t, order}                        one row of C
//   power_basis_row(degree, t, order)                  d^order/dt^order [1 t ... t^degree]
//   constraint_matrix(constraints)                     C, degree = count - 1 (no checks beyond shape)
//   basis_from_constraints(constraints)                -> constraint_basis{c = C, m = M, rcond}
//   basis_from_constraint_matrix(C)                    -> constraint_basis for a C built by hand (rows
//                                                        that are combinations of constraints, e.g.
//                                                        seed 001's Catmull-Rom rows p0 = f(1) - 2 f'(0))
// Matrices are Eigen dynamic-size (`matrix_x<Real>`) so any degree works; convert to matrix4 with
// `matrix4<Real> m = result.m;` for cubics.
/// "The order-th derivative of P at t is the corresponding geometry row" (order 0 = the value).
template <class Real>
struct constraint {
  Real t;
  int order = 0;
};

/// The constraint matrix C, its inverse the basis matrix M, and 1 / cond_1(C) = 1 / (||C||_1 ||M||_1).
template <class Real>
struct constraint_basis {
  matrix_x<Real> c;  // the constraint matrix C: C · a = G
  matrix_x<Real> m;  // the basis matrix M = C^{-1}: P(t) = T(t) · M · G
  Real rcond;        // reciprocal condition number of C in the 1-norm (computed M), in (0, 1]
  /// Degree of the polynomial (number of constraints - 1).
  [[nodiscard]] int degree() const { return static_cast<int>(m.rows()) - 1; }
};

/// d^order/dt^order of [1 t t^2 ... t^degree]: entry k is k!/(k - order)! t^(k - order), 0 for k < order.
template <class Real>
[[nodiscard]] Eigen::Matrix<Real, 1, Eigen::Dynamic> power_basis_row(int degree, const Real& t, int order = 0) {
  validate::derivative_order(order);
  if (degree < 0) validate::fail("degree = " + std::to_string(degree) + ": must be >= 0");
  Eigen::Matrix<Real, 1, Eigen::Dynamic> row = Eigen::Matrix<Real, 1, Eigen::Dynamic>::Zero(degree + 1);
  Real tp(1);  // t^(k - order)
  for (int k = order; k <= degree; ++k) {
    Real falling(1);  // k (k-1) ... (k - order + 1), exact for the degrees used
    for (int j = 0; j < order; ++j) falling *= Real(k - j);
    row(k) = falling * tp;
    tp *= t;
  }
  return row;
}

/// C for the given constraints, degree = count - 1: row j = power_basis_row(degree, t_j, order_j).
/// Only the shape is checked here (at least one constraint, orders >= 0); see basis_from_constraints.
template <class Real>
[[nodiscard]] matrix_x<Real> constraint_matrix(std::span<const constraint<Real>> constraints) {
  validate::count_at_least("constraints", constraints.size(), 1, "one per polynomial coefficient");
  const auto n = static_cast<Eigen::Index>(constraints.size());
  matrix_x<Real> c(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto& k = constraints[static_cast<std::size_t>(j)];
    if (k.order < 0)
      validate::fail(validate::indexed("constraints", static_cast<std::size_t>(j)) +
                     ".order = " + std::to_string(k.order) + ": derivative order must be >= 0");
    c.row(j) = power_basis_row(static_cast<int>(n) - 1, k.t, k.order);
  }
  return c;
}

namespace detail {

// Inverts C with full pivoting; on a (numerically) singular C names the dependent rows with
// row_name(i) and throws.
template <class Real, class RowName>
constraint_basis<Real> invert_constraints(const matrix_x<Real>& c, const RowName& row_name) {
  using std::abs;
  const Eigen::Index n = c.rows();
  Eigen::FullPivLU<matrix_x<Real>> lu(c);
  if (!lu.isInvertible()) {
    // A null vector v of C^T is a vanishing combination sum_i v_i C.row(i): the rows with a
    // non-negligible v_i are the dependent ones.
    Eigen::FullPivLU<matrix_x<Real>> lut(c.transpose());
    const matrix_x<Real> kernel = lut.kernel();
    const Eigen::Matrix<Real, Eigen::Dynamic, 1> v = kernel.col(0);
    Real biggest(0);
    for (Eigen::Index i = 0; i < n; ++i)
      if (abs(v(i)) > biggest) biggest = abs(v(i));
    using std::sqrt;
    const Real cutoff = biggest * sqrt(epsilon<Real>());
    std::string names;
    for (Eigen::Index i = 0; i < n; ++i)
      if (abs(v(i)) > cutoff) names += (names.empty() ? "" : ", ") + row_name(i);
    validate::fail("constraints are singular: " + names + " are linearly dependent (rank " + std::to_string(lu.rank()) +
                   " of " + std::to_string(n) + "); no polynomial of degree " + std::to_string(n - 1) +
                   " is fixed by them");
  }
  matrix_x<Real> m = lu.inverse();
  // 1 / (||C||_1 ||M||_1), computed from M itself (Eigen's rcond estimator needs
  // NumTraits<Real>::infinity(), which Boost.Multiprecision's Eigen traits do not provide).
  auto norm1 = [](const matrix_x<Real>& a) {
    Real best(0);
    for (Eigen::Index j = 0; j < a.cols(); ++j) {
      Real col(0);
      for (Eigen::Index i = 0; i < a.rows(); ++i) col += abs(a(i, j));
      if (col > best) best = col;
    }
    return best;
  };
  const Real rcond = Real(1) / (norm1(c) * norm1(m));
  if (!(rcond >= epsilon<Real>()))
    validate::fail("constraints are numerically singular: reciprocal condition number " + to_text(rcond) +
                   " < eps = " + to_text(epsilon<Real>()) + "; the basis matrix would have no correct digit");
  return constraint_basis<Real>{c, std::move(m), rcond};
}

}  // namespace detail

/// M = C^{-1} for a constraint matrix built by hand (square, finite). Rows are named "row i".
template <class Real>
[[nodiscard]] constraint_basis<Real> basis_from_constraint_matrix(const matrix_x<Real>& c) {
  if (c.rows() == 0 || c.rows() != c.cols())
    validate::fail("constraint matrix: " + std::to_string(c.rows()) + " x " + std::to_string(c.cols()) +
                   ", must be square and non-empty");
  for (Eigen::Index i = 0; i < c.rows(); ++i)
    for (Eigen::Index k = 0; k < c.cols(); ++k)
      if (!is_finite(c(i, k)))
        validate::fail("constraint matrix(" + std::to_string(i) + ", " + std::to_string(k) + ") = " + to_text(c(i, k)) +
                       ": must be finite");
  return detail::invert_constraints<Real>(c, [](Eigen::Index i) { return "row " + std::to_string(i); });
}

/// C and M = C^{-1} for value/derivative constraints; degree = constraints.size() - 1.
template <class Real>
[[nodiscard]] constraint_basis<Real> basis_from_constraints(std::span<const constraint<Real>> constraints) {
  validate::count_at_least("constraints", constraints.size(), 1, "one per polynomial coefficient");
  const std::size_t n = constraints.size();
  const int degree = static_cast<int>(n) - 1;
  auto describe = [&](std::size_t j) {
    return validate::indexed("constraints", j) + " (t = " + to_text(constraints[j].t) + ", order " +
           std::to_string(constraints[j].order) + ")";
  };
  for (std::size_t j = 0; j < n; ++j) {
    const auto& k = constraints[j];
    if (!is_finite(k.t))
      validate::fail(validate::indexed("constraints", j) + ".t = " + to_text(k.t) + ": must be finite");
    if (k.order < 0)
      validate::fail(validate::indexed("constraints", j) + ".order = " + std::to_string(k.order) +
                     ": derivative order must be >= 0");
    if (k.order > degree)
      validate::fail(validate::indexed("constraints", j) + ".order = " + std::to_string(k.order) + " > degree " +
                     std::to_string(degree) + " (" + std::to_string(n) +
                     " constraints fix a polynomial of that degree): its row of C is zero, the constraints are "
                     "singular");
    for (std::size_t i = 0; i < j; ++i)
      if (constraints[i].order == k.order && constraints[i].t == k.t)
        validate::fail(describe(j) + " repeats " + validate::indexed("constraints", i) +
                       ": two equal rows of C, the constraints are singular");
  }
  return detail::invert_constraints<Real>(constraint_matrix(constraints),
                                          [&](Eigen::Index i) { return describe(static_cast<std::size_t>(i)); });
}

/// Braced-list convenience: basis_from_constraints<double>({{0, 0}, {1, 0}, {0, 1}, {1, 1}}).
template <class Real>
[[nodiscard]] constraint_basis<Real> basis_from_constraints(std::initializer_list<constraint<Real>> constraints) {
  return basis_from_constraints(std::span<const constraint<Real>>(constraints.begin(), constraints.size()));
}

/// Vector convenience (deduces Real).
template <class Real>
[[nodiscard]] constraint_basis<Real> basis_from_constraints(const std::vector<constraint<Real>>& constraints) {
  return basis_from_constraints(std::span<const constraint<Real>>(constraints));
}

}  // namespace curvebench::basis
