// curvebench: the command-line tool. main.cpp wires the subcommands and holds list, length,
// accuracy and gate; sample.cpp and check.cpp the two that take a user's parameters and values.
//   curvebench --version                                                                   version and git revision
//   curvebench list [families|tools|methods|cases|vocabulary] [--json]
//   curvebench sample SPEC.json [--count N] [--by u|arclength] [--method ...] [--ease ...]   CSV on stdout
//   curvebench sample SPEC.json --at V1,V2,... | --at-file FILE | --range A:B:STEP [--derivatives K]
//   curvebench check SPEC.json --values FILE [--lengths FILE] [--inverse FILE] [--name NAME]
//                    [--json] [--max-error X] [--thresholds FILE]                           your values vs 50 digits
//   curvebench length SPEC.json [--method ...] [--tol T] [--n N] [--panels P] [--steps N]    JSON on stdout
//   curvebench accuracy [--quick] [--cases DIR] [--out FILE] [--threads N]                 the accuracy runner
//   curvebench gate [--results FILE] [--thresholds FILE]                                   the CI gate
// Method ids are those of harness/vocabulary.hpp (`curvebench list vocabulary --json` prints it all).
// The case directory defaults to the installed share/curvebench/cases beside the executable
// (../share/curvebench/cases), else the source tree's bench/cases.
// Errors (bad spec, bad option) print "curvebench: error: ..." on stderr and exit with 1; usage
// errors exit with CLI11's code.
#include "tool/tool.hpp"

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

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;
namespace vocab = curvebench::harness::vocab;
namespace tool = curvebench::tool;

namespace {

/// The length methods `length --method` takes: every method of the vocabulary with length records.
std::vector<std::string> length_method_ids() {
  std::vector<std::string> ids;
  for (const vocab::method* m : vocab::all_methods)
    if (vocab::lists(m->quantities, vocab::quantities::length.id)) ids.emplace_back(m->id);
  return ids;
}

// ---- length ----------------------------------------------------------------------------------

struct length_args {
  std::string spec;
  std::string method{vocab::methods::adaptive_gk.id};
  double tol = 1e-12;
  int n = 5;
  int panels = 4;
  std::size_t steps = 256;
  bool quiet = false;
};

/// A curve that counts its evaluations and reports them as progress (`length` on a costly curve).
template <int Dim>
struct counted_curve {
  using real_type = double;
  using point_type = cb::point<double, Dim>;
  static constexpr int dimension = Dim;
  cb::any_curve<double, Dim> inner;
  std::shared_ptr<tool::progress> shown;
  std::shared_ptr<std::size_t> count = std::make_shared<std::size_t>(0);

