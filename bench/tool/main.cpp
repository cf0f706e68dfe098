// curvebench: the command-line tool. main.cpp wires the subcommands and holds list, length,
// accuracy and gate; sample.cpp and check.cpp the two that take a user's parameters and values.
//   curvebench --version                                                                   version and git revision
//   curvebench list [families|tools|methods|cases|vocabulary] [--json]
//   curvebench sample SPEC.json [--count N] [--by u|arclength] [--method ...] [--ease ...]   CSV on stdout
//   curvebench sample SPEC.json --at V1,V2,... | --at-file FILE | --range A:B:STEP [--derivatives K]
//   curvebench check SPEC.json --values FILE [--lengths FILE] [--inverse FILE] [--name NAME]
//                    [--json] [--max-error X] [--thresholds FILE]                           your values vs 50 digits
//   curvebench length SPEC.json [--method ...] [--tol T] [--n N] [--estimate nested|none] [--panels P]
//                    [--steps N]                                                            JSON on stdout
//   curvebench accuracy [--quick] [--cases DIR] [--out FILE] [--threads N]                 the accuracy runner
//   curvebench gate [--results FILE] [--thresholds FILE]                                   the CI gate
//   curvebench compare BASE NEW [--json] [--max-error-growth X] [--max-time-growth X]      two runs compared
// Method ids are those of harness/vocabulary.hpp (`curvebench list vocabulary --json` prints it all).
// The case directory defaults to the installed share/curvebench/cases beside the executable
// (../share/curvebench/cases), else the source tree's bench/cases.
// Errors (bad spec, bad option) print "curvebench: error: ..." on stderr and exit with 1; usage
// errors exit with CLI11's code.
#include "tool/tool.hpp"

#include "harness/accuracy.hpp"
#include "harness/cases.hpp"
#include "harness/files.hpp"
#include "harness/gate.hpp"
#include "harness/length_methods.hpp"
#include "harness/peers.hpp"
#include "harness/vocabulary.hpp"
#include "harness/vocabulary_json.hpp"

#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/io/families/svg_path.hpp"
#include "curvebench/io/spec.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <vector>

namespace cb = curvebench;
namespace al = curvebench::arclength;
namespace vocab = curvebench::harness::vocab;
namespace tool = curvebench::tool;

namespace {

namespace h = curvebench::harness;

/// The length methods `length --method` takes: the rows of the length table.
std::vector<std::string> length_method_ids() {
  std::vector<std::string> ids;
  h::for_each_row(h::length_methods, [&](const auto& row) { ids.emplace_back(row.method->id); });
  return ids;
}

// ---- length ----------------------------------------------------------------------------------

/// One option of `length`: a setting the length table's rows give a CLI option, once however many
/// rows share it (they share its default and limits: test_harness checks it).
struct length_option {
  const h::setting_def* def = nullptr;
  std::string help;  ///< each row's help, "method: help; method: help"
  double real = 0;
  long long integer = 0;
  const CLI::Option* cli = nullptr;  ///< the option as the command line has it (given or not)
  [[nodiscard]] double value() const { return def->integer ? static_cast<double>(integer) : real; }
  [[nodiscard]] bool given() const { return cli != nullptr && cli->count() > 0; }
};

/// The options of `length`, in the order of the table's rows and settings.
std::vector<length_option> length_options() {
  std::vector<length_option> out;
  h::for_each_row(h::length_methods, [&](const auto& row) {
    for (const h::setting_def& d : row.settings) {
      if (d.option.empty()) continue;
      auto it = std::find_if(out.begin(), out.end(), [&](const length_option& o) { return o.def->option == d.option; });
      if (it == out.end()) {
        out.push_back(length_option{&d, {}, d.fallback, static_cast<long long>(d.fallback)});
        it = out.end() - 1;
      }
      it->help += (it->help.empty() ? "" : "; ") + std::string(row.method->id) + ": " + std::string(d.help);
    }
  });
  return out;
}

struct length_args {
  std::string spec;
  std::string svg;  ///< --svg FILE: every path and shape of an SVG file instead of a spec
  std::string id;   ///< --id: only the element with this id
  std::string method{vocab::methods::adaptive_gk.id};
  std::vector<length_option> options = length_options();
  /// gauss's estimate (not a setting of the records, which run gauss nested: run_context's
  /// gauss_estimate); "" when --estimate is not given.
  std::string estimate;
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
  [[nodiscard]] point_type value_from_left(double u) const {
    tick();
    return inner.value_from_left(u);
  }
  [[nodiscard]] std::span<const double> breakpoints() const { return inner.breakpoints(); }
  [[nodiscard]] double rounding_bound(int order) const { return inner.rounding_bound(order); }
};

/// The length of the polygon of a Bezier spec's "points" (in double; none when it is not finite or
/// the points are not Dim numbers each: the reader has refused such a spec already).
template <int Dim>
std::optional<double> control_polygon_length(const nlohmann::json& spec) {
  if (!spec.contains("points") || !spec["points"].is_array()) return std::nullopt;
  const nlohmann::json& pts = spec["points"];
  double total = 0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    cb::point<double, Dim> d;
    for (int k = 0; k < Dim; ++k) {
      const nlohmann::json &a = pts[i], &b = pts[i + 1];
      if (!a.is_array() || !b.is_array() || a.size() != Dim || b.size() != Dim || !a[k].is_number() ||
          !b[k].is_number())
        return std::nullopt;
      d[k] = b[k].get<double>() - a[k].get<double>();
    }
    total += cb::safe_norm(d);
  }
  if (!std::isfinite(total)) return std::nullopt;
  return total;
}

