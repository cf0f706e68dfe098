// The check core (harness/check.hpp): column roles, the 50-digit differences through
// case_reference, the summary and the records.
#include "harness/check.hpp"
#include "harness/check_detail.hpp"

#include "harness/record.hpp"
#include "harness/reference.hpp"

#include "curvebench/arclength/result.hpp"
#include "curvebench/core/error.hpp"
#include "curvebench/io/spec.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

namespace curvebench::harness {

namespace detail {

namespace {

/// A column name for a message, cut at 40 characters (a 100 kB name is not echoed whole).
std::string column_name(const std::string& name) { return name.size() <= 40 ? name : name.substr(0, 37) + "..."; }

/// The names joined by commas, each cut by column_name, at most 12 of them: a header of 20000
/// columns must not become a message of that size.
std::string column_list(const std::vector<std::string>& names) {
  constexpr std::size_t shown = 12;
  std::string s;
  for (std::size_t i = 0; i < names.size() && i < shown; ++i) s += (i == 0 ? "" : ",") + column_name(names[i]);
  if (names.size() > shown) s += ", ... (" + std::to_string(names.size()) + " columns)";
  return s;
}

/// The most significant digits over the value columns (0 for a table built in memory).
int most_digits(const csv_table& t, const std::vector<std::size_t>& value_columns) {
  int d = 0;
  for (std::size_t c : value_columns)
    if (c < t.digits.size()) d = std::max(d, t.digits[c]);
  return d;
}

}  // namespace

std::size_t need(const csv_table& t, const std::string& name, const std::string& role) {
  const std::size_t c = t.column(name);
  if (c == csv_table::npos)
    throw invalid_input(t.file + ": row 1 (the header): no column " + name + " (" + role + "); the header names " +
                        column_list(t.columns));
  return c;
}

void only(const csv_table& t, const std::vector<std::string>& allowed, const std::string& kind) {
  for (const auto& c : t.columns)
    if (std::find(allowed.begin(), allowed.end(), c) == allowed.end())
      throw invalid_input(t.file + ": row 1 (the header), column " + column_name(c) + ": unknown column; " + kind +
                          " takes the columns " + column_list(allowed));
}

void choose_unit(check_result& res, const csv_table& t, const std::vector<std::size_t>& value_columns,
                 const check_options& o) {
  if (o.unit) {
    res.unit = *o.unit;
    res.unit_reason = "as asked";
    return;
  }
  const int d = most_digits(t, value_columns);
  if (t.digits.empty()) {
    res.unit = value_unit::ulp_double;
    res.unit_reason = "the default";
  } else if (d >= 10) {
    res.unit = value_unit::ulp_double;
    res.unit_reason = "the values carry up to " + std::to_string(d) + " significant digits, more than a float's 9";
  } else {
    res.unit = value_unit::ulp_float;
    res.unit_reason = "the values carry at most " + std::to_string(d) + " significant digits (a float's 9 or fewer)";
  }
}

void warn_digits(check_result& res, const csv_table& t, const std::vector<std::size_t>& value_columns) {
  if (t.digits.empty()) return;
  const int d = most_digits(t, value_columns);
  // Rounding a value to d significant digits moves it by up to 5 x 10^-d of itself, so up to that
  // fraction of the scale; a unit finer than that cannot be carried by the file.
  const double rounding = 5 * std::pow(10.0, -d);
  const double ulp = res.unit == value_unit::ulp_double  ? std::numeric_limits<double>::epsilon()
                     : res.unit == value_unit::ulp_float ? std::numeric_limits<float>::epsilon()
                                                         : 0.0;
  if (ulp == 0 || rounding <= ulp) return;
  double worst = 0;
  for (const check_row& r : res.rows) worst = std::max(worst, r.relative);
  if (worst <= ulp) return;  // nothing the digits could explain
  res.digits_warning = "the values carry at most " + std::to_string(d) +
                       " significant digits: rounding to them alone can be " + num(rounding / ulp, 2) + " " +
                       std::string(to_string(res.unit)) +
                       "s; write them with %.17g (double) or %.9g (float), or choose --unit";
}

nlohmann::json with_unit(nlohmann::json record, value_unit u, double error_in_unit) {
  record["unit"] = std::string(to_string(u));
  record["error_in_unit"] = finite_or_null(error_in_unit);
  return record;
}

void summarize(check_result& res, std::size_t worst) {
  check_summary& s = res.summary;
  s.rows = res.rows.size();
  for (const check_row& r : res.rows) {
    s.max = std::max(s.max, r.error);
    s.max_relative = std::max(s.max_relative, r.relative);
    if (!std::isnan(s.max_absolute) && !(r.absolute <= s.max_absolute)) s.max_absolute = r.absolute;  // NaN wins
  }
  // Root mean squares scaled by the largest value, so that errors past 1e154 (a claimed length of
  // 1e300) do not overflow in their squares: max x sqrt(mean((x / max)^2)).
  const auto rms = [&](double largest, auto value) {
    if (s.rows == 0 || !(largest > 0) || !std::isfinite(largest)) return largest > 0 ? largest : 0.0;
    double sq = 0;
    for (const check_row& r : res.rows) sq += (value(r) / largest) * (value(r) / largest);
    return largest * std::sqrt(sq / static_cast<double>(s.rows));
  };
  s.rms = rms(s.max, [](const check_row& r) { return r.error; });
  s.rms_relative = rms(s.max_relative, [](const check_row& r) { return r.relative; });
  std::vector<std::size_t> order(res.rows.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return res.rows[a].error > res.rows[b].error; });
  order.resize(std::min(order.size(), worst));
  res.worst = std::move(order);
}

}  // namespace detail

