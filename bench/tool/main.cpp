// curvebench: the command-line tool.
//   curvebench list [families|methods|cases|vocabulary] [--json]
//   curvebench sample SPEC.json [--count N] [--by u|arclength] [--method ...] [--ease ...]   CSV on stdout
//   curvebench length SPEC.json [--method ...] [--tol T] [--n N] [--panels P] [--steps N]    JSON on stdout
//   curvebench accuracy [--quick] [--cases DIR] [--out FILE] [--threads N]                 the accuracy runner
//   curvebench gate [--results FILE] [--thresholds FILE]                                   the CI gate
// Method ids are those of harness/vocabulary.hpp (`curvebench list vocabulary --json` prints it all).
// Errors (bad spec, bad option) print "curvebench: error: ..." on stderr and exit with 1; usage
// errors exit with CLI11's code.
#include "harness/accuracy.hpp"
#include "harness/cases.hpp"
#include "harness/gate.hpp"
#include "harness/vocabulary.hpp"
#include "harness/vocabulary_json.hpp"

#include "curvebench/arclength/adaptive_subdivision.hpp"
#include "curvebench/arclength/forward_difference.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/motion/distance_time.hpp"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;
namespace vocab = curvebench::harness::vocab;

namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw cb::invalid_input(path + ": cannot be read");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// ---- ease ------------------------------------------------------------------------------------

using ease_fn = std::variant<cb::motion::linear_ease<double>, cb::motion::sine_ease<double>,
                             cb::motion::smoothstep_ease<double>, cb::motion::smootherstep_ease<double>,
                             cb::motion::sine_plateau_ease<double>, cb::motion::parabolic_ease<double>>;

/// "linear", "sine", "smoothstep", "smootherstep", "sine_plateau:T1,T2", "parabolic:T1,T2".
ease_fn parse_ease(const std::string& text) {
  const auto colon = text.find(':');
  const std::string name = text.substr(0, colon);
  double t1 = 0, t2 = 1;
  if (name == "sine_plateau" || name == "parabolic") {
    if (colon == std::string::npos || std::sscanf(text.c_str() + colon + 1, "%lf,%lf", &t1, &t2) != 2)
      throw cb::invalid_input("--ease " + text + ": " + name + " needs its phases, e.g. " + name + ":0.25,0.75");
    if (name == "sine_plateau") return cb::motion::sine_plateau_ease<double>(t1, t2);
    return cb::motion::parabolic_ease<double>(t1, t2);
  }
  if (colon != std::string::npos) throw cb::invalid_input("--ease " + text + ": " + name + " takes no parameters");
  if (name == "linear") return cb::motion::linear_ease<double>();
  if (name == "sine") return cb::motion::sine_ease<double>();
  if (name == "smoothstep") return cb::motion::smoothstep_ease<double>();
  if (name == "smootherstep") return cb::motion::smootherstep_ease<double>();
  throw cb::invalid_input("--ease " + text +
                          ": not one of linear, sine, smoothstep, smootherstep, sine_plateau:T1,T2, parabolic:T1,T2");
}

/// The u(s) methods `sample --method` takes (the hermite_table_polished of the records is
/// hermite_table with --polish).
constexpr const vocab::method* sample_methods[] = {&vocab::methods::linear_table, &vocab::methods::hermite_table,
                                                   &vocab::methods::newton};

/// The length methods `length --method` takes: every method of the vocabulary with length records.
std::vector<std::string> length_method_ids() {
  std::vector<std::string> ids;
  for (const vocab::method* m : vocab::all_methods)
    if (vocab::lists(m->quantities, vocab::quantities::length.id)) ids.emplace_back(m->id);
  return ids;
}

al::inversion_method parse_inversion(const std::string& m) {
  if (m == vocab::methods::linear_table.id) return al::inversion_method::linear_table;
  if (m == vocab::methods::hermite_table.id) return al::inversion_method::hermite_table;
  if (m == vocab::methods::newton.id) return al::inversion_method::newton;
  throw cb::invalid_input("--method " + m + ": not a u(s) method of sample");
}

