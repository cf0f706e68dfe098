// Private: a process-wide, thread-safe cache of quadrature rules keyed by their size n.
//
// One cache per rule type (a class template's static members). A rule is computed once, under a
// mutex, and never freed before exit, so the returned reference stays valid for the life of the
// program. Sizes n <= fast_limit are also published through an array of atomic pointers: after
// the first computation a lookup is one acquire load, no lock (hot paths call it per query).
#pragma once

#include <array>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>

namespace curvebench::arclength::detail {

template <class Rule>
class rule_cache {
 public:
  static constexpr int fast_limit = 128;

  /// The rule of size n, computed by make(n) on first use (n is validated by make).
  static const Rule& get(int n, Rule (*make)(int)) {
    if (n >= 0 && n <= fast_limit) {
      const Rule* p = fast()[static_cast<std::size_t>(n)].load(std::memory_order_acquire);
      if (p != nullptr) return *p;
    }
    std::lock_guard<std::mutex> lock(mutex());
    auto& store = rules();
    auto it = store.find(n);
    if (it == store.end()) it = store.emplace(n, std::make_unique<const Rule>(make(n))).first;
    const Rule* p = it->second.get();
    if (n >= 0 && n <= fast_limit) fast()[static_cast<std::size_t>(n)].store(p, std::memory_order_release);
    return *p;
  }

 private:
  static std::mutex& mutex() {
    static std::mutex m;
    return m;
  }
  static std::map<int, std::unique_ptr<const Rule>>& rules() {
    static std::map<int, std::unique_ptr<const Rule>> r;
    return r;
  }
  static std::array<std::atomic<const Rule*>, fast_limit + 1>& fast() {
    static std::array<std::atomic<const Rule*>, fast_limit + 1> f{};
    return f;
  }
};

}  // namespace curvebench::arclength::detail