namespace {

using detail::need;
using detail::num;
using detail::only;
using detail::summarize;

constexpr const char* coordinate_names[] = {"x", "y", "z"};
constexpr int max_derivative = 3;
constexpr std::size_t size_grid = 65;  // equally spaced parameters across the domain that size covers

/// "d" for order 1, "d2", "d3" for higher: the prefix of `sample --derivatives`'s columns.
std::string derivative_prefix(int order) { return order == 1 ? "d" : "d" + std::to_string(order); }

/// The parameter column: u; t is for channel specs, which this one is not.
std::size_t parameter_column(const csv_table& t) {
  if (t.column("u") == csv_table::npos && t.column("t") != csv_table::npos)
    throw invalid_input(t.file +
                        ": row 1 (the header), column t: this spec is a curve, whose parameter is u, not time t "
                        "(name the column u; time columns are for channel specs)");
  return need(t, "u", "the curve parameter");
}

void check_domain(const csv_table& t, std::size_t r, std::size_t c, interval<double> d) {
  const double u = t.rows[r][c];
  if (!(d.lo <= u && u <= d.hi))
    throw invalid_input(t.where(r, c) + ": " + num(u) + " is outside the curve's domain [" + num(d.lo) + ", " +
                        num(d.hi) + "]");
}

/// An empty result of a file: its kind, its name and the curve's length L.
check_result result_of(check_kind kind, const csv_table& t, double length) {
  check_result res;
  res.kind = kind;
  res.file = t.file;
  res.length = length;
  return res;
}

/// Integrates the reference's s(u) at the parameters us (ref.cache_s), reporting progress as the
/// share of the file's rows: this is where a check with arc lengths spends its time, and its rows
/// are then quick lookups (which then report nothing more).
template <int Dim>
void cache_s(case_reference<Dim>& ref, std::span<const double> us, const csv_table& t, const check_options& o) {
  const std::size_t rows = t.rows.size();
  ref.cache_s(us, [&](std::size_t k, std::size_t n) {
    if (o.on_row) o.on_row(n == 0 ? rows : k * rows / n, rows, t.file);
  });
}

/// The columns of a --values file: u, the coordinates, the derivative orders present (all of an
/// order's coordinates, or none) and s (npos when absent). Throws on a missing or unknown column.
template <int Dim>
struct values_layout {
  std::size_t cu{}, cs{};
  std::array<std::size_t, Dim> cp{};
  std::vector<int> orders;
  std::vector<std::array<std::size_t, Dim>> cd;

  explicit values_layout(const csv_table& t) {
    cu = parameter_column(t);
    std::vector<std::string> allowed{"u", "s"};
    for (int i = 0; i < Dim; ++i) {
      allowed.emplace_back(coordinate_names[i]);
      cp[static_cast<std::size_t>(i)] =
          need(t, coordinate_names[i], "coordinate " + std::to_string(i + 1) + " of the point");
    }
    for (int k = 1; k <= max_derivative; ++k) {
      std::array<std::size_t, Dim> cols{};
      int present = 0;
      for (int i = 0; i < Dim; ++i) {
        const std::string name = derivative_prefix(k) + coordinate_names[i];
        allowed.push_back(name);
        cols[static_cast<std::size_t>(i)] = t.column(name);
        if (cols[static_cast<std::size_t>(i)] != csv_table::npos) ++present;
      }
      if (present == 0) continue;
      for (int i = 0; i < Dim; ++i)
        if (present != Dim)
          need(t, derivative_prefix(k) + coordinate_names[i],
               "derivative " + std::to_string(k) + " of coordinate " + coordinate_names[i]);
      orders.push_back(k);
      cd.push_back(cols);
    }
    only(t, allowed, "check --values");
    cs = t.column("s");
  }