/// The length output of `spec` by the method and options of `a`. check_only: everything that
/// refuses the request before the work (the curve, the method's options, its cost), without measuring.
template <int Dim>
nlohmann::json length(const cb::io::field& spec, const length_args& a, bool check_only = false) {
  const cb::any_curve<double, Dim> plain = cb::io::curve_from_spec<double, Dim>(spec);
  const std::size_t segments = plain.breakpoints().size() - 1;
  bool found = false;
  nlohmann::json out;
  h::for_each_row(h::length_methods, [&](const auto& row) {
    if (row.method->id != a.method) return;
    found = true;
    // An option of another method would be ignored: refused, naming the method's own.
    for (const length_option& o : a.options) {
      if (!o.given()) continue;
      const bool own = std::any_of(row.settings.begin(), row.settings.end(),
                                   [&](const h::setting_def& d) { return d.option == o.def->option; });
      if (own) continue;
      std::string mine;
      for (const h::setting_def& d : row.settings)
        if (!d.option.empty()) mine += (mine.empty() ? "" : ", ") + std::string(d.option);
      throw cb::invalid_input(std::string(o.def->option) + " does not apply to --method " + a.method + " (" +
                              (mine.empty() ? "it takes no options" : "its options: " + mine) + ")");
    }
    const bool is_gauss = row.method == &vocab::methods::gauss;
    if (!a.estimate.empty() && !is_gauss)
      throw cb::invalid_input("--estimate " + a.estimate + " does not apply to --method " + a.method +
                              " (only gauss takes it)");
    h::run_context ctx;
    if (a.estimate == "none") ctx.gauss_estimate = al::fixed_estimate::none;
    h::setting_values v;
    for (const h::setting_def& d : row.settings) {
      const auto o = std::find_if(a.options.begin(), a.options.end(), [&](const length_option& x) {
        return !d.option.empty() && x.def->option == d.option;
      });
      v[std::string(d.key)] = o == a.options.end() ? d.fallback : o->value();
    }
    // Progress: evaluations against the method's budget (fixed rules: their exact count). A cost
    // known before the work is refused above its limit, naming the options.
    const h::length_cost cost =
        is_gauss ? h::method_rows::gauss_cost(v, segments, ctx.gauss_estimate) : row.cost(v, segments);
    if (check_only) {
      if (!cost.refusal.empty()) throw cb::invalid_input(spec.path + ": " + cost.refusal);
      return;
    }
    const cb::any_curve<double, Dim> c(
        counted_curve<Dim>{plain, std::make_shared<tool::progress>(
                                      cost.at_most ? "length: evaluations (at most)" : "length: evaluations (planned)",
                                      cost.budget, a.quiet, !cost.at_most)},
        plain.family());
    if (!cost.refusal.empty()) throw cb::invalid_input(cost.refusal);
    al::quadrature_result<double> r = row.prepare(c, v, ctx)();
    if (!row.estimate) r.error_estimate = std::numeric_limits<double>::quiet_NaN();
    tool::require_finite(r.value, spec.path + ": length (" + a.method + ")", c);
    // A length is at least the chords between consecutive breakpoints (each segment's end from the
    // left: a jump adds none). A result without a bound that falls short of them is certainly wrong
    // (the method's nodes missed where the curve moves: rational weights spanning 1e20 put the whole
    // length within 1e-20 of the ends): refused, never printed with exit code 0. 1e-9 of slack: the
    // chords are evaluated in double too, and a result that close is not the garbage meant here.
    if (r.status == al::result_status::not_guaranteed) {
      const std::span<const double> bp = plain.breakpoints();
      double chords = 0;
      for (std::size_t i = 0; i + 1 < bp.size(); ++i)
        chords += cb::safe_norm(cb::point<double, Dim>(cb::value_from_left(plain, bp[i + 1]) - plain(bp[i])));
      if (std::isfinite(chords) && r.value < chords * (1 - 1e-9))
        throw cb::invalid_input(spec.path + ": length (" + a.method + ") " + cb::to_text(r.value) +
                                " is shorter than the chords between the curve's breakpoints, " + cb::to_text(chords) +
                                ": the method missed where the curve moves and has no bound to say so (" +
                                al::to_text(r.reason) + ")");
    }
    // A Bezier curve, rational with positive weights too, is no longer than its control polygon
    // (subdivision's new points are convex combinations of the old: each level's polygon is no
    // longer, and the polygons converge to the curve). A result without a bound beyond it is
    // certainly wrong (weights of 1e-300 on subnormal coordinates underflow in double).
    if (r.status == al::result_status::not_guaranteed && spec.value.is_object() && spec.value.contains("type") &&
        (spec.value["type"] == "bezier" || spec.value["type"] == "rational_bezier")) {
      const std::optional<double> polygon = control_polygon_length<Dim>(spec.value);
      if (polygon && r.value > *polygon * (1 + 1e-9))
        throw cb::invalid_input(spec.path + ": length (" + a.method + ") " + cb::to_text(r.value) +
                                " is longer than the curve's control polygon, " + cb::to_text(*polygon) +
                                ": the method's double evaluation lost the curve and has no bound to say so (" +
                                al::to_text(r.reason) + ")");
    }
    // A length at most degenerate_length_eps eps of the curve's size (the largest |P| at its
    // breakpoints) is rounding noise: the true length may be 0, so the estimate covers that level.
    // A result without a bound (not_guaranteed, null) keeps none: rounding_limited carries an estimate.
    double size = 0;
    for (const double b : c.breakpoints()) size = std::max(size, c(b).cwiseAbs().maxCoeff());
    const double noise = al::degenerate_length_eps * std::numeric_limits<double>::epsilon() * size;
    if (std::isfinite(r.value) && std::abs(r.value) <= noise && r.status != al::result_status::not_guaranteed) {
      r.error_estimate = std::max(r.error_estimate, noise);
      if (!(r.value == 0 && r.status == al::result_status::converged)) {
        r.status = al::result_status::rounding_limited;
        r.reason = al::global_reason<double>(al::reasons::noise_length, std::abs(r.value), noise);
      }
    }
    nlohmann::json j{
        {"method", a.method},
        {"value", r.value},
        {"estimate", std::isfinite(r.error_estimate) ? nlohmann::json(r.error_estimate) : nlohmann::json()},
        {"evaluations", r.evaluations},
        {"status", std::string(al::to_string(r.status))},
        {"reason",
         r.status == al::result_status::converged ? nlohmann::json() : nlohmann::json(al::to_text(r.reason))}};
    out = std::move(j);
  });
  if (!found) throw cb::invalid_input("--method " + a.method + ": not a length method");
  return out;
}

