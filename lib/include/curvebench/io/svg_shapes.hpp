// SVG's basic shapes as the path data SVG 2 defines for them (section 10, "equivalent path"), so
// that a <circle>, <ellipse>, <rect>, <line>, <polyline> or <polygon> is measured as the path it
// draws:
//   circle   cx, cy, r: moveto (cx + r, cy), then four arcs of a quarter each with sweep-flag 1
//            through (cx, cy + r), (cx - r, cy), (cx, cy - r), back to the start, and Z;
//   ellipse  cx, cy, rx, ry likewise (rx or ry absent, SVG 2's "auto": the other one);
//   rect     x, y, width, height, rx, ry: rx and ry absent take each other's value (both absent:
//            0), then are limited to width / 2 and height / 2; with both > 0 the outline starts at
//            (x + rx, y) and goes clockwise in SVG's y-down coordinates: the top edge, a quarter
//            arc, the right edge, ... (lines and arcs; an edge of zero length is omitted); square
//            corners otherwise, from (x, y);
//   line     x1, y1, x2, y2: moveto, lineto;
//   polyline the points in order; polygon the same and Z.
// Attributes absent take SVG's initial value 0. A shape that SVG does not render (r, rx, ry,
// width or height 0 where the shape needs them) draws no path: refused here, since it has no
// length to measure. A negative radius, width or height is an error in SVG and here; the message
// names the element and the attribute. Numbers are written in the shortest form that reads back as
// the same double, so the path data holds exactly the shape's coordinates (sums such as cx + r are
// rounded once, in double, as a browser computes them).
#pragma once

#include "curvebench/core/error.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace curvebench::io::svg {

/// A basic shape: its element's name and its numeric attributes (user units), or its points.
struct shape {
  std::string element;                    ///< circle, ellipse, rect, line, polyline, polygon
  std::map<std::string, double> numbers;  ///< cx, cy, r, rx, ry, x, y, width, height, x1, ... (absent: SVG's default)
  std::vector<std::array<double, 2>> points;  ///< polyline, polygon
};

namespace detail {

/// The shortest decimal that reads back as v (std::to_chars); finite v only.
inline std::string number_text(double v) {
  std::array<char, 32> buf{};
  const auto [end, ec] = std::to_chars(buf.data(), buf.data() + buf.size(), v);
  if (ec != std::errc{}) throw invalid_input("svg shape: cannot write the number");
  return std::string(buf.data(), end);
}

class shape_reader {
 public:
  explicit shape_reader(const shape& s) : s_(s) {}

  /// Attribute `name`, or `fallback` when absent; a non-finite value is refused by name.
  [[nodiscard]] std::optional<double> get(const std::string& name) const {
    const auto it = s_.numbers.find(name);
    if (it == s_.numbers.end()) return std::nullopt;
    if (!std::isfinite(it->second))
      throw invalid_input("svg <" + s_.element + ">: " + name + " = " + number_text_any(it->second) +
                          " is not a finite number");
    return it->second;
  }
  [[nodiscard]] double value(const std::string& name) const { return get(name).value_or(0.0); }
  /// A size (radius, width, height): absent is `absent`; negative is an error; 0 draws nothing.
  [[nodiscard]] std::optional<double> size(const std::string& name) const {
    const std::optional<double> v = get(name);
    if (v && *v < 0)
      throw invalid_input("svg <" + s_.element + ">: " + name + " = " + number_text(*v) +
                          " is negative (SVG allows a " + name + " >= 0)");
    return v;
  }
  [[noreturn]] void draws_nothing(const std::string& why) const {
    throw invalid_input("svg <" + s_.element + ">: " + why +
                        ", so SVG renders nothing and there is no length to measure");
  }

