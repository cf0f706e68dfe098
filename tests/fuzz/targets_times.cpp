// The times target (targets.hpp): `curvebench sample SPEC --at ... / --range ... / --frames ...` on a
// channel spec, in double. The input's first line is the option and its text ("at 0,0.5,1",
// "frames 0:24:0.5", "range 0:1:0.25"), read by the tool's own parsers (bench/tool/parameters.hpp);
// the rest is the spec, read as the tool reads it, and when it is a channel ("type": "channel")
// its tool's model (io::channel_model_of_spec; a glTF rotation's sampler) is evaluated at the
// first 256 times, value and time derivatives of orders 1 and 2, as `sample` prints them.
//
// Properties:
//   documented exceptions only   the parsers, the spec and the model refuse with invalid_input /
//                                io::spec_error only, the evaluation with those or std::domain_error
//                                (an unbounded derivative, a value past double's range), each with a
//                                non-empty message of bounded size
//   parameters as documented     at most max_sample_values, each finite; a grid (range, frames)
//                                non-decreasing
//   no NaN value                 the value (order 0) at a finite time is a number or refused: NaN is
//                                the silent garbage `sample` must never print (a value past double's
//                                range may be +-inf: the tool refuses it as not representable)
//   bounded work                 parsing, building and the evaluations take at most 10 s
#include "guard.hpp"
#include "targets.hpp"

#include "tool/parameters.hpp"

#include "curvebench/io/families/channel.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/io/spec_data.hpp"
#include "curvebench/io/tools/gltf.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace curvebench::fuzz {

namespace {

constexpr std::string_view name = "times";
constexpr std::size_t max_evaluated = 256;

std::vector<double> parse_option(std::string_view line) {
  std::vector<tool::parameter> p;
  const auto space = line.find(' ');
  const std::string option(line.substr(0, space));
  const std::string text(space == std::string_view::npos ? std::string_view() : line.substr(space + 1));
  bool grid = false;
  run_step(name, "option " + option, domain_errors::violation, [&] {
    if (option == "at") {
      p = tool::parse_at(text);
    } else if (option == "range") {
      p = tool::parse_range(text), grid = true;
    } else if (option == "frames") {
      p = tool::parse_range(text, "--frames", 1.0), grid = true;
    }
  });
  if (p.size() > tool::max_sample_values)
    violation(name, "parameters as documented", std::to_string(p.size()) + " parameters from " + option);
  std::vector<double> out;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!std::isfinite(p[i].u)) violation(name, "parameters as documented", p[i].where + " is not finite");
    if (grid && i > 0 && p[i].u < p[i - 1].u)
      violation(name, "parameters as documented", p[i].where + " lies below the value before it");
    if (p[i].where.empty()) violation(name, "parameters as documented", "a parameter without its words");
    out.push_back(p[i].u);
  }
  return out;
}

void evaluate(const io::field& spec, const std::vector<double>& times) {
  const std::size_t n = std::min(times.size(), max_evaluated);
  // Reading "tool" and "path" may refuse the spec already (a tool that is not a string, a path
  // that is neither weights nor rotation): a documented refusal, as the tool reports it.
  bool rotation = false;
  if (!run_step(name, "is_gltf_rotation", domain_errors::violation, [&] { rotation = io::is_gltf_rotation(spec); }))
    return;
  if (rotation) {
    std::optional<channel::gltf::rotation_sampler<double>> r;
    if (!run_step(name, "rotation_of_spec", domain_errors::violation,
                  [&] { r.emplace(io::rotation_of_spec<double>(spec)); }))
      return;
    for (std::size_t i = 0; i < n; ++i)
      for (int order = 0; order <= 2; ++order)
        run_step(name, "rotation sampler", domain_errors::refusal, [&] {
          const auto q = r->derivative(times[i], order);
          for (int d = 0; d < 4; ++d)
            if (order == 0 && std::isnan(q[d]))
              violation(name, "no NaN value", "the rotation at t = " + to_text(times[i]) + " has a NaN component");
        });
    return;
  }
  std::optional<io::channel_model<double>> m;
  if (!run_step(name, "channel_model_of_spec", domain_errors::violation,
                [&] { m.emplace(io::channel_model_of_spec<double>(spec)); }))
    return;
  for (std::size_t i = 0; i < n; ++i)
    for (int order = 0; order <= 2; ++order)
      run_step(name, "channel model", domain_errors::refusal, [&] {
        const double v = m->at(times[i], order);
        if (order == 0 && std::isnan(v))
          violation(name, "no NaN value", "the value at t = " + to_text(times[i]) + " is NaN");
      });
}

}  // namespace

int times_target(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto newline = text.find('\n');
  const auto start = std::chrono::steady_clock::now();
  const std::vector<double> times = parse_option(text.substr(0, newline));
  if (newline != std::string_view::npos) {
    const std::string body(text.substr(newline + 1));
    std::optional<nlohmann::json> j;
    if (run_step(name, "parse", domain_errors::violation, [&] { j.emplace(io::parse(body, "spec.json")); })) {
      const io::field spec = io::root(*j, "spec.json");
      if (j->is_object() && j->contains("type") && (*j)["type"] == "channel") evaluate(spec, times);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (seconds > 10)
    violation(name, "bounded work",
              "the input took " + std::to_string(seconds) + " s (" + std::to_string(size) + " bytes, " +
                  std::to_string(times.size()) + " times)");
  return 0;
}

}  // namespace curvebench::fuzz
