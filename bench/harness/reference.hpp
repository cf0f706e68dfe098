// The 50-digit side of the accuracy runner, behind a facade that speaks double only: a case's
// curve instantiated at real50 (the exact twin of the double data, io::curve_from_spec) and its
// reference arc length (reference::reference_arc_length, ~1e-45), plus the u(s) anchors cache.
// harness/reference.cpp is the one translation unit that instantiates families at real50 (the slow
// one to compile), explicitly for Dim 1, 2 and 3; the sweeps (harness/sweep_*.cpp) compile double
// code only and get every exact quantity they compare against through this class.
#pragma once

#include "curvebench/core/curve.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/io/json_fields.hpp"

#include <cstddef>
#include <functional>
#include <memory>
#include <span>
#include <string>

namespace curvebench::harness {

/// The 50-digit reference of one case, for Dim 1, 2 or 3. Not thread-safe (the u(s) anchors are a
/// cache): one per case and thread.
template <int Dim>
class case_reference {
 public:
  /// Builds the spec's curve at real50 and integrates its reference length (seconds on hard cases).
  explicit case_reference(const io::field& spec);
  ~case_reference();
  case_reference(const case_reference&) = delete;
  case_reference& operator=(const case_reference&) = delete;

  [[nodiscard]] double length() const;             ///< L rounded to double
  [[nodiscard]] std::string length_text() const;   ///< L to 40 significant digits
  [[nodiscard]] double length_error() const;       ///< the reference's own error estimate / L
  [[nodiscard]] std::size_t speed_minima() const;  ///< interior speed minima the reference split at

  /// |value - L| / L, the difference taken in 50 digits.
  [[nodiscard]] double length_error_of(double value) const;

  /// Integrates the exact s(u_j) at the parameters us (inside the domain) for s_error.
  void set_s_parameters(std::span<const double> us);
  /// |value - s(u_j)| / L (L in double) for the j-th parameter of set_s_parameters.
  [[nodiscard]] double s_error(std::size_t j, double value) const;

  /// The u(s) measure |s(u) - s| / L with the exact s(u) of an answer u (inside the domain: the
  /// caller clamps) to the target s. The first answer for a target is integrated from the
  /// reference's splits; every later one (all methods' answers lie near the same u*) from that
  /// anchor, one short panel, unless a split lies between them. The anchors live as long as this
  /// object. Not enough for degree-20 Runge on equispaced nodes: inaccurate answers there cross its
  /// many splits, and each 50-digit s(u) on that curve costs seconds.
  [[nodiscard]] double ds(double u, double s);

  /// The curve's domain (the same doubles as the double curve's: the spec is resolved once).
  [[nodiscard]] interval<double> domain() const;

  /// The exact `order`-th derivative (0: the point; 0..3) at u (inside the domain), rounded.
  [[nodiscard]] point<double, Dim> exact(double u, int order = 0) const;
  /// max over coordinates of |p_i - P^(order)_i(u)|, the difference taken in 50 digits, then rounded.
  [[nodiscard]] double difference(double u, int order, const point<double, Dim>& p) const;

  /// Integrates s(u) at every distinct parameter of us (inside the domain) for length_between,
  /// length_between_error and the first ds of a target: in increasing order, each from the one
  /// before (s_between: one short panel, unless a split of the reference lies between) instead of
  /// from the reference's splits (check's rows: 1e4 rows of the arch took 5.8 s with an s column
  /// and 61 s as lengths before, 1.6 s and 2.6 s with it). Each step's panel meets the reference's
  /// tolerance, so a chain of n rows adds at most n times that (test_reference: 1e-40 over 1000).
  /// on_done(k, n) after each of the n distinct parameters (a progress line).
  void cache_s(std::span<const double> us, const std::function<void(std::size_t, std::size_t)>& on_done = {});

  /// s(u1) - s(u0) (signed; u0, u1 inside the domain), the 50-digit arc length between them, rounded.
  [[nodiscard]] double length_between(double u0, double u1) const;
  /// |value - (s(u1) - s(u0))|, the difference taken in 50 digits, then rounded.
  [[nodiscard]] double length_between_error(double u0, double u1, double value) const;

  /// |q - P(u(s))|, the distance of a point q from the curve's exact point at arc length s
  /// (0 <= s <= L, or the double nearest L above it; u(s) solved at 50 digits), the difference taken
  /// in 50 digits, then rounded.
  [[nodiscard]] double distance_at_length(double s, const point<double, Dim>& q) const;

  /// The point of the curve nearest to q: its parameter, |q - P(u*)|, and the arc length s(u*) (all
  /// at 50 digits, rounded). Candidates are the local minima of |q - P| over 32 samples per segment
  /// (each segment on its own, ending at its limit from the left, so a jump between subpaths is no
  /// candidate), each polished by safeguarded Newton on (P - q) . P' = 0. Only the segments that can
  /// hold a candidate are sampled: a tree of the segments' sample boxes (built on the first call) is
  /// searched nearest first, so a point near one branch of a path of n segments costs O(log n)
  /// boxes and a few segments, not n. Where q lies about as
  /// close to several branches (a loop's crossing, a cusp's two sides: within twice the smallest
  /// distance plus 1e-12 L), the one whose s is nearest s_hint is taken when s_hint is given (not
  /// NaN), the one nearest q otherwise.
  struct nearest_point {
    double u = 0;
    double distance = 0;      ///< |q - P(u*)|
    double s = 0;             ///< s(u*)
    double ds = 0;            ///< |s(u*) - s_hint| / L (0 without a hint)
    std::size_t scanned = 0;  ///< segments sampled: the scan's work, a few for a point near one branch
  };
  [[nodiscard]] nearest_point nearest(const point<double, Dim>& q, double s_hint) const;

  /// Evaluates the exact points P(u_j) at the parameters us and the curve's size (the largest
  /// coordinate magnitude among them; 1 when all are 0) for eval_error.
  void set_eval_parameters(std::span<const double> us);
  /// max over j and coordinates of |p[j] - P(u_j)| / (eps(double) x size), p[j] computed at the
  /// j-th parameter of set_eval_parameters (p.size() must equal their count).
  [[nodiscard]] double eval_error(std::span<const point<double, Dim>> p) const;

 private:
  struct impl;
  std::unique_ptr<impl> impl_;
};

extern template class case_reference<1>;
extern template class case_reference<2>;
extern template class case_reference<3>;

}  // namespace curvebench::harness