/// The subpaths of path data d as JSON, absolute and explicit, for programs that take segments
/// rather than path data (the native arc-length peers): [{"start": [x, y], "closed",
/// "segments": [{"kind": "line" | "quadratic" | "cubic" | "arc", "points": its 2 to 4 control
/// points (an arc's two ends), and for an arc "rx", "ry", "rotation" (degrees), "large", "sweep" as
/// written and "center": its centre form in double (cx, cy, rx, ry after the out-of-range
/// correction, phi radians, theta1, dtheta)}]}]. A closed subpath's closing line, when not of zero
/// length, is its last segment.
nlohmann::json segments_json(const std::string& d) {
  namespace svg = cb::io::svg;
  nlohmann::json out = nlohmann::json::array();
  for (const svg::subpath& sp : svg::parse_path(d)) {
    nlohmann::json segs = nlohmann::json::array();
    for (const svg::segment& s : sp.segments) {
      nlohmann::json pts = nlohmann::json::array();
      for (int i = 0; i < s.points; ++i)
        pts.push_back({s.p[static_cast<std::size_t>(i)].x, s.p[static_cast<std::size_t>(i)].y});
      static constexpr const char* kinds[] = {"line", "quadratic", "cubic", "arc"};
      nlohmann::json j{{"kind", kinds[static_cast<int>(s.kind)]}, {"points", std::move(pts)}};
      if (s.kind == svg::segment_kind::arc) {
        // At 50 digits, then rounded: each number is the nearest double to the arc's own (in double,
        // a start angle near -pi/2 would carry an error of 1e-16 radians beside a sweep of 1e-19).
        const svg::arc_center<cb::real50> c50 = svg::center_form<cb::real50>(s);
        const auto to_double = [](const cb::real50& x) {
          const double v = static_cast<double>(x);
          if (!std::isfinite(v))
            throw cb::invalid_input("svg arc: its centre form " + cb::to_text(x) + " is past double's range");
          return v;
        };
        const svg::arc_center<double> c{to_double(c50.cx),     to_double(c50.cy),  to_double(c50.rx),
                                        to_double(c50.ry),     to_double(c50.phi), to_double(c50.theta1),
                                        to_double(c50.dtheta), to_double(c50.ux),  to_double(c50.uy)};
        j.update({{"rx", s.arc.rx},
                  {"ry", s.arc.ry},
                  {"rotation", s.arc.rotation},
                  {"large", s.arc.large},
                  {"sweep", s.arc.sweep},
                  {"center",
                   {{"cx", c.cx},
                    {"cy", c.cy},
                    {"rx", c.rx},
                    {"ry", c.ry},
                    {"phi", c.phi},
                    {"theta1", c.theta1},
                    {"dtheta", c.dtheta}}}});
      }
      segs.push_back(std::move(j));
    }
    out.push_back({{"start", {sp.start.x, sp.start.y}}, {"closed", sp.closed}, {"segments", std::move(segs)}});
  }
  return out;
}

