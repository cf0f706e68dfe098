// The accuracy runner (see harness/accuracy.hpp). This is the one translation unit that
// instantiates every family at 50 digits; keep it that way, it is the slow one to compile.
#include "harness/accuracy.hpp"
#include "harness/audit_table.hpp"
#include "harness/sweep.hpp"

#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>

namespace curvebench::harness {

namespace {

using json = nlohmann::json;
namespace al = curvebench::arclength;

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();
// Orders are fitted where the error is above the rounding floor of double (~1e-13 relative once
// summed over many panels) and below 1e-2 (pre-asymptotic region).
constexpr double order_floor = 1e-12;
constexpr double order_ceiling = 1e-2;

json finite_or_null(double x) { return std::isfinite(x) ? json(x) : json(); }


/// Collects the records of one case.
struct sink {
  explicit sink(const case_info& info) : c(info) {}
  const case_info& c;
  json records = json::array();
  json orders = json::array();
  std::vector<std::pair<double, double>> series;  // (cost, error) of the current sweep

  /// estimate: relative to L, NaN when the method gives none (infinite estimates are "none" too).
  void add(const std::string& quantity, const std::string& method, const std::string& setting, double error,
           double estimate, double evaluations, std::string_view status) {
    json r{{"case", c.name},       {"group", c.group},         {"quantity", quantity},
           {"method", method},     {"setting", setting},       {"error", finite_or_null(error)},
           {"estimate", finite_or_null(estimate)}, {"evaluations", evaluations}, {"status", std::string(status)}};
    r["bounded"] = std::isfinite(estimate) && std::isfinite(error) ? json(estimate >= error) : json();
    records.push_back(std::move(r));
    series.emplace_back(evaluations, error);
  }

  void begin() { series.clear(); }

