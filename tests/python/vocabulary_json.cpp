// Prints bench/harness/vocabulary.hpp as the JSON that scripts/report.py reads (the shape of
// `curvebench list vocabulary --json`): quantities, methods, peers, operations, counters,
// algorithms and variant keys, space-separated lists as arrays. Used by the bench_counters tests
// until the tool's own command is wired in (tests/CMakeLists.txt, CURVEBENCH_VOCABULARY_COMMAND).
#include "harness/vocabulary.hpp"

#include <cstdio>
#include <string>
#include <string_view>

namespace {

namespace vocab = curvebench::harness::vocab;

std::string quoted(std::string_view s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(c)));
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string words(std::string_view list) {
  std::string out = "[";
  bool first = true;
  while (!list.empty()) {
    const auto space = list.find(' ');
    const auto w = list.substr(0, space);
    if (!w.empty()) {
      out += (first ? "" : ", ") + quoted(w);
      first = false;
    }
    if (space == std::string_view::npos) break;
    list.remove_prefix(space + 1);
  }
  return out + "]";
}

template <class Items, class Item>
void section(const char* name, const Items& items, Item&& item, bool last = false) {
  std::printf("  \"%s\": [", name);
  bool first = true;
  for (const auto* x : items) {
    std::printf("%s\n    {%s}", first ? "" : ",", item(*x).c_str());
    first = false;
  }
  std::printf("\n  ]%s\n", last ? "" : ",");
}

}  // namespace

int main() {
  std::printf("{\n");
  section("quantities", vocab::all_quantities,
          [](const vocab::quantity& q) { return "\"id\": " + quoted(q.id) + ", \"doc\": " + quoted(q.doc); });
  section("methods", vocab::all_methods, [](const vocab::method& m) {
    char theory[32];
    std::snprintf(theory, sizeof theory, "%.17g", m.theory);
    return "\"id\": " + quoted(m.id) + ", \"quantities\": " + words(m.quantities) +
           ", \"settings\": " + words(m.settings) + ", \"theory\": " + theory + ", \"doc\": " + quoted(m.doc);
  });
  section("peers", vocab::all_peers, [](const vocab::peer& p) {
    return "\"id\": " + quoted(p.id) + ", \"library\": " + quoted(p.library) + ", \"doc\": " + quoted(p.doc);
  });
  section("operations", vocab::all_operations,
          [](const vocab::operation& o) { return "\"id\": " + quoted(o.id) + ", \"doc\": " + quoted(o.doc); });
  section("counters", vocab::all_counters, [](const vocab::counter& c) {
    return "\"name\": " + quoted(c.name) + ", \"kind\": " + quoted(c.kind) + ", \"doc\": " + quoted(c.doc);
  });
  section("algorithms", vocab::all_algorithms, [](const vocab::algorithm& a) {
    return "\"id\": " + quoted(a.id) + ", \"settings\": " + words(a.settings) + ", \"doc\": " + quoted(a.doc);
  });
  section(
      "variant_keys", vocab::all_variant_keys,
      [](const vocab::variant_key& k) {
        return "\"id\": " + quoted(k.id) + ", \"values\": " + words(k.values) + ", \"doc\": " + quoted(k.doc);
      },
      true);
  std::printf("}\n");
  return 0;
}
