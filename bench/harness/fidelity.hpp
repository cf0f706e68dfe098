// Fidelity of the tool models: how many channels recorded from the real tools (Blender,
// Autodesk AnimX for Maya, OpenUSD's Ts) each model reproduces, and to what error.
//
// A recording (tests/data/*.json, written by the drivers under scripts/peers/) is
//   {"tool": "blender" | "maya" | "usd" | ...,
//    "source": {"implementation", "repository", "commit", "version", "build", "recorded", "command"},
//    "channels": [{"name", "features": ["tangent:auto", ...], "spec": {a channel spec},
//                  "t": [times], "value": [the real tool's values], "refused": "why" (optional),
//                  "unverified": "why the tool gave no values" (then no "value"), and fields of
//                  the recorder's own (Ts's "pre_value", "ts_widths", ...), kept, not measured}]}
// Each channel's spec is read by curvebench's own reader and evaluated as the tool evaluates it
// (harness::channel_values_of(spec, check_against::tool): the tool's solver and storage precision).
// The channel's error is max over its times of |model - recorded| / (R + |t| |V'(t)|): R the
// recorded values' range (their largest magnitude when they are all equal, 1 when that is 0; taken
// of halves when it passes double, as for values of +-1e308, so that it never overflows to an
// infinity that would make every error 0), and
// |t| |V'(t)| (the model's slope) the reach of the time's own rounding, which both programs suffer
// where t is large (a cycle wrapped a thousand periods out, a frame near 1e5). A
// channel agrees when its error is at most agree_ulps eps of the model's precision (float for a
// float tool): the tool's and the model's own roundings of the same operations, a few dozen ulps
// of the range between them at most (handles, the time solve, de Casteljau, the time's rounding
// times the slope), so a disagreement above it is a different rule, not rounding.
// A channel the reader or the model refuses counts as refused, with today's message (a channel
// recorded as refused that the model now evaluates is measured like the others).
// A time or a value that is not a finite number is refused (invalid_input naming the file, the
// channel's index and name, and the element's index). A channel recorded as "unverified" is
// neither agreement nor disagreement: it is counted apart (`curvebench fidelity
// --require-agreement` fails on it as unverified, and on a recording with no channel evaluated).
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace curvebench::harness {

/// A channel agrees when its error is at most this many eps of the model's precision (see above).
inline constexpr double agree_ulps = 128;

struct fidelity_channel {
  std::string name;
  std::vector<std::string> features;
  std::size_t times = 0;        ///< evaluated times
  double error = 0;             ///< max |model - recorded| / (scale + |t V'(t)|) (inf where the model has none)
  double worst_t = 0;           ///< the time of that error
  double model = 0;             ///< the model's value there
  double recorded = 0;          ///< the tool's value there
  double scale = 1;             ///< the recorded values' range (infinite past double: errors use halves)
  int bits = 64;                ///< the model's precision (32: float)
  bool refused = false;         ///< the spec was refused (reason below)
  std::string reason;           ///< why it was refused or is unverified
  bool marked_refused = false;  ///< the recording says the model refused it when it was recorded
  bool unverified = false;      ///< the tool recorded no values (its "unverified" says why, in reason)
  [[nodiscard]] double tolerance() const;  ///< agree_ulps eps(bits)
  [[nodiscard]] bool agrees() const { return !refused && !unverified && error <= tolerance(); }
  [[nodiscard]] bool evaluated() const { return !refused && !unverified; }
};

struct fidelity_feature {
  std::string feature;
  std::size_t channels = 0, agree = 0, refused = 0, unverified = 0;
  double max_error = 0;  ///< over its evaluated channels
};

struct fidelity_result {
  std::string file;
  std::string tool;
  nlohmann::json source;  ///< the recording's "source" as written
  std::vector<fidelity_channel> channels;
  std::vector<fidelity_feature> features;  ///< sorted by feature
  std::size_t agree = 0, refused = 0, unverified = 0;
  double max_error = 0;  ///< over the evaluated channels
  [[nodiscard]] std::size_t evaluated() const { return channels.size() - refused - unverified; }
};

/// Reads one recording (path: for messages and the result) and measures every channel. Throws
/// invalid_input for a file that is not a recording (naming the field), and for a time or value
/// that is not a finite number (naming the channel and the index); a channel's own spec errors
/// make it refused, not the file.
[[nodiscard]] fidelity_result measure_fidelity(const std::string& path);
/// The same for a recording already read.
[[nodiscard]] fidelity_result measure_fidelity(const nlohmann::json& recording, const std::string& path);

/// {"agree_ulps", "recordings": [{"file", "tool", "source", "channels", "agree", "refused",
///   "unverified", "max_error", "features": [...], "disagree": [{"name", "error", "t", "model",
///   "recorded"}], "refused_channels": [{"name", "reason"}], "unverified_channels": [...]}]}
[[nodiscard]] nlohmann::json to_json(const std::vector<fidelity_result>& results);

}  // namespace curvebench::harness
