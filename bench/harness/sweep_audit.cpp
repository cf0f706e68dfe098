// The property audit of a case: seed 001's properties measured by curvebench::analysis on a 2D
// case. The family registry says which control items a family's audit moves (points, and tangents
// for Hermite slopes) and how a perturbed set of items becomes a spec again, so any family and any
// user case with an audit entry is audited; the markdown row is written by harness/audit_table.hpp.
#include "harness/sweeps.hpp"

#include "harness/audit_table.hpp"

#include "curvebench/analysis/property_audit.hpp"
#include "curvebench/io/registry.hpp"

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace curvebench::harness {

nlohmann::json sweep_audit(const case_info& info) {
  const std::optional<io::audit_items> items = io::audit_items_of(info.spec);
  if (!items) return {};
  const std::string label = info.name + " (" + info.spec.at("type").get<std::string>() + ")";
  std::vector<analysis::control_role> roles;
  roles.reserve(items->roles.size());
  for (const io::audit_role r : items->roles)
    roles.push_back(r == io::audit_role::point ? analysis::control_role::point : analysis::control_role::tangent);
  const auto build = [&](std::span<const point<double, 2>> it) {
    return io::curve_from_spec<double, 2>(io::root(io::with_items(info.spec, it), info.name));
  };
  try {
    const auto r = analysis::audit_properties<double, 2>(build, std::span<const point<double, 2>>(items->items), roles);
    return audit_markdown_row(label, r);
  } catch (const invalid_input& e) {
    // Some families constrain their data (a periodic spline's last point equals its first), so
    // moving one control point alone is not a valid curve: the audit does not apply; say why.
    return "| " + label + " | not audited: " + e.what() + " | | | | | |\n";
  }
}

}  // namespace curvebench::harness
