// The gate target (targets.hpp): what `curvebench gate` does with its two files. The input is the
// results text, a NUL byte, then the thresholds text; without a NUL byte the same text is both (so
// one JSON object holding "records" and "rules" is a whole case, which keeps seeds and mutations
// simple).
//
// Properties:
//   documented exceptions only   io::parse and check_gate refuse with invalid_input only, with a
//                                non-empty message of bounded size
//   no vacuous pass              when check_gate reports no breach, the thresholds hold at least
//                                one rule, each with a check (a numeric max_error or min_order, or
//                                "honest": true), and the results at least one record: a gate that
//                                passes has checked something
//   breaches name their rule     every breach has a rule name and a message
#include "guard.hpp"
#include "targets.hpp"

#include "harness/gate.hpp"

#include "curvebench/io/json_fields.hpp"

#include <string>
#include <vector>

namespace curvebench::fuzz {

int gate_target(const std::uint8_t* data, std::size_t size) {
  constexpr std::string_view name = "gate";
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto nul = text.find('\0');
  const std::string_view results_text = nul == std::string_view::npos ? text : text.substr(0, nul);
  const std::string_view thresholds_text = nul == std::string_view::npos ? text : text.substr(nul + 1);
  io::json results, thresholds;
  if (!run_step(name, "parse results", domain_errors::violation,
                [&] { results = io::parse(results_text, "results.json"); }))
    return 0;
  if (!run_step(name, "parse thresholds", domain_errors::violation,
                [&] { thresholds = io::parse(thresholds_text, "thresholds.json"); }))
    return 0;
  std::vector<harness::breach> breaches;
  if (!run_step(name, "check_gate", domain_errors::violation,
                [&] { breaches = harness::check_gate(results, thresholds, "results.json", "thresholds.json"); }))
    return 0;
  for (const harness::breach& b : breaches)
    if (b.rule.empty() || b.message.empty())
      violation(name, "breaches name their rule", "rule \"" + b.rule + "\", message \"" + b.message + "\"");
  if (breaches.empty()) {
    const bool has_rules = thresholds.is_object() && thresholds.contains("rules") && thresholds["rules"].is_array() &&
                           !thresholds["rules"].empty();
    const bool has_records = results.is_object() && results.contains("records") && results["records"].is_array() &&
                             !results["records"].empty();
    if (!has_rules || !has_records)
      violation(name, "no vacuous pass",
                std::string("the gate passed with ") + (has_rules ? "rules" : "no rules") + " and " +
                    (has_records ? "records" : "no records"));
    for (std::size_t i = 0; i < thresholds["rules"].size(); ++i) {
      const io::json& rule = thresholds["rules"][i];
      const bool checks = rule.is_object() && ((rule.contains("max_error") && rule["max_error"].is_number()) ||
                                               (rule.contains("min_order") && rule["min_order"].is_number()) ||
                                               (rule.contains("honest") && rule["honest"] == true));
      if (!checks)
        violation(name, "no vacuous pass",
                  "the gate passed with rule " + std::to_string(i) +
                      ", which checks nothing: " + io::field::shown_value(rule));
    }
  }
  return 0;
}

}  // namespace curvebench::fuzz
