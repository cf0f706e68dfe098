// curvebench fidelity: how many channels recorded from the real tools (tests/data/*.json in the
// recording format of harness/fidelity.hpp) each tool model reproduces, and to what error.
#include "tool/tool.hpp"

#include "harness/check_detail.hpp"
#include "harness/fidelity.hpp"

#include "curvebench/core/error.hpp"

#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

namespace curvebench::tool {

namespace {

using harness::detail::num;  // "%.*g"

std::string source_line(const nlohmann::json& s) {
  std::string out;
  for (const char* k : {"implementation", "version", "commit", "build"})
    if (s.contains(k) && s[k].is_string() && !s[k].get<std::string>().empty())
      out += (out.empty() ? "" : ", ") + std::string(k == std::string("commit") ? "commit " : "") +
             s[k].get<std::string>();
  return out.empty() ? "(no source given)" : out;
}

void print(const harness::fidelity_result& r) {
  const std::size_t evaluated = r.evaluated();
  const int bits = r.channels.empty() ? 64 : r.channels.front().bits;
  std::cout << r.tool << " against " << source_line(r.source) << " (" << r.file << "):\n  " << r.agree << " of "
            << evaluated << " evaluated channels agree to " << harness::agree_ulps << " eps("
            << (bits == 32 ? "float" : "double") << ") of their scale (the value range + |t V'(t)|); max error "
            << num(r.max_error, 3) << " of the scale";
  if (r.refused > 0) std::cout << "; " << r.refused << " refused (not modelled)";
  if (r.unverified > 0) std::cout << "; " << r.unverified << " without the tool's values (unverified)";
  std::cout << "\n  " << std::left << std::setw(28) << "feature" << std::setw(10) << "channels" << std::setw(8)
            << "agree" << std::setw(9) << "refused"
            << "max error\n";
  for (const harness::fidelity_feature& f : r.features)
    std::cout << "  " << std::setw(28) << f.feature << std::setw(10) << f.channels << std::setw(8) << f.agree
              << std::setw(9) << f.refused << num(f.max_error, 3) << "\n";
  for (const harness::fidelity_channel& c : r.channels) {
    if (c.refused || c.unverified)
      std::cout << (c.refused ? "  refused: " : "  unverified: ") << c.name << ": " << c.reason << "\n";
    else if (!c.agrees())
      std::cout << "  disagrees: " << c.name << ": " << num(c.error, 3) << " of the scale at t = " << num(c.worst_t)
                << " (model " << num(c.model) << ", tool " << num(c.recorded) << ")\n";
  }
  std::cout << std::right;
}

}  // namespace

CLI::App* add_fidelity(CLI::App& app, fidelity_args& a) {
  auto* f = app.add_subcommand(
      "fidelity",
      "how many channels recorded from the real tools (Blender, AnimX for Maya, OpenUSD's Ts) each tool model "
      "reproduces, per feature, and to what error (relative to the channel's value range plus |t V'(t)|, the reach "
      "of the time's rounding)");
  f->add_option("recordings", a.recordings,
                "recording files (tests/data/recorded/*.json: Blender, AnimX, OpenUSD Ts; "
                "{\"tool\", \"source\", \"channels\": [{\"name\", \"features\", \"spec\", \"t\", \"value\"}]})")
      ->required()
      ->check(CLI::ExistingFile);
  f->add_flag("--json", a.json, "JSON on stdout (the report's reports/fidelity.json)");
  f->add_flag("--require-agreement", a.require,
              "exit 1 when a channel disagrees, is refused without the recording saying it was, or is unverified "
              "(recorded without the tool's values: not agreement); a recording with no channel evaluated is an error");
  f->footer(example("curvebench fidelity tests/data/recorded/animx_curves.json"));
  return f;
}

int run_fidelity(const fidelity_args& a) {
  std::vector<harness::fidelity_result> results;
  for (const std::string& path : a.recordings) results.push_back(harness::measure_fidelity(path));
  // A recording with nothing compared proves nothing: "channels": [], or every channel refused or
  // unverified, would pass the gate with nothing checked. Refused before anything is printed.
  if (a.require)
    for (const auto& r : results)
      if (r.evaluated() == 0)
        throw invalid_input(r.file + ": " +
                            (r.channels.empty() ? std::string("holds no channel")
                                                : "no channel was evaluated (" + std::to_string(r.refused) +
                                                      " refused, " + std::to_string(r.unverified) + " unverified)") +
                            ": --require-agreement needs at least one channel compared with the tool");
  if (a.json) {
    nlohmann::json j = harness::to_json(results);
    j["curvebench"] = version_line();  // the models measured: the published table names them
    std::cout << std::setw(1) << j << "\n";
  } else
    for (const auto& r : results) print(r);
  int failed = 0;
  for (const auto& r : results)
    for (const auto& c : r.channels) {
      std::string why;
      if (c.unverified)  // not agreement, nor a disagreement: the tool gave no value to agree with
        why =
            " is unverified (the tool recorded no values: " + validate::visible(c.reason) + "), which is not agreement";
      else if (c.refused && !c.marked_refused)
        why = " is refused but not recorded as refused";
      else if (!c.refused && !c.agrees())
        why = " disagrees with the tool";
      if (why.empty()) continue;
      if (a.require) std::cerr << "curvebench: fidelity: " << r.file << ": " << c.name << why << "\n";
      ++failed;
    }
  return a.require && failed > 0 ? 1 : 0;
}

}  // namespace curvebench::tool