  void tick() const {
    // The clock is read every 4096 evaluations, not on each.
    if ((++*count & 4095) == 0) shown->update(*count);
  }
  [[nodiscard]] cb::interval<double> domain() const { return inner.domain(); }
  [[nodiscard]] point_type operator()(double u) const {
    tick();
    return inner(u);
  }
  [[nodiscard]] point_type derivative(double u, int order) const {
    tick();
    return inner.derivative(u, order);
  }
  [[nodiscard]] std::span<const double> breakpoints() const { return inner.breakpoints(); }
  [[nodiscard]] double rounding_bound(int order) const { return inner.rounding_bound(order); }
};

template <int Dim>
void length(const cb::io::field& spec, const length_args& a) {
  const cb::any_curve<double, Dim> plain = cb::io::curve_from_spec<double, Dim>(spec);
  namespace m = vocab::methods;
  // Progress: evaluations against the method's budget (fixed rules: their exact count).
  const std::size_t segments = plain.breakpoints().size() - 1;
  std::size_t budget = 0;
  if (a.method == m::gauss.id)
    budget = 7 * static_cast<std::size_t>(a.n) * segments;
  else if (a.method == m::composite_gauss.id)
    budget = static_cast<std::size_t>(a.n) * static_cast<std::size_t>(a.panels) * segments;
  else if (a.method == m::adaptive_gk.id)
    budget = al::adaptive_options<double>{}.max_evaluations;
  else if (a.method == m::subdivision.id)
    budget = al::subdivision_options<double>{}.max_evaluations;
  else
    budget = a.steps * segments + 1;
  const cb::any_curve<double, Dim> c(
      counted_curve<Dim>{plain, std::make_shared<tool::progress>("length: evaluations (at most)", budget, a.quiet)},
      plain.family());
  // A fixed rule's cost is known before the work: refuse it above the limit, naming the options.
  auto check_cost = [&](const std::string& options, double evaluations) {
    if (evaluations > static_cast<double>(tool::max_length_evaluations))
      throw cb::invalid_input(options + ": " + std::to_string(segments) + (segments == 1 ? " segment" : " segments") +
                              " need " + cb::to_text(evaluations) + " evaluations, more than the limit of " +
                              std::to_string(tool::max_length_evaluations));
  };
  al::quadrature_result<double> r;
  if (a.method == m::gauss.id) {
    check_cost("--n " + std::to_string(a.n), 7.0 * a.n * static_cast<double>(segments));
    r = al::gauss_length(c, a.n, al::fixed_estimate::nested);
  } else if (a.method == m::composite_gauss.id) {
    check_cost("--n " + std::to_string(a.n) + " --panels " + std::to_string(a.panels),
               static_cast<double>(a.n) * a.panels * static_cast<double>(segments));
    r = al::composite_gauss_length(c, a.panels, al::gauss_legendre<double>(a.n));
  } else if (a.method == m::adaptive_gk.id) {
    al::adaptive_options<double> o;
    o.relative_tolerance = a.tol;
    r = al::adaptive_length(c, o);
  } else if (a.method == m::forward_difference.id || a.method == m::richardson.id) {
    if (a.steps > (al::max_forward_difference_evaluations - 1) / segments)
      throw cb::invalid_input("--steps " + std::to_string(a.steps) + ": " + std::to_string(segments) +
                              (segments == 1 ? " segment" : " segments") + " x " + std::to_string(a.steps) +
                              " steps is more than the limit of " +
                              std::to_string(al::max_forward_difference_evaluations) + " table nodes");
    const al::forward_difference_table<double> t(c, a.steps);
    r = a.method == m::richardson.id ? t.richardson_length() : t.length();
  } else if (a.method == m::subdivision.id) {
    al::subdivision_options<double> o;
    o.tolerance = 0;
    o.relative_tolerance = a.tol;  // relative to the curve's size (adaptive_subdivision.hpp)
    r = al::subdivision_length(c, o);
  } else {
    throw cb::invalid_input("--method " + a.method + ": not a length method");
  }
  tool::require_finite(r.value, spec.path + ": length (" + a.method + ")", c);
  // A length at most degenerate_length_eps eps of the curve's size (the largest |P| at its
  // breakpoints) is rounding noise: the true length may be 0, so the estimate covers that level.
  double size = 0;
  for (const double b : c.breakpoints()) size = std::max(size, c(b).cwiseAbs().maxCoeff());
  const double noise = al::degenerate_length_eps * std::numeric_limits<double>::epsilon() * size;
  if (std::isfinite(r.value) && std::abs(r.value) <= noise) {
    r.error_estimate = std::max(r.error_estimate, noise);
    r.status = r.value == 0 && r.status == al::result_status::converged ? r.status : al::result_status::rounding_limited;
  }
  nlohmann::json j{{"method", a.method},
                   {"value", r.value},
                   {"error_estimate", std::isfinite(r.error_estimate) ? nlohmann::json(r.error_estimate) : nlohmann::json()},
                   {"evaluations", r.evaluations},
                   {"status", std::string(al::to_string(r.status))}};
  std::cout << std::setw(2) << j << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"curvebench: accuracy and speed of keyframe-animation curves"};
  // Usage errors keep CLI11's exit codes but carry the same prefix as every other error.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("curvebench: error: ") + e.what() + "\nRun with --help for more information.\n";
  });
  app.require_subcommand(0, 1);
  bool version = false;
  app.add_flag("--version", version, "print the version and the git revision the tool was built from");
  app.footer(tool::example("curvebench sample bench/cases/arch_cubic_bezier.json --at 0,0.5,1 --derivatives 2"));

  std::string list_what = "all";
  bool list_json = false;
  auto* list =
      app.add_subcommand("list", "list curve families (spec types), keyframe tools, methods, cases or the vocabulary");
  list->add_option("what", list_what, "families, tools, methods, cases, vocabulary or all")
      ->check(CLI::IsMember({"families", "tools", "methods", "cases", "vocabulary", "all"}));
  list->add_flag("--json", list_json,
                 "vocabulary: as JSON (quantities, methods, peers, operations, counters, algorithms, tools)");
  std::string cases_dir = tool::default_cases_dir();
  list->add_option("--cases", cases_dir, "case directory (default " + cases_dir + ")")->check(CLI::ExistingDirectory);
  list->footer(tool::example("curvebench list families"));

  tool::sample_args sa;
  auto* samp = tool::add_sample(app, sa);

  tool::check_args ca;
  auto* chk = tool::add_check(app, ca);

  length_args la;
  auto* len = app.add_subcommand("length", "arc length of a curve spec: JSON value, error estimate, evaluations");
  len->add_option("spec", la.spec, "JSON curve spec")->required()->check(CLI::ExistingFile);
  const std::vector<std::string> length_ids = length_method_ids();
  std::string length_help;
  for (const auto& id : length_ids) length_help += (length_help.empty() ? "" : ", ") + id;
  len->add_option("--method", la.method, length_help)->check(CLI::IsMember(length_ids));
  const std::string limit = std::to_string(tool::max_length_evaluations);
  len->add_option("--tol", la.tol,
                  "relative tolerance (adaptive_gk: of the length; subdivision: of the curve's size, the polygon "
                  "through breakpoints and midpoints); adaptive_gk stops at 2^24 evaluations, subdivision at 2^22, with status cap_hit")
      ->check(tool::positive_finite());
  len->add_option("--n", la.n, "Gauss points per panel (gauss: n x 7 x segments evaluations, at most " + limit + ")")
      ->check(CLI::Range(1, 200));
  len->add_option("--panels", la.panels,
                  "panels per segment (composite_gauss: n x panels x segments evaluations, at most " + limit + ")")
      ->check(CLI::Range(1, 1000000));
  len->add_option("--steps", la.steps,
                  "table steps per segment (forward_difference, richardson: steps x segments, at most " +
                      std::to_string(al::max_forward_difference_evaluations) + ")")
      ->check(CLI::Range(1, 10000000));
  len->add_flag("--quiet", la.quiet,
                "no progress lines on stderr (evaluations against the method's budget, once a run takes over a second)");
  len->footer(tool::example("curvebench length arch.json --method gauss --n 8"));

  cb::harness::accuracy_options ao;
  ao.cases_dir = cases_dir;
  auto* acc = app.add_subcommand("accuracy", "run the accuracy sweep against 50-digit references");
  acc->add_flag("--quick", ao.quick, "fewer cases and settings (a few minutes)");
  acc->add_option("--cases", ao.cases_dir, "case directory (default " + cases_dir + ")")->check(CLI::ExistingDirectory);
  acc->add_option("--out", ao.out, "results JSON (a CSV is written beside it)");
  acc->add_option("--threads", ao.threads, "worker threads (0: all cores)");
  acc->add_option("--only", ao.only, "run only cases whose name contains this text");
  acc->add_flag("--quiet", ao.quiet, "no progress lines on stderr (case k of n, percent, elapsed)");
  acc->footer(tool::example("curvebench accuracy --quick --only helix --out reports/accuracy.json"));

  std::string results = "reports/accuracy.json", thresholds = tool::default_thresholds();
  auto* gate = app.add_subcommand("gate", "check accuracy results against thresholds; exit 1 naming every breach");
  gate->add_option("--results", results, "accuracy results (default reports/accuracy.json)")->check(CLI::ExistingFile);
  gate->add_option("--thresholds", thresholds,
                   "threshold rules (default reports/thresholds.json, else the installed share/curvebench/thresholds.json)")
      ->check(CLI::ExistingFile);
  gate->footer(tool::example("curvebench gate --results reports/accuracy.json --thresholds reports/thresholds.json"));

  CLI11_PARSE(app, argc, argv);
  if (version) {
    std::cout << tool::version_line() << "\n";
    return 0;
  }
  if (app.get_subcommands().empty()) {
    std::cerr << "curvebench: error: a subcommand is required (curvebench --help lists them)\n";
    return 1;
  }

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
      if (list_what == "tools" || list_what == "all" || list_what == "vocabulary") {
        std::cout << "tools (a channel spec's \"tool\"; name, storage bits, default time solver):\n";
        cb::io::for_each_tool([](auto t) {
          using T = typename decltype(t)::type;
          std::cout << "  " << std::left << std::setw(10) << T::name << std::setw(4)
                    << cb::channel::storage_bits_of<typename T::storage_type> << std::setw(16)
                    << cb::channel::to_string(T::default_solver) << T::summary << "\n";
        });
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
    if (*samp) {
      tool::run_sample(sa);
      return 0;
    }
    if (*chk) return tool::run_check(ca);
    if (*len) {
      const auto j = tool::read_spec(la.spec);
      const auto spec = cb::io::root(j, la.spec);
      tool::with_dimension(spec, [&](auto dim) { length<decltype(dim)::value>(spec, la); });
      return 0;
    }
    if (*acc) return cb::harness::run_accuracy(ao);
    if (*gate) {
      // io::parse names the file in a syntax error and refuses deep nesting and repeated keys;
      // check_gate names it for a malformed structure.
      const auto r = cb::io::parse(tool::read_file(results), results);
      const auto t = cb::io::parse(tool::read_file(thresholds), thresholds);
      const auto breaches = cb::harness::check_gate(r, t, results, thresholds);
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
