// The method tables: every arc-length method and every u(s) method of the harness, each declared
// once, as one row: its vocabulary method (id, setting keys, fitted theory order), its settings by
// name (the CLI's default and limits, and the `curvebench length` option that sets each), the
// setting series the accuracy sweep runs it over, for a length method its cost before the work
// (the CLI's progress budget and its refusal above the limit), whether it carries an error
// estimate, and its run on a curve.
//
// Iterated by the accuracy sweeps (harness/sweep_length.cpp, harness/sweep_u_of_s.cpp), the
// per-case benchmarks (bench/bench_arclength_cases.cpp, through for_each_length_method),
// `curvebench length` (bench/tool/main.cpp: its --method list, options, budget and dispatch) and
// the spec fuzz target (tests/fuzz/targets_spec.cpp); the vocabulary's method list follows them
// (vocab::all_methods(), harness/vocabulary.cpp). A row's vocabulary entry (vocab::methods::<id>:
// its id, quantities, setting keys, theory order and doc) is declared here, just before the row.
// Adding a method is its library header, its entry and row here, its one entry in length_methods
// or u_of_s_methods, and its test.
//
// A row's run is prepared in two steps, prepare(curve, settings, context) -> a callable returning
// the result: what does not belong to the timed work (a rule looked up in a cache) happens in
// prepare, the work (set-up included) in the call, which bench_arclength_cases times. The callable
// refers to the curve, which must outlive it.
#pragma once

#include "harness/setting.hpp"
#include "harness/sweep.hpp"
#include "harness/vocabulary.hpp"

#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/error.hpp"

#include <array>
#include <bit>
#include <cstddef>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace curvebench::harness {

/// One setting of a method, by its key.
struct setting_def {
  std::string_view key;     ///< its key in records and benchmark names (the vocab method's `settings`, in order)
  std::string_view option;  ///< the `curvebench length` option that sets it ("--n"); "" when the CLI does not
  double fallback;          ///< the CLI's default (methods sharing an option share it)
  double min, max;          ///< the CLI's limits, inclusive (a real setting: > min when min is 0)
  bool integer;             ///< printed as an integer ("n=8"); the CLI takes integers only
  std::string_view help;    ///< what it does for this method (the CLI's help of its option)
};

/// A method's setting values by key.
using setting_values = std::map<std::string, double, std::less<>>;

/// The value of `key` in v; invalid_input naming the method and the key when v has none.
inline double value_of(const setting_values& v, std::string_view key, std::string_view method) {
  const auto it = v.find(key);
  if (it == v.end())
    throw invalid_input("setting of method " + std::string(method) + ": no value for key \"" + std::string(key) + "\"");
  return it->second;
}

/// A setting value as records and benchmark names print it: integers as integers ("256"), reals
/// through fmt ("1e-06").
inline std::string setting_text(const setting_def& d, double value) {
  return d.integer ? std::to_string(static_cast<long long>(value)) : fmt(value);
}

/// The record setting of a row's values, "key=value[,key=value]" in the row's order. Throws
/// invalid_input when the row's keys are not its vocabulary method's declared `settings`.
template <class Row>
std::string format_setting(const Row& row, const setting_values& v) {
  std::string out, keys;
  for (const setting_def& d : row.settings) {
    keys += (keys.empty() ? "" : " ") + std::string(d.key);
    out += (out.empty() ? "" : ",") + std::string(d.key) + "=" + setting_text(d, value_of(v, d.key, row.method->id));
  }
  if (keys != row.method->settings)
    throw invalid_input("method table row " + std::string(row.method->id) + ": setting keys \"" + keys +
                        "\" are not the vocabulary's \"" + std::string(row.method->settings) + "\"");
  return out;
}

/// The row's CLI options with their values, as a refusal names them: "--n 5 --panels 4".
template <class Row>
std::string options_text(const Row& row, const setting_values& v) {
  std::string out;
  for (const setting_def& d : row.settings)
    if (!d.option.empty())
      out +=
          (out.empty() ? "" : " ") + std::string(d.option) + " " + setting_text(d, value_of(v, d.key, row.method->id));
  return out;
}

/// The row's settings at their CLI defaults.
template <class Row>
setting_values default_settings(const Row& row) {
  setting_values v;
  for (const setting_def& d : row.settings) v[std::string(d.key)] = d.fallback;
  return v;
}

