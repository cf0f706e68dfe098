// The svg target (targets.hpp): `curvebench length --svg FILE` up to its measurement. An input that
// starts with "d=" is path data (the rest): the path parser and the svg_path family's curve, as a
// spec's "d" is read. Any other input is an SVG file, read by the tool's own reader
// (bench/tool/svg_file.hpp: pugixml and the XML, namespace and SVG checks), with a limit of 1000
// elements; then each of the first 64 elements' path data is parsed again and its curve built and
// evaluated at its ends, as the tool does before it measures.
//
// Properties:
//   documented exceptions only   the reader, the path parser and the family refuse with invalid_input
//                                / io::spec_error only, each with a non-empty message of bounded size
//   errors name the file         every refusal of an SVG file names it ("drawing.svg")
//   elements as documented       at most the limit; indices 0, 1, 2, ... in order; each element's
//                                where names the file and its index; element a measured name
//   printable output             element, id and d are UTF-8 that the JSON writer takes (a
//                                non-UTF-8 id once threw nlohmann's exception after part of the
//                                output was printed)
//   XML characters only          id and d hold no character XML refuses (a C0 control other than tab,
//                                LF, CR: &#0; was once decoded into d, which then ended there)
//   validated before output      the path data the reader returns parses again (the reader refuses
//                                what the parser refuses, before anything is printed)
//   no NaN value                 a built curve's points at its ends are numbers
//   bounded work                 an input takes at most 10 s
#include "guard.hpp"
#include "targets.hpp"

#include "tool/svg_file.hpp"

#include "curvebench/io/families/svg_path.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/io/svg_path.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>

namespace curvebench::fuzz {

namespace {

constexpr std::string_view name = "svg";
constexpr std::size_t limit = 1000;
constexpr std::size_t max_built = 64;
const std::string file = "drawing.svg";

/// The curve of svg_path spec `spec` built and evaluated at its ends, as `length` starts.
void build(const io::field& spec) {
  std::optional<any_curve<double, 2>> c;
  if (!run_step(name, "svg_path build", domain_errors::violation,
                [&] { c.emplace(io::svg_path_family::build<double, 2>(spec)); }))
    return;
  const interval<double> d = c->domain();
  for (const double u : {d.lo, d.hi}) {
    const auto p = (*c)(u);
    if (std::isnan(p[0]) || std::isnan(p[1]))
      violation(name, "no NaN value", "the point at u = " + std::to_string(u) + " of " + spec.path + " is NaN");
  }
}

void path_data(std::string_view d) {
  run_step(name, "parse_path", domain_errors::violation, [&] { (void)io::svg::parse_path(d); });
  const nlohmann::json j{{"type", "svg_path"}, {"d", std::string(d)}};
  build(io::root(j, "path.json"));
}

void svg_file(std::string_view text) {
  std::optional<tool::svg_document> doc;
  try {
    doc.emplace(tool::svg_elements_of(text, file, limit));
  } catch (const invalid_input& e) {
    check_message(name, "svg_elements_of", e.what());
    if (!std::string_view(e.what()).starts_with(file + ": "))
      violation(name, "errors name the file", std::string(e.what()).substr(0, 300));
    return;
  } catch (...) {
    // Anything else: sorted by run_step into a violation naming its type.
    run_step(name, "svg_elements_of", domain_errors::violation, [&] { throw; });
    return;
  }
  if (doc->elements.size() > limit)
    violation(name, "elements as documented", std::to_string(doc->elements.size()) + " elements past the limit");
  static constexpr std::string_view measured[] = {"path", "circle", "ellipse", "rect", "line", "polyline", "polygon"};
  for (std::size_t i = 0; i < doc->elements.size(); ++i) {
    const tool::svg_element& e = doc->elements[i];
    if (e.index != i) violation(name, "elements as documented", e.where + ": index " + std::to_string(e.index));
    if (!e.where.starts_with(file + ": <") ||
        e.where.find(" (shape or path " + std::to_string(i) + ",") == std::string::npos)
      violation(name, "elements as documented", "where = " + e.where.substr(0, 300));
    if (std::find(std::begin(measured), std::end(measured), e.element) == std::end(measured))
      violation(name, "elements as documented", e.where + ": element " + e.element);
    try {
      (void)nlohmann::json{{"element", e.element}, {"id", e.id}, {"d", e.d}}.dump();
    } catch (const std::exception& x) {
      violation(name, "printable output", e.where.substr(0, 300) + ": " + x.what());
    }
    for (const std::string* value : {&e.id, &e.d})
      for (const char c : *value)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r')
          violation(name, "XML characters only", e.where.substr(0, 300) + ": a control character in its id or d");
    try {
      (void)io::svg::parse_path(e.d);
    } catch (const std::exception& x) {
      violation(name, "validated before output", e.where.substr(0, 300) + ": " + x.what());
    }
    if (i < max_built) build(io::root(e.spec, e.where));
  }
}

}  // namespace

int svg_target(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto start = std::chrono::steady_clock::now();
  if (text.starts_with("d="))
    path_data(text.substr(2));
  else
    svg_file(text);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (seconds > 10)
    violation(name, "bounded work",
              "the input took " + std::to_string(seconds) + " s (" + std::to_string(size) + " bytes)");
  return 0;
}

}  // namespace curvebench::fuzz
