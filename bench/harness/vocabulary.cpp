// The method list of the vocabulary, derived from the method tables: a length or u(s) method is
// listed because it has a row, so adding one takes no entry here.
#include "harness/vocabulary.hpp"

#include "harness/length_methods.hpp"

#include <algorithm>
#include <vector>

namespace curvebench::harness::vocab {

namespace {
std::vector<const method*> make_all_methods() {
  std::vector<const method*> out;
  const auto add = [&out](const method* m) {
    if (std::find(out.begin(), out.end(), m) == out.end()) out.push_back(m);
  };
  for_each_row(length_methods, [&](const auto& row) { add(row.method); });
  add(&methods::segments_adaptive);  // s(u), between the length and the u(s) methods as records list them
  for_each_row(u_of_s_methods, [&](const auto& row) { add(row.method); });
  for (const method* m : methods_without_row) add(m);
  return out;
}
}  // namespace

std::span<const method* const> all_methods() {
  static const std::vector<const method*> list = make_all_methods();
  return list;
}

const method* find_method(std::string_view id) {
  for (const method* m : all_methods())
    if (m->id == id) return m;
  return nullptr;
}

}  // namespace curvebench::harness::vocab
