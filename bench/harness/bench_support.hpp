// The benchmarks' side of the vocabulary (vocabulary.hpp): the only way a benchmark names itself,
// sets a counter or declares what it times, so that every name, counter and label scripts/report.py
// reads is an id declared there.
//   benchmark_name     family/algorithm[/key:value]..., the algorithm a method, a peer or an
//                      algorithm id; numbers formatted as the records' settings ("1e-10", "256")
//   set_counter        a plain value per operation (never a rate): counts, errors, settings
//   per_operation      the operation timed and how many of it one iteration performs: Google
//                      Benchmark's items processed and the label, from which report.py derives the
//                      time per operation (a batch of 1024 evaluations reads per evaluation)
#pragma once

#include "vocabulary.hpp"  // beside this header: found from any includer

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::bench {

namespace vocab = curvebench::harness::vocab;

/// Sets counter c to value (a plain number: Google Benchmark reports it as given).
inline void set_counter(benchmark::State& state, const vocab::counter& c, double value) {
  state.counters[std::string(c.name)] = benchmark::Counter(value);
}

/// Declares that each iteration performs per_iteration operations op (items processed and label).
inline void per_operation(benchmark::State& state, const vocab::operation& op, double per_iteration) {
  state.SetItemsProcessed(static_cast<std::int64_t>(static_cast<double>(state.iterations()) * per_iteration));
  state.SetLabel(std::string(op.id));
}

/// A benchmark name family/algorithm[/key:value]... built from vocabulary ids.
class benchmark_name {
 public:
  benchmark_name(std::string_view family, const vocab::method& m) : s_(join(family, m.id)) {}
  benchmark_name(std::string_view family, const vocab::peer& p) : s_(join(family, p.id)) {}
  benchmark_name(std::string_view family, const vocab::algorithm& a) : s_(join(family, a.id)) {}

  /// Appends /key:value.
  benchmark_name& arg(std::string_view key, std::string_view value) {
    s_.append("/").append(key).append(":").append(value);
    return *this;
  }
  benchmark_name& arg(std::string_view key, const char* value) { return arg(key, std::string_view(value)); }
  /// Appends /key:value with the number as the records' settings print it (1e-10, 256, 0.5).
  benchmark_name& arg(std::string_view key, double value) {
    std::ostringstream os;
    os << value;
    return arg(key, std::string_view(os.str()));
  }
  benchmark_name& arg(std::string_view key, long long value) {
    return arg(key, std::string_view(std::to_string(value)));
  }
  benchmark_name& arg(std::string_view key, int value) { return arg(key, static_cast<long long>(value)); }
  benchmark_name& arg(std::string_view key, std::size_t value) {
    return arg(key, std::string_view(std::to_string(value)));
  }
  /// Appends /key:value of a variant (calls:sorted, estimate:nested); std::invalid_argument when
  /// the key does not list the value.
  benchmark_name& variant(const vocab::variant_key& key, std::string_view value) {
    if (!vocab::lists(key.values, value))
      throw std::invalid_argument(s_ + ": variant " + std::string(key.id) + " has no value '" + std::string(value) +
                                  "' (allowed: " + std::string(key.values) + ")");
    return arg(key.id, value);
  }

  [[nodiscard]] const std::string& str() const { return s_; }
  operator const std::string&() const { return s_; }  // NOLINT: a name is its string

 private:
  static std::string join(std::string_view family, std::string_view algorithm) {
    std::string s(family);
    s.append("/").append(algorithm);
    return s;
  }
  std::string s_;
};

/// n query parameters in [lo, hi], uniformly random with a fixed seed (the same in every run and
/// every program, so that ours and a peer's rows query the same points), or the same ones sorted.
inline std::vector<double> query_parameters(double lo, double hi, std::size_t n, bool sorted) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> dist(lo, hi);
  std::vector<double> u(n);
  for (double& x : u) x = dist(rng);
  if (sorted) std::sort(u.begin(), u.end());
  return u;
}

/// Registers fn(state) under name (Google Benchmark copies the name).
template <class F>
benchmark::internal::Benchmark* register_benchmark(const benchmark_name& name, F&& fn) {
  return benchmark::RegisterBenchmark(name.str().c_str(), std::forward<F>(fn));
}

}  // namespace curvebench::bench