/// `length --svg FILE [--id ID]`: a JSON array, one object per path or shape of the file (or the
/// one with the id), each the length output of its svg_path spec with its element, id and index,
/// the path data measured and its segments (segments_json). Everything that refuses the file (its
/// XML, an element, the method's options or cost on any element) is checked before the first
/// element is measured; then each element is printed as it is measured (the array is never held
/// whole), so that an error that only the measurement finds leaves an unterminated array on stdout,
/// which no JSON reader takes for a result, and exit code 1.
void length_of_svg(const length_args& a) {
  tool::svg_document doc = tool::read_svg_elements(a.svg);
  std::vector<tool::svg_element>& elements = doc.elements;
  if (!a.id.empty()) {
    const auto it =
        std::find_if(elements.begin(), elements.end(), [&](const tool::svg_element& e) { return e.id == a.id; });
    if (it == elements.end()) {
      std::string ids;
      std::size_t shown = 0;
      for (const auto& e : elements)
        if (!e.id.empty() && shown++ < 20) ids += (ids.empty() ? "" : ", ") + cb::validate::visible(e.id);
      throw cb::invalid_input("--id " + cb::validate::visible(a.id) + ": no path or shape of " + a.svg +
                              " has this id (" + (ids.empty() ? std::string("none has an id") : "ids: " + ids) + ")");
    }
    elements = {std::move(*it)};
  }
  for (const tool::svg_element& e : elements) length<2>(cb::io::root(e.spec, e.where), a, true);
  if (doc.skipped && !a.quiet)
    std::cerr << "curvebench: note: " << a.svg << ": " << doc.skipped << " <path> or shape element"
              << (doc.skipped == 1 ? " is" : "s are") << " not in the SVG namespace (" << tool::svg_namespace
              << ") and not measured; the first: " << doc.first_skipped << "\n";
  // The array as `std::setw(2) << json` prints it: each element's lines indented by two more.
  std::cout << "[\n";
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const tool::svg_element& e = elements[i];
    const cb::io::field spec = cb::io::root(e.spec, e.where);
    nlohmann::json j{{"element", e.element}, {"id", e.id}, {"index", e.index}, {"segments", segments_json(e.d)}};
    j["d"] = e.d;
    j.update(length<2>(spec, a));
    std::string text = "  " + j.dump(2);
    for (std::size_t k = text.find('\n'); k != std::string::npos; k = text.find('\n', k + 3)) text.insert(k + 1, "  ");
    std::cout << text << (i + 1 < elements.size() ? ",\n" : "\n");
  }
  std::cout << "]\n";
}

}  // namespace

