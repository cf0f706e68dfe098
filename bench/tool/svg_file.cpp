// curvebench length --svg: the paths and basic shapes of an SVG file as svg_path specs, read with
// pugixml (Debian's libpugixml-dev), never a hand-written XML parser; what pugixml leaves unchecked
// of XML 1.0 and Namespaces in XML is checked here (svg_file.hpp).
#include "tool/svg_file.hpp"

#include "harness/files.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/families/svg_path.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/io/svg_path.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

namespace curvebench::tool {

namespace {

constexpr std::string_view xml_namespace = "http://www.w3.org/XML/1998/namespace";
constexpr std::string_view xmlns_namespace = "http://www.w3.org/2000/xmlns/";
// The longest message of the path parser shown (it quotes one character and a few words).
constexpr std::size_t max_message = 1000;

/// The UTF-8 sequence at text[i] as a code point and its length in bytes; length 0 when the bytes
/// there are not UTF-8 (an overlong form, a surrogate, past U+10FFFF, cut or a stray continuation).
std::pair<char32_t, std::size_t> decode_utf8(std::string_view text, std::size_t i) {
  const auto b = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char c = b(i);
  if (c < 0x80) return {c, 1};
  std::size_t n = 0;
  char32_t cp = 0, least = 0;
  if (c >= 0xc2 && c <= 0xdf) {
    n = 2, cp = c & 0x1fu, least = 0x80;
  } else if (c >= 0xe0 && c <= 0xef) {
    n = 3, cp = c & 0x0fu, least = 0x800;
  } else if (c >= 0xf0 && c <= 0xf4) {
    n = 4, cp = c & 0x07u, least = 0x10000;
  } else {
    return {0, 0};
  }
  if (i + n > text.size()) return {0, 0};
  for (std::size_t k = 1; k < n; ++k) {
    if ((b(i + k) & 0xc0u) != 0x80u) return {0, 0};
    cp = (cp << 6) | (b(i + k) & 0x3fu);
  }
  if (cp < least || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff)) return {0, 0};
  return {cp, n};
}

/// XML 1.0's Char production: tab, LF, CR, and U+0020..U+D7FF, U+E000..U+FFFD, U+10000..U+10FFFF.
bool is_xml_char(char32_t c) {
  return c == 0x9 || c == 0xa || c == 0xd || (c >= 0x20 && c <= 0xd7ff) || (c >= 0xe000 && c <= 0xfffd) ||
         (c >= 0x10000 && c <= 0x10ffff);
}

/// XML 1.0 (fifth edition)'s NameStartChar and NameChar.
bool is_name_start(char32_t c) {
  return c == ':' || c == '_' || (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= 0xc0 && c <= 0xd6) ||
         (c >= 0xd8 && c <= 0xf6) || (c >= 0xf8 && c <= 0x2ff) || (c >= 0x370 && c <= 0x37d) ||
         (c >= 0x37f && c <= 0x1fff) || (c >= 0x200c && c <= 0x200d) || (c >= 0x2070 && c <= 0x218f) ||
         (c >= 0x2c00 && c <= 0x2fef) || (c >= 0x3001 && c <= 0xd7ff) || (c >= 0xf900 && c <= 0xfdcf) ||
         (c >= 0xfdf0 && c <= 0xfffd) || (c >= 0x10000 && c <= 0xeffff);
}
bool is_name_char(char32_t c) {
  return is_name_start(c) || c == '-' || c == '.' || (c >= '0' && c <= '9') || c == 0xb7 ||
         (c >= 0x300 && c <= 0x36f) || (c >= 0x203f && c <= 0x2040);
}

/// "U+0000" for messages.
std::string code_point_text(char32_t c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
  return buf;
}

void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out.push_back(static_cast<char>(c));
  } else if (c < 0x800) {
    out.push_back(static_cast<char>(0xc0 | (c >> 6)));
    out.push_back(static_cast<char>(0x80 | (c & 0x3f)));
  } else if (c < 0x10000) {
    out.push_back(static_cast<char>(0xe0 | (c >> 12)));
    out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3f)));
    out.push_back(static_cast<char>(0x80 | (c & 0x3f)));
  } else {
    out.push_back(static_cast<char>(0xf0 | (c >> 18)));
    out.push_back(static_cast<char>(0x80 | ((c >> 12) & 0x3f)));
    out.push_back(static_cast<char>(0x80 | ((c >> 6) & 0x3f)));
    out.push_back(static_cast<char>(0x80 | (c & 0x3f)));
  }
}