  /// Throws naming the first row whose u lies outside the domain d.
  void check_rows(const csv_table& t, interval<double> d) const {
    for (std::size_t r = 0; r < t.rows.size(); ++r) check_domain(t, r, cu, d);
  }
};

template <int Dim>
check_result check_values(case_reference<Dim>& ref, const csv_table& t, const check_options& o) {
  check_result res = result_of(check_kind::values, t, ref.length());
  const values_layout<Dim> lay(t);
  const std::size_t cu = lay.cu, cs = lay.cs;
  const auto& cp = lay.cp;
  const auto& orders = lay.orders;
  const auto& cd = lay.cd;
  std::vector<std::size_t> value_columns(cp.begin(), cp.end());
  for (const auto& cols : cd) value_columns.insert(value_columns.end(), cols.begin(), cols.end());
  detail::choose_unit(res, t, value_columns, o);
  const interval<double> d = ref.domain();
  lay.check_rows(t, d);

  // Sizes: the largest exact coordinate magnitude at the rows' parameters and a grid.
  std::vector<double> us;
  for (std::size_t j = 0; j < size_grid; ++j)
    us.push_back(j + 1 == size_grid ? d.hi : d.lo + (d.hi - d.lo) * static_cast<double>(j) / (size_grid - 1));
  for (const auto& row : t.rows) us.push_back(row[cu]);
  const auto size_of = [&](int order) {
    double m = 0;
    for (double u : us) {
      const point<double, Dim> p = ref.exact(u, order);
      for (int i = 0; i < Dim; ++i) m = std::max(m, std::abs(p[i]));
    }
    return m > 0 ? m : 1.0;
  };
  res.size = size_of(0);
  const int K = orders.empty() ? 0 : orders.back();
  res.derivative_sizes.assign(static_cast<std::size_t>(K), std::numeric_limits<double>::quiet_NaN());
  for (int k : orders) res.derivative_sizes[static_cast<std::size_t>(k - 1)] = size_of(k);
  const bool cached = cs != csv_table::npos;
  if (cached) cache_s(ref, std::span<const double>(us).subspan(size_grid), t, o);  // the rows' u

  constexpr double eps = std::numeric_limits<double>::epsilon();
  double worst_point = 0, worst_s = 0, worst_point_in_unit = 0;
  std::vector<double> worst_derivative(static_cast<std::size_t>(K), 0.0), worst_derivative_in_unit = worst_derivative;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto& row = t.rows[r];
    check_row cr;
    cr.line = t.lines[r];
    cr.u = row[cu];
    point<double, Dim> p;
    for (int i = 0; i < Dim; ++i) p[i] = row[cp[static_cast<std::size_t>(i)]];
    cr.absolute = ref.difference(cr.u, 0, p);
    cr.point_ulps = cr.absolute / res.size / eps;  // scale first: eps x 1e-308 underflows
    cr.error = in_unit(cr.absolute, res.size, res.unit);
    cr.relative = cr.absolute / res.size;
    worst_point = std::max(worst_point, cr.point_ulps);
    worst_point_in_unit = std::max(worst_point_in_unit, cr.error);
    if (K > 0) cr.derivative_ulps.assign(static_cast<std::size_t>(K), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t oi = 0; oi < orders.size(); ++oi) {
      const int k = orders[oi];
      for (int i = 0; i < Dim; ++i) p[i] = row[cd[oi][static_cast<std::size_t>(i)]];
      const auto ki = static_cast<std::size_t>(k - 1);
      const double a = ref.difference(cr.u, k, p);
      const double e = a / res.derivative_sizes[ki] / eps;
      cr.derivative_ulps[ki] = e;
      worst_derivative[ki] = std::max(worst_derivative[ki], e);
      const double in = in_unit(a, res.derivative_sizes[ki], res.unit);
      worst_derivative_in_unit[ki] = std::max(worst_derivative_in_unit[ki], in);
      cr.error = std::max(cr.error, in);
      cr.relative = std::max(cr.relative, a / res.derivative_sizes[ki]);
    }
    if (cs != csv_table::npos) {
      cr.s = row[cs];
      cr.s_error = ref.ds(cr.u, cr.s);
      worst_s = std::max(worst_s, cr.s_error);
    }
    res.rows.push_back(std::move(cr));
    if (o.on_row && !cached) o.on_row(res.rows.size(), t.rows.size(), t.file);
  }
  detail::warn_digits(res, t, value_columns);
  const auto n = static_cast<double>(t.rows.size());
  res.records.push_back(detail::with_unit(subject_record(o.case_name, o.group, "eval", o.name, "", worst_point, n),
                                          res.unit, worst_point_in_unit));
  for (int k : orders) {
    const auto ki = static_cast<std::size_t>(k - 1);
    res.records.push_back(detail::with_unit(subject_record(o.case_name, o.group, "eval", o.name,
                                                           "derivative=" + std::to_string(k), worst_derivative[ki], n),
                                            res.unit, worst_derivative_in_unit[ki]));
  }
  if (cs != csv_table::npos)
    res.records.push_back(subject_record(o.case_name, o.group, "s_of_u", o.name, "", worst_s, n));
  return res;
}

