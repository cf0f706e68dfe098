#include "harness/vocabulary_json.hpp"

#include "harness/vocabulary.hpp"

#include "curvebench/channel/tool_model.hpp"
#include "curvebench/io/tools/all.hpp"

#include <string>
#include <string_view>

namespace curvebench::harness {

namespace {
nlohmann::json words(std::string_view list) {
  nlohmann::json out = nlohmann::json::array();
  while (!list.empty()) {
    const auto space = list.find(' ');
    if (space != 0) out.push_back(std::string(list.substr(0, space)));
    if (space == std::string_view::npos) break;
    list.remove_prefix(space + 1);
  }
  return out;
}
std::string str(std::string_view s) { return std::string(s); }
}  // namespace

nlohmann::json vocabulary_json() {
  nlohmann::json v{{"quantities", nlohmann::json::array()},   {"methods", nlohmann::json::array()},
                   {"peers", nlohmann::json::array()},        {"operations", nlohmann::json::array()},
                   {"counters", nlohmann::json::array()},     {"algorithms", nlohmann::json::array()},
                   {"variant_keys", nlohmann::json::array()}, {"tools", nlohmann::json::array()}};
  for (const vocab::quantity* q : vocab::all_quantities)
    v["quantities"].push_back({{"id", str(q->id)}, {"doc", str(q->doc)}});
  for (const vocab::method* m : vocab::all_methods())
    v["methods"].push_back({{"id", str(m->id)},
                            {"quantities", words(m->quantities)},
                            {"settings", words(m->settings)},
                            {"theory", m->theory},
                            {"doc", str(m->doc)}});
  for (const vocab::peer* p : vocab::all_peers)
    v["peers"].push_back({{"id", str(p->id)}, {"library", str(p->library)}, {"doc", str(p->doc)}});
  for (const vocab::operation* o : vocab::all_operations)
    v["operations"].push_back({{"id", str(o->id)}, {"doc", str(o->doc)}});
  for (const vocab::counter* c : vocab::all_counters)
    v["counters"].push_back({{"name", str(c->name)}, {"kind", str(c->kind)}, {"doc", str(c->doc)}});
  for (const vocab::algorithm* a : vocab::all_algorithms)
    v["algorithms"].push_back({{"id", str(a->id)}, {"settings", words(a->settings)}, {"doc", str(a->doc)}});
  for (const vocab::variant_key* k : vocab::all_variant_keys)
    v["variant_keys"].push_back({{"id", str(k->id)}, {"values", words(k->values)}, {"doc", str(k->doc)}});
  // The keyframe tools (io::all_tools): the name is the spec's "tool", the benchmark's algorithm of
  // the tool's model (setting bits, its storage precision) and the report's column.
  io::for_each_tool([&](auto t) {
    using T = typename decltype(t)::type;
    v["tools"].push_back({{"id", str(T::name)},
                          {"storage_bits", channel::storage_bits_of<typename T::storage_type>},
                          {"default_solver", channel::to_string(T::default_solver)},
                          {"settings", words("bits")},
                          {"doc", str(T::summary)},
                          {"rules", str(T::rules)},
                          {"verification", str(T::verification)}});
  });
  return v;
}

}  // namespace curvebench::harness