  /// Closes a sweep: records the fitted order when at least 3 points lie in the fitting window.
  void end(const std::string& quantity, const std::string& method, double theory) {
    const double order = fit_order(series, order_floor, order_ceiling);
    if (std::isfinite(order))
      orders.push_back({{"case", c.name},
                        {"group", c.group},
                        {"quantity", quantity},
                        {"method", method},
                        {"observed", order},
                        {"theory", theory}});
    series.clear();
  }
};

template <int Dim>
using curve_d = any_curve<double, Dim>;
template <int Dim>
using curve_q = any_curve<real50, Dim>;

double rel(const real50& value, const real50& exact) {
  using std::abs;
  return static_cast<double>(abs(value - exact) / exact);
}

/// n sample fractions in [0, 1]: 0, 1 and the golden-ratio sequence frac(j / phi) in between.
/// The points are spread evenly but never on a uniform grid, so they do not coincide with the
/// nodes of the tables being measured (which would measure the table's exact nodes, not its error).
std::vector<double> sample_fractions(std::size_t n) {
  std::vector<double> f(n);
  const double inv_phi = 0.6180339887498949;  // 1 / golden ratio
  for (std::size_t j = 0; j < n; ++j) f[j] = j == 0 ? 0.0 : j + 1 == n ? 1.0 : std::fmod(static_cast<double>(j) * inv_phi, 1.0);
  return f;
}

/// |value - exact| / L for a double value and a 50-digit exact value.
double rel_abs(double value, const real50& exact, double L) {
  using std::abs;
  return static_cast<double>(abs(real50(value) - exact)) / L;
}

template <int Dim>
void lengths(sink& k, const curve_d<Dim>& c, const real50& L, const sweep& w) {
  const double Ld = static_cast<double>(L);
  std::string current;  // the method whose series is open
  double current_theory = 0;
  const auto close = [&] {
    if (current_theory > 0)
      k.end("length", current, current_theory);
    else
      k.begin();
  };
  k.begin();
  for_each_length_method(c, w, Ld, [&](const std::string& method, const std::string& setting, double theory, auto run) {
    if (method != current) {
      close();
      current = method;
      current_theory = theory;
    }
    const auto r = run();
    k.add("length", method, setting, rel(r.value, L), r.error_estimate / Ld, static_cast<double>(r.evaluations),
          al::to_string(r.status));
  });
  close();
}

template <int Dim>
void s_of_u(sink& k, const curve_d<Dim>& c, const std::vector<double>& us, const std::vector<real50>& s_ref,
            const real50& L, const sweep& w) {
  const double segments = static_cast<double>(c.breakpoints().size() - 1);
  const double Ld = static_cast<double>(L);
  {
    al::parameterization_options<double> o;
    o.method = al::inversion_method::newton;  // no table: s(u) uses the segment lengths only
    const al::parameterization<curve_d<Dim>> p(c, o);
    double err = 0, est = 0, evals = 0;
    for (std::size_t j = 0; j < us.size(); ++j) {
      const auto r = p.s_result(us[j]);
      err = std::max(err, rel_abs(r.value, s_ref[j], Ld));
      est = std::max(est, r.error_estimate / Ld);
      evals += static_cast<double>(r.evaluations);
    }
    k.add("s_of_u", "segments_adaptive", "default", err, est,
          evals / static_cast<double>(us.size()) + static_cast<double>(p.construction_evaluations()) / amortized_queries,
          al::to_string(p.length_result().status));
  }
  k.begin();
  for (std::size_t steps : w.table_steps) {
    if (static_cast<double>(steps) * segments > w.max_table_evals) break;
    const al::forward_difference_table<double> t(c, steps);
    double err = 0;
    for (std::size_t j = 0; j < us.size(); ++j) err = std::max(err, rel_abs(t.s(us[j]), s_ref[j], Ld));
    k.add("s_of_u", "forward_difference", "steps=" + std::to_string(steps), err, nan_value,
          static_cast<double>(t.evaluations()) / amortized_queries, "not_guaranteed");
  }
  k.end("s_of_u", "forward_difference", 2);
}

template <int Dim>
void u_of_s(sink& k, const curve_d<Dim>& c, const reference::reference_arc_length<curve_q<Dim>>& ref, const sweep& w) {
  const real50 L = ref.length();
  const double Ld = static_cast<double>(L);
  std::vector<double> targets = sample_fractions(w.params);
  for (double& t : targets) t = std::min(Ld * t, Ld);
  // |s(u) - s_j| / L with the exact s of the returned parameter. The first answer for a target
  // is integrated from the reference's splits; every later one (all methods' answers lie near the
  // same u*) from that anchor, one short panel, unless a split lies between them. Not enough for
  // degree-20 Runge on equispaced nodes: inaccurate answers there cross its many splits, and each
  // 50-digit s(u) on that curve costs seconds (its full sweep runs over 10 minutes).
  std::map<double, std::pair<real50, real50>> anchors;  // target -> (u, s(u))
  const auto ds = [&](double u, double s) {
    using std::abs;
    const interval<double> d = c.domain();
    const real50 uq(std::clamp(u, d.lo, d.hi));
    const auto it = anchors.find(s);
    const real50 su = it == anchors.end() ? ref.s(uq) : it->second.second + ref.s_between(it->second.first, uq);
    if (it == anchors.end()) anchors.emplace(s, std::make_pair(uq, su));
    return static_cast<double>(abs(su - real50(s)) / L);
  };
  // theory = 0: no algebraic order to fit (the polished table converges as fast as Newton does).
  const auto table_sweep = [&](al::inversion_method m, bool polish, const std::string& name, double theory) {
    k.begin();
    for (std::size_t intervals : w.table_intervals) {
      al::parameterization_options<double> o;
      o.method = m;
      o.table_intervals = intervals;
      o.newton_polish = polish;
      const al::parameterization<curve_d<Dim>> p(c, o);
      double err = 0, est = 0, query = 0;
      for (double target : targets) {
        // The target may exceed this method's own L by an ulp of rounding; u(s) rejects s > L.
        const double s = std::min(target, p.length());
        if (polish) {
          const auto r = p.invert(s, m);
          err = std::max(err, ds(r.u, target));
          est = std::max(est, r.s_error_estimate / Ld);
          query += static_cast<double>(r.evaluations);
        } else {
          err = std::max(err, ds(p.u(s, m), target));
        }
      }
      if (!polish) est = m == al::inversion_method::hermite_table ? p.table_error() / Ld : nan_value;
      k.add("u_of_s", name, "M=" + std::to_string(intervals), err, est,
            query / static_cast<double>(targets.size()) +
                static_cast<double>(p.construction_evaluations()) / amortized_queries,
            al::to_string(p.table_status()));
    }
    if (theory > 0)
      k.end("u_of_s", name, theory);
    else
      k.begin();
  };
  table_sweep(al::inversion_method::linear_table, false, "linear_table", 2);
  table_sweep(al::inversion_method::hermite_table, false, "hermite_table", 4);
  table_sweep(al::inversion_method::hermite_table, true, "hermite_table_polished", 0);
  for (double tol : w.newton_tol) {
    al::parameterization_options<double> o;
    o.method = al::inversion_method::newton;
    o.newton.relative_tolerance = tol;
    const al::parameterization<curve_d<Dim>> p(c, o);
    double err = 0, est = 0, query = 0;
    std::string status = "converged";
    for (double target : targets) {
      const auto r = p.invert(std::min(target, p.length()), al::inversion_method::newton);
      err = std::max(err, ds(r.u, target));
      est = std::max(est, r.s_error_estimate / Ld);
      query += static_cast<double>(r.evaluations);
      if (r.status != al::result_status::converged) status = al::to_string(r.status);
    }
    k.add("u_of_s", "newton", "tol=" + fmt(tol), err, est,
          query / static_cast<double>(targets.size()) +
              static_cast<double>(p.construction_evaluations()) / amortized_queries,
          status);
  }
  const double segments = static_cast<double>(c.breakpoints().size() - 1);
  k.begin();
  for (std::size_t steps : w.table_steps) {
    if (static_cast<double>(steps) * segments > w.max_table_evals) break;
    const al::forward_difference_table<double> t(c, steps);
    double err = 0;
    for (double target : targets) err = std::max(err, ds(t.u(std::min(target, t.length().value)), target));
    k.add("u_of_s", "forward_difference", "steps=" + std::to_string(steps), err, nan_value,
          static_cast<double>(t.evaluations()) / amortized_queries, "not_guaranteed");
  }
  k.end("u_of_s", "forward_difference", 2);
}

/// Evaluation error of each algorithm the family offers, in eps(double) x the curve's size.
template <int Dim>
void evaluation(sink& k, const curve_d<Dim>& c, const curve_q<Dim>& q, const sweep& w, const json& spec) {
  const interval<double> d = c.domain();
  std::vector<double> us = sample_fractions(w.eval_params);
  for (double& u : us) u = u == 1.0 ? d.hi : d.lo + (d.hi - d.lo) * u;
  std::vector<point<real50, Dim>> exact(us.size());
  real50 scale(0);
  for (std::size_t j = 0; j < us.size(); ++j) {
    exact[j] = q(real50(us[j]));
    for (int i = 0; i < Dim; ++i) {
      using std::abs;
      scale = std::max(scale, real50(abs(exact[j][i])));
    }
  }
  if (!(scale > 0)) scale = 1;
  const auto measure = [&](const std::string& method, auto&& eval) {
    real50 worst(0);
    for (std::size_t j = 0; j < us.size(); ++j) {
      const point<double, Dim> p = eval(us[j]);
      for (int i = 0; i < Dim; ++i) {
        using std::abs;
        worst = std::max(worst, real50(abs(real50(p[i]) - exact[j][i])));
      }
    }
    k.add("eval", method, c.family(), static_cast<double>(worst / (scale * real50(epsilon<double>()))), nan_value,
          static_cast<double>(us.size()), "ok");
  };
  measure("default", [&](double u) { return c(u); });
  if (const auto* b = c.template target<bezier<double, Dim>>()) {
    for (auto a : {bezier_algorithm::de_casteljau, bezier_algorithm::bernstein_sum, bezier_algorithm::horner})
      measure(to_string(a), [&](double u) { return b->evaluate(u, a); });
  }
  const auto cubic = [&](const auto* f) {
    if (!f) return;
    for (auto a : {cubic_algorithm::power, cubic_algorithm::matrix, cubic_algorithm::bezier})
      measure(to_string(a), [&](double u) { return f->engine().evaluate(u, 0, a); });
  };
  cubic(c.template target<cardinal_spline<double, Dim>>());
  cubic(c.template target<hermite_spline<double, Dim>>());
  cubic(c.template target<kochanek_bartels<double, Dim>>());
  cubic(c.template target<natural_cubic_spline<double, Dim>>());
  const auto spline = [&](const auto* f) {
    if (!f) return;
    for (auto a : {bspline_evaluation::de_boor, bspline_evaluation::basis_sum})
      measure(to_string(a), [&](double u) { return f->evaluate(u, 0, a); });
  };
  spline(c.template target<bspline<double, Dim>>());
  spline(c.template target<nurbs<double, Dim>>());
  if (c.family() == "lagrange") {  // the algorithm is fixed at construction: build both from the spec
    for (const char* a : {"barycentric", "monomial"}) {
      json twin = spec;
      twin["algorithm"] = a;
      const curve_d<Dim> t = io::curve_from_spec<double, Dim>(io::root(twin));
      measure(a, [&](double u) { return t(u); });
    }
  }
}

/// Seed 001's properties measured on a 2D case (up to 40 control points): the family is rebuilt from
/// the spec with each perturbed set of points (Hermite slopes enter as tangent items), so any
/// family and any user case can be audited. Returns the markdown row, or null when not audited.
json audit(const case_info& info) {
  static constexpr std::string_view point_families[] = {"polyline", "lagrange", "bezier", "rational_bezier",
                                                        "cardinal", "catmull_rom", "kochanek_bartels",
                                                        "natural_cubic", "bspline", "nurbs", "hermite"};
  const io::field spec = io::root(info.spec, info.name);
  const std::string type = spec.member("type").string();
  if (std::find(std::begin(point_families), std::end(point_families), type) == std::end(point_families)) return {};
  if (!spec.has("points") || spec.member("points").value.is_object() || spec.member("points").array_size() > 40)
    return {};
  const bool hermite = type == "hermite";
  if (hermite && !spec.has("slopes")) return {};
  point_list<double, 2> items = spec.member("points").points<double, 2>();
  const std::size_t n = items.size();
  std::vector<analysis::control_role> roles(n, analysis::control_role::point);
  if (hermite) {
    const point_list<double, 2> slopes = spec.member("slopes").points<double, 2>();
    items.insert(items.end(), slopes.begin(), slopes.end());
    roles.resize(items.size(), analysis::control_role::tangent);
  }
  const auto build = [&](std::span<const point<double, 2>> it) {
    json s = info.spec;
    s["points"] = io::detail::points_json<2>(it.first(n));
    if (hermite) s["slopes"] = io::detail::points_json<2>(it.subspan(n));
    return io::curve_from_spec<double, 2>(io::root(s, info.name));
  };
  try {
    const auto r = analysis::audit_properties<double, 2>(build, std::span<const point<double, 2>>(items), roles);
    return audit_markdown_row(info.name + " (" + type + ")", r);
  } catch (const invalid_input& e) {
    // Some families constrain their data (a periodic spline's last point equals its first), so
    // moving one control point alone is not a valid curve: the audit does not apply; say why.
    return "| " + info.name + " (" + type + ") | not audited: " + e.what() + " | | | | | |\n";
  }
}

template <int Dim>
json run_dim(const case_info& info, bool quick) {
  const auto t0 = std::chrono::steady_clock::now();
  const sweep w = settings(quick);
  const io::field spec = io::root(info.spec, info.name);
  const curve_d<Dim> c = io::curve_from_spec<double, Dim>(spec);
  const curve_q<Dim> q = io::curve_from_spec<real50, Dim>(spec);
  const reference::reference_arc_length<curve_q<Dim>> ref(q);
  const real50 L = ref.length();
  sink k(info);
  lengths<Dim>(k, c, L, w);
  const interval<double> d = c.domain();
  std::vector<double> us = sample_fractions(w.params);
  std::vector<real50> s_ref(w.params);
  for (std::size_t j = 0; j < us.size(); ++j) {
    us[j] = us[j] == 1.0 ? d.hi : d.lo + (d.hi - d.lo) * us[j];
    s_ref[j] = ref.s(real50(us[j]));
  }
  s_of_u<Dim>(k, c, us, s_ref, L, w);
  u_of_s<Dim>(k, c, ref, w);
  evaluation<Dim>(k, c, q, w, info.spec);
  json properties;
  if constexpr (Dim == 2) properties = audit(info);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::ostringstream length_text;
  length_text << std::setprecision(40) << L;
  return {{"records", k.records},
          {"orders", k.orders},
          {"case",
           {{"name", info.name},
            {"group", info.group},
            {"reason", info.reason},
            {"family", c.family()},
            {"dimension", Dim},
            {"segments", c.breakpoints().size() - 1},
            {"reference_length", length_text.str()},
            {"reference_error", static_cast<double>(ref.length_error() / L)},
            {"speed_minima", ref.speed_minima().size()},
            {"properties", properties},
            {"seconds", seconds}}}};
}

void write_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp);
    if (!out) throw invalid_input("--out " + path + ": cannot be written");
    out << text;
  }
  std::filesystem::rename(tmp, path);
}

