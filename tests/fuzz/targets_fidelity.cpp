// The fidelity target (targets.hpp): what `curvebench fidelity` does with a recording of a tool:
// io::parse, then harness::measure_fidelity (each channel's spec read and evaluated as the tool
// evaluates it), then its JSON.
//
// Properties:
//   documented exceptions only   io::parse and measure_fidelity refuse with invalid_input only
//                                (a channel's own spec errors make it refused, not the file), with a
//                                non-empty message of bounded size
//   counts add up                agree + disagree + refused + unverified is every channel, the
//                                evaluated count is what is neither refused nor unverified, and
//                                the per-feature counts are each at most the recording's
//   measured errors              an evaluated channel's error is >= 0 and not NaN, its scale > 0,
//                                and it agrees exactly when its error is within its tolerance
//   recorded values are finite   a channel measured has only finite times and values (a NaN or an
//                                infinity is refused: measured, it would read as error 0)
//   JSON output                  to_json of the result dumps
#include "guard.hpp"
#include "targets.hpp"

#include "harness/fidelity.hpp"

#include "curvebench/io/json_fields.hpp"

#include <cmath>
#include <string>

namespace curvebench::fuzz {

int fidelity_target(const std::uint8_t* data, std::size_t size) {
  constexpr std::string_view name = "fidelity";
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  io::json recording;
  if (!run_step(name, "parse", domain_errors::violation, [&] { recording = io::parse(text, "rec.json"); })) return 0;
  harness::fidelity_result r;
  if (!run_step(name, "measure_fidelity", domain_errors::violation,
                [&] { r = harness::measure_fidelity(recording, "rec.json"); }))
    return 0;
  std::size_t agree = 0, disagree = 0, refused = 0, unverified = 0;
  for (const harness::fidelity_channel& c : r.channels) {
    if (c.refused) {
      ++refused;
    } else if (c.unverified) {
      ++unverified;
    } else {
      if (std::isnan(c.error) || c.error < 0 || !(c.scale > 0))
        violation(name, "measured errors",
                  c.name + ": error " + std::to_string(c.error) + ", scale " + std::to_string(c.scale));
      if (c.agrees() != (c.error <= c.tolerance()))
        violation(name, "measured errors", c.name + ": agrees() disagrees with its error and tolerance");
      if (!std::isfinite(c.recorded) || !std::isfinite(c.worst_t))
        violation(name, "recorded values are finite", c.name + ": a non-finite time or value was measured");
      (c.agrees() ? agree : disagree) += 1;
    }
  }
  if (agree != r.agree || refused != r.refused || unverified != r.unverified ||
      agree + disagree + refused + unverified != r.channels.size() || r.evaluated() != agree + disagree)
    violation(name, "counts add up",
              std::to_string(r.agree) + " agree, " + std::to_string(r.refused) + " refused, " +
                  std::to_string(r.unverified) + " unverified of " + std::to_string(r.channels.size()) + "; counted " +
                  std::to_string(agree) + ", " + std::to_string(refused) + ", " + std::to_string(unverified));
  for (const harness::fidelity_feature& f : r.features)
    if (f.channels > r.channels.size() || f.agree + f.refused + f.unverified > f.channels)
      violation(name, "counts add up", "feature " + f.feature + ": counts past its channels");
  std::string json_text;
  if (!run_step(name, "to_json", domain_errors::violation, [&] { json_text = harness::to_json({r}).dump(); }))
    violation(name, "JSON output", "to_json refused a result it had measured");
  return 0;
}

}  // namespace curvebench::fuzz
