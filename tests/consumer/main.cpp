// Downstream use of the installed package: the umbrella header and the spec reader compile together
// from the installed tree, and a cubic Bezier read from a JSON spec evaluates to its closed form.
#include <curvebench/curvebench.hpp>
#include <curvebench/io/spec.hpp>

#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>

int main() {
  namespace cb = curvebench;
  try {
    const auto doc = cb::io::parse(R"({"type": "bezier", "points": [[0, 0], [1, 2], [3, 2], [4, 0]]})");
    const cb::any_curve<double, 2> c = cb::io::curve_from_spec<double, 2>(cb::io::root(doc));
    // At t = 1/2 the Bernstein weights are 1/8, 3/8, 3/8, 1/8: (0 + 3 + 9 + 4)/8 = 2 and
    // (0 + 6 + 6 + 0)/8 = 1.5, both exact in double (as are all the products and sums below).
    const cb::point<double, 2> p0(0, 0), p1(1, 2), p2(3, 2), p3(4, 0);
    const cb::point<double, 2> expected = 0.125 * p0 + 0.375 * p1 + 0.375 * p2 + 0.125 * p3;
    const cb::point<double, 2> got = c(0.5);
    // de Casteljau at 1/2 halves sums of small integers: every step is exact, but allow 4 ulps of
    // the curve's size (4) so the check does not depend on the evaluation order.
    const double tolerance = 4 * std::numeric_limits<double>::epsilon() * 4;
    const double error = (got - expected).cwiseAbs().maxCoeff();
    std::printf("bezier spec at 0.5 = (%.17g, %.17g), closed form (%.17g, %.17g), error %.3g\n", got.x(), got.y(),
                expected.x(), expected.y(), error);
    if (!(error <= tolerance)) {
      std::fprintf(stderr, "consumer: error %.3g exceeds %.3g\n", error, tolerance);
      return 1;
    }
    // The domain of the spec is the default [0, 1], and the end points are interpolated exactly.
    if (c.domain().lo != 0.0 || c.domain().hi != 1.0 || c(0.0) != p0 || c(1.0) != p3) {
      std::fprintf(stderr, "consumer: domain or end points differ from the spec\n");
      return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
  return 0;
}