/// The checks of one document: its text (pugixml parses a copy in place, so every name and value
/// pointer lies in `buf` and its distance from the start is the byte offset in the file).
class reader {
 public:
  reader(std::string_view text, const std::string& file, std::size_t limit) : file_(file), buf_(text), limit_(limit) {}

  svg_document read() {
    check_characters();
    pugi::xml_document doc;
    // No decoding by pugixml (escapes, end-of-line, attribute white space): the values stay the
    // file's bytes, decoded and checked below; comments, PIs, the declaration and the DOCTYPE kept
    // as nodes so that their content and position are checked.
    // parse_fragment keeps text outside the root as nodes (refused below), which pugixml otherwise
    // drops; in place it overwrites the buffer's last byte, so one byte of white space (XML's Misc
    // at the end of a document) is added for it.
    const unsigned options = pugi::parse_cdata | pugi::parse_comments | pugi::parse_pi | pugi::parse_declaration |
                             pugi::parse_doctype | pugi::parse_fragment;
    const std::size_t size = buf_.size();
    buf_.push_back('\n');
    const pugi::xml_parse_result parsed =
        doc.load_buffer_inplace(buf_.data(), buf_.size(), options, pugi::encoding_utf8);
    if (!parsed) fail(std::min(static_cast<std::size_t>(parsed.offset), size), parsed.description());
    check_top_level(doc);
    walk(doc.document_element());
    if (out_.elements.empty())
      throw invalid_input(file_ + ": no <path> or basic shape (circle, ellipse, rect, line, polyline, polygon)" +
                          (out_.skipped ? " in the SVG namespace (" + std::to_string(out_.skipped) +
                                              " outside it were skipped, the first " + out_.first_skipped + ")"
                                        : std::string()));
    return std::move(out_);
  }

 private:
  const std::string& file_;
  std::string buf_;  // the document, parsed in place
  std::size_t limit_;
  svg_document out_;
  // In-scope namespace bindings: prefix ("" for the default namespace) to a stack of URIs.
  std::unordered_map<std::string, std::vector<std::string>> scope_;

  [[noreturn]] void fail(std::size_t offset, const std::string& why, const char* kind = "well-formed") const {
    throw invalid_input(file_ + ": not " + kind + " XML at byte offset " + std::to_string(offset) + ": " + why);
  }
  [[noreturn]] void fail_ns(std::size_t offset, const std::string& why) const {
    fail(offset, why, "namespace-well-formed");
  }
  std::size_t offset_of(const char* p) const { return static_cast<std::size_t>(p - buf_.data()); }

  /// Every byte UTF-8 and every character an XML Char, before pugixml sees the text (it takes any
  /// byte); a UTF-8 byte order mark at the start is allowed.
  void check_characters() const {
    if (buf_.size() >= 2 && ((buf_[0] == '\xfe' && buf_[1] == '\xff') || (buf_[0] == '\xff' && buf_[1] == '\xfe')))
      throw invalid_input(file_ + ": starts with a UTF-16 byte order mark: curvebench reads SVG files in UTF-8 only");
    for (std::size_t i = buf_.starts_with("\xef\xbb\xbf") ? 3 : 0; i < buf_.size();) {
      const auto [c, n] = decode_utf8(buf_, i);
      if (n == 0)
        throw invalid_input(file_ + ": not UTF-8 at byte offset " + std::to_string(i) + " (byte " +
                            validate::visible(std::string_view(buf_).substr(i, 1)) +
                            "): curvebench reads SVG files in UTF-8 (XML's default encoding) only");
      if (!is_xml_char(c)) fail(i, "character " + code_point_text(c) + " is not allowed in XML (XML 1.0 Char)");
      i += n;
    }
  }

