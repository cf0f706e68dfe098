// The Boost.Math and Eigen peers of the accuracy runner, the libraries the speed tables
// already time, now measured against the same 50-digit reference as curvebench's methods on every
// case they can represent. Called by sweep_peers (harness/sweep_peers.cpp) for each case.
//
//   length  quadrature::gauss_kronrod<double, 15> and <double, 31> (adaptive, max_depth 15, Boost's
//           default) and quadrature::tanh_sinh<double> (max_refinements 15) of the speed |P'(u)|
//           over the whole domain, tol = each adaptive_gk tolerance of the sweep (Boost's tolerance
//           is relative to the integral's L1 norm, here the length itself). Estimate: the error
//           Boost returns, / L. Boost has no status; both stop when their error estimate is at most
//           tol x L1 or at their depth cap, so the record says which ("converged" or "cap_hit").
//           Counterpart: adaptive_gk at the same tol, timed once per case for GSL's and Boost's rules
//           (peers_detail::adaptive_gk_times).
//   eval    values and first derivatives (peers_detail::eval_records) of
//           - interpolators::catmull_rom (the Barry-Goldman form, alpha from the spec) on catmull_rom
//             cases without given knots: Boost always takes the wrapped neighbours (P_{n-1} before
//             P_0, P_0 after P_{n-1}) for its end tangents (tests/test_spline_peers.cpp), so it is the
//             case's curve on a closed case ("end": "closed", Boost's closed loop), on the whole
//             domain with "end": "control_points" (whose ends only shape the end segments), and on
//             the interior segments [u_1, u_{n-2}] otherwise (setting "segments=interior");
//           - interpolators::cubic_hermite, one per coordinate, on hermite cases with one slope per
//             key ("slopes"; a broken tangent has no cubic_hermite);
//           - interpolators::cardinal_cubic_b_spline, one per coordinate, given both end
//             derivatives, on natural_cubic cases with "end": "clamped" and uniform knots (the
//             clamped C2 spline on t0 + i h; tests/test_spline_peers.cpp);
//           - Eigen::Spline with the degree fixed at compile time (3 and 5) and dynamic, on the
//             bspline cases' own knot vector and control points (clamped, uniform or periodic).
//           Boost and Eigen report no status; an exception (Boost's domain errors) is the record's
//           peer_status and leaves it without a value.
#include "harness/length_methods.hpp"  // the vocabulary entry of adaptive_gk
#include "harness/peer_record.hpp"
#include "harness/peers.hpp"
#include "harness/sweeps.hpp"

#include "harness/setting.hpp"

#include "curvebench/arclength/length.hpp"
#include "curvebench/curves/bspline.hpp"
#include "curvebench/curves/cardinal_spline.hpp"
#include "curvebench/io/spec_data.hpp"

#include <boost/math/interpolators/cardinal_cubic_b_spline.hpp>
#include <boost/math/interpolators/catmull_rom.hpp>
#include <boost/math/interpolators/cubic_hermite.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/version.hpp>
#include <unsupported/Eigen/Splines>

#include <array>
#include <exception>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace curvebench::harness {

