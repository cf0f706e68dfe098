// The harness's one vocabulary: quantities, method ids and their settings, peers, benchmark
// operations and counters, each declared once: here, but for the length and u(s) methods, whose
// entries are declared with their rows in the method tables (harness/length_methods.hpp) and
// listed by all_methods(). The CLI (`curvebench length --method`,
// `sample --method`), the accuracy records, the benchmark names, the gate's thresholds and
// scripts/report.py (through `curvebench list vocabulary --json`, which scripts/bench.sh writes to
// reports/vocabulary.json) all use these ids; code names them through the constants below, so a
// misspelled id does not compile, and the gate rejects a rule naming an id that is not here.
//
// Formats:
//   record setting     "key=value[,key=value]"         ("n=8", "tol=1e-10", "n=3,panels=4")
//   benchmark name     family/algorithm[/key:value]... (Google Benchmark's argument convention;
//                      algorithm: a method, a peer or an algorithm id below)
//   peers              algorithm ids start with "peer_" and name the library
// Every benchmark reports its time per operation: it declares the operation it times (the label)
// and how many it performs per iteration (items processed), so a batch of 1024 evaluations and a
// single evaluation compare directly.
#pragma once

#include <algorithm>
#include <span>
#include <string_view>

namespace curvebench::harness::vocab {

/// What the accuracy runner measures; errors are relative to the case's reference length L except eval.
struct quantity {
  std::string_view id;
  std::string_view doc;
};

namespace quantities {
inline constexpr quantity length{"length", "|L_method - L| / L for the whole curve"};
inline constexpr quantity s_of_u{"s_of_u", "max over parameters u_j of |s_method(u_j) - s(u_j)| / L"};
inline constexpr quantity u_of_s{"u_of_s", "max over targets s_j of |s(u_method(s_j)) - s_j| / L"};
inline constexpr quantity eval{"eval", "max |P_method(u) - P(u)|_inf / (eps(double) x the curve's size)"};
// Keyframe channels (cases of type "channel"); bits=32 / bits=64 is the precision of the model
// (float: its keys rounded to float as a float runtime holds them; the query times are rounded too,
// and the truth is taken at the rounded time).
inline constexpr quantity channel_value{"channel_value",
                                        "max over sample times of |v_model(t) - v(t)| / (eps x the channel's value "
                                        "range): ulps of the range (record field rms: the RMS in the same unit)"};
inline constexpr quantity channel_keys{"channel_keys",
                                       "max over the key times of |v_model(t_k) - v(t_k)| / (eps x the value range)"};
inline constexpr quantity channel_monotone{"channel_monotone",
                                           "consecutive sorted sample pairs where the model's value moves against "
                                           "the exact value's direction (monotonicity violations)"};
inline constexpr quantity channel_time{"channel_time",
                                       "max over samples in bezier segments of |x(u_solver) - t| / (eps x the "
                                       "segment's duration), the time solver's residual (record fields "
                                       "iterations_mean, iterations_max, not_converged)"};
// glTF rotation channels (gltf cases with "path": "rotation"): the model's quaternion against the
// same sampler's formula at 50 digits, as a rotation angle (unit quaternions: the angle of q_a q_b^-1).
inline constexpr quantity channel_rotation{"channel_rotation",
                                           "max over sample times of the rotation angle between q_model(t) and "
                                           "q(t), in eps(Real) radians (record fields rms, and norm: the max "
                                           "| |q_model| - 1 | in eps(Real))"};
}  // namespace quantities

inline constexpr const quantity* all_quantities[] = {
    &quantities::length,          &quantities::s_of_u,       &quantities::u_of_s,           &quantities::eval,
    &quantities::channel_value,   &quantities::channel_keys, &quantities::channel_monotone, &quantities::channel_time,
    &quantities::channel_rotation};

/// A method of the library, as the CLI, the records and the benchmarks name it.
struct method {
  std::string_view id;
  std::string_view quantities;  ///< the quantity ids it produces records for, space-separated
  std::string_view settings;    ///< its setting keys, space-separated ("" when it has none)
  double theory;                ///< convergence order in evaluations fitted over its sweep; 0: none fitted
  std::string_view doc;
};

namespace methods {
inline constexpr method segments_adaptive{"segments_adaptive", "s_of_u", "", 0,
                                          "s(u): adaptive segment lengths plus one adaptive partial integral"};
inline constexpr method eval_default{"default", "eval", "", 0,
                                     "the family's default evaluation; the other eval methods are the algorithms "
                                     "each family offers in the family registry"};
// The time solvers of a channel's bezier segments (channel/time_solver.hpp), ids as the library
// and the channel spec's "solver" field name them; setting bits=32 or bits=64.
#define CURVEBENCH_CHANNEL_QUANTITIES "channel_value channel_keys channel_monotone channel_time"
inline constexpr method solver_closed_form{
    "closed_form", CURVEBENCH_CHANNEL_QUANTITIES, "bits", 0,
    "time solver: Cardano / trigonometric roots of the time cubic (Blender, USD)"};
inline constexpr method solver_table_newton{"table_newton", CURVEBENCH_CHANNEL_QUANTITIES, "bits", 0,
                                            "time solver: 11-sample table, at most 4 Newton steps, then bisection "
                                            "(WebKit / Chromium, epsilon 1e-7)"};
inline constexpr method solver_newton_bisection{"newton_bisection", CURVEBENCH_CHANNEL_QUANTITIES, "bits", 0,
                                                "time solver: Newton from u = x for at most 8 steps, then bisection "
                                                "(Servo, unitbezier)"};
inline constexpr method solver_bisection12{"bisection12", CURVEBENCH_CHANNEL_QUANTITIES, "bits", 0,
                                           "time solver: 12 bisection steps"};
inline constexpr method solver_bisection30{"bisection30", CURVEBENCH_CHANNEL_QUANTITIES, "bits", 0,
                                           "time solver: 30 bisection steps"};
inline constexpr method solver_isolate_brent{"isolate_brent", CURVEBENCH_CHANNEL_QUANTITIES, "bits", 0,
                                             "time solver: roots of x'(u) isolate a monotone bracket, then Brent "
                                             "(Maya's published evaluator)"};
inline constexpr method solver_curvebench{"curvebench", CURVEBENCH_CHANNEL_QUANTITIES, "bits", 0,
                                          "time solver: curvebench's own (Halley on the power form in a bracket, "
                                          "handing over to exact's safeguarded Newton near a vertical tangent)"};
inline constexpr method solver_exact{"exact", CURVEBENCH_CHANNEL_QUANTITIES, "bits", 0,
                                     "time solver: safeguarded Newton-bisection on the de Casteljau residual "
                                     "to the precision's last bit"};
#undef CURVEBENCH_CHANNEL_QUANTITIES
// The glTF rotation samplers (channel/gltf.hpp rotation_sampler); setting bits=32 or bits=64.
inline constexpr method rotation_step{"rotation_step", "channel_rotation", "bits", 0,
                                      "glTF rotation, STEP: the key at or before t"};
inline constexpr method rotation_slerp{"rotation_slerp", "channel_rotation", "bits", 0,
                                       "glTF rotation, LINEAR: slerp on the short path (the spec's formula; angle "
                                       "by Kahan's atan2 of two norms)"};
inline constexpr method rotation_nlerp{"rotation_nlerp", "channel_rotation", "bits", 0,
                                       "glTF rotation, LINEAR as players approximate it: normalize((1 - s) v + s w)"};
inline constexpr method rotation_cubicspline{"rotation_cubicspline", "channel_rotation", "bits", 0,
                                             "glTF rotation, CUBICSPLINE: the Hermite on the 4 components, "
                                             "normalized"};
}  // namespace methods

/// The time-solver methods, in channel::all_time_solvers' order.
inline constexpr const method* time_solver_methods[] = {
    &methods::solver_closed_form, &methods::solver_table_newton, &methods::solver_newton_bisection,
    &methods::solver_bisection12, &methods::solver_bisection30,  &methods::solver_isolate_brent,
    &methods::solver_curvebench,  &methods::solver_exact};

/// The methods that have no row in the method tables (harness/length_methods.hpp), in the order
/// all_methods() gives them after the tables' rows.
inline constexpr const method* methods_without_row[] = {
    &methods::segments_adaptive,       &methods::eval_default,
    &methods::solver_closed_form,      &methods::solver_table_newton,
    &methods::solver_newton_bisection, &methods::solver_bisection12,
    &methods::solver_bisection30,      &methods::solver_isolate_brent,
    &methods::solver_curvebench,       &methods::solver_exact,
    &methods::rotation_step,           &methods::rotation_slerp,
    &methods::rotation_nlerp,          &methods::rotation_cubicspline};

/// Every method: the rows of the length table, the s(u) method, the rows of the u(s) table (a
/// method in both tables once), then the other methods of methods_without_row. The length and u(s)
/// methods are declared with their rows (harness/length_methods.hpp), so that adding one is its row
/// and its entry in its table; this list follows the tables (harness/vocabulary.cpp).
[[nodiscard]] std::span<const method* const> all_methods();

/// A library users would pick instead, timed (and measured) on the same data.
struct peer {
  std::string_view id;  ///< the benchmark algorithm id, always "peer_..."
  std::string_view library;
  std::string_view doc;
};

namespace peers {
inline constexpr peer boost_gauss{"peer_boost_gauss", "Boost.Math", "quadrature::gauss<double, N> (fixed rule)"};
inline constexpr peer boost_gauss_kronrod15{"peer_boost_gauss_kronrod15", "Boost.Math",
                                            "quadrature::gauss_kronrod<double, 15> (adaptive)"};
inline constexpr peer boost_gauss_kronrod31{"peer_boost_gauss_kronrod31", "Boost.Math",
                                            "quadrature::gauss_kronrod<double, 31> (adaptive)"};
inline constexpr peer boost_tanh_sinh{"peer_boost_tanh_sinh", "Boost.Math", "quadrature::tanh_sinh<double>"};
inline constexpr peer boost_catmull_rom{"peer_boost_catmull_rom", "Boost.Math", "interpolators::catmull_rom"};
inline constexpr peer boost_cubic_hermite{"peer_boost_cubic_hermite", "Boost.Math", "interpolators::cubic_hermite"};
inline constexpr peer boost_cardinal_cubic_b_spline{"peer_boost_cardinal_cubic_b_spline", "Boost.Math",
                                                    "interpolators::cardinal_cubic_b_spline"};
inline constexpr peer eigen_spline_fixed_degree{"peer_eigen_spline_fixed_degree", "Eigen",
                                                "Spline<double, 3, 3> (degree fixed at compile time)"};
inline constexpr peer eigen_spline_dynamic_degree{"peer_eigen_spline_dynamic_degree", "Eigen",
                                                  "Spline<double, 3, Dynamic>"};
inline constexpr peer bisection_reintegration{"peer_bisection_full_reintegration", "common practice",
                                              "u(s) by bisection on s(u) re-integrated from u0 (16-point Gauss)"};
// GSL: gsl_spline per coordinate on the spline's knots, and QUADPACK's adaptive
// Gauss-Kronrod integrating the speed |P'(u)| over the whole domain (epsabs 0, epsrel = tol).
inline constexpr peer gsl_cspline{"peer_gsl_cspline", "GSL", "gsl_spline, gsl_interp_cspline (natural cubic spline)"};
inline constexpr peer gsl_cspline_periodic{"peer_gsl_cspline_periodic", "GSL",
                                           "gsl_spline, gsl_interp_cspline_periodic (periodic cubic spline)"};
inline constexpr peer gsl_akima{"peer_gsl_akima", "GSL", "gsl_spline, gsl_interp_akima (Akima's local cubic)"};
inline constexpr peer gsl_steffen{"peer_gsl_steffen", "GSL",
                                  "gsl_spline, gsl_interp_steffen (Steffen's monotone cubic)"};
inline constexpr peer gsl_qag{"peer_gsl_qag", "GSL",
                              "gsl_integration_qag, 15-point Gauss-Kronrod, of the speed over the whole domain"};
inline constexpr peer gsl_qags{"peer_gsl_qags", "GSL",
                               "gsl_integration_qags (21-point Gauss-Kronrod with epsilon-algorithm "
                               "extrapolation) of the speed over the whole domain"};
inline constexpr peer gsl_qag_brent{"peer_gsl_qag_brent", "GSL",
                                    "u(s): gsl_root_fsolver_brent on s(u) - s, each s(u) a gsl_integration_qag "
                                    "(15-point Gauss-Kronrod) from the domain's start, epsrel = tol, until "
                                    "|s(u) - s| <= tol L"};
// SciPy (optional: scripts/peers.sh runs scripts/peers/scipy_driver.py, curvebench check
// measures it, the records come from reports/peers_scipy.json).
inline constexpr peer scipy_cubic_spline{"peer_scipy_cubic_spline", "SciPy",
                                         "scipy.interpolate.CubicSpline (natural, clamped, not-a-knot, periodic)"};
inline constexpr peer scipy_make_interp_spline{"peer_scipy_make_interp_spline", "SciPy",
                                               "scipy.interpolate.make_interp_spline, k = 3 (B-spline collocation)"};
inline constexpr peer scipy_bspline{"peer_scipy_bspline", "SciPy", "scipy.interpolate.BSpline on the spec's knots"};
inline constexpr peer scipy_quad{"peer_scipy_quad", "SciPy",
                                 "scipy.integrate.quad (QUADPACK qags) of the speed of SciPy's own spline, "
                                 "epsabs 0, epsrel = tol, limit 50"};
inline constexpr peer scipy_quad_brentq{"peer_scipy_quad_brentq", "SciPy",
                                        "u(s): scipy.optimize.brentq on s(u) - s, each s(u) a scipy.integrate.quad "
                                        "from the domain's start (epsabs 0, epsrel = tol), xtol = tol x the domain"};
// JavaScript easing evaluators (optional: scripts/peers.sh runs
// scripts/peers/easing_driver.mjs on the CSS cubic-bezier cases, npm versions pinned).
inline constexpr peer bezier_easing_3{"peer_bezier_easing_3", "bezier-easing",
                                      "bezier-easing 3.2.0: cubic-bezier easing, x(t) = x solved in closed form"};
inline constexpr peer bezier_easing_2{"peer_bezier_easing_2", "bezier-easing",
                                      "bezier-easing 2.1.0: cubic-bezier easing, sample table then Newton or "
                                      "bisection"};
inline constexpr peer mapbox_unitbezier{"peer_mapbox_unitbezier", "@mapbox/unitbezier",
                                        "@mapbox/unitbezier 1.0.0: solve(x) with its default epsilon 1e-6"};
// d3-ease (optional: scripts/peers/penner_driver.mjs, npm version pinned): Penner's easing
// equations as functions of normalized time, against their documented definitions.
inline constexpr peer d3_ease{"peer_d3_ease", "d3-ease", "d3-ease 3.0.2: Penner's easing equations on [0, 1]"};
// Headless Chromium (optional: scripts/peers/chromium_driver.py, Debian's chromium pinned): Blink's
// own CSS easing through the Web Animations API.
inline constexpr peer chromium_waapi{"peer_chromium_waapi", "Chromium",
                                     "Chromium (Debian): CSS cubic-bezier() and steps() as "
                                     "effect.getComputedTiming().progress of a paused animation"};
// Real Blender (optional: scripts/peers/blender_channels.py, when blender is on PATH): the channel
// cases' keys as F-curves, fcurve.evaluate at the query times.
inline constexpr peer blender_fcurve{"peer_blender_fcurve", "Blender",
                                     "Blender (Debian, headless): fcurve.evaluate of an F-curve built from the keys"};
// three.js (optional: scripts/peers/gltf_driver.mjs, npm version pinned): the glTF channel cases
// loaded as GLBs by its GLTFLoader, evaluated by the animation track's interpolant (float32).
inline constexpr peer three_gltf{"peer_three_gltf", "three",
                                 "three 0.187.0: GLTFLoader's animation track, track.createInterpolant().evaluate(t)"};
// Arc length and point at length in shipped software (optional: scripts/peers.sh runs
// scripts/peers/shipped_browser_driver.py and shipped_node_driver.mjs on shipped_request.py's
// request, `curvebench check --at-length` measures them into reports/peers_shipped_*.json).
inline constexpr peer chromium_path{"peer_chromium_path", "Chromium",
                                    "Chromium (Debian): SVGPathElement getTotalLength / getPointAtLength of a <path>"};
inline constexpr peer chromium_shape{"peer_chromium_shape", "Chromium",
                                     "Chromium (Debian): getTotalLength / getPointAtLength of a <circle>, <ellipse> or "
                                     "<rect> (Skia's contour measure)"};
inline constexpr peer firefox_path{"peer_firefox_path", "Firefox ESR",
                                   "Firefox ESR (Debian): getTotalLength / getPointAtLength of a <path>"};
inline constexpr peer firefox_shape{"peer_firefox_shape", "Firefox ESR",
                                    "Firefox ESR (Debian): getTotalLength / getPointAtLength of a basic shape"};
inline constexpr peer bezier_js{"peer_bezier_js", "bezier-js", "bezier-js: Bezier.length() (one Gauss-Legendre panel)"};
inline constexpr peer svg_path_properties{"peer_svg_path_properties", "svg-path-properties",
                                          "svg-path-properties: getTotalLength / getPointAtLength"};
inline constexpr peer paper{"peer_paper", "paper", "paper.js (headless): Path length / getPointAt"};
inline constexpr peer svg_path_commander{"peer_svg_path_commander", "svg-path-commander",
                                         "svg-path-commander: getTotalLength / getPointAtLength utilities"};
inline constexpr peer three_curve{"peer_three_curve", "three",
                                  "three: CubicBezierCurve / QuadraticBezierCurve getLength, getPointAt, "
                                  "getSpacedPoints (arcLengthDivisions chords)"};
inline constexpr peer three_svgloader{"peer_three_svgloader", "three",
                                      "three: SVGLoader's paths as CurvePath, getLength / getPointAt"};
inline constexpr peer skia_contour_measure{"peer_skia_contour_measure", "Skia",
                                           "Skia through canvaskit-wasm: ContourMeasureIter length and getPosTan, "
                                           "resScale as the setting"};
inline constexpr peer babylon_curve3{"peer_babylon_curve3", "Babylon.js",
                                     "@babylonjs/core: Curve3.CreateCubicBezier / CreateQuadraticBezier length(), "
                                     "Path3D getPointAt"};
inline constexpr peer babylon_bezier_interpolate{"peer_babylon_bezier_interpolate", "Babylon.js",
                                                 "@babylonjs/core: BezierCurve.Interpolate, a cubic-bezier easing by 5 "
                                                 "Newton steps from t, clamped, without a convergence test"};
inline constexpr peer lottie_bezier_easing{"peer_lottie_bezier_easing", "lottie-web",
                                           "lottie-web: its player's BezierEaser (float32 sample table, Newton or "
                                           "bisection), a cubic-bezier easing"};
inline constexpr peer three_catmull_rom{
    "peer_three_catmull_rom", "three",
    "three: CatmullRomCurve3 (uniform, centripetal, chordal) getLength, getPointAt, "
    "getUtoTmapping, getSpacedPoints and getPoint"};
// Native arc-length peers (optional: bench/peers/<peer> under CURVEBENCH_PEER_*, run by
// scripts/peers.sh on the shipped request and measured the same way).
inline constexpr peer qt_painterpath{"peer_qt_painterpath", "Qt",
                                     "Qt 5 (Debian): QPainterPath length, percentAtLength + pointAtPercent (absolute "
                                     "tolerance 0.01)"};
inline constexpr peer qt_easing_curve{"peer_qt_easing_curve", "Qt",
                                      "Qt 5 (Debian): QEasingCurve BezierSpline with addCubicBezierSegment, "
                                      "valueForProgress"};
inline constexpr peer occt_gcpnts{"peer_occt_gcpnts", "OpenCASCADE",
                                  "OpenCASCADE (Debian): GCPnts_AbscissaPoint::Length and the abscissa point, "
                                  "GCPnts_UniformAbscissa, with and without a tolerance"};
inline constexpr peer lib2geom{"peer_2geom", "lib2geom",
                               "lib2geom (Debian): Curve::length (bezier_length), length of the SBasis form, "
                               "arc_length_parametrization"};
inline constexpr peer fonttools_calc{"peer_fonttools_calc", "fontTools",
                                     "fontTools (Debian): calcCubicArcLength / calcQuadraticArcLength, tolerance as "
                                     "the setting"};
inline constexpr peer fonttools_approx{"peer_fonttools_approx", "fontTools",
                                       "fontTools (Debian): approximateCubicArcLength (one 5-point Gauss-Lobatto "
                                       "panel) / approximateQuadraticArcLength"};
inline constexpr peer blender_calc_length{"peer_blender_calc_length", "Blender",
                                          "Blender (Debian, headless): Spline.calc_length at resolution_u, Follow Path "
                                          "positions"};
inline constexpr peer godot_curve2d{"peer_godot_curve2d", "Godot",
                                    "Godot 3.2 (Debian godot3-server): Curve2D get_baked_length, interpolate_baked, "
                                    "bake_interval as the setting"};
inline constexpr peer godot_bezier_track{"peer_godot_bezier_track", "Godot",
                                         "Godot 3.2 (Debian godot3-server): Animation.bezier_track_interpolate of a "
                                         "cubic-bezier easing"};
inline constexpr peer lottie_web_position{"peer_lottie_web_position", "lottie-web",
                                          "lottie-web in headless Chromium: a layer's position along spatial Bezier "
                                          "keyframes with eased timing"};
}  // namespace peers

inline constexpr const peer* all_peers[] = {&peers::boost_gauss,
                                            &peers::boost_gauss_kronrod15,
                                            &peers::boost_gauss_kronrod31,
                                            &peers::boost_tanh_sinh,
                                            &peers::boost_catmull_rom,
                                            &peers::boost_cubic_hermite,
                                            &peers::boost_cardinal_cubic_b_spline,
                                            &peers::eigen_spline_fixed_degree,
                                            &peers::eigen_spline_dynamic_degree,
                                            &peers::bisection_reintegration,
                                            &peers::gsl_cspline,
                                            &peers::gsl_cspline_periodic,
                                            &peers::gsl_akima,
                                            &peers::gsl_steffen,
                                            &peers::gsl_qag,
                                            &peers::gsl_qags,
                                            &peers::gsl_qag_brent,
                                            &peers::scipy_cubic_spline,
                                            &peers::scipy_make_interp_spline,
                                            &peers::scipy_bspline,
                                            &peers::scipy_quad,
                                            &peers::scipy_quad_brentq,
                                            &peers::bezier_easing_3,
                                            &peers::bezier_easing_2,
                                            &peers::mapbox_unitbezier,
                                            &peers::d3_ease,
                                            &peers::chromium_waapi,
                                            &peers::blender_fcurve,
                                            &peers::three_gltf,
                                            &peers::chromium_path,
                                            &peers::chromium_shape,
                                            &peers::firefox_path,
                                            &peers::firefox_shape,
                                            &peers::bezier_js,
                                            &peers::svg_path_properties,
                                            &peers::paper,
                                            &peers::svg_path_commander,
                                            &peers::three_curve,
                                            &peers::three_svgloader,
                                            &peers::skia_contour_measure,
                                            &peers::babylon_curve3,
                                            &peers::babylon_bezier_interpolate,
                                            &peers::lottie_bezier_easing,
                                            &peers::three_catmull_rom,
                                            &peers::qt_painterpath,
                                            &peers::qt_easing_curve,
                                            &peers::occt_gcpnts,
                                            &peers::lib2geom,
                                            &peers::fonttools_calc,
                                            &peers::fonttools_approx,
                                            &peers::blender_calc_length,
                                            &peers::godot_curve2d,
                                            &peers::godot_bezier_track,
                                            &peers::lottie_web_position};

/// What one item of a benchmark is: the unit of its time per operation.
struct operation {
  std::string_view id;
  std::string_view doc;
};

namespace operations {
inline constexpr operation evaluation{"evaluation", "one point (or derivative) of a curve at one parameter"};
inline constexpr operation basis{"basis", "all n + 1 basis functions at one parameter"};
inline constexpr operation length{"length", "one arc length of the whole curve (set-up included)"};
inline constexpr operation query{"query", "one u(s) or s(u) query (tables built beforehand)"};
inline constexpr operation table_build{"table_build",
                                       "one u(s) table built (segment lengths, nodes and cells), sized to its target"};
inline constexpr operation frame{"frame", "one frame of a motion path: P(U(L S(t)))"};
inline constexpr operation ease{"ease", "one ease value and its velocity"};
inline constexpr operation channel_value{"channel_value",
                                         "one keyframe channel's value at one time (segment search and time "
                                         "inversion included)"};
}  // namespace operations

inline constexpr const operation* all_operations[] = {
    &operations::evaluation,  &operations::basis, &operations::length, &operations::query,
    &operations::table_build, &operations::frame, &operations::ease,   &operations::channel_value};

/// An algorithm a benchmark times that is not a method above: the evaluation algorithms each
/// family offers (and the ease functions), as the benchmark names spell them.
struct algorithm {
  std::string_view id;
  std::string_view settings;  ///< its setting keys in benchmark names, space-separated ("" when none)
  std::string_view doc;
};

namespace algorithms {
inline constexpr algorithm power{"power", "",
                                 "piecewise cubic: Horner on power-basis coefficients (the engine's default)"};
inline constexpr algorithm matrix{"matrix", "", "piecewise cubic: T M G per call (basis matrix times geometry)"};
inline constexpr algorithm bezier{"bezier", "", "piecewise cubic: de Casteljau on the segment's Bezier form"};
inline constexpr algorithm to_piecewise_cubic{"to_piecewise_cubic", "",
                                              "a cubic B-spline converted once to the piecewise cubic engine "
                                              "(power form; O(1) segment lookup on uniform knots)"};
inline constexpr algorithm de_casteljau{"de_casteljau", "", "Bezier: de Casteljau's algorithm, O(degree^2)"};
inline constexpr algorithm bernstein_sum{"bernstein_sum", "", "Bezier: the Bernstein sum, O(degree)"};
inline constexpr algorithm horner{"horner", "", "Bezier: Horner on power coefficients converted once, O(degree)"};
inline constexpr algorithm barycentric{"barycentric", "",
                                       "Lagrange: the second barycentric form (the spec's \"algorithm\" field)"};
inline constexpr algorithm monomial{"monomial", "",
                                    "Lagrange: Horner on monomial coefficients solved from the Vandermonde system"};
inline constexpr algorithm de_boor{"de_boor", "",
                                   "B-spline/NURBS: de Boor's algorithm (NURBS: in homogeneous "
                                   "coordinates, derivatives by the quotient rule)"};
inline constexpr algorithm basis_sum{"basis_sum", "",
                                     "B-spline/NURBS: the Cox-de Boor basis functions times the points"};
inline constexpr algorithm recursion{"recursion", "",
                                     "all Bernstein polynomials of degree n by the triangular recursion"};
inline constexpr algorithm closed_form{"closed_form", "", "each Bernstein polynomial by its closed form"};
inline constexpr algorithm ease_linear{"linear", "", "ease: S(t) = t"};
inline constexpr algorithm ease_sine{"sine", "", "ease: sine ease-in/ease-out"};
inline constexpr algorithm ease_sine_plateau{"sine_plateau", "t1 t2",
                                             "ease: sine acceleration, constant speed, sine deceleration"};
inline constexpr algorithm ease_parabolic{"parabolic", "t1 t2",
                                          "ease: constant acceleration, constant speed, constant deceleration"};
inline constexpr algorithm ease_smootherstep{"smootherstep", "", "ease: the quintic 6t^5 - 15t^4 + 10t^3"};
inline constexpr algorithm ease_distance_keys{"distance_keys", "",
                                              "ease: monotone interpolation of (time, distance) keys"};
inline constexpr algorithm ease_speed_curve{"speed_curve", "interpolation",
                                            "ease: the integral of an interpolated speed curve"};
// Floors (ids start with "floor_"): the simplest correct hand-written kernel for the same work,
// timed in the same run beside the library's rows; the report gives each row's ratio to them.
inline constexpr algorithm floor_horner{"floor_horner", "",
                                        "floor: scalar Horner on one flat array of power coefficients, t = (u - u_i) / "
                                        "h_i, segment by the O(1) uniform index (uniform knots) or std::upper_bound, "
                                        "no checks"};
inline constexpr algorithm floor_soa_sorted{"floor_soa_sorted", "",
                                            "floor: sorted batch, coefficients hoisted per segment, coordinates in "
                                            "separate arrays (SoA) in and out, one branch-free loop per segment"};
inline constexpr algorithm floor_store_stream{"floor_store_stream", "",
                                              "floor: a store-only stream of the batch's output bytes (the memory "
                                              "bound of a batch that does not fit in cache)"};
inline constexpr algorithm monotone_cubic{"monotone_cubic", "",
                                          "motion::monotone_cubic: C1 shape-preserving cubic (Fritsch-Butland "
                                          "slopes), binary search and Horner"};
}  // namespace algorithms

inline constexpr const algorithm* all_algorithms[] = {&algorithms::power,
                                                      &algorithms::matrix,
                                                      &algorithms::bezier,
                                                      &algorithms::to_piecewise_cubic,
                                                      &algorithms::de_casteljau,
                                                      &algorithms::bernstein_sum,
                                                      &algorithms::horner,
                                                      &algorithms::barycentric,
                                                      &algorithms::monomial,
                                                      &algorithms::de_boor,
                                                      &algorithms::basis_sum,
                                                      &algorithms::recursion,
                                                      &algorithms::closed_form,
                                                      &algorithms::ease_linear,
                                                      &algorithms::ease_sine,
                                                      &algorithms::ease_sine_plateau,
                                                      &algorithms::ease_parabolic,
                                                      &algorithms::ease_smootherstep,
                                                      &algorithms::ease_distance_keys,
                                                      &algorithms::ease_speed_curve,
                                                      &algorithms::floor_horner,
                                                      &algorithms::floor_soa_sorted,
                                                      &algorithms::floor_store_stream,
                                                      &algorithms::monotone_cubic};

/// The evaluation algorithms the families offer besides their default (the eval records' methods
/// other than methods::eval_default), each once, in the family registry's order (io/registry.hpp;
/// test_gate checks the two agree): the gate reads them here without the registry.
inline constexpr const algorithm* eval_algorithms[] = {
    &algorithms::barycentric, &algorithms::monomial, &algorithms::de_casteljau, &algorithms::bernstein_sum,
    &algorithms::horner,      &algorithms::de_boor,  &algorithms::basis_sum,    &algorithms::power,
    &algorithms::matrix,      &algorithms::bezier};

/// A benchmark-name key whose value picks a variant of how the algorithm is called, not the data
/// or the method's setting: the report ranks rows that differ only in these keys and in settings
/// together (e.g. single calls against a sorted batch, per evaluation).
struct variant_key {
  std::string_view id;
  std::string_view values;  ///< its allowed values, space-separated
  std::string_view doc;
};

namespace variant_keys {
inline constexpr variant_key calls{"calls", "single batch sorted",
                                   "single: one call per evaluation; batch: one call over 1024 parameters; "
                                   "sorted: one call over the same 1024 parameters sorted"};
inline constexpr variant_key estimate{"estimate", "none nested",
                                      "none: the rule alone; nested: with the nested estimate (fixed_estimate)"};
inline constexpr variant_key api{"api", "newton_invert",
                                 "newton_invert: the solver called directly, not through the parameterization"};
inline constexpr variant_key timing{"timing", "throughput latency",
                                    "throughput: independent evaluations (parameters fixed in advance); latency: a "
                                    "dependent chain (each parameter depends on the previous result)"};
}  // namespace variant_keys

inline constexpr const variant_key* all_variant_keys[] = {&variant_keys::calls, &variant_keys::estimate,
                                                          &variant_keys::api, &variant_keys::timing};

/// A benchmark counter. Kinds: "error" (an error of the result, compared across methods),
/// "estimate" (the method's own error estimate), "count" (per operation), "setting" (an input).
struct counter {
  std::string_view name;
  std::string_view kind;
  std::string_view doc;
};

namespace counters {
inline constexpr counter evaluations{"evaluations", "count",
                                     "curve or derivative evaluations per operation (set-up included)"};
inline constexpr counter iterations{"iterations", "count", "solver iterations per operation"};
inline constexpr counter table_intervals{"table_intervals", "setting", "intervals of the u(s) table"};
inline constexpr counter rel_error{"rel_error", "error", "|value - reference| / reference (a length)"};
inline constexpr counter max_ds_rel{"max_ds_rel", "error", "max |s(u_j) - s_j| / L over the query set (u(s), frames)"};
inline constexpr counter max_err_eps{"max_err_eps", "error", "max evaluation error in eps(double) x the curve's size"};
inline constexpr counter max_err_range_eps{"max_err_range_eps", "error",
                                           "max channel value error in eps(Real) x the channel's value range"};
inline constexpr counter estimate_rel{"estimate_rel", "estimate", "the method's own error estimate / L"};
inline constexpr counter flops{"flops", "count",
                               "floating-point operations per evaluation in the kernel's arithmetic, counted by "
                               "hand (power: t's subtraction and division plus Horner's 6 per coordinate)"};
}  // namespace counters

inline constexpr const counter* all_counters[] = {
    &counters::evaluations,       &counters::iterations,   &counters::table_intervals,
    &counters::rel_error,         &counters::max_ds_rel,   &counters::max_err_eps,
    &counters::max_err_range_eps, &counters::estimate_rel, &counters::flops};

/// The method with this id, or nullptr.
[[nodiscard]] const method* find_method(std::string_view id);

/// Whether a space-separated list holds the word w.
[[nodiscard]] constexpr bool lists(std::string_view words, std::string_view w) {
  while (!words.empty()) {
    const auto space = words.find(' ');
    if (words.substr(0, space) == w) return true;
    if (space == std::string_view::npos) break;
    words.remove_prefix(space + 1);
  }
  return false;
}

[[nodiscard]] constexpr const quantity* find_quantity(std::string_view id) {
  for (const quantity* q : all_quantities)
    if (q->id == id) return q;
  return nullptr;
}

[[nodiscard]] constexpr const algorithm* find_algorithm(std::string_view id) {
  for (const algorithm* a : all_algorithms)
    if (a->id == id) return a;
  return nullptr;
}

[[nodiscard]] constexpr const counter* find_counter(std::string_view name) {
  for (const counter* c : all_counters)
    if (c->name == name) return c;
  return nullptr;
}

}  // namespace curvebench::harness::vocab