/// The columns of a --lengths file: u0, u1, length.
struct lengths_layout {
  std::size_t c0, c1, cl;
  explicit lengths_layout(const csv_table& t)
      : c0(need(t, "u0", "the segment's start parameter")),
        c1(need(t, "u1", "the segment's end parameter")),
        cl(need(t, "length", "your arc length from u0 to u1")) {
    only(t, {"u0", "u1", "length"}, "check --lengths");
  }
  void check_rows(const csv_table& t, interval<double> d) const {
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      check_domain(t, r, c0, d);
      check_domain(t, r, c1, d);
      // A length runs forwards: a row from u0 to an earlier u1 would be charged against the signed
      // -(s(u0) - s(u1)), twice its length off when the user wrote the length itself.
      if (t.rows[r][c1] < t.rows[r][c0])
        throw invalid_input(t.where(r, c1) + ": u1 = " + num(t.rows[r][c1]) + " is below u0 = " + num(t.rows[r][c0]) +
                            ": a length runs from u0 to u1 >= u0 (swap them)");
    }
  }
};

template <int Dim>
check_result check_lengths(case_reference<Dim>& ref, const csv_table& t, const check_options& o) {
  check_result res = result_of(check_kind::lengths, t, ref.length());
  const lengths_layout lay(t);
  const std::size_t c0 = lay.c0, c1 = lay.c1, cl = lay.cl;
  lay.check_rows(t, ref.domain());
  std::vector<double> ends;
  for (const auto& row : t.rows) {
    ends.push_back(row[c0]);
    ends.push_back(row[c1]);
  }
  cache_s(ref, ends, t, o);
  double worst = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto& row = t.rows[r];
    check_row cr;
    cr.line = t.lines[r];
    cr.u = row[c0];
    cr.u1 = row[c1];
    const double diff = ref.length_between_error(cr.u, cr.u1, row[cl]);
    const double segment = std::abs(ref.length_between(cr.u, cr.u1));
    cr.absolute = diff;
    cr.error = diff / res.length;
    cr.relative = segment > 0 ? diff / segment : (diff > 0 ? std::numeric_limits<double>::infinity() : 0.0);
    worst = std::max(worst, cr.error);
    res.rows.push_back(std::move(cr));
  }
  res.records.push_back(
      subject_record(o.case_name, o.group, "length", o.name, "", worst, static_cast<double>(t.rows.size())));
  return res;
}

/// The columns of an --inverse file: s, u.
struct inverse_layout {
  std::size_t cs, cu;
  explicit inverse_layout(const csv_table& t)
      : cs(need(t, "s", "the arc length from the domain's start")), cu(parameter_column(t)) {
    only(t, {"s", "u"}, "check --inverse");
  }
  /// The answers' domain (an answer outside it is a finding instead with outside_is_finding).
  void check_rows(const csv_table& t, interval<double> d, const check_options& o) const {
    if (o.outside_is_finding) return;
    for (std::size_t r = 0; r < t.rows.size(); ++r) check_domain(t, r, cu, d);
  }
};

template <int Dim>
check_result check_inverse(case_reference<Dim>& ref, const csv_table& t, const check_options& o) {
  check_result res = result_of(check_kind::inverse, t, ref.length());
  const inverse_layout lay(t);
  const std::size_t cs = lay.cs, cu = lay.cu;
  const interval<double> d = ref.domain();
  lay.check_rows(t, d, o);
  // s may exceed the rounded L by a few ulps of rounding in the user's program.
  const double s_max = res.length * (1 + 64 * std::numeric_limits<double>::epsilon());
  std::vector<double> answers;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto& row = t.rows[r];
    if (!(row[cs] >= 0 && row[cs] <= s_max))
      throw invalid_input(t.where(r, cs) + ": " + num(row[cs]) + " is outside [0, L] = [0, " + num(res.length) +
                          "], the curve's arc-length range");
    answers.push_back(std::clamp(row[cu], d.lo, d.hi));
  }
  cache_s(ref, answers, t, o);
  double worst = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto& row = t.rows[r];
    check_row cr;
    cr.line = t.lines[r];
    cr.s = row[cs];
    cr.u = row[cu];
    const double inside = std::clamp(cr.u, d.lo, d.hi);
    cr.error = ref.ds(inside, cr.s);
    if (inside != cr.u) {  // outside_is_finding: beyond an end, along the end tangent
      const point<double, Dim> tangent = ref.exact(inside, 1);
      double speed = 0;
      for (int i = 0; i < Dim; ++i) speed += tangent[i] * tangent[i];
      cr.error += std::abs(cr.u - inside) * std::sqrt(speed) / res.length;
      res.findings.push_back(t.where(r, cu) + ": u = " + num(cr.u) + " is outside the domain [" + num(d.lo) + ", " +
                             num(d.hi) + "] by " + num(std::abs(cr.u - inside), 3) +
                             "; measured at the end plus that distance along its tangent");
    }
    cr.relative = cr.error;
    cr.absolute = cr.error * res.length;  // ds and the tangent's run are both divided by L
    worst = std::max(worst, cr.error);
    res.rows.push_back(std::move(cr));
  }
  res.records.push_back(
      subject_record(o.case_name, o.group, "u_of_s", o.name, "", worst, static_cast<double>(t.rows.size())));
  return res;
}

