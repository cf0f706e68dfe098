// curvebench length --svg: the paths and basic shapes of an SVG file as svg_path specs, read with
// pugixml (Debian's libpugixml-dev), never a hand-written XML parser.
#include "tool/tool.hpp"

#include "harness/files.hpp"

#include "curvebench/core/error.hpp"

#include <pugixml.hpp>

#include <charconv>
#include <cstring>
#include <string_view>

namespace curvebench::tool {

namespace {

/// An SVG <length> or <number> attribute in user units: a number, optionally followed by "px"
/// (1 user unit); surrounding white space allowed. Anything else (%, em, mm: units that need a
/// viewport or a font) is refused naming the element and the attribute.
double user_units(const std::string& where, const char* name, const char* text) {
  std::string_view v(text);
  auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; };
  while (!v.empty() && space(v.front())) v.remove_prefix(1);
  while (!v.empty() && space(v.back())) v.remove_suffix(1);
  if (v.size() > 2 && v.substr(v.size() - 2) == "px") v.remove_suffix(2);
  double x = 0;
  const char* first = v.data();
  if (!v.empty() && v.front() == '+') ++first;  // SVG's numbers may carry a '+'; from_chars takes none
  const auto [end, ec] = std::from_chars(first, v.data() + v.size(), x);
  if (v.empty() || ec != std::errc{} || end != v.data() + v.size() || !std::isfinite(x))
    throw invalid_input(where + ": " + name + "=\"" + validate::visible(text) +
                        "\" is not a number in user units (a number, optionally with px; %, em and other units need a "
                        "viewport or a font and are not read)");
  return x;
}

const char* const shape_attributes[] = {"cx",    "cy",     "r",  "rx", "ry", "x", "y",
                                        "width", "height", "x1", "y1", "x2", "y2"};

}  // namespace

std::vector<svg_element> read_svg_elements(const std::string& file) {
  const std::string text = harness::read_input_file(file);
  pugi::xml_document doc;
  const pugi::xml_parse_result parsed = doc.load_buffer(text.data(), text.size(), pugi::parse_default);
  if (!parsed)
    throw invalid_input(file + ": not well-formed XML at byte offset " + std::to_string(parsed.offset) + ": " +
                        parsed.description());
  const pugi::xml_node root = doc.document_element();
  if (std::strcmp(root.name(), "svg") != 0)
    throw invalid_input(file + ": the root element is <" + validate::visible(root.name()) + ">, not <svg>");
  std::vector<svg_element> out;
  std::size_t index = 0;
  // Document order, at any depth (<g>, <defs>, <symbol>: getTotalLength answers on all of them).
  for (const pugi::xpath_node& x : doc.select_nodes("//*")) {
    const pugi::xml_node n = x.node();
    const std::string element = n.name();
    const bool shape = element == "circle" || element == "ellipse" || element == "rect" || element == "line" ||
                       element == "polyline" || element == "polygon";
    if (element != "path" && !shape) continue;
    svg_element e;
    e.element = element;
    e.index = index++;
    e.id = n.attribute("id").value();
    e.where = file + ": <" + element + (e.id.empty() ? "" : " id=\"" + validate::visible(e.id) + "\"") +
              "> (shape or path " + std::to_string(e.index) + ", byte " + std::to_string(n.offset_debug()) + ")";
    if (element == "path") {
      const pugi::xml_attribute d = n.attribute("d");
      if (!d) throw invalid_input(e.where + ": has no d attribute");
      e.spec = {{"type", "svg_path"}, {"d", d.value()}};
    } else if (element == "polyline" || element == "polygon") {
      // SVG's points list uses the path data's number grammar: as path data it is a moveto with
      // implicit linetos, so the path parser reads it and names an offset within it (+ 1 for "M").
      const pugi::xml_attribute p = n.attribute("points");
      if (!p) throw invalid_input(e.where + ": has no points attribute");
      e.spec = {{"type", "svg_path"}, {"d", "M" + std::string(p.value()) + (element == "polygon" ? " Z" : "")}};
    } else {
      nlohmann::json s{{"element", element}};
      for (const char* name : shape_attributes)
        if (const pugi::xml_attribute a = n.attribute(name)) {
          if (std::strcmp(a.value(), "auto") == 0 && (std::strcmp(name, "rx") == 0 || std::strcmp(name, "ry") == 0))
            continue;  // SVG 2's auto: as absent
          s[name] = user_units(e.where, name, a.value());
        }
      e.spec = {{"type", "svg_path"}, {"shape", s}};
    }
    out.push_back(std::move(e));
  }
  if (out.empty())
    throw invalid_input(file + ": no <path> or basic shape (circle, ellipse, rect, line, polyline, polygon)");
  return out;
}

}  // namespace curvebench::tool