  /// The Name at `p` (pugixml checks only its first character's class).
  void check_name(const char* p, std::string_view what) const {
    const std::string_view name(p);
    for (std::size_t i = 0; i < name.size();) {
      const auto [c, n] = decode_utf8(name, i);
      if (!(i == 0 ? is_name_start(c) : is_name_char(c)))
        fail(offset_of(p) + i, std::string(what) + " " + validate::visible(name) + " is not an XML Name (character " +
                                   code_point_text(c) + " at its position " + std::to_string(i) + ")");
      i += n;
    }
  }

  /// Replaces the references of raw text at `p` (an attribute value when `attribute`, else
  /// character data): character references to XML characters and the five predefined entities;
  /// refuses any other and a bare '&', '<' in a value, "]]>" in text. An attribute value is then
  /// normalised (XML 1.0 section 3.3.3: CR LF, CR, LF and tab as one space each; a referenced
  /// character stays as it is).
  std::string decode(const char* p, bool attribute) const {
    const std::string_view raw(p);
    const std::size_t base = offset_of(p);
    std::string out;
    out.reserve(raw.size());
    for (std::size_t i = 0; i < raw.size(); ++i) {
      const char c = raw[i];
      if (c == '<' && attribute) fail(base + i, "'<' in an attribute value (write &lt;)");
      if (c == ']' && !attribute && raw.substr(i).starts_with("]]>"))
        fail(base + i, "\"]]>\" in character data (write ]]&gt;)");
      if (attribute && (c == '\t' || c == '\n' || c == '\r')) {
        if (c == '\r' && i + 1 < raw.size() && raw[i + 1] == '\n') ++i;
        out.push_back(' ');
        continue;
      }
      if (c != '&') {
        out.push_back(c);
        continue;
      }
      const std::size_t semi = raw.find(';', i);
      const std::string_view ref = raw.substr(i + 1, semi == std::string_view::npos ? 0 : semi - i - 1);
      if (semi == std::string_view::npos || ref.empty())
        fail(base + i, "'&' that does not start a reference (write &amp;)");
      if (ref.front() == '#') {
        const bool hex = ref.size() > 1 && ref[1] == 'x';
        const std::string_view digits = ref.substr(hex ? 2 : 1);
        std::uint32_t v = 0;
        bool ok = !digits.empty();
        for (const char d : digits) {
          const int k = d >= '0' && d <= '9'          ? d - '0'
                        : hex && d >= 'a' && d <= 'f' ? d - 'a' + 10
                        : hex && d >= 'A' && d <= 'F' ? d - 'A' + 10
                                                      : -1;
          if (k < 0) ok = false;
          v = ok ? std::min<std::uint32_t>(v * (hex ? 16 : 10) + static_cast<std::uint32_t>(k), 0x110000) : v;
        }
        if (!ok)
          fail(base + i, "&" + validate::visible(ref, 40) + "; is not a character reference (&#DIGITS; or &#xHEX;)");
        if (!is_xml_char(v))
          fail(base + i, "character reference &" + validate::visible(ref, 40) + "; is to " +
                             (v > 0x10ffff ? std::string("a number past U+10FFFF") : code_point_text(v)) +
                             ", a character XML does not allow (XML 1.0 Char)");
        append_utf8(out, v);
      } else if (ref == "lt") {
        out.push_back('<');
      } else if (ref == "gt") {
        out.push_back('>');
      } else if (ref == "amp") {
        out.push_back('&');
      } else if (ref == "apos") {
        out.push_back('\'');
      } else if (ref == "quot") {
        out.push_back('"');
      } else {
        fail(base + i, "entity &" + validate::visible(ref, 40) +
                           "; is not declared (curvebench reads the five predefined entities and character "
                           "references; a DOCTYPE's declarations are not read)");
      }
      i = semi;
    }
    return out;
  }