/// The columns of an --at-length file: the point x[,y[,z]], optionally s, the arc length it was
/// asked for, and with s optionally L, the total length on the scale of that s (a tool's own,
/// getTotalLength()'s: s is then the fraction s / L of the way along).
template <int Dim>
struct at_length_layout {
  std::size_t cs = csv_table::npos, cl = csv_table::npos;
  std::array<std::size_t, Dim> cp{};
  explicit at_length_layout(const csv_table& t) {
    std::vector<std::string> allowed{"s", "L"};
    for (int i = 0; i < Dim; ++i) {
      allowed.emplace_back(coordinate_names[i]);
      cp[static_cast<std::size_t>(i)] =
          need(t, coordinate_names[i], "coordinate " + std::to_string(i + 1) + " of the point");
    }
    cs = t.column("s");
    cl = t.column("L");
    only(t, allowed, "check --at-length");
    if (cl != csv_table::npos && cs == csv_table::npos)
      throw invalid_input(t.file +
                          ": row 1 (the header), column L: L is the total length on the scale of the s "
                          "column, and there is no s column");
    if (t.rows.size() > max_at_length_rows)
      throw invalid_input(t.where(max_at_length_rows) + ": more than " + std::to_string(max_at_length_rows) +
                          " rows: each row solves u(s) and the nearest point at 50 digits (tens of milliseconds); "
                          "split the file");
    // One tool, one path: one total length. Rows that disagree are two measurements mixed.
    if (cl != csv_table::npos)
      for (std::size_t r = 0; r < t.rows.size(); ++r)
        if (const double l = t.rows[r][cl]; !(l > 0) || l != t.rows[0][cl])
          throw invalid_input(t.where(r, cl) + ": " + num(l) +
                              (l > 0 ? " differs from row " + std::to_string(t.lines[0]) + "'s " + num(t.rows[0][cl]) +
                                           ": L is the one total length of the path on the scale of s"
                                     : " is not a positive length"));
  }
};

template <int Dim>
check_result check_at_length(case_reference<Dim>& ref, const csv_table& t, const check_options& o) {
  check_result res = result_of(check_kind::at_length, t, ref.length());
  const at_length_layout<Dim> lay(t);
  const bool asked = lay.cs != csv_table::npos;
  // s on the tool's scale [0, L_tool] is asked at the fraction s / L_tool of the true length.
  const double given_length = lay.cl != csv_table::npos ? t.rows[0][lay.cl] : res.length;
  if (lay.cl != csv_table::npos) {
    res.tool_length = given_length;
    res.tool_length_error = ref.length_error_of(given_length);
  }
  const double s_max = given_length * (1 + 64 * std::numeric_limits<double>::epsilon());
  if (asked)
    for (std::size_t r = 0; r < t.rows.size(); ++r)
      if (const double s = t.rows[r][lay.cs]; !(s >= 0 && s <= s_max))
        throw invalid_input(
            t.where(r, lay.cs) + ": " + num(s) + " is outside [0, L] = [0, " + num(given_length) + "], " +
            (lay.cl != csv_table::npos ? "the arc-length range on the scale of the L column"
                                       : "the curve's arc-length range (a tool's own s, on the scale of "
                                         "its own total length: give that length as an L column)"));
  double worst_s = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto& row = t.rows[r];
    check_row cr;
    cr.line = t.lines[r];
    point<double, Dim> q;
    for (int i = 0; i < Dim; ++i) q[i] = row[lay.cp[static_cast<std::size_t>(i)]];
    cr.s = asked
               ? std::min(lay.cl != csv_table::npos ? row[lay.cs] / given_length * res.length : row[lay.cs], res.length)
               : 0.0;
    const auto near = ref.nearest(q, asked ? cr.s : std::numeric_limits<double>::quiet_NaN());
    cr.u = near.u;
    cr.s_true = near.s;
    cr.off_curve = near.distance / res.length;
    if (asked) {
      cr.absolute = ref.distance_at_length(cr.s, q);
      cr.error = cr.absolute / res.length;
      cr.s_error = near.ds;
      worst_s = std::max(worst_s, cr.s_error);
    } else {
      cr.absolute = near.distance;
      cr.error = cr.off_curve;
    }
    cr.relative = cr.error;
    res.rows.push_back(std::move(cr));
    if (o.on_row) o.on_row(r + 1, t.rows.size(), t.file);
  }
  // The s error at the returned point is the u(s) measure of the accuracy runner (|s(u) - s| / L).
  if (asked)
    res.records.push_back(
        subject_record(o.case_name, o.group, "u_of_s", o.name, "", worst_s, static_cast<double>(t.rows.size())));
  // The tool's own total length is a length measurement of its own.
  if (lay.cl != csv_table::npos)
    res.records.push_back(subject_record(o.case_name, o.group, "length", o.name, "", res.tool_length_error, 1));
  return res;
}

