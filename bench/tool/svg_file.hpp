// The reader of `curvebench length --svg FILE` (svg_file.cpp): the paths and basic shapes of an SVG
// file as svg_path specs. Its own header so that the svg fuzz target (tests/fuzz/targets_svg.cpp)
// calls the same reader as the tool, without the tool's main or CLI11.
//
// XML: parsed by pugixml (Debian's libpugixml-dev) in place with its own decoding switched off, so
// that every attribute value is the file's bytes and an offset in it is a byte offset of the file;
// then checked against what XML 1.0 (fifth edition) and Namespaces in XML 1.0 refuse and pugixml
// accepts: bytes that are not UTF-8 or not XML characters (Char), character references to
// characters XML does not allow (&#0;, &#1;..&#8;, surrogates, &#xFFFE;), entity references other
// than the five predefined ones (a DOCTYPE that declares entities or default attributes is refused:
// they are not expanded), '<' or a bare '&' in an attribute value, "]]>" in text, "--" in a comment,
// a second attribute of the same name (Unique Att Spec) or of the same namespace and local name,
// names that are not Names or QNames, undeclared prefixes, misplaced XML declarations, DOCTYPEs and
// top-level text, and more than one root element. Attribute values are then normalised as XML 1.0
// section 3.3.3 says for CDATA attributes (references replaced; tab, CR, LF and CR LF as one space).
//
// SVG: elements are recognised by namespace, http://www.w3.org/2000/svg under any prefix or as the
// default namespace; the root must be that namespace's <svg>. A <path> or basic shape of another
// namespace (or of none) is not SVG: it is skipped and counted (svg_document::skipped). Every error
// about an element names the file, the element as written, its index among the measured elements,
// its id when it has one and its byte offset; an error in path data adds the attribute, its byte
// offset in the file and the character offset in the value that the path parser names.
//
// Bounded: the file is read up to harness::read_input_file's limit; at most max_svg_elements paths
// and shapes, refused at the one past the limit before anything is measured.
#pragma once

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace curvebench::tool {

/// The most paths and shapes `length --svg` measures in one file. Measured with the default method:
/// a line costs about 40 us and prints 0.65 kB of JSON, a circle (four arcs) 240 us and 2.9 kB, so
/// 1e5 elements take up to about half a minute and 300 MB of output (1e5 lines: 4 s, 78 MB of
/// memory); a file with more is refused at the one past the limit, before any work (1e6 lines, a
/// 21 MB file: refused in 1 s with 210 MB of memory, pugixml's tree of the whole file).
inline constexpr std::size_t max_svg_elements = 100000;

/// The SVG namespace (SVG 1.1 and SVG 2).
inline constexpr std::string_view svg_namespace = "http://www.w3.org/2000/svg";

/// A path or basic shape of an SVG file, as an svg_path spec.
struct svg_element {
  std::string element;    ///< path, circle, ellipse, rect, line, polyline, polygon (the local name)
  std::string id;         ///< its id attribute ("" without), references replaced
  std::size_t index = 0;  ///< its position among the file's paths and shapes, from 0, in document order
  std::string where;      ///< "FILE: <path id="a"> (shape or path 0, byte 120)", for messages
  nlohmann::json spec;    ///< {"type": "svg_path", "d": ...} or {"type": "svg_path", "shape": {...}}
  std::string d;          ///< the path data measured (a shape's: the path SVG 2 defines for it), parsed once
};

/// The paths and shapes of one SVG file, in document order at any depth.
struct svg_document {
  std::vector<svg_element> elements;
  std::size_t skipped = 0;    ///< <path> and shape elements of another namespace (or none), not measured
  std::string first_skipped;  ///< the first of them, "<path> at byte 40 (namespace \"\")"
};

/// The paths and shapes of an SVG document's text (see the header); `file` names it in messages.
/// invalid_input naming the file, the byte offset and, for an element, the element, for every
/// refusal listed above, a shape attribute that is not a number in user units, path data the path
/// parser refuses, more than `limit` elements, or a file without any.
svg_document svg_elements_of(std::string_view text, const std::string& file, std::size_t limit = max_svg_elements);

/// svg_elements_of on the file at `file` (read by harness::read_input_file).
svg_document read_svg_elements(const std::string& file);

}  // namespace curvebench::tool