  /// The document's top level: [declaration] Misc* [DOCTYPE Misc*] root Misc*, where Misc is a
  /// comment, a PI or white space; a DOCTYPE without declarations in its internal subset.
  void check_top_level(const pugi::xml_document& doc) const {
    const std::size_t start = buf_.starts_with("\xef\xbb\xbf") ? 3 : 0;
    bool first = true, doctype = false, root = false;
    for (const pugi::xml_node n : doc.children()) {
      switch (n.type()) {
        case pugi::node_declaration: {
          const std::size_t at = offset_of(n.name()) - 2;
          if (!first || at != start) fail(at, "an XML declaration is allowed only at the very start of the file");
          check_declaration(n);
          break;
        }
        case pugi::node_doctype: {
          const std::size_t at = offset_of(n.value());
          if (doctype) fail(at, "a second DOCTYPE");
          if (root) fail(at, "a DOCTYPE after the root element");
          doctype = true;
          const std::string_view v(n.value());
          for (const std::string_view decl : {"<!ENTITY", "<!ATTLIST"})
            if (const std::size_t k = v.find(decl); k != std::string_view::npos)
              fail(at + k, "the DOCTYPE declares " +
                               std::string(decl == "<!ENTITY" ? "entities" : "default attributes") +
                               ", which curvebench does not read (they would change the document)");
          break;
        }
        case pugi::node_element:
          if (root) fail(offset_of(n.name()) - 1, "a second root element (a document has one)");
          root = true;
          break;
        case pugi::node_comment: check_comment(n); break;
        case pugi::node_pi: check_pi(n); break;
        default: fail(offset_of(n.value()), "text outside the root element");
      }
      first = false;
    }
    if (!root) fail(buf_.size() - 1, "no root element");
  }

  void check_declaration(const pugi::xml_node& n) const {
    const pugi::xml_attribute version = n.attribute("version");
    if (!version) fail(offset_of(n.name()), "the XML declaration has no version");
    const std::string v = decode(version.value(), true);
    if (!(v.size() >= 3 && v.starts_with("1.") && v.find_first_not_of("0123456789", 2) == std::string::npos))
      fail(offset_of(version.value()), "XML version \"" + validate::visible(v) + "\" (curvebench reads XML 1.x)");
    if (const pugi::xml_attribute e = n.attribute("encoding")) {
      std::string name = decode(e.value(), true);
      for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (name != "utf-8" && name != "utf8")
        fail(offset_of(e.value()), "encoding \"" + validate::visible(e.value()) +
                                       "\": curvebench reads SVG files in UTF-8 only (convert the file)");
    }
  }

  void check_comment(const pugi::xml_node& n) const {
    const std::string_view v(n.value());
    if (const std::size_t k = v.find("--"); k != std::string_view::npos)
      fail(offset_of(n.value()) + k, "\"--\" inside a comment");
    if (v.ends_with('-')) fail(offset_of(n.value()) + v.size() - 1, "a comment ending in \"--->\"");
  }

  void check_pi(const pugi::xml_node& n) const {
    const std::string_view target(n.name());
    check_name(n.name(), "processing-instruction target");
    if (target.size() == 3 && std::tolower(target[0]) == 'x' && std::tolower(target[1]) == 'm' &&
        std::tolower(target[2]) == 'l')
      fail(offset_of(n.name()), "processing-instruction target " + validate::visible(target) +
                                    " is reserved (an XML declaration is allowed only at the start)");
    if (target.find(':') != std::string_view::npos)
      fail_ns(offset_of(n.name()), "processing-instruction target " + validate::visible(target) + " has a colon");
  }

