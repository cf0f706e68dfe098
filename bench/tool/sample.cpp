// curvebench sample: a spec's points (and derivatives) at equally spaced u, at equal arc-length
// steps through a distance-time function, or at the parameters a user gives (--at, --at-file,
// --range), as CSV on stdout with the column names `curvebench check --values` reads back.
#include "tool/tool.hpp"

#include "harness/check.hpp"
#include "harness/check_detail.hpp"

#include "harness/csv.hpp"
#include "harness/length_methods.hpp"
#include "harness/vocabulary.hpp"

#include "curvebench/arclength/parameterization.hpp"
#include "curvebench/channel/channel.hpp"
#include "curvebench/io/spec_data.hpp"
#include "curvebench/motion/distance_time.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <variant>

namespace curvebench::tool {

namespace {

namespace al = curvebench::arclength;
namespace vocab = curvebench::harness::vocab;
using harness::parse_finite;
using harness::quote_cell;

using ease_fn =
    std::variant<motion::linear_ease<double>, motion::sine_ease<double>, motion::smoothstep_ease<double>,
                 motion::smootherstep_ease<double>, motion::sine_plateau_ease<double>, motion::parabolic_ease<double>>;

/// "linear", "sine", "smoothstep", "smootherstep", "sine_plateau:T1,T2", "parabolic:T1,T2". The
/// phases are exactly two finite numbers: trailing text or a third value is an error, not ignored.
ease_fn parse_ease(const std::string& given) {
  const std::string text = given.empty() ? "linear" : given;  // the default
  const auto colon = text.find(':');
  const std::string name = text.substr(0, colon);
  if (name == "sine_plateau" || name == "parabolic") {
    const std::string where = "--ease " + quote_cell(text) + ": ";
    const std::string expected = "expected " + name + ":T1,T2 with two finite numbers, e.g. " + name + ":0.25,0.75";
    if (colon == std::string::npos) throw invalid_input(where + name + " needs its phases: " + expected);
    const std::vector<std::string> phases = split(text.substr(colon + 1), ',');
    if (phases.size() != 2)
      throw invalid_input(where + std::to_string(phases.size()) + (phases.size() == 1 ? " phase" : " phases") +
                          " given, " + expected);
    double t[2] = {0, 0};
    for (std::size_t i = 0; i < 2; ++i)
      if (!parse_finite(phases[i], t[i]))
        throw invalid_input(where + "phase T" + std::to_string(i + 1) + " " + quote_cell(phases[i]) +
                            " is not a finite number, " + expected);
    // The ease's own refusals (t2 < t1, a phase outside [0, 1]) name the option and its phases.
    try {
      if (name == "sine_plateau") return motion::sine_plateau_ease<double>(t[0], t[1]);
      return motion::parabolic_ease<double>(t[0], t[1]);
    } catch (const invalid_input& x) {
      throw invalid_input(where + "phases T1 " + quote_cell(phases[0]) + ", T2 " + quote_cell(phases[1]) + ": " +
                          x.what());
    }
  }
  if (colon != std::string::npos)
    throw invalid_input("--ease " + quote_cell(text) + ": " + name + " takes no parameters");
  if (name == "linear") return motion::linear_ease<double>();
  if (name == "sine") return motion::sine_ease<double>();
  if (name == "smoothstep") return motion::smoothstep_ease<double>();
  if (name == "smootherstep") return motion::smootherstep_ease<double>();
  throw invalid_input("--ease " + quote_cell(text) +
                      ": not one of linear, sine, smoothstep, smootherstep, sine_plateau:T1,T2, parabolic:T1,T2");
}

/// The u(s) methods `sample --method` takes: the rows of the method table that name a
/// parameterization method (the records' hermite_table_polished is hermite_table with --polish).
std::vector<std::pair<std::string, al::inversion_method>> sample_methods() {
  std::vector<std::pair<std::string, al::inversion_method>> out;
  harness::for_each_row(harness::u_of_s_methods, [&](const auto& row) {
    if (row.sample_method) out.emplace_back(std::string(row.method->id), *row.sample_method);
  });
  return out;
}

al::inversion_method parse_inversion(const std::string& given) {
  const std::string m = given.empty() ? std::string(vocab::methods::hermite_table.id) : given;  // the default
  for (const auto& [id, method] : sample_methods())
    if (id == m) return method;
  throw invalid_input("--method " + m + ": not a u(s) method of sample");
}

/// One value per line, or a CSV whose header names the parameter's column (u, or t for a channel
/// spec: the CSV `sample` writes); its other columns are ignored, lines starting with # too.
std::vector<parameter> parse_at_file(const std::string& path, const std::string& name) {
  std::string text = read_file(path);
  if (text.starts_with("\xEF\xBB\xBF")) text.erase(0, 3);  // a UTF-8 byte order mark, as editors on Windows write
  std::vector<parameter> out;
  std::size_t line_no = 0, u_column = std::string::npos, columns = 1;
  bool first = true;
  for (const std::string& raw : split(text, '\n')) {
    ++line_no;
    std::string line = raw;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first_char = line.find_first_not_of(" \t");
    if (first_char == std::string::npos || line[first_char] == '#') continue;
    const std::string row = "--at-file " + path + ": row " + std::to_string(line_no);
    const std::vector<std::string> cells = split(line, ',');
    double u = 0;
    if (first) {
      first = false;
      if (!parse_finite(cells[0], u)) {  // a header
        columns = cells.size();
        for (std::size_t c = 0; c < cells.size(); ++c) {
          const auto b = cells[c].find_first_not_of(" \t"), e = cells[c].find_last_not_of(" \t");
          const std::string cell = b == std::string::npos ? "" : cells[c].substr(b, e - b + 1);
          if (cell != name) continue;
          if (u_column != std::string::npos)
            throw invalid_input(row + ": the header names the " + name + " column twice (columns " +
                                std::to_string(u_column + 1) + " and " + std::to_string(c + 1) + ")");
          u_column = c;
        }
        if (u_column == std::string::npos)
          throw invalid_input(row + ": " + quote_cell(line) + " is neither a finite number nor a CSV header naming a " +
                              name + " column" +
                              (name == "t" ? " (this spec is a channel: its parameter is time t)" : ""));
        continue;
      }
      u_column = 0;
    }
    if (cells.size() != columns)
      throw invalid_input(row + ": " + std::to_string(cells.size()) + " values, expected " + std::to_string(columns) +
                          (columns == 1 ? " (one value per line)" : " (as many as the header names)"));
    const std::string where = row + (columns > 1 ? ", column " + name : "");
    if (!parse_finite(cells[u_column], u))
      throw invalid_input(where + ": " + quote_cell(cells[u_column]) + " is not a finite number");
    out.push_back({u, where});
    check_count(out.size(), "--at-file " + path);
  }
  if (out.empty()) throw invalid_input("--at-file " + path + ": no values (the file is empty or a header only)");
  return out;
}

/// The shortest text that reads back as x (std::to_chars): the time column prints 0.3, not
/// 0.29999999999999999.
std::string shortest(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

/// The parameters that --at, --at-file, --range or --frames give (empty when none does); `name`
/// is the parameter's column in an --at-file CSV (u, or t for a channel).
std::vector<parameter> given_parameters(const sample_args& a, const std::string& name = "u") {
  if (!a.at.empty()) return parse_at(a.at);
  if (!a.at_file.empty()) return parse_at_file(a.at_file, name);
  if (!a.range.empty()) return parse_range(a.range);
  if (!a.frames.empty()) return parse_range(a.frames, "--frames", 1.0);
  return {};
}

template <int Dim>
void sample(const io::field& spec, const sample_args& a) {
  const std::vector<parameter> given = given_parameters(a);
  const any_curve<double, Dim> c = io::curve_from_spec<double, Dim>(spec);
  al::parameterization_options<double> opt;
  // Samples at given or equally spaced u need s(u) only: Newton's method builds no u(s) table
  // (minutes on degree-20 Runge), and s(u) is then the segment lengths plus one adaptive integral.
  // That also leaves a degenerate curve (length 0 or rounding noise) its points and s(u).
  const bool by_arclength = given.empty() && a.by == "arclength";
  opt.method = by_arclength ? parse_inversion(a.method) : al::inversion_method::newton;
  opt.newton_polish = a.polish;
  if (a.table_tol > 0) opt.table_tolerance = a.table_tol;
  // A degenerate curve (length 0 or rounding noise) has no u(s), a non-finite length no s(u): the
  // library's error, naming the spec.
  auto build = [&] {
    try {
      al::parameterization<any_curve<double, Dim>> p(c, opt);
      if (by_arclength && p.degenerate()) (void)p.u(0.0);  // newton builds no table: ask it
      return p;
    } catch (const invalid_input& e) {
      if (!by_arclength) throw invalid_input(a.spec + ": " + e.what());
      throw invalid_input(a.spec + ": sample --by arclength: " + e.what() +
                          " (sample --by u gives the points of a curve of any length)");
    }
  };
  const ease_fn ease = parse_ease(a.ease);  // refused before the table is built
  const auto built_at = std::chrono::steady_clock::now();
  const al::parameterization<any_curve<double, Dim>> param = build();
  if (param.table_intervals() > 0 && !a.quiet) {
    // The table's size, measured error, status and cost: what the O(1) lookups cost to set up.
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - built_at).count();
    std::cerr << "sample: u(s) table of " << param.table_intervals() << " cells over "
              << param.segments().segment_count() << (param.segments().segment_count() == 1 ? " segment" : " segments")
              << ", measured error "
              << (std::isfinite(param.table_error()) ? harness::fmt(param.table_error() / param.length()) + " L"
                                                     : std::string("none (not measured)"))
              << " (" << al::to_string(param.table_status()) << ", target " << harness::fmt(opt.table_tolerance)
              << " L), " << param.construction_evaluations() << " evaluations, built in " << harness::fmt(seconds)
              << " s\n";
    if (!param.table_reason().empty())
      std::cerr << "sample: the table is " << al::to_string(param.table_status()) << ": "
                << al::to_text(param.table_reason()) << "\n";
  }
  const auto dom = c.domain();
  for (const parameter& p : given)
    if (!(dom.lo <= p.u && p.u <= dom.hi)) {
      std::ostringstream os;
      os << std::setprecision(17) << p.where << ": u = " << p.u << " is outside the curve's domain [" << dom.lo << ", "
         << dom.hi << "]";
      throw invalid_input(os.str());
    }
  std::cout << "u,s";
  const char* names[] = {"x", "y", "z", "w"};
  for (int d = 0; d < Dim; ++d) std::cout << "," << names[d];
  for (int k = 1; k <= a.derivatives; ++k)
    for (int d = 0; d < Dim; ++d) std::cout << ",d" << (k == 1 ? "" : std::to_string(k)) << names[d];
  std::cout << "\n" << std::setprecision(17);
  const double L = param.length();
  const std::size_t count = given.empty() ? a.count : given.size();
  progress shown("sample", count, a.quiet);
  for (std::size_t i = 0; i < count; ++i) {
    shown.update(i);
    const double f = count == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(count - 1);
    double u = 0, s = 0;
    if (!given.empty()) {
      u = given[i].u;
      s = param.s(u);
    } else if (a.by == "u") {
      u = i + 1 == count ? dom.hi : dom.lo + f * (dom.hi - dom.lo);
      s = param.s(u);
    } else {
      s = std::visit([&](const auto& e) { return e(f); }, ease) * L;
      if (s > L) s = L;  // S(1) = 1 exactly, but S(f) * L may round past L by one ulp
      u = param.u(s);
    }
    const point<double, Dim> p = c(u);
    const std::string row = spec.path + ": row " + std::to_string(i + 1) + " (u = " + to_text(u) + ")";
    require_finite(s, row + ": s", c);
    for (int d = 0; d < Dim; ++d) require_finite(p[d], row + ": " + names[d], c);
    std::cout << u << "," << s;
    for (int d = 0; d < Dim; ++d) std::cout << "," << p[d];
    for (int k = 1; k <= a.derivatives; ++k) {
      const point<double, Dim> dp = c.derivative(u, k);
      for (int d = 0; d < Dim; ++d) {
        require_finite(dp[d], row + ": derivative " + std::to_string(k) + " " + names[d], c);
        std::cout << "," << dp[d];
      }
    }
    std::cout << "\n";
  }
}

/// A glTF rotation channel at given times: t, the quaternion x, y, z, w and its time derivatives
/// (orders 1..K, K <= 2: nlerp and cubicspline rotations have no third; io::rotation_of_spec).
void sample_rotation(const io::field& spec, const sample_args& a, const std::vector<parameter>& given) {
  const auto r = io::rotation_of_spec<double>(spec);
  const char* names[] = {"x", "y", "z", "w"};
  const char* orders[] = {"", "d", "d2"};  // the column prefix of each derivative order
  std::cout << "t";
  for (int k = 0; k <= a.derivatives; ++k)
    for (const char* n : names) std::cout << "," << orders[k] << n;
  std::cout << "\n" << std::setprecision(17);
  progress shown("sample", given.size(), a.quiet);
  for (std::size_t i = 0; i < given.size(); ++i) {
    shown.update(i);
    const double t = given[i].u;
    std::cout << shortest(t);
    for (int k = 0; k <= a.derivatives; ++k) {
      const auto row = [&] { return spec.path + ": " + given[i].where + " (t = " + to_text(t) + "): "; };
      point<double, 4> q;
      try {
        q = r.derivative(t, k);
      } catch (const std::domain_error& e) {  // a cubicspline quaternion that vanishes
        throw invalid_input(row() + e.what());
      }
      for (int d = 0; d < 4; ++d) {
        if (!std::isfinite(q[d])) throw invalid_input(row() + orders[k] + names[d] + " is " + to_text(q[d]));
        std::cout << "," << q[d];
      }
    }
    std::cout << "\n";
  }
}

/// A channel spec at given times: t, the value and its time derivatives (orders 1..min(K, 2)):
/// the channel's truth rounded to double, or with --as-tool the tool's own evaluation
/// (harness::channel_values_of), said by a first comment line. A derivative cell is empty where
/// the derivative is infinite or unbounded (said on stderr), as `check` reads it back.
void sample_times(const io::field& spec, const sample_args& a) {
  const std::vector<parameter> given = given_parameters(a, "t");
  if (a.derivatives > 2)
    throw invalid_input("--derivatives " + std::to_string(a.derivatives) +
                        ": a channel's time derivatives go to order 2 (d2value)");
  if (io::is_gltf_rotation(spec)) {
    if (a.as_tool) throw invalid_input("--as-tool: a glTF rotation is printed as its sampler evaluates it already");
    return sample_rotation(spec, a, given);
  }
  const harness::channel_values ch =
      harness::channel_values_of(spec, a.as_tool ? harness::check_against::tool : harness::check_against::truth);
  std::cout << "# curvebench sample: " << ch.what
            << (a.as_tool ? "" : ", rounded to double; --as-tool for the tool's own evaluation") << "\n";
  std::cout << "t,value";
  for (int k = 1; k <= a.derivatives; ++k) std::cout << (k == 1 ? ",dvalue" : ",d2value");
  std::cout << "\n" << std::setprecision(ch.bits == 32 ? 9 : 17);
  progress shown("sample", given.size(), a.quiet);
  // A derivative that is infinite or unbounded at t (a vertical tangent, a circ ease at its key) or
  // not representable leaves its cell empty and is reported on stderr: the values, which are
  // finite, are still printed and `check` reads the CSV back (an empty cell: not given there).
  std::size_t empty_cells = 0;
  std::string first_empty;
  for (std::size_t i = 0; i < given.size(); ++i) {
    shown.update(i);
    const double t = given[i].u;
    const std::optional<double> v = ch.at(t, 0);
    if (!v || !std::isfinite(*v))
      throw invalid_input(
          spec.path + ": " + given[i].where + " (t = " + to_text(t) + "): " +
          (a.as_tool
               ? std::string("the tool's own evaluation in ") + (ch.bits == 32 ? "float " : "double ") +
                     (v ? "is " + to_text(*v) : std::string("is not finite")) + ": its intermediate results pass " +
                     (ch.bits == 32 ? "float's range (about 3.4e38)" : "double's range (about 1.8e308)") +
                     "; without --as-tool, sample gives the channel's truth"
               : std::string("the value is not representable in double")));
    std::cout << shortest(t) << "," << *v;
    for (int k = 1; k <= a.derivatives; ++k) {
      std::cout << ",";
      const std::optional<double> d = ch.at(t, k);
      if (d && std::isfinite(*d)) {
        std::cout << *d;
        continue;
      }
      if (empty_cells++ == 0)
        first_empty = given[i].where + " (t = " + to_text(t) + "), " + (k == 1 ? "dvalue" : "d2value") + ": " +
                      (d ? "infinite or past double's range (a vertical tangent, or a slope beyond 1.8e308)"
                         : "unbounded or not representable in double");
    }
    std::cout << "\n";
  }
  if (empty_cells > 0)
    std::cerr << "curvebench: note: " << empty_cells << " derivative cell" << (empty_cells == 1 ? " is" : "s are")
              << " empty (infinite, unbounded or not representable); the first: " << first_empty << "\n";
}

}  // namespace

CLI::App* add_sample(CLI::App& app, sample_args& a) {
  auto* samp = app.add_subcommand(
      "sample", "sample a curve spec: CSV of u, s (arc length from the domain's start), the point and derivatives");
  samp->add_option("spec", a.spec, "JSON curve spec")->required()->check(CLI::ExistingFile);
  const std::string max = std::to_string(max_sample_values);
  auto* count =
      samp->add_option("--count", a.count, "number of equally spaced samples (default 11, at most " + max + ")")
          ->check(CLI::Range(std::size_t(1), max_sample_values));
  samp->add_option("--by", a.by, "spacing: equal steps in u, or in arc length (with --ease)")
      ->check(CLI::IsMember({"u", "arclength"}));
  std::vector<std::string> sample_ids;
  for (const auto& m : sample_methods()) sample_ids.push_back(m.first);
  samp->add_option("--method", a.method, "u(s) method for --by arclength (default hermite_table)")
      ->check(CLI::IsMember(sample_ids));
  samp->add_flag("--polish", a.polish, "one Newton step after a table lookup");
  samp->add_option("--table-tol", a.table_tol,
                   "the u(s) table's target, relative to the length: it is sized per segment until its measured "
                   "error is below it (default 1e-15; its size, error and build time are printed on stderr)")
      ->check(CLI::PositiveNumber);
  samp->add_option("--ease", a.ease,
                   "distance-time function for --by arclength: linear, sine, smoothstep, smootherstep, "
                   "sine_plateau:T1,T2, parabolic:T1,T2 (default linear)");
  auto* at = samp->add_option("--at", a.at, "evaluate at these parameters: V1,V2,... (at most " + max + ")")
                 ->check(non_empty());
  auto* at_file = samp->add_option("--at-file", a.at_file,
                                   "evaluate at the parameters of FILE: one value per line, or a CSV whose header "
                                   "names a u column (t for a channel spec; other columns and # lines ignored)")
                      ->check(CLI::ExistingFile);
  auto* range = samp->add_option("--range", a.range,
                                 "evaluate at A, A+STEP, ... up to B (inclusive when B lies on the grid): A:B:STEP")
                    ->check(non_empty());
  auto* frames = samp->add_option("--frames", a.frames,
                                  "times A, A+STEP, ... up to B for channel specs (whose --at, --frames and --range "
                                  "values are times): A:B[:STEP], STEP 1 by default")
                     ->check(non_empty());
  for (CLI::Option* o : {at, at_file, range, frames}) {
    o->excludes(count);
    for (CLI::Option* other : {at, at_file, range, frames})
      if (other != o) o->excludes(other);
  }
  samp->add_option("--derivatives", a.derivatives,
                   "derivative columns of orders 1..K (0-3; default 1): dx,dy for the first, d2x,d2y, d3x,d3y")
      ->check(CLI::Range(0, 3));
  samp->add_flag("--quiet", a.quiet, "no progress lines on stderr (printed once a run takes over a second)");
  samp->add_flag("--as-tool", a.as_tool,
                 "channel specs: print what the tool itself evaluates (its time solver, in its precision: WebKit's "
                 "table and Newton for css, float32 for blender) instead of the channel's exact value");
  samp->footer(
      example("curvebench sample bench/cases/arch_cubic_bezier.json --at 0,0.25,0.5 --derivatives 2 > values.csv") +
      example("curvebench sample bench/cases/css_overshoot.json --frames 0:1:0.125 --as-tool > easing.csv"));
  return samp;
}

namespace {
/// std::cout held in memory until the whole sample is computed (at most max_sample_values rows,
/// tens of MB): an error part-way (a value past double's range at the 7th frame) then prints its
/// message alone, not a partial CSV before it.
class held_stdout {
 public:
  held_stdout() : old_(std::cout.rdbuf(held_.rdbuf())) {}
  held_stdout(const held_stdout&) = delete;
  held_stdout& operator=(const held_stdout&) = delete;
  // On an error the held text is dropped. After release() the buffer is not set again: rdbuf()
  // clears the stream's state, which lost a failed write of the text (sample > /dev/full, exit 0).
  ~held_stdout() {
    if (!released_) std::cout.rdbuf(old_);
  }
  void release() {
    std::cout.rdbuf(old_);
    released_ = true;
    std::cout << held_.str();
    held_.str({});
  }