/// How a run reads its settings beyond their values.
struct run_context {
  /// > 0: a tolerance relative to the length is tol x this length, absolute (the sweep gives the
  /// reference L, so that a setting means the same on every case); 0: the method's own relative
  /// measure, as `curvebench length` runs it (subdivision: relative to the curve's size).
  double reference_length = 0;
  /// The adaptive methods' cap on evaluations (0: the library's default).
  std::size_t max_evaluations = 0;
  /// gauss's estimate: nested (the records' and the default) or none, the benchmarks' fast fixed rule
  /// without an estimate (status not_guaranteed, estimate null). Not a setting of the records (their
  /// gauss setting is n alone, always nested): `curvebench length --estimate` sets it.
  arclength::fixed_estimate gauss_estimate = arclength::fixed_estimate::nested;
};

/// What a length method costs before the work, on a curve of `segments` segments.
struct length_cost {
  std::size_t budget = 0;  ///< the most evaluations it spends (the CLI's progress total)
  std::string refusal;     ///< "" or why the CLI refuses the setting (above its limit), naming the options
  /// false: budget is the planned work, which the curve may exceed (gauss's nested estimate splits a
  /// segment at each deep speed minimum and refines the minimum first: up to 17 pieces and 90
  /// evaluations per minimum on top of 7n per piece; and halves a piece that fails its order test,
  /// up to 4 levels, 7n per try: at most 31 x 7n per piece), so the progress says "planned", not
  /// "at most".
  bool at_most = true;
};

/// The most evaluations `curvebench length` spends on a fixed rule (gauss, composite_gauss),
/// checked before the work: --n x --panels x segments (x 7 for gauss's nested estimate).
inline constexpr std::size_t max_fixed_rule_evaluations = std::size_t(1) << 26;

/// The cost of a fixed rule of `evaluations` evaluations: refused above max_fixed_rule_evaluations.
inline length_cost fixed_rule_cost(const std::string& options, double evaluations, std::size_t segments) {
  length_cost c;
  if (evaluations > static_cast<double>(max_fixed_rule_evaluations)) {
    c.refusal = options + ": " + std::to_string(segments) + (segments == 1 ? " segment" : " segments") + " need " +
                to_text(evaluations) + " evaluations, more than the limit of " +
                std::to_string(max_fixed_rule_evaluations);
    return c;
  }
  c.budget = static_cast<std::size_t>(evaluations);
  return c;
}

/// A row of the length table. series(const sweep&, double segments) -> std::vector<setting_values>;
/// cost(const setting_values&, std::size_t segments) -> length_cost; prepare(const Curve&, const
/// setting_values&, const run_context&) -> a callable () -> arclength::quadrature_result<double>
/// (evaluations include the set-up, e.g. a forward-difference table's).
template <std::size_t N, class Series, class Cost, class Prepare>
struct length_method {
  const vocab::method* method;
  std::array<setting_def, N> settings;
  bool estimate;  ///< whether its result carries an error estimate (else the estimate is not read)
  Series series;
  Cost cost;
  Prepare prepare;
};
template <std::size_t N, class Series, class Cost, class Prepare>
length_method(const vocab::method*, std::array<setting_def, N>, bool, Series, Cost, Prepare)
    -> length_method<N, Series, Cost, Prepare>;

/// The answer of a u(s) method at one target.
struct u_of_s_answer {
  double u = 0;
  double estimate = std::numeric_limits<double>::quiet_NaN();  ///< its |s(u) - s| bound, when per query
  double evaluations = 0;                                      ///< the query's own (set-up excluded)
  arclength::result_status status = arclength::result_status::converged;
  std::string reason;  ///< why status is not converged (arclength::to_text of the reason), "" for none
};

/// A u(s) method built on a curve.
struct u_of_s_run {
  double length = 0;                     ///< its own L: targets are clamped to it (u(s) rejects s > L)
  double construction_evaluations = 0;   ///< evaluations of the set-up (tables, segment lengths)
  std::optional<double> table_estimate;  ///< its |s(u) - s| bound over the whole table, when not per query
  std::function<u_of_s_answer(double)> query;
};

