// The keyframe-channel sweep: for a case of type "channel", its value under every time solver in
// float and in double against the same spec evaluated at 50 digits with the exact inversion, and
// the case's channel summary for the report (the value range, the models of the tools on the same
// keys and where they disagree, a picture of the keys and handles). See sweeps.hpp for what each
// record measures. This unit instantiates the channel at real50 (the truth) besides reference.cpp.
// The tools compared on an exact case's keys are io::all_tools (harness/channel_models.hpp).
#include "harness/channel_models.hpp"
#include "harness/sweeps.hpp"

#include "curvebench/io/families/channel.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace curvebench::harness {

namespace {

using json = nlohmann::json;
using curvebench::real50;

// The spec with its solver replaced (the sweep runs every solver on the same keys).
json with_solver(const json& spec, std::string_view solver) {
  json s = spec;
  s["solver"] = std::string(solver);
  return s;
}

// The spec's fields as a parsable root (name, group and reason are case metadata the parser skips).
template <class Real>
io::channel_model<Real> model_of(const json& spec, const std::string& name) {
  return io::channel_model_of_spec<Real>(io::root(spec, name));
}

// Sample times over the keyed range widened by a quarter period on each side (extrapolation and
// cycles included), sorted: the golden-ratio fractions of sample_fractions, so that no sample
// lands on a key by construction (the key times are measured separately).
std::vector<double> sample_times(double first, double last, std::size_t n) {
  const double span = last - first;
  const double lo = span > 0 ? first - span / 4 : first - 1, hi = span > 0 ? last + span / 4 : last + 1;
  std::vector<double> ts = sample_parameters(lo, hi, n);
  std::sort(ts.begin(), ts.end());
  return ts;
}

// The truth at the times a Real model is asked (times rounded to Real first, so that the time's
// own rounding is not counted as the evaluator's error).
template <class Real>
std::vector<real50> truth_at(const io::channel_model<real50>& truth, const std::vector<double>& ts) {
  std::vector<real50> exact(ts.size());
  for (std::size_t j = 0; j < ts.size(); ++j) exact[j] = truth.at(real50(static_cast<Real>(ts[j])), 0);
  return exact;
}

// |x(u) - t| at 50 digits, x the time of segment [k0, k1] from the keys' exact data (so that a
// rounding of the control times the evaluator works with counts as its time error).
template <class Real>
real50 time_residual(const channel::key<Real>& k0, const channel::key<Real>& k1, const Real& u, const Real& t) {
  const real50 t0(k0.time), h = real50(k1.time) - t0;
  const real50 c1(k0.out.dt), c2 = h + real50(k1.in.dt);
  const real50 w(u), m = 1 - w;
  const real50 x = t0 + 3 * m * m * w * c1 + 3 * m * w * w * c2 + w * w * w * h;
  return abs(x - real50(t));
}

struct solver_figures {
  double max_ulps = 0, rms_ulps = 0, key_ulps = 0, time_ulps = 0;
  double monotone_violations = 0, evaluations = 0, iterations_mean = 0, iterations_max = 0, not_converged = 0;
};

// One solver in one precision: value errors at the samples and at the key times, monotonicity
// over the sorted samples, and the solver's own time residual and iterations on the samples that
// fall inside bezier segments of the keyed range.
template <class Real>
solver_figures measure_solver(const io::channel_model<Real>& m, const std::vector<double>& ts,
                              const std::vector<real50>& truth, const std::vector<double>& key_ts,
                              const std::vector<real50>& key_truth, double range) {
  const double unit = static_cast<double>(std::numeric_limits<Real>::epsilon()) * range;
  solver_figures f;
  std::vector<Real> values(ts.size());
  double sum2 = 0;
  for (std::size_t j = 0; j < ts.size(); ++j) {
    values[j] = m.at(static_cast<Real>(ts[j]), 0);
    const double e = static_cast<double>(abs(real50(values[j]) - truth[j])) / unit;
    f.max_ulps = std::max(f.max_ulps, e);
    sum2 += e * e;
  }
  f.rms_ulps = std::sqrt(sum2 / static_cast<double>(ts.size()));
  for (std::size_t j = 0; j + 1 < ts.size(); ++j) {
    const real50 dt = truth[j + 1] - truth[j];
    const Real dm = values[j + 1] - values[j];
    if ((dt > 0 && dm < Real(0)) || (dt < 0 && dm > Real(0))) ++f.monotone_violations;
  }
  for (std::size_t j = 0; j < key_ts.size(); ++j)
    f.key_ulps = std::max(
        f.key_ulps, static_cast<double>(abs(real50(m.at(static_cast<Real>(key_ts[j]), 0)) - key_truth[j])) / unit);
  // The solver alone, on the bezier segments of the channel the tool evaluates.
  const auto keys = m.source().keys();
  double iterations = 0, solved = 0;
  for (double td : ts) {
    const Real t = static_cast<Real>(td);
    if (keys.size() < 2 || t < keys.front().time || t > keys.back().time) continue;
    const std::size_t i = m.source().segment_at(t);
    if (keys[i].interp != channel::interpolation::bezier) continue;
    if (t == keys[i + 1].time) continue;  // the segment's end: the key, no inversion
    // The cubic the channel inverts (control times relative to the segment's start).
    const channel::time_cubic<Real> c = m.source().segment_time_cubic(i);
    const auto s = channel::solve_time(m.source().solver(), c, Real(t - keys[i].time));
    const double h = static_cast<double>(c.t3);
    f.time_ulps = std::max(f.time_ulps, static_cast<double>(time_residual(keys[i], keys[i + 1], s.u, t)) /
                                            (static_cast<double>(std::numeric_limits<Real>::epsilon()) * h));
    iterations += s.iterations;
    f.iterations_max = std::max(f.iterations_max, static_cast<double>(s.iterations));
    f.not_converged += s.status == result_status::cap_hit ? 1 : 0;  // stopped by its iteration cap
    f.evaluations += s.evaluations;
    ++solved;
  }
  f.iterations_mean = solved > 0 ? iterations / solved : 0;
  f.evaluations = solved > 0 ? f.evaluations / solved : 0;
  return f;
}

void add_records(record_sink& k, const vocab::method& solver, int bits, const solver_figures& f, double samples) {
  namespace q = vocab::quantities;
  const std::string s = setting(solver, {{"bits", bits}});
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::string_view status = "not_guaranteed";
  k.add(q::channel_value, solver, s, f.max_ulps, nan, samples, status);
  k.annotate({{"rms", f.rms_ulps}});
  k.add(q::channel_keys, solver, s, f.key_ulps, nan, samples, status);
  k.add(q::channel_monotone, solver, s, f.monotone_violations, nan, samples, status);
  k.add(q::channel_time, solver, s, f.time_ulps, nan, f.evaluations, status);
  k.annotate({{"iterations_mean", f.iterations_mean},
              {"iterations_max", f.iterations_max},
              {"not_converged", f.not_converged}});
}

// The report's picture: the value at 400 times over the sampled window and, for up to 60 keys,
// the keys and their handles' ends.
json picture(const io::channel_model<double>& m, double lo, double hi) {
  json p{{"t", json::array()}, {"v", json::array()}, {"keys", json::array()}};
  constexpr int n = 400;
  for (int j = 0; j <= n; ++j) {
    const double t = lo + (hi - lo) * j / n;
    p["t"].push_back(t);
    p["v"].push_back(m.at(t, 0));
  }
  const auto keys = m.source().keys();
  if (keys.size() <= 60)
    for (std::size_t i = 0; i < keys.size(); ++i) {
      const auto& k = keys[i];
      const bool bez_out = i + 1 < keys.size() && k.interp == channel::interpolation::bezier;
      const bool bez_in = i > 0 && keys[i - 1].interp == channel::interpolation::bezier;
      json h{{"t", k.time}, {"v", k.value}};
      if (bez_in) h["in"] = {k.time + k.in.dt, k.value + k.in.dv};
      if (bez_out) h["out"] = {k.time + k.out.dt, k.value + k.out.dv};
      p["keys"].push_back(h);
    }
  return p;
}

// A rotation model in one precision against the truth at the same (rounded) times: the angle
// between the quaternions, and how far the model's quaternion is from unit length.
struct rotation_figures {
  double max_eps = 0, rms_eps = 0, norm_eps = 0;
};

template <class Real>
rotation_figures measure_rotation(const channel::gltf::rotation_sampler<Real>& m,
                                  const channel::gltf::rotation_sampler<real50>& truth, const std::vector<double>& ts) {
  const double eps = static_cast<double>(std::numeric_limits<Real>::epsilon());
  rotation_figures f;
  double sum2 = 0;
  for (double td : ts) {
    const Real t = static_cast<Real>(td);
    const point<Real, 4> q = m(t);
    point<real50, 4> q50;
    for (int d = 0; d < 4; ++d) q50[d] = real50(q[d]);
    const double e = static_cast<double>(channel::gltf::angular_distance<real50>(q50, truth(real50(t)))) / eps;
    f.max_eps = std::max(f.max_eps, e);
    sum2 += e * e;
    f.norm_eps = std::max(f.norm_eps, static_cast<double>(abs(sqrt(q50.dot(q50)) - real50(1))) / eps);
  }
  f.rms_eps = std::sqrt(sum2 / static_cast<double>(ts.size()));
  return f;
}

}  // namespace

