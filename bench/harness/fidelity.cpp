// The fidelity of the tool models against recordings of the real tools (harness/fidelity.hpp).
#include "harness/fidelity.hpp"

#include "harness/check.hpp"
#include "harness/files.hpp"
#include "harness/record.hpp"  // finite_or_null

#include "curvebench/core/error.hpp"
#include "curvebench/io/json_fields.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace curvebench::harness {

namespace {

/// The array `key` of recorded channel `c` (named `name` in messages): finite numbers only, each
/// other element refused naming the channel and its index (a NaN or an infinity is no value a tool
/// computed at a time, and an error measured against it would mean nothing).
std::vector<double> recorded_numbers(const io::field& c, const char* key, const char* what, const std::string& name) {
  const io::field list = c.member(key, what);
  std::vector<double> out;
  out.reserve(list.array_size());
  for (std::size_t i = 0; i < list.array_size(); ++i) {
    const io::field e = list.element(i);
    if (!e.value.is_number() || !std::isfinite(e.value.get<double>()))
      e.fail("channel \"" + validate::visible(name) + "\": " + key + "[" + std::to_string(i) +
             "] is not a finite number, got " + e.shown());
    out.push_back(e.value.get<double>());
  }
  return out;
}

/// Measures one channel of a recording; refused when its spec or the model refuses it.
fidelity_channel measure_channel(const io::field& c) {
  fidelity_channel out;
  out.name = c.member("name", "each recorded channel has a name").string();
  if (c.has("features")) {
    const io::field f = c.member("features");
    for (std::size_t i = 0; i < f.array_size(); ++i) out.features.push_back(f.element(i).string());
  }
  if (c.has("unverified")) {  // the tool computes no value for it (Ts 24.11 and Hermite segments)
    out.unverified = true;
    out.reason = c.member("unverified").string();
    return out;
  }
  const std::vector<double> ts = recorded_numbers(c, "t", "the times the tool evaluated", out.name);
  const std::vector<double> vs = recorded_numbers(c, "value", "the tool's values at t", out.name);
  if (ts.size() != vs.size())
    c.fail("has " + std::to_string(ts.size()) + " times and " + std::to_string(vs.size()) +
           " values: one value per time");
  if (ts.empty()) c.member("t").fail("is empty: a recorded channel has at least one time");
  out.times = ts.size();
  out.marked_refused = c.has("refused");
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, magnitude = 0;
  for (double v : vs) lo = std::min(lo, v), hi = std::max(hi, v), magnitude = std::max(magnitude, std::abs(v));
  out.scale = hi > lo ? hi - lo : (magnitude > 0 ? magnitude : 1.0);
  // The same of halves, for when the range or a gap passes double: max - min of +-1e308 is
  // infinite, and every error divided by it was 0, so a model far off "agreed". Halving is exact
  // for the normal numbers such values are.
  const double half_scale = hi > lo ? hi / 2 - lo / 2 : (magnitude > 0 ? magnitude / 2 : 0.5);

  const io::field spec = c.member("spec", "the channel as a curvebench channel spec");
  std::optional<channel_values> model;
  try {
    model = channel_values_of(spec, check_against::tool);
  } catch (const invalid_input& e) {  // the reader or the model refuses it (spec_error is one)
    out.refused = true;
    out.reason = e.what();
    return out;
  }
  out.bits = model->bits;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const std::optional<double> m = model->at(ts[i], 0);
    // The time's own rounding moves a value by up to |t| eps |V'(t)| in either program (a wrapped
    // cycle far out, a frame near 1e5), so the scale at t adds |t| |V'(t)| to the range.
    const std::optional<double> slope = model->at(ts[i], 1);
    const double reach = slope && std::isfinite(*slope) ? std::abs(ts[i] * *slope) : 0.0;
    double e = std::numeric_limits<double>::infinity();
    if (m && std::isfinite(*m)) {
      const double gap = std::abs(*m - vs[i]), room = out.scale + reach;
      e = std::isfinite(gap) && std::isfinite(room) ? gap / room
                                                    : std::abs(*m / 2 - vs[i] / 2) / (half_scale + reach / 2);
    }
    if (i == 0 || e > out.error) {
      out.error = e;
      out.worst_t = ts[i];
      out.model = m ? *m : std::numeric_limits<double>::quiet_NaN();
      out.recorded = vs[i];
    }
  }
  return out;
}

}  // namespace