namespace {

using namespace peers_detail;

/// Boost and Eigen return values without a status.
const std::string returned = "returned a value (no status)";

std::string boost_library() { return "Boost.Math " + boost_version(); }
std::string eigen_library() { return "Eigen " + eigen_version(); }

// ---- arc length --------------------------------------------------------------------------------

template <int Dim>
void boost_length(const case_info& info, json& out, const any_curve<double, Dim>& c, const case_reference<Dim>& ref,
                  const sweep& w, adaptive_gk_times<Dim>& adaptive_gk_ns) {
  constexpr unsigned max_depth = 15;  // gauss_kronrod's default
  namespace q = boost::math::quadrature;
  namespace m = vocab::methods;
  const interval<double> d = c.domain();
  const double L = ref.length();
  q::tanh_sinh<double> ts;  // max_refinements 15, its default
  for (const vocab::peer* peer :
       {&vocab::peers::boost_gauss_kronrod15, &vocab::peers::boost_gauss_kronrod31, &vocab::peers::boost_tanh_sinh}) {
    for (double tol : w.adaptive_tol) {
      std::size_t calls = 0;
      double error = nan, L1 = nan;
      std::size_t levels = 0;
      const auto speed = [&](double u) {
        ++calls;
        return arclength::speed(c, u);
      };
      const auto integrate = [&] {
        if (peer == &vocab::peers::boost_gauss_kronrod15)
          return q::gauss_kronrod<double, 15>::integrate(speed, d.lo, d.hi, max_depth, tol, &error, &L1);
        if (peer == &vocab::peers::boost_gauss_kronrod31)
          return q::gauss_kronrod<double, 31>::integrate(speed, d.lo, d.hi, max_depth, tol, &error, &L1);
        return ts.integrate(speed, d.lo, d.hi, tol, &error, &L1, &levels);
      };
      double value = nan;
      std::string failure;
      try {
        value = integrate();
      } catch (const std::exception& e) {
        failure = e.what();
      }
      const std::size_t evaluations = calls;
      const std::string s = setting(m::adaptive_gk, {{"tol", tol}});
      const bool has_value = failure.empty() && std::isfinite(value);
      // Both rules stop refining where their estimate is within tol x L1 (L1 = the length: the
      // speed is never negative); an estimate above it means they stopped at their depth cap.
      const bool met = has_value && error <= tol * L1;
      peer_record r{&vocab::quantities::length,
                    peer,
                    s,
                    has_value ? ref.length_error_of(value) : nan,
                    has_value ? error / L : nan,
                    static_cast<double>(evaluations),
                    std::string(arclength::to_string(!has_value ? arclength::result_status::not_guaranteed
                                                     : met      ? arclength::result_status::converged
                                                                : arclength::result_status::cap_hit)),
                    !failure.empty() ? failure
                    : met            ? "error estimate <= tol x L1"
                    : peer == &vocab::peers::boost_tanh_sinh
                        ? "max_refinements (15) reached with the error estimate above tol x L1"
                        : "max_depth (15) reached with the error estimate above tol x L1",
                    nan,
                    std::string(m::adaptive_gk.id),
                    s,
                    nan};
      if (has_value) {
        r.ns_per_op = ns_per_call([&] {
          const double v = integrate();
          asm volatile("" : : "g"(&v) : "memory");
        });
        r.counterpart_ns_per_op = adaptive_gk_ns(tol);
      }
      out.push_back(to_json(info, r, boost_library()));
    }
  }
}

// ---- evaluation --------------------------------------------------------------------------------

template <int Dim>
point<double, Dim> to_point(const std::array<double, Dim>& a) {
  point<double, Dim> p;
  for (int i = 0; i < Dim; ++i) p[i] = a[static_cast<std::size_t>(i)];
  return p;
}

/// The evaluation of one Boost interpolator per coordinate (value or prime), for eval_records.
template <int Dim, class Spline>
auto per_coordinate(const std::vector<Spline>& splines) {
  return [&splines](double u, int order, std::string&) {
    point<double, Dim> v;
    for (int k = 0; k < Dim; ++k) v[k] = order == 0 ? splines[k](u) : splines[k].prime(u);
    return v;
  };
}

template <int Dim>
void boost_catmull_rom(const case_info& info, json& out, const any_curve<double, Dim>& c, case_reference<Dim>& ref,
                       const sweep& w, const io::field& spec) {
  if (spec.member("type").string() != "catmull_rom" || spec.has("knots") || spec.has("s") || spec.has("tension"))
    return;  // Boost computes its own knots, with s = 1/2
  const std::string end = spec.has("end") ? spec.member("end").string() : "phantom";
  const double alpha = spec.has("alpha") ? spec.member("alpha").number() : 0.0;
  const point_list<double, Dim> p = io::points_of<double, Dim>(spec);
  if (p.size() < 4) return;  // Boost's minimum
  using bpoint = std::array<double, Dim>;
  std::vector<bpoint> a(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int k = 0; k < Dim; ++k) a[i][static_cast<std::size_t>(k)] = p[i][k];
  const bool closed = end == "closed";
  std::optional<boost::math::catmull_rom<bpoint>> cr;
  std::string refused;
  try {
    cr.emplace(std::move(a), closed, alpha);
  } catch (const std::exception& e) {
    refused = e.what();
  }
  // The part of the domain where Boost's curve is the case's (see the top of the file).
  interval<double> part = c.domain();
  std::string part_setting;
  if (!closed && end != "control_points") {
    const std::vector<double> k = alpha_knots<double, Dim>(std::span<const point<double, Dim>>(p), alpha);
    part = {k[1], k[k.size() - 2]};
    part_setting = "segments=interior";
  }
  const std::vector<double> us = sample_parameters(part.lo, part.hi, w.eval_params);
  eval_records<Dim>(
      info, out, c, ref, us, vocab::peers::boost_catmull_rom, boost_library(), part_setting, returned, refused,
      [&](double u, int order, std::string&) { return to_point<Dim>(order == 0 ? (*cr)(u) : cr->prime(u)); });
}

template <int Dim>
void boost_cubic_hermite(const case_info& info, json& out, const any_curve<double, Dim>& c, case_reference<Dim>& ref,
                         const sweep& w, const io::field& spec) {
  if (spec.member("type").string() != "hermite" || !spec.has("slopes")) return;
  const point_list<double, Dim> p = io::points_of<double, Dim>(spec);
  const point_list<double, Dim> slopes = spec.member("slopes").points<double, Dim>();
  const std::vector<double> x = io::knots_of<double>(spec, p.size());
  using hermite = boost::math::interpolators::cubic_hermite<std::vector<double>>;
  std::vector<hermite> h;
  std::string refused;
  try {
    for (int k = 0; k < Dim; ++k) {
      std::vector<double> y(p.size()), dydx(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) {
        y[i] = p[i][k];
        dydx[i] = slopes[i][k];
      }
      h.emplace_back(std::vector<double>(x), std::move(y), std::move(dydx));
    }
  } catch (const std::exception& e) {
    refused = e.what();
  }
  const interval<double> d = c.domain();
  eval_records<Dim>(info, out, c, ref, sample_parameters(d.lo, d.hi, w.eval_params), vocab::peers::boost_cubic_hermite,
                    boost_library(), "", returned, refused, per_coordinate<Dim>(h));
}

template <int Dim>
void boost_cardinal_cubic_b_spline(const case_info& info, json& out, const any_curve<double, Dim>& c,
                                   case_reference<Dim>& ref, const sweep& w, const io::field& spec) {
  if (spec.member("type").string() != "natural_cubic" || !spec.has("end") || spec.member("end").string() != "clamped")
    return;
  const point_list<double, Dim> p = io::points_of<double, Dim>(spec);
  const std::vector<double> x = io::knots_of<double>(spec, p.size());
  const double h = (x.back() - x.front()) / static_cast<double>(x.size() - 1);
  for (std::size_t i = 0; i < x.size(); ++i)
    if (x[i] != x.front() + static_cast<double>(i) * h) return;  // Boost's knots are t0 + i h exactly
  const point<double, Dim> start = io::point_of<double, Dim>(spec.member("start_slope"));
  const point<double, Dim> end = io::point_of<double, Dim>(spec.member("end_slope"));
  using spline = boost::math::interpolators::cardinal_cubic_b_spline<double>;
  std::vector<spline> b;
  std::string refused;
  try {
    for (int k = 0; k < Dim; ++k) {
      std::vector<double> y(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) y[i] = p[i][k];
      b.emplace_back(y.data(), y.size(), x.front(), h, start[k], end[k]);
    }
  } catch (const std::exception& e) {
    refused = e.what();
  }
  const interval<double> d = c.domain();
  eval_records<Dim>(info, out, c, ref, sample_parameters(d.lo, d.hi, w.eval_params),
                    vocab::peers::boost_cardinal_cubic_b_spline, boost_library(), "", returned, refused,
                    per_coordinate<Dim>(b));
}

/// Eigen::Spline<double, Dim, Degree> (Degree = Eigen::Dynamic: the degree given at run time) on
/// the B-spline's knots and control points.
template <int Dim, int Degree>
void eigen_spline(const case_info& info, json& out, const any_curve<double, Dim>& c, case_reference<Dim>& ref,
                  const std::vector<double>& us, const bspline<double, Dim>& b, const vocab::peer& peer) {
  using spline = Eigen::Spline<double, Dim, Degree>;
  const auto t = b.knots();
  const auto cp = b.control_points();
  typename spline::KnotVectorType knots(static_cast<Eigen::Index>(t.size()));
  for (std::size_t i = 0; i < t.size(); ++i) knots(static_cast<Eigen::Index>(i)) = t[i];
  typename spline::ControlPointVectorType ctrls(Dim, static_cast<Eigen::Index>(cp.size()));
  for (std::size_t i = 0; i < cp.size(); ++i) ctrls.col(static_cast<Eigen::Index>(i)) = cp[i];
  const spline s(knots, ctrls);
  eval_records<Dim>(info, out, c, ref, us, peer, eigen_library(), "", returned, "",
                    [&](double u, int order, std::string&) -> point<double, Dim> {
                      if (order == 0) return s(u);
                      return s.derivatives(u, 1).col(1);
                    });
}

template <int Dim>
void eigen_splines(const case_info& info, json& out, const any_curve<double, Dim>& c, case_reference<Dim>& ref,
                   const sweep& w) {
  const bspline<double, Dim>* b = c.template target<bspline<double, Dim>>();
  if (!b) return;
  const interval<double> d = c.domain();
  const std::vector<double> us = sample_parameters(d.lo, d.hi, w.eval_params);
  if (b->degree() == 3) eigen_spline<Dim, 3>(info, out, c, ref, us, *b, vocab::peers::eigen_spline_fixed_degree);
  if (b->degree() == 5) eigen_spline<Dim, 5>(info, out, c, ref, us, *b, vocab::peers::eigen_spline_fixed_degree);
  eigen_spline<Dim, Eigen::Dynamic>(info, out, c, ref, us, *b, vocab::peers::eigen_spline_dynamic_degree);
}

}  // namespace