/// An error past double's range cannot be reported, compared or gated: the row is refused.
void refuse_overflow(const check_result& r, const csv_table& t) {
  for (std::size_t i = 0; i < r.rows.size(); ++i)
    if (std::isinf(r.rows[i].error) || std::isinf(r.rows[i].absolute))
      throw invalid_input(t.where(i) +
                          ": the error overflows double: the row's values lie further than 1.8e308 "
                          "from the curve's");
}

template <int Dim>
std::vector<check_result> run_dim(const io::field& spec, const std::vector<const check_input*>& inputs,
                                  const check_options& o) {
  // Every file's columns, then its parameters against the double curve's domain, are checked before
  // the 50-digit reference is built (seconds on hard curves): a wrong file fails at once. A spec
  // whose double curve cannot be built (data only real50 resolves) skips the domain here; the
  // checks below see it against the reference's domain, as they always do.
  std::optional<interval<double>> domain;
  try {
    domain = io::curve_from_spec<double, Dim>(spec).domain();
  } catch (const invalid_input&) {
  }
  for (const check_input* in : inputs) {
    const interval<double> d = domain.value_or(
        interval<double>{-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()});
    if (in->kind == check_kind::values) values_layout<Dim>(in->table).check_rows(in->table, d);
    if (in->kind == check_kind::lengths) lengths_layout(in->table).check_rows(in->table, d);
    if (in->kind == check_kind::inverse) inverse_layout(in->table).check_rows(in->table, d, o);
    if (in->kind == check_kind::at_length) at_length_layout<Dim>{in->table};
  }
  case_reference<Dim> ref(spec);
  // A check by arc length grades answers by a reference that must be far better than double: 1e-20
  // of L still resolves a double answer's error (>= ~1e-16 of L) to 4 digits. A curve whose speed
  // is rounding at 50 digits (a circle of radius 1e-150 centred at 1e10) has no such reference; its
  // rows would be graded against noise.
  const bool by_length = std::any_of(inputs.begin(), inputs.end(), [](const check_input* in) {
    return in->kind == check_kind::lengths || in->kind == check_kind::inverse || in->kind == check_kind::at_length;
  });
  if (by_length && ref.length() > 0 && !(ref.length_error() <= 1e-20))
    throw invalid_input("the 50-digit reference length L = " + num(ref.length()) + " of this curve is good to " +
                        num(ref.length_error(), 3) +
                        " of L only (its speed is rounding at 50 digits: the curve is too small for its coordinates); "
                        "--lengths, --inverse and --at-length need 1e-20");
  std::vector<check_result> out;
  for (const check_input* in : inputs) {
    check_result r = in->kind == check_kind::values      ? check_values(ref, in->table, o)
                     : in->kind == check_kind::lengths   ? check_lengths(ref, in->table, o)
                     : in->kind == check_kind::at_length ? check_at_length(ref, in->table, o)
                                                         : check_inverse(ref, in->table, o);
    refuse_overflow(r, in->table);
    summarize(r, o.worst);
    out.push_back(std::move(r));
  }
  return out;
}

/// Whether an input is checked by time: a times table, or the values of a channel spec with a t
/// column (a u column checks the channel's planar curve (t(u), v(u)) instead).
bool by_time(const io::field& spec, const check_input& in) {
  if (in.kind == check_kind::times) return true;
  return in.kind == check_kind::values && detail::is_channel_spec(spec) && in.table.column("u") == csv_table::npos &&
         in.table.column("t") != csv_table::npos;
}

nlohmann::json row_json(const check_result& res, const check_row& r) {
  nlohmann::json j{{"line", r.line}};
  switch (res.kind) {
    case check_kind::values:
      j["u"] = r.u;
      j["point_ulps"] = r.point_ulps;
      if (!r.derivative_ulps.empty()) {
        nlohmann::json d = nlohmann::json::array();
        for (double e : r.derivative_ulps) d.push_back(finite_or_null(e));
        j["derivative_ulps"] = d;
      }
      if (r.s_error >= 0) {
        j["s"] = r.s;
        j["s_error"] = r.s_error;
      }
      j["absolute"] = r.absolute;
      break;
    case check_kind::times: {
      j["t"] = r.t;
      j["absolute"] = r.absolute;
      j["scale"] = r.scale;
      j["time_error"] = finite_or_null(r.time_error);
      nlohmann::json d = nlohmann::json::array();
      for (double e : r.derivative_errors) d.push_back(finite_or_null(e));
      if (!d.empty()) j["derivative_errors"] = d;
      break;
    }
    case check_kind::lengths:
      j["u0"] = r.u;
      j["u1"] = r.u1;
      j["absolute"] = finite_or_null(r.absolute);
      break;
    case check_kind::inverse:
      j["s"] = r.s;
      j["u"] = r.u;
      j["absolute"] = finite_or_null(r.absolute);
      break;
    case check_kind::at_length:
      if (r.s_error >= 0) {
        j["s"] = r.s;
        j["s_error"] = r.s_error;
      }
      j["u"] = r.u;
      j["s_true"] = r.s_true;
      j["off_curve"] = r.off_curve;
      j["absolute"] = finite_or_null(r.absolute);
      break;
  }
  j["error"] = finite_or_null(r.error);
  j["relative"] = finite_or_null(r.relative);
  return j;
}

}  // namespace