namespace {

int run(int argc, char** argv) {
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

  tool::fidelity_args fa;
  auto* fid = tool::add_fidelity(app, fa);
  tool::compare_args cma;
  auto* cmp = tool::add_compare(app, cma);

  length_args la;
  auto* len = app.add_subcommand(
      "length",
      "arc length of a curve spec: JSON value, estimate (absolute, in the curve's length units: a bound of |value - L| "
      "unless the status is not_guaranteed, when it is null), evaluations, status, reason (why the status is not "
      "converged: the failed bound or the cap, the segment and parameter interval where the method knows them, the "
      "quantity against its bound; null when converged)");
  len->add_option("spec", la.spec, "JSON curve spec (or --svg)")->check(CLI::ExistingFile);
  len->add_option("--svg", la.svg,
                  "an SVG file instead of a spec: the length of every <path> and basic shape (circle, ellipse, rect, "
                  "line, polyline, polygon) in document order, as a JSON array with each one's element, id, "
                  "index and the path data measured (a shape's: the path SVG 2 defines for it); transforms are not "
                  "applied (SVG's getTotalLength measures in the element's own units)")
      ->check(CLI::ExistingFile);
  len->add_option("--id", la.id, "with --svg: only the path or shape with this id")->check(tool::non_empty());
  const std::vector<std::string> length_ids = length_method_ids();
  std::string length_help;
  for (const auto& id : length_ids) length_help += (length_help.empty() ? "" : ", ") + id;
  len->add_option("--method", la.method, length_help)->check(CLI::IsMember(length_ids));
  for (length_option& o : la.options) {
    const h::setting_def& d = *o.def;
    if (d.integer) {
      o.cli = len->add_option(std::string(d.option), o.integer, o.help)
                  ->capture_default_str()
                  ->check(CLI::Range(static_cast<long long>(d.min), static_cast<long long>(d.max)));
    } else {
      auto* opt = len->add_option(std::string(d.option), o.real, o.help)->capture_default_str();
      if (d.min == 0 && d.max == std::numeric_limits<double>::infinity())
        opt->check(tool::positive_finite());
      else
        opt->check(CLI::Range(d.min, d.max));
      o.cli = opt;
    }
  }
  len->add_option("--estimate", la.estimate,
                  "gauss: nested (default: the rule on 1, 2 and 4 panels per piece, converged with a bound when the "
                  "order test passes) or none (the benchmarks' fast fixed rule, n evaluations per segment: it carries "
                  "no estimate, status not_guaranteed, estimate null)")
      ->check(CLI::IsMember({"nested", "none"}));
  len->add_flag(
      "--quiet", la.quiet,
      "no progress lines on stderr (evaluations against the method's budget, once a run takes over a second)");
  len->footer(tool::example("curvebench length bench/cases/arch_cubic_bezier.json --method gauss --n 8"));

  cb::harness::accuracy_options ao;
  ao.peers = &cb::harness::library_peers();  // GSL, Boost.Math and Eigen beside curvebench's methods
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
  gate->add_option(
          "--thresholds", thresholds,
          "threshold rules (default reports/thresholds.json, else the installed share/curvebench/thresholds.json)")
      ->check(CLI::ExistingFile);
  gate->footer(tool::example("curvebench gate --results reports/accuracy.json --thresholds reports/thresholds.json"));

  // An empty value refused by every option that takes one, naming it: `--ease ''` ran as linear,
  // `--threads ''` on all cores, `check --name ''` wrote records of method "" (found by a sweep). The
  // validator has no name, so the help's types stay as they are.
  const CLI::Validator given(
      [](std::string& text) { return text.empty() ? std::string("an empty value") : std::string(); }, "");
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    for (CLI::Option* o : sub->get_options([](CLI::Option* opt) { return opt->get_type_size_min() > 0; }))
      o->check(given);

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
        for (const cb::io::family_descriptor& f : cb::io::families()) {
          std::cout << "  " << std::left << std::setw(18) << f.type << f.summary << "\n"
                    << "  " << std::setw(18) << ""
                    << "fields: " << cb::io::fields_line(f) << "\n";
          if (f.type != "channel") continue;
          std::string names;
          cb::io::for_each_tool(
              [&](auto t) { names += (names.empty() ? "" : ", ") + std::string(decltype(t)::type::name); });
          std::cout << "  " << std::setw(18) << ""
                    << "tools: " << names
                    << " (curvebench list tools: each model's rules and what it is verified against)\n";
        }
      }
      if (list_what == "tools" || list_what == "all" || list_what == "vocabulary") {
        std::cout << "tools (a channel spec's \"tool\"; name, storage bits, default time solver):\n";
        cb::io::for_each_tool([](auto t) {
          using T = typename decltype(t)::type;
          std::cout << "  " << std::left << std::setw(10) << T::name << std::setw(4)
                    << cb::channel::storage_bits_of<typename T::storage_type> << std::setw(16)
                    << cb::channel::to_string(T::default_solver) << T::summary << "\n"
                    << "  " << std::setw(30) << ""
                    << "verification: " << T::verification << "\n";
        });
      }
      if (list_what == "methods" || list_what == "all") {
        std::cout << "methods (length --method takes those with length records; sample --method linear_table, "
                     "hermite_table, newton):\n";
        for (const vocab::method* m : vocab::all_methods()) {
          std::cout << "  " << std::left << std::setw(24) << m->id << std::setw(28) << std::string(m->quantities)
                    << std::setw(12) << (m->settings.empty() ? std::string("-") : std::string(m->settings)) << m->doc
                    << "\n";
        }
      }
      if (list_what == "vocabulary") {
        std::cout << "quantities:\n";
        for (const vocab::quantity* q : vocab::all_quantities)
          std::cout << "  " << std::left << std::setw(24) << q->id << q->doc << "\n";
        std::cout << "methods:\n";
        for (const vocab::method* m : vocab::all_methods())
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
        // Columns as wide as their longest entry: a long name never runs into its group.
        const auto cases = cb::harness::load_cases(cases_dir);
        std::size_t name_w = 0, group_w = 0;
        for (const auto& c : cases)
          name_w = std::max(name_w, c.name.size()), group_w = std::max(group_w, c.group.size());
        for (const auto& c : cases)
          std::cout << "  " << std::left << std::setw(static_cast<int>(name_w + 2)) << c.name
                    << std::setw(static_cast<int>(group_w + 2)) << c.group << c.reason << "\n";
      }
      return 0;
    }
    if (*samp) {
      tool::run_sample(sa);
      return 0;
    }
    if (*chk) return tool::run_check(ca);
    if (*fid) return tool::run_fidelity(fa);
    if (*cmp) return tool::run_compare(cma);
    if (*len) {
      if (la.spec.empty() == la.svg.empty())
        throw cb::invalid_input(la.spec.empty() ? "length: give a spec file or --svg FILE"
                                                : "length: give a spec file or --svg FILE, not both");
      if (!la.id.empty() && la.svg.empty()) throw cb::invalid_input("length: --id selects an element of --svg FILE");
      if (!la.svg.empty()) {
        length_of_svg(la);
        return 0;
      }
      const auto j = tool::read_spec(la.spec);
      const auto spec = cb::io::root(j, la.spec);
      tool::with_dimension(
          spec, [&](auto dim) { std::cout << std::setw(2) << length<decltype(dim)::value>(spec, la) << "\n"; });
      return 0;
    }
    if (*acc) return cb::harness::run_accuracy(ao);
    if (*gate) {
      // io::parse names the file in a syntax error and refuses deep nesting and repeated keys;
      // check_gate names it for a malformed structure.
      const auto r = cb::io::parse(cb::harness::read_input_file(results, "", cb::harness::max_results_bytes), results);
      const auto t = cb::io::parse(tool::read_file(thresholds), thresholds);
      const auto breaches = cb::harness::check_gate(r, t, results, thresholds);
      for (const auto& b : breaches)
        std::cout << "gate: BREACH " << b.rule << " " << b.where << ": " << b.message << "\n";
      std::cout << "gate: " << t.at("rules").size() << " rules, " << breaches.size() << " breaches\n";
      if (!breaches.empty()) tool::say_verdict("gate", breaches.size(), "breach", "breaches");
      return breaches.empty() ? 0 : 1;
    }
  } catch (const std::exception& e) {
    std::cerr << "curvebench: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const int status = run(argc, argv);
  // Output the system did not take (a full disk, stdout on /dev/full) is an error, not a silently
  // truncated file with exit 0.
  std::cout.flush();
  if (!std::cout) {
    std::cerr << "curvebench: error: writing the standard output failed (a full disk or device): the output is "
                 "incomplete\n";
    return status == 0 ? 1 : status;
  }
  return status;
}