  /// A QName's prefix ("" without) and local part; refuses a name that is not a QName.
  std::pair<std::string_view, std::string_view> split_qname(const char* p, std::string_view what) const {
    const std::string_view name(p);
    const std::size_t colon = name.find(':');
    if (colon == std::string_view::npos) return {{}, name};
    if (colon == 0 || colon + 1 == name.size() || name.find(':', colon + 1) != std::string_view::npos)
      fail_ns(offset_of(p), std::string(what) + " " + validate::visible(name) +
                                " is not a QName (at most one colon, between a prefix and a local name)");
    // The local part must start with a NameStartChar other than ':' (a digit is not one).
    const auto [c, n] = decode_utf8(name, colon + 1);
    if (!is_name_start(c))
      fail_ns(offset_of(p) + colon + 1, std::string(what) + " " + validate::visible(name) +
                                            ": its local name does not start with a name character");
    return {name.substr(0, colon), name.substr(colon + 1)};
  }

  /// The URI bound to `prefix` here ("" for no namespace); refuses an undeclared prefix.
  std::string_view uri_of(std::string_view prefix, const char* at, std::string_view what) const {
    if (prefix == "xml") return xml_namespace;
    const auto it = scope_.find(std::string(prefix));
    if (it == scope_.end() || it->second.empty()) {
      if (prefix.empty()) return {};
      fail_ns(offset_of(at), std::string(what) + " " + validate::visible(at) + ": prefix " + validate::visible(prefix) +
                                 " is not declared (xmlns:" + validate::visible(prefix) + "=\"...\")");
    }
    return it->second.back();
  }

  /// An element's namespace declarations bound (their prefixes returned, to unbind at its end).
  std::vector<std::string> declare(const pugi::xml_node& n) {
    std::vector<std::string> bound;
    for (const pugi::xml_attribute a : n.attributes()) {
      const std::string_view name(a.name());
      if (name != "xmlns" && !name.starts_with("xmlns:")) continue;
      const std::string prefix(name == "xmlns" ? std::string_view() : name.substr(6));
      const std::string uri = decode(a.value(), true);
      const std::size_t at = offset_of(a.name());
      if (prefix == "xmlns") fail_ns(at, "the prefix xmlns cannot be declared");
      if (prefix == "xml" && uri != xml_namespace)
        fail_ns(at, "the prefix xml is bound to " + std::string(xml_namespace) + " only");
      if (prefix != "xml" && (uri == xml_namespace || uri == xmlns_namespace))
        fail_ns(at, validate::visible(name) + " binds the reserved namespace " + validate::visible(uri));
      if (!prefix.empty() && uri.empty())
        fail_ns(at, validate::visible(name) + "=\"\": a prefix cannot be undeclared in XML 1.0");
      scope_[prefix].push_back(uri);
      bound.push_back(prefix);
    }
    return bound;
  }
  void undeclare(const std::vector<std::string>& bound) {
    for (const std::string& prefix : bound) scope_[prefix].pop_back();
  }

  /// An element's attributes: Names, QNames with declared prefixes, unique by name and by
  /// namespace and local name.
  void check_attributes(const pugi::xml_node& n) const {
    std::unordered_set<std::string_view> names;
    std::unordered_set<std::string> expanded;
    for (const pugi::xml_attribute a : n.attributes()) {
      check_name(a.name(), "attribute");
      const std::string_view name(a.name());
      if (!names.insert(name).second)
        fail(offset_of(a.name()), "attribute " + validate::visible(name) + " appears twice on <" +
                                      validate::visible(n.name()) + "> (XML 1.0: Unique Att Spec)");
      if (name == "xmlns" || name.starts_with("xmlns:")) {
        split_qname(a.name(), "attribute");
        continue;
      }
      const auto [prefix, local] = split_qname(a.name(), "attribute");
      if (prefix.empty()) continue;  // in no namespace: unique by name, checked above
      const std::string key = std::string(uri_of(prefix, a.name(), "attribute")) + '\n' + std::string(local);
      if (!expanded.insert(key).second)
        fail_ns(offset_of(a.name()), "attribute " + validate::visible(name) + " on <" + validate::visible(n.name()) +
                                         "> has the namespace and local name of another of its attributes");
    }
    for (const pugi::xml_attribute a : n.attributes()) decode(a.value(), true);
  }