std::string csv(const json& records) {
  std::ostringstream os;
  os << std::setprecision(17) << "case,group,quantity,method,setting,error,estimate,bounded,evaluations,status\n";
  for (const auto& r : records) {
    const auto cell = [](const json& v) -> std::string {
      if (v.is_null()) return "";
      if (v.is_string()) return v.get<std::string>();
      return v.dump();
    };
    os << cell(r["case"]) << "," << cell(r["group"]) << "," << cell(r["quantity"]) << "," << cell(r["method"]) << ","
       << cell(r["setting"]) << "," << cell(r["error"]) << "," << cell(r["estimate"]) << "," << cell(r["bounded"])
       << "," << cell(r["evaluations"]) << "," << cell(r["status"]) << "\n";
  }
  return os.str();
}

}  // namespace

double fit_order(const std::vector<std::pair<double, double>>& cost_error, double floor, double ceiling) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const auto& [cost, err] : cost_error) {
    if (!(err > floor && err < ceiling && cost > 0)) continue;
    const double x = std::log(cost), y = std::log(err);
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++n;
  }
  if (n < 3) return nan_value;
  const double denom = n * sxx - sx * sx;
  if (!(denom > 0)) return nan_value;
  return -(n * sxy - sx * sy) / denom;
}

json run_case(const case_info& c, bool quick) {
  switch (c.dimension) {
    case 2: return run_dim<2>(c, quick);
    case 3: return run_dim<3>(c, quick);
    default:
      throw invalid_input(c.file + ": the accuracy runner takes 2D and 3D cases, this one is " +
                          std::to_string(c.dimension) + "D");
  }
}

