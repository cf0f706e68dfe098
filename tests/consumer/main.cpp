// Downstream use of the installed package: the cubic Bernstein basis must sum to one.
#include <curvebench/basis/bernstein.hpp>

#include <array>
#include <cmath>
#include <cstdio>

int main() {
  std::array<double, 4> b{};
  curvebench::basis::bernstein_all(3, 0.3, std::span<double>(b));
  const double sum = b[0] + b[1] + b[2] + b[3];
  std::printf("sum of cubic Bernstein basis at 0.3 = %.17g\n", sum);
  return std::abs(sum - 1.0) < 1e-15 ? 0 : 1;
}