  /// The element's unprefixed attribute `name` (SVG's attributes are in no namespace), decoded.
  static pugi::xml_attribute plain(const pugi::xml_node& n, const char* name) { return n.attribute(name); }

  /// Document order, at any depth (<g>, <defs>, <symbol>: getTotalLength answers on all of them),
  /// without recursion (a document may nest deeper than the stack allows).
  void walk(const pugi::xml_node& root) {
    std::vector<std::vector<std::string>> bound;  // the namespace declarations of each open element
    pugi::xml_node n = root;
    while (true) {
      visit(n, bound, n == root);
      if (n.first_child()) {
        n = n.first_child();
        continue;
      }
      // No child: close n and the elements it ends, up to the next sibling in document order.
      while (true) {
        if (n.type() == pugi::node_element) undeclare(bound.back()), bound.pop_back();
        if (n == root) return;
        if (n.next_sibling()) {
          n = n.next_sibling();
          break;
        }
        n = n.parent();
      }
    }
  }

  void visit(const pugi::xml_node& n, std::vector<std::vector<std::string>>& bound, bool is_root) {
    switch (n.type()) {
      case pugi::node_element: break;
      case pugi::node_pcdata: decode(n.value(), false); return;
      case pugi::node_cdata: return;
      case pugi::node_comment: check_comment(n); return;
      case pugi::node_pi: check_pi(n); return;
      case pugi::node_declaration: fail(offset_of(n.name()) - 2, "an XML declaration inside an element");
      case pugi::node_doctype: fail(offset_of(n.value()), "a DOCTYPE inside an element");
      default: return;
    }
    check_name(n.name(), "element");
    bound.push_back(declare(n));
    check_attributes(n);
    const auto [prefix, local] = split_qname(n.name(), "element");
    const std::string_view uri = uri_of(prefix, n.name(), "element");
    const std::size_t at = offset_of(n.name()) - 1;
    if (is_root && !(uri == svg_namespace && local == "svg"))
      throw invalid_input(file_ + ": the root element is <" + validate::visible(n.name()) + ">" +
                          (uri.empty() ? " in no namespace" : " of namespace " + validate::visible(uri)) +
                          ", not SVG's <svg> (namespace " + std::string(svg_namespace) + ": xmlns=\"" +
                          std::string(svg_namespace) + "\" on the root)");
    static constexpr std::string_view measured[] = {"path", "circle", "ellipse", "rect", "line", "polyline", "polygon"};
    if (std::find(std::begin(measured), std::end(measured), local) == std::end(measured)) return;
    if (uri != svg_namespace) {
      if (out_.skipped++ == 0)
        out_.first_skipped = "<" + validate::visible(n.name()) + "> at byte " + std::to_string(at) + " (namespace \"" +
                             validate::visible(uri) + "\")";
      return;
    }
    if (out_.elements.size() >= limit_)
      throw invalid_input(file_ + ": more than " + std::to_string(limit_) +
                          " path and shape elements (the limit per file of curvebench length --svg; element " +
                          std::to_string(out_.elements.size()) + " is <" + validate::visible(n.name()) + "> at byte " +
                          std::to_string(at) + "): split the file");
    out_.elements.push_back(element(n, std::string(local), at));
  }