std::string_view to_string(check_kind k) {
  switch (k) {
    case check_kind::values: return "values";
    case check_kind::lengths: return "lengths";
    case check_kind::inverse: return "inverse";
    case check_kind::times: return "times";
    case check_kind::at_length: return "at_length";
  }
  return "?";
}

std::string_view to_string(value_unit u) {
  switch (u) {
    case value_unit::ulp_double: return "ulp-double";
    case value_unit::ulp_float: return "ulp-float";
    case value_unit::rel: return "rel";
    case value_unit::abs: return "abs";
  }
  return "?";
}

value_unit value_unit_of(std::string_view name, const std::string& argument) {
  for (value_unit u : {value_unit::ulp_double, value_unit::ulp_float, value_unit::rel, value_unit::abs})
    if (name == to_string(u)) return u;
  throw invalid_input(argument + " \"" + std::string(name.substr(0, 40)) +
                      "\": not a unit (ulp-double, ulp-float, rel, abs)");
}

double in_unit(double absolute, double scale, value_unit u) {
  // Divided by the scale first: eps x a scale near the smallest doubles (a channel of values 1e-308)
  // underflows to 0 or a subnormal, which made every error 0 / 0 = nan and failed right values.
  switch (u) {
    case value_unit::ulp_double: return absolute / scale / std::numeric_limits<double>::epsilon();
    case value_unit::ulp_float: return absolute / scale / static_cast<double>(std::numeric_limits<float>::epsilon());
    case value_unit::rel: return absolute / scale;
    case value_unit::abs: return absolute;
  }
  return absolute;
}

std::string unit_text(const check_result& r) {
  if (r.kind == check_kind::lengths || r.kind == check_kind::inverse || r.kind == check_kind::at_length)
    return "relative to L";
  const char* of = r.kind != check_kind::times ? "size"
                   : detail::is_ulp(r.unit)    ? "max(|value|, value range)"
                                               : "the value range";
  switch (r.unit) {
    case value_unit::ulp_double: return std::string("ulps of double x ") + of;
    case value_unit::ulp_float: return std::string("ulps of float x ") + of;
    case value_unit::rel: return std::string("relative to ") + of;
    case value_unit::abs: return "absolute";
  }
  return "?";
}

nlohmann::json subject_record(const std::string& case_name, const std::string& group, std::string_view quantity,
                              const std::string& method, const std::string& setting, double error, double evaluations) {
  // A user's values carry no estimate: estimate and bounded are null.
  record r =
      record::measured(case_name, group, quantity, method, setting, error, std::numeric_limits<double>::quiet_NaN(),
                       evaluations, arclength::to_string(arclength::result_status::not_guaranteed));
  r.subject = true;
  return to_json(r);
}

