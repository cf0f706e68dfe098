// Private: dense Gaussian elimination with partial pivoting in any Real (small systems only:
// the Kronrod construction solves systems of size <= 2n + 1 once per rule). Works for
// multiprecision Real without Eigen's NumTraits.
#pragma once

#include "curvebench/core/error.hpp"

#include <cstddef>
#include <utility>
#include <vector>

namespace curvebench::arclength::detail {

/// Solves A x = b in place (A row-major m x m, overwritten); returns x. Throws invalid_input when a
/// pivot is exactly zero (singular system).
template <class Real>
std::vector<Real> solve_dense(std::vector<Real> a, std::vector<Real> b, std::size_t m) {
  using std::abs;
  for (std::size_t col = 0; col < m; ++col) {
    std::size_t piv = col;
    for (std::size_t r = col + 1; r < m; ++r)
      if (abs(a[r * m + col]) > abs(a[piv * m + col])) piv = r;
    if (a[piv * m + col] == Real(0)) validate::fail("solve_dense: singular system at column " + std::to_string(col));
    if (piv != col) {
      for (std::size_t c = 0; c < m; ++c) std::swap(a[piv * m + c], a[col * m + c]);
      std::swap(b[piv], b[col]);
    }
    for (std::size_t r = col + 1; r < m; ++r) {
      const Real f = a[r * m + col] / a[col * m + col];
      if (f == Real(0)) continue;
      for (std::size_t c = col; c < m; ++c) a[r * m + c] -= f * a[col * m + c];
      b[r] -= f * b[col];
    }
  }
  std::vector<Real> x(m, Real(0));
  for (std::size_t i = m; i-- > 0;) {
    Real s = b[i];
    for (std::size_t c = i + 1; c < m; ++c) s -= a[i * m + c] * x[c];
    x[i] = s / a[i * m + i];
  }
  return x;
}

}  // namespace curvebench::arclength::detail