  svg_element element(const pugi::xml_node& n, std::string local, std::size_t at) const {
    svg_element e;
    e.element = std::move(local);
    e.index = out_.elements.size();
    if (const pugi::xml_attribute id = plain(n, "id")) e.id = decode(id.value(), true);
    e.where = file_ + ": <" + validate::visible(n.name()) +
              (e.id.empty() ? "" : " id=\"" + validate::visible(e.id) + "\"") + "> (shape or path " +
              std::to_string(e.index) + ", byte " + std::to_string(at) + ")";
    // The attribute the path data comes from, for messages, and its offset in the path data (the
    // points of a polyline or polygon follow an "M").
    const char* source = nullptr;
    std::size_t shift = 0;
    if (e.element == "path") {
      const pugi::xml_attribute d = plain(n, "d");
      if (!d) throw invalid_input(e.where + ": has no d attribute");
      e.spec = {{"type", "svg_path"}, {"d", decode(d.value(), true)}};
      source = d.value();
    } else if (e.element == "polyline" || e.element == "polygon") {
      // SVG's points list uses the path data's number grammar: as path data it is a moveto with
      // implicit linetos, so the path parser reads it and names an offset within it.
      const pugi::xml_attribute p = plain(n, "points");
      if (!p) throw invalid_input(e.where + ": has no points attribute");
      e.spec = {{"type", "svg_path"}, {"d", "M" + decode(p.value(), true) + (e.element == "polygon" ? " Z" : "")}};
      source = p.value(), shift = 1;
    } else {
      nlohmann::json s{{"element", e.element}};
      for (const char* name : shape_attributes)
        if (const pugi::xml_attribute a = plain(n, name)) {
          const std::string v = decode(a.value(), true);
          if (v == "auto" && (std::strcmp(name, "rx") == 0 || std::strcmp(name, "ry") == 0))
            continue;  // SVG 2's auto: as absent
          s[name] = user_units(e.where, name, v);
        }
      e.spec = {{"type", "svg_path"}, {"shape", s}};
    }
    // The path data measured, parsed here so that an error names the element before anything is
    // measured or printed.
    const io::field spec = io::root(e.spec, e.where);
    try {
      e.d = io::svg_path_family::path_data(spec);
      (void)io::svg::parse_path(e.d);
    } catch (const invalid_input& x) {
      if (!source) throw;
      const std::string name = e.element == "path" ? "d" : "points";
      throw invalid_input(e.where + ": " + name + " (value at byte " + std::to_string(offset_of(source)) + ": \"" +
                          validate::visible(decode(source, true), 40) + "\"): " + shifted(x.what(), shift));
    }
    return e;
  }

  /// The path parser's message with its "at offset N" moved back by `shift` (the "M" put before a
  /// points list), so that it counts in the attribute's value.
  static std::string shifted(const std::string& text, std::size_t shift) {
    static constexpr std::string_view key = "at offset ";
    // The parser quotes the byte it found, which may be one byte of a UTF-8 sequence: shown \xNN.
    const std::string message = validate::visible(text, max_message);
    const std::size_t k = message.find(key);
    if (shift == 0 || k == std::string::npos) return message;
    std::size_t offset = 0;
    const char* first = message.data() + k + key.size();
    const auto [end, ec] = std::from_chars(first, message.data() + message.size(), offset);
    if (ec != std::errc{} || offset < shift) return message;
    return message.substr(0, k + key.size()) + std::to_string(offset - shift) +
           message.substr(static_cast<std::size_t>(end - message.data()));
  }

  /// An SVG <length> or <number> attribute in user units: a number, optionally followed by "px"
  /// (1 user unit); surrounding white space allowed. Anything else (%, em, mm: units that need a
  /// viewport or a font) is refused naming the element and the attribute.
  static double user_units(const std::string& where, const char* name, const std::string& text) {
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
                          "\" is not a number in user units (a number, optionally with px; %, em and other units need "
                          "a viewport or a font and are not read)");
    return x;
  }

  static constexpr const char* shape_attributes[] = {"cx",    "cy",     "r",  "rx", "ry", "x", "y",
                                                     "width", "height", "x1", "y1", "x2", "y2"};
};

}  // namespace

svg_document svg_elements_of(std::string_view text, const std::string& file, std::size_t limit) {
  return reader(text, file, limit).read();
}

svg_document read_svg_elements(const std::string& file) {
  return svg_elements_of(harness::read_input_file(file), file);
}

}  // namespace curvebench::tool