/// A row of the u(s) table. series as a length row's; prepare(const Curve&, const setting_values&)
/// -> u_of_s_run.
template <std::size_t N, class Series, class Prepare>
struct u_of_s_method {
  const vocab::method* method;
  std::array<setting_def, N> settings;
  bool estimate;  ///< whether it carries an error estimate (else the records' estimate is null)
  Series series;
  Prepare prepare;
  /// The parameterization's method it measures, when `sample --method` offers it (a polished table
  /// is sample's --polish, not a method of its own).
  std::optional<arclength::inversion_method> sample_method{};
};
template <std::size_t N, class Series, class Prepare>
u_of_s_method(const vocab::method*, std::array<setting_def, N>, bool, Series, Prepare)
    -> u_of_s_method<N, Series, Prepare>;
template <std::size_t N, class Series, class Prepare>
u_of_s_method(const vocab::method*, std::array<setting_def, N>, bool, Series, Prepare,
              std::optional<arclength::inversion_method>) -> u_of_s_method<N, Series, Prepare>;

namespace method_rows {

namespace al = curvebench::arclength;

/// The table steps of the sweep that stay within its budget of w.max_table_evals on `segments`.
inline std::vector<setting_values> table_steps_series(const sweep& w, double segments) {
  std::vector<setting_values> out;
  for (std::size_t steps : w.table_steps) {
    if (static_cast<double>(steps) * segments > w.max_table_evals) break;
    out.push_back({{"steps", static_cast<double>(steps)}});
  }
  return out;
}

/// One setting of each value of `values` under `key`.
template <class T>
std::vector<setting_values> series_of(std::string_view key, const std::vector<T>& values) {
  std::vector<setting_values> out;
  for (const T& x : values) out.push_back({{std::string(key), static_cast<double>(x)}});
  return out;
}

inline constexpr setting_def tol_of_length{
    "tol",
    "--tol",
    1e-12,
    0,
    std::numeric_limits<double>::infinity(),
    false,
    "relative tolerance of the length; stops at 2^24 evaluations with status cap_hit (the first 31-point panel of "
    "each segment always computed: 31 x segments when that is more)"};
inline constexpr setting_def steps_per_segment{
    "steps", "--steps", 256, 1, 10000000, true, "table steps per segment (steps x segments nodes, at most 2^24)"};

}  // namespace method_rows

namespace vocab::methods {
inline constexpr method forward_difference{"forward_difference", "length s_of_u u_of_s", "steps", 2,
                                           "chord sums of a table of N steps per segment (seed 002)"};
}  // namespace vocab::methods

namespace method_rows {

/// The refusal of a forward-difference table above its node limit.
inline length_cost table_cost(const setting_values& v, std::size_t segments) {
  const auto steps = static_cast<std::size_t>(value_of(v, "steps", vocab::methods::forward_difference.id));
  length_cost c;
  if (steps > (al::max_forward_difference_evaluations - 1) / segments) {
    c.refusal = "--steps " + std::to_string(steps) + ": " + std::to_string(segments) +
                (segments == 1 ? " segment" : " segments") + " x " + std::to_string(steps) +
                " steps is more than the limit of " + std::to_string(al::max_forward_difference_evaluations) +
                " table nodes";
    return c;
  }
  c.budget = steps * segments + 1;
  return c;
}

/// gauss's cost with its estimate: nested, the planned work (at_most false: see length_cost); none,
/// exactly n per segment.
inline length_cost gauss_cost(const setting_values& v, std::size_t segments, al::fixed_estimate estimate) {
  const double n = value_of(v, "n", "gauss");
  const std::string options = "--n " + std::to_string(static_cast<long long>(n));
  if (estimate == al::fixed_estimate::none)
    return fixed_rule_cost(options + " --estimate none", n * static_cast<double>(segments), segments);
  // The planned work: 7n per segment and its 17 speed samples (speed_features); a speed minimum
  // adds a piece of 7n and its Newton refinement, and a piece failing the order test its halves'
  // tries (up to 30 more of 7n), which no count before the work knows.
  length_cost c = fixed_rule_cost(options, (7.0 * n + 17.0) * static_cast<double>(segments), segments);
  c.at_most = false;
  return c;
}

}  // namespace method_rows