 private:
  static std::string number_text_any(double v) { return std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf"; }
  const shape& s_;
};

/// Path data of an ellipse centred at (cx, cy) with radii rx, ry > 0 (SVG 2's four arcs).
inline std::string ellipse_data(double cx, double cy, double rx, double ry) {
  const std::string r = number_text(rx) + " " + number_text(ry) + " 0 0 1 ";
  auto at = [](double x, double y) { return number_text(x) + " " + number_text(y); };
  return "M" + at(cx + rx, cy) + " A" + r + at(cx, cy + ry) + " A" + r + at(cx - rx, cy) + " A" + r + at(cx, cy - ry) +
         " A" + r + at(cx + rx, cy) + " Z";
}

}  // namespace detail

/// The path data SVG 2 defines for shape s (see the header); invalid_input naming the element and
/// attribute for an unknown element, a negative size, or a shape SVG would not render.
[[nodiscard]] inline std::string shape_path_data(const shape& s) {
  using detail::number_text;
  const detail::shape_reader a(s);
  auto at = [](double x, double y) { return number_text(x) + " " + number_text(y); };
  if (s.element == "circle") {
    const double r = a.size("r").value_or(0.0);
    if (r == 0) a.draws_nothing("r is 0 or absent");
    return detail::ellipse_data(a.value("cx"), a.value("cy"), r, r);
  }
  if (s.element == "ellipse") {
    std::optional<double> rx = a.size("rx"), ry = a.size("ry");
    if (!rx) rx = ry;
    if (!ry) ry = rx;
    if (!rx || *rx == 0 || *ry == 0) a.draws_nothing("rx or ry is 0 or both are absent");
    return detail::ellipse_data(a.value("cx"), a.value("cy"), *rx, *ry);
  }
  if (s.element == "rect") {
    const double w = a.size("width").value_or(0.0), h = a.size("height").value_or(0.0);
    if (w == 0 || h == 0) a.draws_nothing("width or height is 0 or absent");
    std::optional<double> rxo = a.size("rx"), ryo = a.size("ry");
    if (!rxo) rxo = ryo;
    if (!ryo) ryo = rxo;
    const double rx = std::min(rxo.value_or(0.0), w / 2), ry = std::min(ryo.value_or(0.0), h / 2);
    const double x = a.value("x"), y = a.value("y");
    if (!(rx > 0 && ry > 0))
      return "M" + at(x, y) + " H" + number_text(x + w) + " V" + number_text(y + h) + " H" + number_text(x) + " Z";
    const std::string arc = " A" + number_text(rx) + " " + number_text(ry) + " 0 0 1 ";
    std::string d = "M" + at(x + rx, y);
    // An edge of zero length (rx = w / 2 or ry = h / 2) is left out rather than written as a lineto
    // that draws nothing.
    if (x + w - rx != x + rx) d += " H" + number_text(x + w - rx);
    d += arc + at(x + w, y + ry);
    if (y + h - ry != y + ry) d += " V" + number_text(y + h - ry);
    d += arc + at(x + w - rx, y + h);
    if (x + rx != x + w - rx) d += " H" + number_text(x + rx);
    d += arc + at(x, y + h - ry);
    if (y + ry != y + h - ry) d += " V" + number_text(y + ry);
    return d + arc + at(x + rx, y) + " Z";
  }
  if (s.element == "line") return "M" + at(a.value("x1"), a.value("y1")) + " L" + at(a.value("x2"), a.value("y2"));
  if (s.element == "polyline" || s.element == "polygon") {
    if (s.points.size() < 2)
      throw invalid_input("svg <" + s.element + ">: points holds " + std::to_string(s.points.size()) +
                          " point(s); at least 2 are needed to draw a segment");
    std::string d;
    for (std::size_t i = 0; i < s.points.size(); ++i) {
      const auto& p = s.points[i];
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]))
        throw invalid_input("svg <" + s.element + ">: points[" + std::to_string(i) + "] is not finite");
      d += (i == 0 ? "M" : " L") + at(p[0], p[1]);
    }
    return s.element == "polygon" ? d + " Z" : d;
  }
  throw invalid_input("svg: <" + s.element +
                      "> is not a shape curvebench measures (path, circle, ellipse, rect, line, polyline, polygon)");
}

}  // namespace curvebench::io::svg