json sweep_rotation(record_sink& k, const case_info& info, const sweep& w) {
  namespace g = channel::gltf;
  const io::field root = io::root(info.spec, info.name);
  const g::rotation_sampler<double> plain = io::rotation_of_spec<double>(root);
  const auto times = plain.input();
  const std::vector<double> ts = sample_times(times.front(), times.back(), w.channel_times);
  // Linear rotations are measured both ways the players blend them; the spec's blend is the default.
  // Step and cubicspline take none (a spec's blend there is refused: it would be ignored).
  std::vector<std::pair<const vocab::method*, std::string>> runs;
  switch (plain.mode()) {
    case g::interpolation::step: runs.push_back({&vocab::methods::rotation_step, ""}); break;
    case g::interpolation::linear:
      runs.push_back({&vocab::methods::rotation_slerp, "slerp"});
      runs.push_back({&vocab::methods::rotation_nlerp, "nlerp"});
      break;
    case g::interpolation::cubicspline: runs.push_back({&vocab::methods::rotation_cubicspline, ""}); break;
  }
  json refused = json::object();
  double largest = 0;
  for (std::size_t i = 0; i + 1 < plain.key_count(); ++i) largest = std::max(largest, plain.segment_angle(i));
  for (const auto& run : runs) {
    // Named copies, not a structured binding: clang 14 refuses bindings captured by the lambda below.
    const auto* method = run.first;
    const auto& blend = run.second;
    json spec = info.spec;
    if (!blend.empty()) spec["blend"] = blend;
    const io::field r = io::root(spec, info.name);
    const g::rotation_sampler<real50> truth = io::rotation_of_spec<real50>(r);
    const double samples = static_cast<double>(ts.size());
    const auto add = [&](int bits, const rotation_figures& f) {
      k.add(vocab::quantities::channel_rotation, *method, setting(*method, {{"bits", bits}}), f.max_eps,
            std::numeric_limits<double>::quiet_NaN(), samples, "not_guaranteed");
      k.annotate({{"rms", f.rms_eps}, {"norm", f.norm_eps}});
    };
    add(64, measure_rotation(io::rotation_of_spec<double>(r), truth, ts));
    try {
      add(32, measure_rotation(io::rotation_of_spec<float>(r), truth, ts));
    } catch (const invalid_input& x) {
      refused[std::string(method->id)] = std::string("float: ") + x.what();
    }
  }
  return {{"tool", channel::tools::gltf::name},
          {"path", "rotation"},
          {"interpolation", g::to_string(plain.mode())},
          {"keys", plain.key_count()},
          {"largest_segment_angle", largest},
          {"window", {ts.front(), ts.back()}},
          {"samples", ts.size()},
          {"refused", refused}};
}

