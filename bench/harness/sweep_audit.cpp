// The property audit of a case (seed 001's properties measured on a 2D case, up to 40 control
// points): the family is rebuilt from the spec with each perturbed set of points (Hermite slopes
// enter as tangent items), so any family and any user case can be audited. To be replaced by the
// audit of lib/include/curvebench/analysis/ with its markdown in harness/audit_table.hpp.
#include "harness/sweeps.hpp"

#include "curvebench/curves/property_audit.hpp"
#include "curvebench/io/spec.hpp"

#include <algorithm>
#include <iterator>
#include <span>
#include <string>
#include <string_view>

namespace curvebench::harness {

nlohmann::json sweep_audit(const case_info& info) {
  using json = nlohmann::json;
  static constexpr std::string_view point_families[] = {"polyline", "lagrange", "bezier", "rational_bezier",
                                                        "cardinal", "catmull_rom", "kochanek_bartels",
                                                        "natural_cubic", "bspline", "nurbs", "hermite"};
  const io::field spec = io::root(info.spec, info.name);
  const std::string type = spec.member("type").string();
  if (std::find(std::begin(point_families), std::end(point_families), type) == std::end(point_families)) return {};
  if (!spec.has("points") || spec.member("points").value.is_object() || spec.member("points").array_size() > 40)
    return {};
  const bool hermite = type == "hermite";
  if (hermite && !spec.has("slopes")) return {};
  point_list<double, 2> items = spec.member("points").points<double, 2>();
  const std::size_t n = items.size();
  std::vector<control_role> roles(n, control_role::point);
  if (hermite) {
    const point_list<double, 2> slopes = spec.member("slopes").points<double, 2>();
    items.insert(items.end(), slopes.begin(), slopes.end());
    roles.resize(items.size(), control_role::tangent);
  }
  const auto build = [&](std::span<const point<double, 2>> it) {
    json s = info.spec;
    s["points"] = io::detail::points_json<2>(it.first(n));
    if (hermite) s["slopes"] = io::detail::points_json<2>(it.subspan(n));
    return io::curve_from_spec<double, 2>(io::root(s, info.name));
  };
  try {
    const auto r = audit_properties<double, 2>(build, std::span<const point<double, 2>>(items), roles);
    return audit_markdown_row(info.name + " (" + type + ")", r);
  } catch (const invalid_input& e) {
    // Some families constrain their data (a periodic spline's last point equals its first), so
    // moving one control point alone is not a valid curve: the audit does not apply; say why.
    return "| " + info.name + " (" + type + ") | not audited: " + e.what() + " | | | | | |\n";
  }
}

}  // namespace curvebench::harness