int run_accuracy(const accuracy_options& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<case_info> all = load_cases(opt.cases_dir);
  std::vector<case_info> cases;
  for (auto& c : all)
    if ((opt.only.empty() || c.name.find(opt.only) != std::string::npos) && !(opt.quick && !c.quick))
      cases.push_back(std::move(c));
  if (cases.empty()) throw invalid_input("--only " + opt.only + ": no case matches");
  // The most expensive cases first, so that the cores stay busy to the end.
  std::vector<std::size_t> order(cases.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return !cases[a].quick && cases[b].quick; });
  std::vector<json> results(cases.size());
  std::vector<std::string> failures(cases.size());
  std::atomic<std::size_t> next{0}, done{0};
  std::mutex print;
  const unsigned threads =
      std::max(1u, std::min<unsigned>(opt.threads ? opt.threads : std::thread::hardware_concurrency(),
                                      static_cast<unsigned>(cases.size())));
  const auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < order.size();) {
      const case_info& c = cases[order[i]];
      try {
        results[order[i]] = run_case(c, opt.quick);
      } catch (const std::exception& e) {
        failures[order[i]] = c.name + ": " + e.what();
      }
      const std::lock_guard<std::mutex> lock(print);
      const std::size_t k = ++done;
      std::cerr << "accuracy: [" << k << "/" << cases.size() << "] " << c.name
                << (failures[order[i]].empty() ? "" : " FAILED: " + failures[order[i]]) << " ("
                << std::setprecision(3)
                << (results[order[i]].is_null() ? 0.0 : results[order[i]]["case"]["seconds"].get<double>()) << " s)\n";
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();

  json out{{"schema", 1},
           {"suite", {{"name", suite_name}, {"version", suite_version}, {"cases", cases.size()}}},
           {"records", json::array()},
           {"orders", json::array()},
           {"cases", json::array()}};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (!failures[i].empty()) continue;
    for (auto& r : results[i]["records"]) out["records"].push_back(std::move(r));
    for (auto& o : results[i]["orders"]) out["orders"].push_back(std::move(o));
    out["cases"].push_back(results[i]["case"]);
  }
  const char* revision = std::getenv("CURVEBENCH_REVISION");
  out["context"] = {{"revision", revision ? revision : "unknown"},
                    {"compiler", std::string("g++ ") + __VERSION__},
                    {"flags", CURVEBENCH_FLAGS},
                    {"quick", opt.quick},
                    {"threads", threads},
                    {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()}};
  std::filesystem::create_directories(std::filesystem::path(opt.out).parent_path().empty()
                                          ? std::filesystem::path(".")
                                          : std::filesystem::path(opt.out).parent_path());
  write_atomic(opt.out, out.dump(1) + "\n");
  std::string csv_path = opt.out;
  if (csv_path.size() > 5 && csv_path.ends_with(".json")) csv_path.resize(csv_path.size() - 5);
  write_atomic(csv_path + ".csv", csv(out["records"]));
  std::size_t failed = 0;
  for (const auto& f : failures)
    if (!f.empty()) {
      std::cerr << "accuracy: case failed: " << f << "\n";
      ++failed;
    }
  std::cerr << "accuracy: " << out["records"].size() << " records, " << out["orders"].size() << " orders from "
            << cases.size() - failed << " cases in " << std::setprecision(3)
            << out["context"]["seconds"].get<double>() << " s -> " << opt.out << "\n";
  return failed == 0 ? 0 : 1;
}

}  // namespace curvebench::harness