json sweep_channel(record_sink& k, const case_info& info, const sweep& w) {
  const json& spec = info.spec;
  const io::channel_model<real50> truth = model_of<real50>(with_solver(spec, "exact"), info.name);
  const io::channel_model<double> plain = model_of<double>(spec, info.name);
  const auto keys = plain.source().keys();
  const double first = keys.front().time, last = keys.back().time;
  const std::vector<double> ts = sample_times(first, last, w.channel_times);
  std::vector<double> key_ts;
  for (const auto& key : keys) key_ts.push_back(key.time);

  // Truth at the double times and at the float-rounded ones (and at the key times).
  const std::vector<real50> truth64 = truth_at<double>(truth, ts), truth32 = truth_at<float>(truth, ts);
  const std::vector<real50> key64 = truth_at<double>(truth, key_ts), key32 = truth_at<float>(truth, key_ts);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const real50& v : truth64) lo = std::min(lo, static_cast<double>(v)), hi = std::max(hi, static_cast<double>(v));
  for (const real50& v : key64) lo = std::min(lo, static_cast<double>(v)), hi = std::max(hi, static_cast<double>(v));
  // The unit of every value error: the channel's value range (the largest magnitude for a flat one).
  const double range = hi > lo ? hi - lo : std::max(1.0, std::max(std::abs(lo), std::abs(hi)));

  json refused = json::object();
  for (const vocab::method* solver : vocab::time_solver_methods) {
    const json s = with_solver(spec, solver->id);
    const double samples = static_cast<double>(ts.size());
    add_records(k, *solver, 64, measure_solver(model_of<double>(s, info.name), ts, truth64, key_ts, key64, range),
                samples);
    try {
      // Keys rounded to float may be refused (a handle at the regression limit can regress by an ulp).
      const io::channel_model<float> m32 = model_of<float>(s, info.name);
      add_records(k, *solver, 32, measure_solver(m32, ts, truth32, key_ts, key32, range), samples);
    } catch (const invalid_input& x) {
      refused[std::string(solver->id)] = std::string("float: ") + x.what();
    }
  }

  json out{{"tool", spec.value("tool", "")},
           {"keys", keys.size()},
           {"value_range", range},
           {"window", {ts.front(), ts.back()}},
           {"samples", ts.size()},
           {"refused", refused},
           {"picture", picture(plain, ts.front(), ts.back())}};
  // Where the tools disagree on the same keys: max |a - b| over the keyed range / value range.
  if (spec.value("tool", "") == channel::tools::exact::name) {
    json skipped = json::object();
    const std::vector<channel::key<double>> kv(keys.begin(), keys.end());
    std::vector<keys_model> models = tool_models(kv, skipped);
    models.insert(models.begin(), {channel::tools::exact::name, "the keys as given, inverted at 50 digits", 64,
                                   [&truth](double t) { return static_cast<double>(truth.at(real50(t), 0)); }});
    std::vector<double> inside;
    for (double t : ts)
      if (t >= first && t <= last) inside.push_back(t);
    std::vector<std::vector<double>> values(models.size());
    for (std::size_t a = 0; a < models.size(); ++a)
      for (double t : inside) values[a].push_back(models[a].at(t));
    json pairs = json::array();
    for (std::size_t a = 0; a < models.size(); ++a)
      for (std::size_t b = a + 1; b < models.size(); ++b) {
        double d = 0;
        for (std::size_t j = 0; j < inside.size(); ++j) d = std::max(d, std::abs(values[a][j] - values[b][j]));
        pairs.push_back({{"a", std::string(models[a].name)}, {"b", std::string(models[b].name)}, {"max", d / range}});
      }
    json rules = json::object();
    for (const auto& m : models) rules[std::string(m.name)] = std::string(m.rules);
    out["models"] = {{"rules", rules}, {"skipped", skipped}, {"disagreement", pairs}};
  }
  return out;
}

}  // namespace curvebench::harness