namespace vocab::methods {
inline constexpr method gauss{
    "gauss", "length", "n", 0,
    "fixed n-point Gauss-Legendre per segment; estimate from the same rule on 1, 2 and 4 panels"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr length_method gauss{
    &vocab::methods::gauss,
    std::array{setting_def{"n", "--n", 5, 1, 200, true,
                           "Gauss points (nested estimate: 7n per piece plus 17 samples per segment, at most 2^26 "
                           "planned; a segment is split at its deep speed minima, each refined first, and a piece "
                           "failing the order test is halved, up to 4 levels, each try counted; --estimate none: n "
                           "per segment, no estimate)"}},
    true,
    [](const sweep& w, double) { return series_of("n", w.gauss_n); },
    [](const setting_values& v, std::size_t segments) { return gauss_cost(v, segments, al::fixed_estimate::nested); },
    [](const auto& c, const setting_values& v, const run_context& x) {
      const int n = static_cast<int>(value_of(v, "n", "gauss"));
      // The rule cache outlives every run (gauss_legendre returns a reference into it).
      const al::gauss_legendre_rule<double>* rule = &al::gauss_legendre<double>(n);
      const al::fixed_estimate e = x.gauss_estimate;
      return [&c, rule, e] { return al::gauss_length(c, *rule, e); };
    }};

}  // namespace method_rows

namespace vocab::methods {
inline constexpr method composite_gauss{"composite_gauss", "length", "n panels", 6,
                                        "n-point Gauss-Legendre on equal panels per segment (theory 2n: 6 for n = 3)"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr length_method composite_gauss{
    &vocab::methods::composite_gauss,
    std::array{setting_def{"n", "--n", 5, 1, 200, true,
                           "Gauss points per panel (the composite rule carries no estimate: status not_guaranteed, "
                           "estimate null)"},
               setting_def{"panels", "--panels", 4, 1, 1000000, true,
                           "panels per segment (n x panels x segments evaluations, at most 2^26)"}},
    true,
    [](const sweep& w, double) {
      std::vector<setting_values> out;
      for (int p : w.panels) out.push_back({{"n", composite_gauss_n}, {"panels", static_cast<double>(p)}});
      return out;
    },
    [](const setting_values& v, std::size_t segments) {
      const double n = value_of(v, "n", "composite_gauss"), panels = value_of(v, "panels", "composite_gauss");
      return fixed_rule_cost("--n " + std::to_string(static_cast<long long>(n)) + " --panels " +
                                 std::to_string(static_cast<long long>(panels)),
                             n * panels * static_cast<double>(segments), segments);
    },
    [](const auto& c, const setting_values& v, const run_context&) {
      const int p = static_cast<int>(value_of(v, "panels", "composite_gauss"));
      // The rule cache outlives every run (gauss_legendre returns a reference into it).
      const al::gauss_legendre_rule<double>* rule =
          &al::gauss_legendre<double>(static_cast<int>(value_of(v, "n", "composite_gauss")));
      return [&c, p, rule] { return al::composite_gauss_length(c, p, *rule); };
    }};

/// adaptive_length computes one G15-K31 panel (31 evaluations) per segment before it refines any
/// (arclength/length.hpp); the budget (2^24) bounds the refinement after them.
inline constexpr std::size_t adaptive_first_panel_evaluations = 31;

/// adaptive_gk's most evaluations: its budget, or the first panels where they alone pass it (more
/// than 541200 segments), which are always computed (the progress total; the CLI's text says so).
inline length_cost adaptive_cost(const setting_values&, std::size_t segments) {
  const std::size_t budget = al::adaptive_options<double>{}.max_evaluations;
  const std::size_t first = segments * adaptive_first_panel_evaluations;
  return length_cost{first > budget ? first : budget, {}};
}

}  // namespace method_rows

namespace vocab::methods {
inline constexpr method adaptive_gk{"adaptive_gk", "length", "tol", 0,
                                    "adaptive Gauss-Kronrod G7-K15 to a relative tolerance, split at speed minima"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr length_method adaptive_gk{&vocab::methods::adaptive_gk,
                                           std::array{tol_of_length},
                                           true,
                                           [](const sweep& w, double) { return series_of("tol", w.adaptive_tol); },
                                           adaptive_cost,
                                           [](const auto& c, const setting_values& v, const run_context& x) {
                                             al::adaptive_options<double> o;
                                             o.relative_tolerance = value_of(v, "tol", "adaptive_gk");
                                             if (x.max_evaluations > 0) o.max_evaluations = x.max_evaluations;
                                             return [&c, o] { return al::adaptive_length(c, o); };
                                           }};

inline constexpr length_method forward_difference{
    &vocab::methods::forward_difference,
    std::array{steps_per_segment},
    true,
    table_steps_series,
    table_cost,
    [](const auto& c, const setting_values& v, const run_context&) {
      const auto steps = static_cast<std::size_t>(value_of(v, "steps", "forward_difference"));
      return [&c, steps] {
        const al::forward_difference_table<double> t(c, steps);
        return t.length();
      };
    }};

}  // namespace method_rows

namespace vocab::methods {
inline constexpr method richardson{"richardson", "length", "steps", 4,
                                   "Richardson extrapolation of the chord sums of N and N/2 steps"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr length_method richardson{&vocab::methods::richardson,
                                          std::array{steps_per_segment},
                                          true,
                                          table_steps_series,
                                          table_cost,
                                          [](const auto& c, const setting_values& v, const run_context&) {
                                            const auto steps =
                                                static_cast<std::size_t>(value_of(v, "steps", "richardson"));
                                            return [&c, steps] {
                                              const al::forward_difference_table<double> t(c, steps);
                                              return t.richardson_length();
                                            };
                                          }};

}  // namespace method_rows

namespace vocab::methods {
inline constexpr method subdivision{"subdivision", "length", "tol", 2,
                                    "adaptive subdivision, the piece with the largest chord / control-polygon bracket "
                                    "halved first; tolerance relative to the length"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr length_method subdivision{
    &vocab::methods::subdivision,
    std::array{setting_def{"tol", "--tol", 1e-12, 0, std::numeric_limits<double>::infinity(), false,
                           "relative tolerance of the curve's size (the polygon through breakpoints and midpoints); "
                           "stops at 2^22 evaluations with status cap_hit"}},
    true,
    [](const sweep& w, double) { return series_of("tol", w.subdivision_tol); },
    [](const setting_values&, std::size_t) {
      return length_cost{al::subdivision_options<double>{}.max_evaluations, {}};
    },
    [](const auto& c, const setting_values& v, const run_context& x) {
      const double tol = value_of(v, "tol", "subdivision");
      al::subdivision_options<double> o;
      if (x.reference_length > 0) {
        o.tolerance = tol * x.reference_length;
        o.relative_tolerance = 0;  // tol is relative to the reference length, given absolute here
      } else {
        o.tolerance = 0;
        o.relative_tolerance = tol;  // relative to the curve's size (adaptive_subdivision.hpp)
      }
      if (x.max_evaluations > 0) o.max_evaluations = x.max_evaluations;
      return [&c, o] { return al::subdivision_length(c, o); };
    }};

/// A u(s) table of M intervals (setting M): linear or Hermite, optionally polished by one Newton step.
inline constexpr setting_def table_intervals{
    "M", "", 0, 1, 1 << 20, true, "table cells in s, shared by the segments in proportion to their lengths"};

/// The u(s) run of a table built with options o, by Method, polished or not: its status and reason
/// are the table's (worded once, here), its estimate the table's measured error when `estimate`.
template <al::inversion_method Method, bool Polish, class Curve>
u_of_s_run table_run(const Curve& c, const al::parameterization_options<double>& o, bool estimate) {
  const auto p = std::make_shared<const al::parameterization<Curve>>(c, o);
  u_of_s_run r;
  r.length = p->length();
  r.construction_evaluations = static_cast<double>(p->construction_evaluations());
  if (estimate) r.table_estimate = p->table_error();
  r.query = [p, reason = al::to_text(p->table_reason())](double s) {
    u_of_s_answer a;
    if constexpr (Polish) {
      const auto q = p->invert(s, Method);
      a.u = q.u;
      a.estimate = q.s_error_estimate;
      a.evaluations = static_cast<double>(q.evaluations);
    } else {
      a.u = p->u(s, Method);
    }
    a.status = p->table_status();  // the record's status is the table's
    a.reason = reason;
    return a;
  };
  return r;
}

template <al::inversion_method Method, bool Polish>
inline constexpr auto table_prepare = [](const auto& c, const setting_values& v) {
  al::parameterization_options<double> o;
  o.method = Method;
  o.table_intervals = static_cast<std::size_t>(value_of(v, "M", "u(s) table"));
  o.newton_polish = Polish;
  return table_run<Method, Polish>(c, o, Method == al::inversion_method::hermite_table && !Polish);
};

/// The M of a fixed table is its total, shared by the segments: on a curve of more than 16
/// segments the sweep's series is scaled by bit_ceil(segments) / 4, so that its first table has
/// about 4 cells per segment (unscaled, M = 16 to 1024 on 1000 segments all gave one cell per
/// segment, and the fitted order, 0.86, measured nothing); a setting past the library's cap on
/// cells (max_table_intervals) is left out.
inline std::vector<setting_values> table_intervals_series(const sweep& w, double segments) {
  const std::size_t n = static_cast<std::size_t>(segments);
  const std::size_t scale = n > 16 ? std::bit_ceil(n) / 4 : 1;
  std::vector<setting_values> out;
  for (const std::size_t m : w.table_intervals) {
    if (m * scale > al::parameterization_options<double>{}.max_table_intervals) break;
    out.push_back({{"M", static_cast<double>(m * scale)}});
  }
  return out;
}

}  // namespace method_rows

namespace vocab::methods {
inline constexpr method linear_table{"linear_table", "u_of_s", "M", 2,
                                     "u(s): table of M cells in s shared by the segments by length, linear "
                                     "interpolation"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr u_of_s_method linear_table{&vocab::methods::linear_table,
                                            std::array{table_intervals},
                                            false,
                                            table_intervals_series,
                                            table_prepare<al::inversion_method::linear_table, false>,
                                            al::inversion_method::linear_table};
}  // namespace method_rows

namespace vocab::methods {
inline constexpr method hermite_table{"hermite_table", "u_of_s", "M", 4,
                                      "u(s): table of M cells in s shared by the segments by length, cubic Hermite "
                                      "interpolation (du/ds = 1/|P'|)"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr u_of_s_method hermite_table{&vocab::methods::hermite_table,
                                             std::array{table_intervals},
                                             true,
                                             table_intervals_series,
                                             table_prepare<al::inversion_method::hermite_table, false>,
                                             al::inversion_method::hermite_table};
}  // namespace method_rows

namespace vocab::methods {
inline constexpr method hermite_table_polished{"hermite_table_polished", "u_of_s", "M", 0,
                                               "u(s): the Hermite table followed by one safeguarded Newton step"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr u_of_s_method hermite_table_polished{&vocab::methods::hermite_table_polished,
                                                      std::array{table_intervals}, true, table_intervals_series,
                                                      table_prepare<al::inversion_method::hermite_table, true>};

/// A u(s) table sized per segment to tol x L (setting tol), linear or Hermite: its size, status and
/// measured error are the table's (parameterization.hpp); its evaluations include the build.
template <al::inversion_method Method>
inline constexpr auto sized_table_prepare = [](const auto& c, const setting_values& v) {
  al::parameterization_options<double> o;
  o.method = Method;
  o.table_tolerance = value_of(v, "tol", "u(s) sized table");
  return table_run<Method, false>(c, o, true);
};

inline constexpr setting_def table_tol{"tol",
                                       "",
                                       1e-12,
                                       0,
                                       std::numeric_limits<double>::infinity(),
                                       false,
                                       "target of the table's measured |s(u) - s|, relative to L"};

}  // namespace method_rows

namespace vocab::methods {
inline constexpr method linear_table_sized{"linear_table_sized", "u_of_s", "tol", 0,
                                           "u(s): linear table sized per segment until its measured error is below "
                                           "tol x L, the worst segment halved first"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr u_of_s_method linear_table_sized{
    &vocab::methods::linear_table_sized, std::array{table_tol}, true,
    [](const sweep& w, double) { return series_of("tol", w.linear_table_tol); },
    sized_table_prepare<al::inversion_method::linear_table>};
}  // namespace method_rows

namespace vocab::methods {
inline constexpr method hermite_table_sized{"hermite_table_sized", "u_of_s", "tol", 0,
                                            "u(s): Hermite table sized per segment until its measured error is below "
                                            "tol x L, the worst segment halved first"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr u_of_s_method hermite_table_sized{
    &vocab::methods::hermite_table_sized, std::array{table_tol}, true,
    [](const sweep& w, double) { return series_of("tol", w.hermite_table_tol); },
    sized_table_prepare<al::inversion_method::hermite_table>};

}  // namespace method_rows

namespace vocab::methods {
inline constexpr method newton{"newton", "u_of_s", "tol", 0,
                               "u(s): Newton on s(u) - s from the segment bracket, no table, to a relative tolerance"};
}  // namespace vocab::methods

namespace method_rows {

inline constexpr u_of_s_method newton{
    &vocab::methods::newton,
    std::array{
        setting_def{"tol", "", 1e-12, 0, std::numeric_limits<double>::infinity(), false, "relative tolerance of s"}},
    true,
    [](const sweep& w, double) { return series_of("tol", w.newton_tol); },
    [](const auto& c, const setting_values& v) {
      using curve = std::decay_t<decltype(c)>;
      al::parameterization_options<double> o;
      o.method = al::inversion_method::newton;
      o.newton.relative_tolerance = value_of(v, "tol", "newton");
      const auto p = std::make_shared<const al::parameterization<curve>>(c, o);
      u_of_s_run r;
      r.length = p->length();
      r.construction_evaluations = static_cast<double>(p->construction_evaluations());
      r.query = [p](double s) {
        const auto q = p->invert(s, al::inversion_method::newton);
        return u_of_s_answer{q.u, q.s_error_estimate, static_cast<double>(q.evaluations), q.status,
                             al::to_text(q.reason)};
      };
      return r;
    },
    al::inversion_method::newton};

inline constexpr u_of_s_method forward_difference_u_of_s{
    &vocab::methods::forward_difference, std::array{steps_per_segment}, false, table_steps_series,
    [](const auto& c, const setting_values& v) {
      const auto t = std::make_shared<const al::forward_difference_table<double>>(
          c, static_cast<std::size_t>(value_of(v, "steps", "forward_difference")));
      u_of_s_run r;
      r.length = t->length().value;
      r.construction_evaluations = static_cast<double>(t->evaluations());
      r.query = [t](double s) {
        return u_of_s_answer{t->u(s), std::numeric_limits<double>::quiet_NaN(), 0, al::result_status::not_guaranteed,
                             std::string(al::reasons::chord_table_no_estimate)};
      };
      return r;
    }};

}  // namespace method_rows

/// The length methods, in the order of the records and benchmarks.
inline constexpr auto length_methods = std::tuple{method_rows::gauss,       method_rows::composite_gauss,
                                                  method_rows::adaptive_gk, method_rows::forward_difference,
                                                  method_rows::richardson,  method_rows::subdivision};

/// The u(s) methods, in the order of the records.
inline constexpr auto u_of_s_methods = std::tuple{method_rows::linear_table,
                                                  method_rows::hermite_table,
                                                  method_rows::hermite_table_polished,
                                                  method_rows::linear_table_sized,
                                                  method_rows::hermite_table_sized,
                                                  method_rows::newton,
                                                  method_rows::forward_difference_u_of_s};

/// Calls f(row) for every row of a table (length_methods, u_of_s_methods), in order.
template <class Table, class F>
void for_each_row(const Table& table, F&& f) {
  std::apply([&f](const auto&... row) { (f(row), ...); }, table);
}

/// Calls f(method, setting, run) for every length method (a vocab::method; its `theory` is the
/// convergence order in evaluations to fit over its series, 0 where none is fitted) and setting of
/// the sweep, in series: run() (which refers to c, so c must outlive it) computes the length of c
/// once and returns its quadrature_result. `length` scales the tolerances relative to the length
/// (run_context::reference_length).
template <class C, class F>
void for_each_length_method(const C& c, const sweep& w, double length, F&& f) {
  const double segments = static_cast<double>(c.breakpoints().size() - 1);
  run_context x;
  x.reference_length = length;
  for_each_row(length_methods, [&](const auto& row) {
    for (const setting_values& v : row.series(w, segments))
      f(*row.method, format_setting(row, v), row.prepare(c, v, x));
  });
}

}  // namespace curvebench::harness