 private:
  std::ostringstream held_;
  std::streambuf* old_;
  bool released_ = false;
};

/// run_sample's work, writing to std::cout (held by run_sample).
void sample_parsed(const sample_args& a) {
  const bool given = !a.at.empty() || !a.at_file.empty() || !a.range.empty() || !a.frames.empty();
  if (a.by == "arclength" && given)
    throw invalid_input(
        "sample: --by arclength spaces the samples itself; it does not go with --at, --at-file or "
        "--range (which give the parameters)");
  // An option that does not apply to this sampling is refused, not ignored.
  if (a.by != "arclength")
    for (const auto& [set, option] : {std::pair{!a.method.empty(), "--method"}, std::pair{!a.ease.empty(), "--ease"},
                                      std::pair{a.polish, "--polish"}, std::pair{a.table_tol > 0, "--table-tol"}})
      if (set)
        throw invalid_input(std::string("sample: ") + option +
                            " applies to --by arclength (samples spaced by arc length); these samples are " +
                            (given ? "at the parameters given" : "spaced by u") + ", where it would be ignored");
  if (a.table_tol > 0 && a.method == vocab::methods::newton.id)
    throw invalid_input("sample: --table-tol sizes a u(s) table; --method newton builds none");
  const nlohmann::json j = read_spec(a.spec);
  const io::field spec = io::root(j, a.spec);
  const bool channel = harness::detail::is_channel_spec(spec);
  if (!channel && a.as_tool)
    throw invalid_input(
        "sample --as-tool: " + a.spec +
        " is a curve spec; --as-tool evaluates a channel spec (\"type\": \"channel\") as its tool does");
  if (!channel && !a.frames.empty())
    throw invalid_input("sample --frames gives the times of a channel spec; " + a.spec +
                        " is a curve spec, whose parameter is u: --range A:B:STEP or --at give u");
  if (channel && a.as_tool && !given)
    throw invalid_input(
        "sample --as-tool evaluates the channel at times: give them with --at, --at-file, --range or --frames "
        "(without them, sample prints the channel's planar curve (t(u), v(u)) by u)");
  if (channel && given) {
    sample_times(spec, a);
    return;
  }
  with_dimension(spec, [&](auto dim) { sample<decltype(dim)::value>(spec, a); });
}

}  // namespace

void run_sample(const sample_args& a) {
  held_stdout out;
  sample_parsed(a);
  out.release();
}

}  // namespace curvebench::tool