std::string boost_version() {
  return std::to_string(BOOST_VERSION / 100000) + "." + std::to_string(BOOST_VERSION / 100 % 1000) + "." +
         std::to_string(BOOST_VERSION % 100);
}

std::string eigen_version() {
  return std::to_string(EIGEN_WORLD_VERSION) + "." + std::to_string(EIGEN_MAJOR_VERSION) + "." +
         std::to_string(EIGEN_MINOR_VERSION);
}

template <int Dim>
void boost_eigen_peers(const case_info& info, json& out, const any_curve<double, Dim>& c, case_reference<Dim>& ref,
                       const sweep& w, const io::field& spec, adaptive_gk_times<Dim>& adaptive_gk_ns) {
  boost_catmull_rom<Dim>(info, out, c, ref, w, spec);
  boost_cubic_hermite<Dim>(info, out, c, ref, w, spec);
  boost_cardinal_cubic_b_spline<Dim>(info, out, c, ref, w, spec);
  eigen_splines<Dim>(info, out, c, ref, w);
  boost_length<Dim>(info, out, c, ref, w, adaptive_gk_ns);
}

template void boost_eigen_peers<2>(const case_info&, json&, const any_curve<double, 2>&, case_reference<2>&,
                                   const sweep&, const io::field&, adaptive_gk_times<2>&);
template void boost_eigen_peers<3>(const case_info&, json&, const any_curve<double, 3>&, case_reference<3>&,
                                   const sweep&, const io::field&, adaptive_gk_times<3>&);

}  // namespace curvebench::harness