std::vector<check_result> run_checks(const io::field& spec, const std::vector<check_input>& inputs,
                                     const check_options& options) {
  // read_csv refuses non-finite cells and ragged rows, but tables built in memory (the subject
  // API's) do not pass through it: a NaN there would drop out of every max and pass a gate.
  for (const check_input& in : inputs)
    for (std::size_t r = 0; r < in.table.rows.size(); ++r) {
      const auto& row = in.table.rows[r];
      if (row.size() != in.table.columns.size())
        throw invalid_input(in.table.where(r) + ": " + std::to_string(row.size()) + " values for " +
                            std::to_string(in.table.columns.size()) + " columns");
      for (std::size_t c = 0; c < row.size(); ++c) {
        if (std::isfinite(row[c])) continue;
        // An empty derivative cell of a channel's times (read as NaN): not given at that time.
        const std::string& name = in.table.columns[c];
        if (std::isnan(row[c]) && by_time(spec, in) && (name == "dvalue" || name == "d2value")) continue;
        const std::string what = !std::isnan(row[c])       ? num(row[c])
                                 : in.table.digits.empty() ? std::string("nan")
                                                           : std::string("an empty cell");
        throw invalid_input(in.table.where(r, c) + ": " + what + " is not finite");
      }
    }
  std::vector<check_result> out(inputs.size());
  std::vector<const check_input*> by_u;
  std::vector<std::size_t> at;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    if (by_time(spec, inputs[i])) {
      out[i] = detail::check_times(spec, inputs[i].table, options);
      refuse_overflow(out[i], inputs[i].table);
      summarize(out[i], options.worst);
    } else {
      // The tool's own evaluation is a channel's at times; a table by u is checked against the
      // curve's 50-digit reference, which would ignore `against`.
      if (options.against == check_against::tool || options.against_given)
        throw invalid_input(inputs[i].table.file + ": checked by u against the curve's 50-digit reference; against = " +
                            std::string(options.against == check_against::tool ? "tool" : "truth") +
                            " (check --against " + (options.against == check_against::tool ? "tool" : "truth") +
                            ") applies to a channel spec's values at times (a t column, no u column)");
      by_u.push_back(&inputs[i]);
      at.push_back(i);
    }
  }
  if (by_u.empty()) return out;
  std::vector<check_result> checked;
  switch (io::spec_dimension(spec)) {
    case 1: checked = run_dim<1>(spec, by_u, options); break;
    case 2: checked = run_dim<2>(spec, by_u, options); break;
    case 3: checked = run_dim<3>(spec, by_u, options); break;
    default:
      spec.fail("describes a " + std::to_string(io::spec_dimension(spec)) +
                "D curve: check measures 1D to 3D curves (the 50-digit reference is built for those)");
  }
  for (std::size_t k = 0; k < checked.size(); ++k) out[at[k]] = std::move(checked[k]);
  return out;
}

check_result run_check(const io::field& spec, check_kind kind, const csv_table& table, const check_options& options) {
  return std::move(run_checks(spec, {check_input{kind, table}}, options).front());
}

nlohmann::json to_json(const check_result& r) {
  nlohmann::json rows = nlohmann::json::array(), worst = nlohmann::json::array();
  for (const check_row& row : r.rows) rows.push_back(row_json(r, row));
  for (std::size_t i : r.worst) worst.push_back(rows[i]);
  nlohmann::json j{{"kind", std::string(to_string(r.kind))},
                   {"file", r.file},
                   {"length", r.length},
                   {"unit", unit_text(r)},
                   {"summary",
                    {{"rows", r.summary.rows},
                     {"max", finite_or_null(r.summary.max)},
                     {"rms", finite_or_null(r.summary.rms)},
                     {"max_relative", finite_or_null(r.summary.max_relative)},
                     {"rms_relative", finite_or_null(r.summary.rms_relative)},
                     {"max_absolute", finite_or_null(r.summary.max_absolute)}}},
                   {"worst", worst},
                   {"rows", rows},
                   {"records", r.records}};
  if (r.kind == check_kind::values || r.kind == check_kind::times) {
    j["unit_id"] = std::string(to_string(r.unit));
    j["unit_reason"] = r.unit_reason;
    if (!r.digits_warning.empty()) j["digits_warning"] = r.digits_warning;
  }
  if (!r.findings.empty()) j["findings"] = r.findings;
  if (!std::isnan(r.tool_length)) {
    j["tool_length"] = r.tool_length;
    j["tool_length_error"] = r.tool_length_error;
  }
  if (r.kind == check_kind::times) {
    j["against"] = r.against;
    j["value_range"] = r.size;
    j["unchecked"] = r.unchecked;
    nlohmann::json d = nlohmann::json::array();
    for (double s : r.derivative_sizes) d.push_back(finite_or_null(s));
    j["derivative_sizes"] = d;
  }
  if (r.kind == check_kind::values) {
    j["size"] = r.size;
    nlohmann::json d = nlohmann::json::array();
    for (double s : r.derivative_sizes) d.push_back(finite_or_null(s));
    j["derivative_sizes"] = d;
  }
  return j;
}

std::vector<std::string> rows_over(const check_result& r, double max_error) {
  std::vector<std::string> out;
  for (const check_row& row : r.rows) {
    if (row.error <= max_error) continue;  // NaN is over too
    std::string at;
    switch (r.kind) {
      case check_kind::values: at = "u = " + num(row.u); break;
      case check_kind::lengths: at = "u0 = " + num(row.u) + ", u1 = " + num(row.u1); break;
      case check_kind::inverse: at = "s = " + num(row.s) + ", u = " + num(row.u); break;
      case check_kind::times: at = "t = " + num(row.t); break;
      case check_kind::at_length: at = row.s_error >= 0 ? "s = " + num(row.s) : "nearest s = " + num(row.s_true); break;
    }
    out.push_back(r.file + ": row " + std::to_string(row.line) + " (" + at + "): error " + num(row.error, 3) +
                  " > allowed " + num(max_error, 3) + " " + unit_text(r));
  }
  return out;
}

}  // namespace curvebench::harness