double fidelity_channel::tolerance() const {
  const double eps =
      bits == 32 ? static_cast<double>(std::numeric_limits<float>::epsilon()) : std::numeric_limits<double>::epsilon();
  return agree_ulps * eps;
}

fidelity_result measure_fidelity(const nlohmann::json& recording, const std::string& path) {
  const io::field root = io::root(recording, path);
  root.only_members({"tool", "source", "channels", "note"});
  fidelity_result r;
  r.file = path;
  r.tool = root.member("tool", "the tool whose evaluation was recorded").string();
  r.source = root.member("source", "where the values come from (implementation, version, build)").value;
  if (!r.source.is_object()) root.member("source").fail("must be an object");
  const io::field channels = root.member("channels", "the recorded channels");
  std::map<std::string, fidelity_feature> features;
  for (std::size_t i = 0; i < channels.array_size(); ++i) {
    const io::field c = channels.element(i);
    fidelity_channel fc = measure_channel(c);
    if (fc.evaluated()) {
      const io::field tool = c.member("spec").member("tool", "a channel spec names its tool");
      if (tool.string() != r.tool)
        tool.fail("is not the recording's tool \"" + r.tool + "\": a recording holds one tool's channels");
    }
    std::vector<std::string> tags = fc.features;
    tags.push_back("all");
    for (const std::string& tag : tags) {
      fidelity_feature& f = features[tag];
      f.feature = tag;
      ++f.channels;
      if (fc.refused) {
        ++f.refused;
      } else if (fc.unverified) {
        ++f.unverified;
      } else {
        f.agree += fc.agrees() ? 1 : 0;
        f.max_error = std::max(f.max_error, fc.error);
      }
    }
    r.channels.push_back(std::move(fc));
  }
  // The recording's totals are the tally of the tag every channel carries.
  const fidelity_feature& all = features["all"];
  r.agree = all.agree, r.refused = all.refused, r.unverified = all.unverified, r.max_error = all.max_error;
  features.erase("all");
  for (auto& [tag, f] : features) r.features.push_back(std::move(f));
  return r;
}

fidelity_result measure_fidelity(const std::string& path) {
  return measure_fidelity(io::parse(read_input_file(path, "recording "), path), path);
}

nlohmann::json to_json(const std::vector<fidelity_result>& results) {
  nlohmann::json recs = nlohmann::json::array();
  for (const fidelity_result& r : results) {
    nlohmann::json features = nlohmann::json::array(), disagree = nlohmann::json::array(),
                   refused = nlohmann::json::array(), unverified = nlohmann::json::array();
    for (const fidelity_feature& f : r.features)
      features.push_back({{"feature", f.feature},
                          {"channels", f.channels},
                          {"agree", f.agree},
                          {"refused", f.refused},
                          {"unverified", f.unverified},
                          {"max_error", finite_or_null(f.max_error)}});
    double tolerance = 0;
    for (const fidelity_channel& c : r.channels) {
      if (c.refused || c.unverified) {
        (c.refused ? refused : unverified).push_back({{"name", c.name}, {"reason", c.reason}});
        continue;
      }
      tolerance = std::max(tolerance, c.tolerance());
      if (!c.agrees())
        disagree.push_back({{"name", c.name},
                            {"features", c.features},
                            {"error", finite_or_null(c.error)},
                            {"t", c.worst_t},
                            {"model", finite_or_null(c.model)},
                            {"recorded", c.recorded}});
    }
    recs.push_back({{"file", r.file},
                    {"tool", r.tool},
                    {"source", r.source},
                    {"channels", r.channels.size()},
                    {"agree", r.agree},
                    {"refused", r.refused},
                    {"unverified", r.unverified},
                    {"tolerance", tolerance},
                    {"max_error", finite_or_null(r.max_error)},
                    {"features", features},
                    {"disagree", disagree},
                    {"refused_channels", refused},
                    {"unverified_channels", unverified}});
  }
  return {{"agree_ulps", agree_ulps}, {"recordings", recs}};
}

}  // namespace curvebench::harness