// ---- sample ----------------------------------------------------------------------------------

struct sample_args {
  std::string spec;
  std::size_t count = 11;
  std::string by = "u";
  std::string method{vocab::methods::hermite_table.id};
  bool polish = false;
  std::string ease = "linear";
};

template <int Dim>
void sample(const cb::io::field& spec, const sample_args& a) {
  const cb::any_curve<double, Dim> c = cb::io::curve_from_spec<double, Dim>(spec);
  al::parameterization_options<double> opt;
  opt.method = parse_inversion(a.method);
  opt.newton_polish = a.polish;
  const al::parameterization<cb::any_curve<double, Dim>> param(c, opt);
  const ease_fn ease = parse_ease(a.ease);
  const auto dom = c.domain();
  std::cout << "u,s";
  const char* names[] = {"x", "y", "z", "w"};
  for (int d = 0; d < Dim; ++d) std::cout << "," << names[d];
  for (int d = 0; d < Dim; ++d) std::cout << ",d" << names[d];
  std::cout << "\n" << std::setprecision(17);
  const double L = param.length();
  for (std::size_t i = 0; i < a.count; ++i) {
    const double f = a.count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(a.count - 1);
    double u = 0, s = 0;
    if (a.by == "u") {
      u = i + 1 == a.count ? dom.hi : dom.lo + f * (dom.hi - dom.lo);
      s = param.s(u);
    } else {
      s = std::visit([&](const auto& e) { return e(f); }, ease) * L;
      if (s > L) s = L;  // S(1) = 1 exactly, but S(f) * L may round past L by one ulp
      u = param.u(s);
    }
    const cb::point<double, Dim> p = c(u);
    const cb::point<double, Dim> dp = c.derivative(u, 1);
    std::cout << u << "," << s;
    for (int d = 0; d < Dim; ++d) std::cout << "," << p[d];
    for (int d = 0; d < Dim; ++d) std::cout << "," << dp[d];
    std::cout << "\n";
  }
}

// ---- length ----------------------------------------------------------------------------------

struct length_args {
  std::string spec;
  std::string method{vocab::methods::adaptive_gk.id};
  double tol = 1e-12;
  int n = 5;
  int panels = 4;
  std::size_t steps = 256;
};

template <int Dim>
void length(const cb::io::field& spec, const length_args& a) {
  const cb::any_curve<double, Dim> c = cb::io::curve_from_spec<double, Dim>(spec);
  namespace m = vocab::methods;
  al::quadrature_result<double> r;
  if (a.method == m::gauss.id) {
    r = al::gauss_length(c, a.n, al::fixed_estimate::nested);
  } else if (a.method == m::composite_gauss.id) {
    r = al::composite_gauss_length(c, a.panels, al::gauss_legendre<double>(a.n));
  } else if (a.method == m::adaptive_gk.id) {
    al::adaptive_options<double> o;
    o.relative_tolerance = a.tol;
    r = al::adaptive_length(c, o);
  } else if (a.method == m::forward_difference.id || a.method == m::richardson.id) {
    const al::forward_difference_table<double> t(c, a.steps);
    r = a.method == m::richardson.id ? t.richardson_length() : t.length();
  } else if (a.method == m::subdivision.id) {
    al::subdivision_options<double> o;
    o.tolerance = a.tol;
    r = al::subdivision_length(c, o);
  } else {
    throw cb::invalid_input("--method " + a.method + ": not a length method");
  }
  nlohmann::json j{{"method", a.method},
                   {"value", r.value},
                   {"error_estimate", std::isfinite(r.error_estimate) ? nlohmann::json(r.error_estimate) : nlohmann::json()},
                   {"evaluations", r.evaluations},
                   {"status", std::string(al::to_string(r.status))}};
  std::cout << std::setw(2) << j << "\n";
}

