// What every tool's spec parser (io/tools/<tool>.hpp) shares: the tool_spec template each one
// specializes, and the readers of fields that several tools have (a handle [dt, dv], the time
// solver, the channel extrapolation names).
//
// tool_spec<Tool> (Tool a channel::tool, channel/tool_model.hpp) provides
//   fields     the tool's own fields of a "channel" spec with their docs (the channel family's
//              field docs are assembled from these, io/families/channel.hpp);
//   example    one spec text that parses and builds;
//   parse<Real>(spec)  the tool's model (Tool::model<Real>) of the spec;
// and optionally
//   check_curve_view(spec, dim)  invalid_input when the spec has no planar curve view of dimension
//                                dim (besides the family's own 2D rule);
//   dimension(spec)              the curve's dimension when it is not 2.
#pragma once

#include "curvebench/channel/channel.hpp"
#include "curvebench/channel/time_solver.hpp"
#include "curvebench/io/family.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace curvebench::io {

template <class Tool>
struct tool_spec;

namespace detail {

template <class Real>
channel::handle<Real> handle_of(const field& key, std::string_view side) {
  if (!key.has(side)) return {Real(0), Real(0)};
  const field h = key.member(side);
  const std::vector<Real> v = h.reals<Real>();
  if (v.size() != 2) h.fail("expected [dt, dv], two numbers, got " + std::to_string(v.size()));
  return {v[0], v[1]};
}

inline channel::extrapolation extrapolation_of(const field& spec, std::string_view side) {
  if (!spec.has(side)) return channel::extrapolation::constant;
  return channel::from_string<channel::extrapolation>(
      spec.member(side).one_of({"constant", "linear", "cycle", "cycle_offset", "oscillate"}));
}

inline channel::time_solver solver_of(const field& spec, channel::time_solver fallback) {
  if (!spec.has("solver")) return fallback;
  const field f = spec.member("solver");
  const std::string id = f.string();
  for (channel::time_solver s : channel::all_time_solvers)
    if (channel::to_string(s) == id) return s;
  std::string list;
  for (channel::time_solver s : channel::all_time_solvers)
    list += (list.empty() ? "" : ", ") + std::string(to_string(s));
  f.fail("not a time solver: one of " + list);
  return fallback;
}

}  // namespace detail

}  // namespace curvebench::io
