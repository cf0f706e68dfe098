// The times check (harness/check.hpp): a user's values of a keyframe channel at times against the
// channel at 50 digits (the truth: the tool's rules with the exact time inversion) or against the
// tool's own evaluation (its solver, its storage precision). This unit instantiates the channel at
// real50 besides harness/sweep_channel.cpp.
#include "harness/check_detail.hpp"
#include "harness/record.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/families/channel.hpp"
#include "curvebench/io/spec_data.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

namespace curvebench::harness {

namespace {

using curvebench::real50;

constexpr std::size_t scale_grid = 65;  // equally spaced times across the keys that the scales cover
constexpr int max_order = 2;            // dvalue, d2value

/// The value or derivative `order` at t of what the check compares with; std::nullopt where it
/// is unbounded or not representable (a circ ease's slope at its key); an infinite slope (a
/// vertical tangent) is infinite.
using reference_fn = std::function<std::optional<real50>(double, int)>;

template <class Real>
reference_fn reference_of(io::channel_model<Real> m) {
  return [m = std::move(m)](double t, int order) -> std::optional<real50> {
    using std::isnan;
    try {
      const Real v = m.at(static_cast<Real>(t), order);
      if (isnan(v)) return std::nullopt;
      return real50(v);
    } catch (const std::domain_error&) {
      return std::nullopt;
    }
  };
}

/// What a check or a sample compares with or prints (see check_times).
struct channel_reference {
  reference_fn at;
  std::string what;          ///< in words
  int bits = 64;             ///< the precision of its values: 32 for a float tool's own evaluation
  std::vector<double> keys;  ///< the key times (the truth's)
};

channel_reference channel_reference_of(const io::field& spec, check_against against) {
  if (io::is_gltf_rotation(spec))
    spec.fail("a glTF rotation channel's values are quaternions: check by time takes scalar channels");
  // The truth: the spec under its tool's rules with the exact time inversion, at 50 digits. The
  // spec's own solver is replaced there, and checked first: a misspelt one is an error either way.
  (void)io::detail::solver_of(spec, channel::time_solver::exact);
  nlohmann::json exact = spec.value;
  exact["solver"] = "exact";
  const io::channel_model<real50> truth = io::channel_model_of_spec<real50>(io::field{exact, spec.path});
  channel_reference out;
  for (const auto& k : truth.key_times) out.keys.push_back(static_cast<double>(k));
  if (against == check_against::truth) {
    out.at = reference_of(truth);
    out.what = "the channel at 50 digits (the tool's rules, the time solver exact)";
    return out;
  }
  const std::string tool = spec.member("tool").string();
  io::visit_tool(tool, [&](auto tl) {
    using Tool = typename decltype(tl)::type;
    using Storage = typename Tool::storage_type;
    out.at = reference_of(io::channel_model_of_spec<Storage>(spec));
    out.bits = static_cast<int>(sizeof(Storage) * 8);
    std::string solver =
        spec.has("solver") ? spec.member("solver").string() : std::string(channel::to_string(Tool::default_solver));
    if constexpr (requires { Tool::own_solver; })
      if (!spec.has("solver")) solver = std::string(Tool::own_solver);
    out.what = "tool " + tool + "'s own evaluation (solver " + solver + ", in " +
               (sizeof(Storage) == 4 ? "float at float(t)" : "double") + ")";
  });
  return out;
}

}  // namespace

channel_values channel_values_of(const io::field& spec, check_against against) {
  channel_reference r = channel_reference_of(spec, against);
  channel_values out;
  out.what = r.what;
  out.bits = r.bits;
  out.keys = r.keys;
  out.at = [at = std::move(r.at)](double t, int order) -> std::optional<double> {
    const std::optional<real50> v = at(t, order);
    if (!v) return std::nullopt;
    return static_cast<double>(*v);
  };
  return out;
}

namespace detail {

bool is_channel_spec(const io::field& spec) {
  return spec.value.is_object() && spec.value.contains("type") && spec.value["type"] == "channel";
}

check_result check_times(const io::field& spec, const csv_table& t, const check_options& o) {
  check_result res;
  res.kind = check_kind::times;
  res.file = t.file;
  const std::size_t ct = need(t, "t", "the time");
  const std::size_t cv = need(t, "value", "your channel's value at t");
  const std::array<std::size_t, max_order> cd{t.column("dvalue"), t.column("d2value")};
  only(t, {"t", "value", "dvalue", "d2value"}, "check --values on a channel spec");
  std::vector<std::size_t> value_columns{cv};
  for (std::size_t c : cd)
    if (c != csv_table::npos) value_columns.push_back(c);
  choose_unit(res, t, value_columns, o);

  const channel_reference cr0 = channel_reference_of(spec, o.against);
  const reference_fn& ref = cr0.at;
  res.against = cr0.what;
  const auto keys = cr0.keys;
  // Scales: the value range and the derivatives' largest magnitudes over the rows' times and a grid
  // across the keys.
  std::vector<double> ts;
  if (!keys.empty()) {
    const double first = keys.front(), last = keys.back();
    for (std::size_t j = 0; j < scale_grid; ++j)
      ts.push_back(j + 1 == scale_grid ? last : first + (last - first) * static_cast<double>(j) / (scale_grid - 1));
  }
  for (const auto& row : t.rows) ts.push_back(row[ct]);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, magnitude = 0;
  std::array<double, max_order> dscale{};
  for (double x : ts) {
    if (const auto v = ref(x, 0); v && isfinite(*v)) {
      const double d = static_cast<double>(*v);
      lo = std::min(lo, d), hi = std::max(hi, d), magnitude = std::max(magnitude, std::abs(d));
    }
    for (int k = 1; k <= max_order; ++k)
      if (cd[static_cast<std::size_t>(k - 1)] != csv_table::npos)
        if (const auto v = ref(x, k); v && isfinite(*v))
          dscale[static_cast<std::size_t>(k - 1)] =
              std::max(dscale[static_cast<std::size_t>(k - 1)], std::abs(static_cast<double>(*v)));
  }
  res.size = hi > lo ? hi - lo : (magnitude > 0 ? magnitude : 1.0);
  for (std::size_t k = 0; k < max_order; ++k)
    if (cd[k] != csv_table::npos) {
      res.derivative_sizes.resize(k + 1, std::numeric_limits<double>::quiet_NaN());
      res.derivative_sizes[k] = dscale[k] > 0 ? dscale[k] : 1.0;
    }

  // The ulp units (and the records, in ulps of double) scale a row's value error by max(|V(t)|,
  // range): a float or double holds a value to half an ulp of the value itself, so a location at
  // 1.0 moving by 0.08 cannot be stored closer than ulps of 1.0, and a range alone would count that
  // storage rounding as 12.5 float ulps; the range keeps values near zero (a channel crossing 0)
  // from being judged relative to nothing. rel and abs keep the range: the motion's own size.
  constexpr double eps = std::numeric_limits<double>::epsilon();
  double worst_value = 0, worst_value_in_unit = 0;
  std::array<double, max_order> worst_derivative{}, worst_derivative_in_unit{};
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    const auto& row = t.rows[r];
    check_row cr;
    cr.line = t.lines[r];
    cr.t = row[ct];
    const std::optional<real50> v = ref(cr.t, 0);
    if (!v || !isfinite(*v))
      throw invalid_input(t.where(r, ct) + ": " + num(cr.t) + ": the channel's value is not representable there");
    cr.absolute = static_cast<double>(abs(real50(row[cv]) - *v));
    const double value_scale = std::max(std::abs(static_cast<double>(*v)), res.size);
    cr.scale = is_ulp(res.unit) ? value_scale : res.size;
    cr.error = in_unit(cr.absolute, cr.scale, res.unit);
    cr.relative = cr.absolute / cr.scale;
    worst_value = std::max(worst_value, cr.absolute / value_scale / eps);  // scale first (in_unit)
    worst_value_in_unit = std::max(worst_value_in_unit, cr.error);
    const std::optional<real50> slope = ref(cr.t, 1);
    cr.time_error = cr.absolute == 0                           ? 0.0
                    : slope && isfinite(*slope) && *slope != 0 ? cr.absolute / std::abs(static_cast<double>(*slope))
                                                               : std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < max_order; ++k) {
      if (cd[k] == csv_table::npos) continue;
      cr.derivative_errors.resize(k + 1, std::numeric_limits<double>::quiet_NaN());
      const std::optional<real50> d = ref(cr.t, static_cast<int>(k + 1));
      if (std::isnan(row[cd[k]]) || !d || !isfinite(*d)) {  // not given, or unbounded there
        ++res.unchecked;
        continue;
      }
      const double a = static_cast<double>(abs(real50(row[cd[k]]) - *d));
      cr.derivative_errors[k] = in_unit(a, res.derivative_sizes[k], res.unit);
      worst_derivative_in_unit[k] = std::max(worst_derivative_in_unit[k], cr.derivative_errors[k]);
      cr.error = std::max(cr.error, cr.derivative_errors[k]);
      cr.relative = std::max(cr.relative, a / res.derivative_sizes[k]);
      worst_derivative[k] = std::max(worst_derivative[k], a / res.derivative_sizes[k] / eps);
    }
    res.rows.push_back(std::move(cr));
    if (o.on_row) o.on_row(res.rows.size(), t.rows.size(), t.file);
  }
  warn_digits(res, t, value_columns);
  const auto n = static_cast<double>(t.rows.size());
  res.records.push_back(with_unit(subject_record(o.case_name, o.group, "eval", o.name, "", worst_value, n), res.unit,
                                  worst_value_in_unit));
  for (std::size_t k = 0; k < max_order; ++k)
    if (cd[k] != csv_table::npos)
      res.records.push_back(with_unit(subject_record(o.case_name, o.group, "eval", o.name,
                                                     "derivative=" + std::to_string(k + 1), worst_derivative[k], n),
                                      res.unit, worst_derivative_in_unit[k]));
  return res;
}

}  // namespace detail

}  // namespace curvebench::harness