template <class F>
void with_dimension(const cb::io::field& spec, F&& f) {
  switch (cb::io::spec_dimension(spec)) {
    case 1: f(std::integral_constant<int, 1>{}); break;
    case 2: f(std::integral_constant<int, 2>{}); break;
    case 3: f(std::integral_constant<int, 3>{}); break;
    default: f(std::integral_constant<int, 4>{}); break;
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"curvebench: accuracy and speed of keyframe-animation curves"};
  app.require_subcommand(1);

  std::string list_what = "all";
  bool list_json = false;
  auto* list = app.add_subcommand("list", "list curve families (spec types), methods, cases or the vocabulary");
  list->add_option("what", list_what, "families, methods, cases, vocabulary or all")
      ->check(CLI::IsMember({"families", "methods", "cases", "vocabulary", "all"}));
  list->add_flag("--json", list_json, "vocabulary: as JSON (quantities, methods, peers, operations, counters)");
  std::string cases_dir = CURVEBENCH_CASES_DIR;
  list->add_option("--cases", cases_dir, "case directory")->check(CLI::ExistingDirectory);

  sample_args sa;
  auto* samp = app.add_subcommand("sample", "sample a curve spec: CSV of u, s, point, first derivative");
  samp->add_option("spec", sa.spec, "JSON curve spec")->required()->check(CLI::ExistingFile);
  samp->add_option("--count", sa.count, "number of samples")->check(CLI::Range(1, 100000000));
  samp->add_option("--by", sa.by, "spacing: equal steps in u, or in arc length (with --ease)")
      ->check(CLI::IsMember({"u", "arclength"}));
  std::vector<std::string> sample_ids;
  for (const vocab::method* m : sample_methods) sample_ids.emplace_back(m->id);
  samp->add_option("--method", sa.method, "u(s) method for --by arclength")->check(CLI::IsMember(sample_ids));
  samp->add_flag("--polish", sa.polish, "one Newton step after a table lookup");
  samp->add_option("--ease", sa.ease,
                   "distance-time function for --by arclength: linear, sine, smoothstep, smootherstep, "
                   "sine_plateau:T1,T2, parabolic:T1,T2");

  length_args la;
  auto* len = app.add_subcommand("length", "arc length of a curve spec: JSON value, error estimate, evaluations");
  len->add_option("spec", la.spec, "JSON curve spec")->required()->check(CLI::ExistingFile);
  const std::vector<std::string> length_ids = length_method_ids();
  std::string length_help;
  for (const auto& id : length_ids) length_help += (length_help.empty() ? "" : ", ") + id;
  len->add_option("--method", la.method, length_help)->check(CLI::IsMember(length_ids));
  len->add_option("--tol", la.tol, "tolerance (adaptive: relative; subdivision: absolute)")->check(CLI::PositiveNumber);
  len->add_option("--n", la.n, "Gauss points per panel")->check(CLI::Range(1, 200));
  len->add_option("--panels", la.panels, "panels per segment (composite_gauss)")->check(CLI::Range(1, 1000000));
  len->add_option("--steps", la.steps, "table steps per segment (forward_difference)")->check(CLI::Range(1, 10000000));

  cb::harness::accuracy_options ao;
  ao.cases_dir = CURVEBENCH_CASES_DIR;
  auto* acc = app.add_subcommand("accuracy", "run the accuracy sweep against 50-digit references");
  acc->add_flag("--quick", ao.quick, "fewer cases and settings (a few minutes)");
  acc->add_option("--cases", ao.cases_dir, "case directory")->check(CLI::ExistingDirectory);
  acc->add_option("--out", ao.out, "results JSON (a CSV is written beside it)");
  acc->add_option("--threads", ao.threads, "worker threads (0: all cores)");
  acc->add_option("--only", ao.only, "run only cases whose name contains this text");

  std::string results = "reports/accuracy.json", thresholds = "reports/thresholds.json";
  auto* gate = app.add_subcommand("gate", "check accuracy results against thresholds; exit 1 naming every breach");
  gate->add_option("--results", results)->check(CLI::ExistingFile);
  gate->add_option("--thresholds", thresholds)->check(CLI::ExistingFile);

  CLI11_PARSE(app, argc, argv);

  try {
    if (*list) {
      if (list_what == "vocabulary" && list_json) {
        std::cout << std::setw(1) << cb::harness::vocabulary_json() << "\n";
        return 0;
      }
      if (list_json) throw cb::invalid_input("list " + list_what + " --json: only the vocabulary is listed as JSON");
      if (list_what == "families" || list_what == "all") {
        std::cout << "families (spec types):\n";
        for (const cb::io::family_descriptor& f : cb::io::families())
          std::cout << "  " << std::left << std::setw(18) << f.type << f.summary << "\n"
                    << "  " << std::setw(18) << "" << "fields: " << cb::io::fields_line(f) << "\n";
      }
      if (list_what == "methods" || list_what == "all") {
        std::cout << "methods (length --method takes those with length records; sample --method linear_table, "
                     "hermite_table, newton):\n";
        for (const vocab::method* m : vocab::all_methods) {
          std::cout << "  " << std::left << std::setw(24) << m->id << std::setw(28)
                    << std::string(m->quantities) << std::setw(12)
                    << (m->settings.empty() ? std::string("-") : std::string(m->settings)) << m->doc << "\n";
        }
      }
      if (list_what == "vocabulary") {
        std::cout << "quantities:\n";
        for (const vocab::quantity* q : vocab::all_quantities)
          std::cout << "  " << std::left << std::setw(24) << q->id << q->doc << "\n";
        std::cout << "methods:\n";
        for (const vocab::method* m : vocab::all_methods)
          std::cout << "  " << std::left << std::setw(24) << m->id << m->doc << "\n";
        std::cout << "peers:\n";
        for (const vocab::peer* p : vocab::all_peers)
          std::cout << "  " << std::left << std::setw(36) << p->id << p->library << ": " << p->doc << "\n";
        std::cout << "operations:\n";
        for (const vocab::operation* o : vocab::all_operations)
          std::cout << "  " << std::left << std::setw(24) << o->id << o->doc << "\n";
        std::cout << "counters:\n";
        for (const vocab::counter* c : vocab::all_counters)
          std::cout << "  " << std::left << std::setw(24) << c->name << std::setw(10) << c->kind << c->doc << "\n";
      }
      if (list_what == "cases" || list_what == "all") {
        std::cout << "cases (" << cases_dir << "):\n";
        for (const auto& c : cb::harness::load_cases(cases_dir))
          std::cout << "  " << std::left << std::setw(34) << c.name << std::setw(12) << c.group << c.reason << "\n";
      }
      return 0;
    }
    if (*samp || *len) {
      const std::string path = *samp ? sa.spec : la.spec;
      const auto j = cb::io::parse(read_file(path), path);
      const auto spec = cb::io::root(j, path);
      with_dimension(spec, [&](auto dim) {
        if (*samp)
          sample<decltype(dim)::value>(spec, sa);
        else
          length<decltype(dim)::value>(spec, la);
      });
      return 0;
    }
    if (*acc) return cb::harness::run_accuracy(ao);
    if (*gate) {
      const auto r = nlohmann::json::parse(read_file(results));
      const auto t = nlohmann::json::parse(read_file(thresholds));
      const auto breaches = cb::harness::check_gate(r, t);
      for (const auto& b : breaches) std::cout << "gate: BREACH " << b.rule << " " << b.where << ": " << b.message << "\n";
      std::cout << "gate: " << t.at("rules").size() << " rules, " << breaches.size() << " breaches\n";
      return breaches.empty() ? 0 : 1;
    }
  } catch (const std::exception& e) {
    std::cerr << "curvebench: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
