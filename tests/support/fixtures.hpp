// Test support: the small fixtures several test files share.
//   - points_from<Real>(data)        control points typed in as double arrays, converted to Real
//                                    (the data are chosen exact in float, so every Real holds the
//                                    same points and the real50 twin of a curve is exact);
//   - random_points<Real, Dim>(...)  points uniform in [-1, 1]^Dim, drawn in double and rounded
//                                    once to Real (so the real50 copy of the rounded points is exact);
//   - invalid_input_of(f)            the what() of the invalid_input f throws (other exceptions propagate);
//   - message_of(f)                  the what() of the exception f throws, for tests that check an
//                                    error message's wording ("(no exception)" when none);
//   - runge_samples()                21 equispaced samples (x, 1 / (1 + 25 x^2)), x in [-1, 1], in
//                                    double: bench/cases/runge_lagrange_equispaced.json's data;
//   - unit_hash(x)                   a deterministic value in [-1, 1) per double x (splitmix64 of
//                                    its bits): reproducible "rounding noise" for integrands.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace curvebench::testing {

template <class Real, std::size_t Dim>
point_list<Real, static_cast<int>(Dim)> points_from(const std::vector<std::array<double, Dim>>& data) {
  point_list<Real, static_cast<int>(Dim)> r;
  r.reserve(data.size());
  for (const auto& p : data) {
    point<Real, static_cast<int>(Dim)> q;
    for (std::size_t d = 0; d < Dim; ++d) q[static_cast<int>(d)] = Real(p[d]);
    r.push_back(q);
  }
  return r;
}

template <class Real, int Dim>
point_list<Real, Dim> random_points(int count, std::mt19937& gen) {
  std::uniform_real_distribution<double> dist(-1.0, 1.0);
  point_list<Real, Dim> p(static_cast<std::size_t>(count));
  for (auto& q : p)
    for (int d = 0; d < Dim; ++d) q[d] = static_cast<Real>(dist(gen));
  return p;
}

template <class Real, int Dim>
point_list<Real, Dim> random_points(int count, unsigned seed) {
  std::mt19937 gen(seed);
  return random_points<Real, Dim>(count, gen);
}

inline point_list<double, 2> runge_samples() {
  point_list<double, 2> p;
  for (int j = 0; j <= 20; ++j) {
    const double x = -1 + j / 10.0;
    p.emplace_back(x, 1 / (1 + 25 * x * x));
  }
  return p;
}

inline double unit_hash(double x) {
  std::uint64_t z = std::bit_cast<std::uint64_t>(x) + 0x9e3779b97f4a7c15ULL;  // splitmix64
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) / 4503599627370496.0 - 1;  // 53 bits / 2^52 - 1
}

/// The what() of the curvebench::invalid_input f throws, "(no invalid_input)" when it throws none;
/// any other exception propagates (and fails the test): for checks of a refusal's wording.
inline std::string invalid_input_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const curvebench::invalid_input& e) {
    return e.what();
  }
  return "(no invalid_input)";
}

inline std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(no exception)";
}

}  // namespace curvebench::testing
