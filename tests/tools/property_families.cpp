// The families of docs/properties.md's measured table (see property_families.hpp). Every family is
// built from data(); knots are uniform unless the label says otherwise.
#include "tools/property_families.hpp"

#include "harness/audit_table.hpp"

#include "curvebench/curves/bezier.hpp"
#include "curvebench/curves/composite_bezier.hpp"
#include "curvebench/curves/hermite_spline.hpp"
#include "curvebench/curves/kochanek_bartels.hpp"
#include "curvebench/curves/lagrange.hpp"
#include "curvebench/curves/natural_cubic_spline.hpp"
#include "curvebench/curves/nurbs.hpp"
#include "curvebench/curves/polyline.hpp"
#include "curvebench/curves/rational_bezier.hpp"

#include <cstddef>
#include <stdexcept>
#include <utility>

namespace curvebench::property_families {

namespace {

namespace an = analysis;

std::vector<double> uniform(std::size_t count) {
  std::vector<double> k(count);
  for (std::size_t i = 0; i < count; ++i) k[i] = static_cast<double>(i);
  return k;
}

// Weights 0.5, 1.5, 2.5, 0.5, ... for the rational families.
std::vector<double> weights(std::size_t count) {
  std::vector<double> w(count);
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = 0.5 + static_cast<double>(i % 3);
  return w;
}

kochanek_bartels<double, 2> kb_with(span2 p, tcb<double> k) {
  return kochanek_bartels<double, 2>(list2(p.begin(), p.end()), std::vector<tcb<double>>(p.size(), k),
                                     typename kochanek_bartels<double, 2>::options{});
}
// A chain of cubics on knots 0, 1, 2, ... whose segments share their end items: P0..P3, P3..P6,
// P6..P9 (C0 at the joints, no handle constraint).
composite_bezier<double, 2> shared_joints(span2 p) {
  std::vector<list2> seg;
  std::vector<double> k{0};
  for (std::size_t i = 0; i + 3 < p.size(); i += 3) {
    seg.push_back(list2(p.begin() + static_cast<std::ptrdiff_t>(i), p.begin() + static_cast<std::ptrdiff_t>(i) + 4));
    k.push_back(k.back() + 1);
  }
  return composite_bezier<double, 2>(std::span<const list2>(seg), std::span<const double>(k));
}
// A chain of cubics whose items are all handles, each joint the midpoint of the two handles around
// it (P0 P1 P2 J, J P3 P4 J', ..., J'' P7 P8 P9 with J = (P2 + P3)/2, ...): C1 by construction, like
// TrueType's implied on-curve points.
composite_bezier<double, 2> implied_joints(span2 p) {
  std::vector<list2> seg;
  std::vector<double> k{0};
  P2 start = p[0];
  std::size_t i = 1;
  while (i + 4 < p.size()) {  // a middle segment: start, p[i], p[i+1], joint with p[i+2]
    const P2 joint = 0.5 * (p[i + 1] + p[i + 2]);
    seg.push_back({start, p[i], p[i + 1], joint});
    start = joint;
    i += 2;
    k.push_back(k.back() + 1);
  }
  seg.push_back({start, p[i], p[i + 1], p[i + 2]});
  k.push_back(k.back() + 1);
  return composite_bezier<double, 2>(std::span<const list2>(seg), std::span<const double>(k));
}

template <class Builder>
family_row audit(std::string label, Builder&& build, span2 items, std::span<const an::control_role> roles = {}) {
  return {std::move(label), an::audit_properties<double, 2>(build, items, roles)};
}

}  // namespace

const list2& data() {
  static const list2 d{{0, 0}, {1, 0}, {2.5, 0}, {3, 1.5}, {4, 1.5}, {5, 1.25}, {6, 3}, {7, 0.5}, {8, 1}, {9, 2.5}};
  return d;
}

bspline<double, 2> uniform_cubic_bspline(span2 p) {
  return bspline<double, 2>(4, bspline_uniform_knots<double>(p.size(), 4), list2(p.begin(), p.end()));
}
bspline<double, 2> clamped_cubic_bspline(span2 p) {
  return bspline<double, 2>(4, bspline_clamped_knots<double>(p.size(), 4, 0.0, 1.0), list2(p.begin(), p.end()));
}
cardinal_spline<double, 2> catmull_rom(span2 p) { return cardinal_spline<double, 2>(list2(p.begin(), p.end())); }
// Seed 001's cardinal spline: n points, n - 3 segments from P_1 to P_{n-2}; the end points only
// shape the end tangents s (P_2 - P_0) and s (P_{n-1} - P_{n-3}).
cardinal_spline<double, 2> seed_cardinal_spline(span2 p) {
  cardinal_options<double, 2> o;
  o.end = cardinal_end::given_tangents;
  o.start_tangent = 0.5 * (p[2] - p[0]);
  o.end_tangent = 0.5 * (p[p.size() - 1] - p[p.size() - 3]);
  return cardinal_spline<double, 2>(uniform(p.size() - 2), list2(p.begin() + 1, p.end() - 1), o);
}
cardinal_spline<double, 2> centripetal_catmull_rom(span2 p) {
  cardinal_options<double, 2> o;
  o.alpha = 0.5;
  return cardinal_spline<double, 2>(list2(p.begin(), p.end()), o);
}
std::vector<family_row> measure_all() {
  const list2& d = data();
  // Seed 001's Hermite chain: the first six points, each followed by a tangent item.
  list2 chain;
  std::vector<an::control_role> roles;
  for (std::size_t i = 0; i < 6; ++i) {
    chain.push_back(d[i]);
    chain.push_back(P2(1.0, (i % 2 == 0) ? 0.75 : -0.5));
    roles.push_back(an::control_role::point);
    roles.push_back(an::control_role::tangent);
  }
  std::vector<family_row> rows;
  rows.push_back(audit("B-spline, cubic, uniform knots", uniform_cubic_bspline, d));
  rows.push_back(audit("B-spline, cubic, clamped knots", clamped_cubic_bspline, d));
  rows.push_back(audit(
      "NURBS, cubic, clamped, weights 0.5..2.5",
      [](span2 p) {
        return nurbs<double, 2>(4, bspline_clamped_knots<double>(p.size(), 4, 0.0, 1.0), list2(p.begin(), p.end()),
                                weights(p.size()));
      },
      d));
  rows.push_back(audit(
      "Bezier, single, degree 9", [](span2 p) { return bezier<double, 2>(p); }, d));
  rows.push_back(audit(
      "rational Bezier, degree 9, weights 0.5..2.5",
      [](span2 p) {
        const std::vector<double> w = weights(p.size());
        return rational_bezier<double, 2>(p, std::span<const double>(w));
      },
      d));
  rows.push_back(audit(
      "Hermite chain (points + tangents)", [](span2 p) { return hermite_spline<double, 2>::chain(p); }, chain, roles));
  rows.push_back(audit("Catmull-Rom, seed 001 ends (n - 3 segments)", seed_cardinal_spline, d));
  rows.push_back(audit("Catmull-Rom, phantom ends, uniform", catmull_rom, d));
  rows.push_back(audit("Catmull-Rom, centripetal (alpha = 1/2)", centripetal_catmull_rom, d));
  rows.push_back(audit(
      "Kochanek-Bartels, t = 0.25, c = 0, b = -0.5",
      [](span2 p) {
        return kb_with(p, {0.25, 0.0, -0.5});
      },
      d));
  rows.push_back(audit(
      "Kochanek-Bartels, c = 0.5",
      [](span2 p) {
        return kb_with(p, {0.0, 0.5, 0.0});
      },
      d));
  rows.push_back(audit(
      "natural cubic spline (natural ends)",
      [](span2 p) {
        return natural_cubic_spline<double, 2>(uniform(p.size()), list2(p.begin(), p.end()), spline_end::natural);
      },
      d));
  rows.push_back(audit("composite Bezier, cubic, shared joints", shared_joints, d));
  rows.push_back(audit("composite Bezier, cubic, implied midpoint joints", implied_joints, d));
  rows.push_back(audit(
      "Lagrange, degree 9, equispaced", [](span2 p) { return lagrange<double, 2>(p); }, d));
  rows.push_back(audit(
      "polyline", [](span2 p) { return polyline<double, 2>(p); }, d));
  rows.push_back(audit(
      "B-spline, linear (order 2, clamped)",
      [](span2 p) {
        return bspline<double, 2>(2, bspline_clamped_knots<double>(p.size(), 2, 0.0, 1.0), list2(p.begin(), p.end()));
      },
      d));
  return rows;
}

std::string markdown_table(const std::vector<family_row>& rows) {
  std::string t = harness::audit_markdown_header();
  for (const family_row& r : rows) t += harness::audit_markdown_row(r.label, r.report);
  return t;
}

std::string document_path() { return std::string(CURVEBENCH_SOURCE_DIR) + "/docs/properties.md"; }

namespace {
// The offsets just after the begin marker and at the end marker.
std::pair<std::size_t, std::size_t> table_span(const std::string& document) {
  const std::size_t b = document.find(table_begin);
  if (b == std::string::npos) throw std::runtime_error(std::string("marker not found: ") + table_begin);
  const std::size_t start = b + std::string(table_begin).size();
  const std::size_t e = document.find(table_end, start);
  if (e == std::string::npos) throw std::runtime_error(std::string("marker not found: ") + table_end);
  return {start, e};
}
}  // namespace

std::string table_in(const std::string& document) {
  const auto [start, end] = table_span(document);
  return document.substr(start, end - start);
}

std::string with_table(const std::string& document, const std::string& table) {
  const auto [start, end] = table_span(document);
  return document.substr(0, start) + table + document.substr(end);
}

}  // namespace curvebench::property_families
