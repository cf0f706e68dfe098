// run_case and run_accuracy: the sweeps of one case composed, and the cases run on the worker pool.
#include "harness/accuracy.hpp"

#include "harness/pool.hpp"
#include "harness/records.hpp"
#include "harness/reference.hpp"
#include "harness/sweeps.hpp"
#include "harness/writers.hpp"

#include "curvebench/io/spec.hpp"
#include "curvebench/io/spec_data.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <utility>

namespace curvebench::harness {

namespace {

using json = nlohmann::json;

template <int Dim>
json run_dim(const case_info& info, bool quick, const peer_sweeps* peers) {
  const auto t0 = std::chrono::steady_clock::now();
  const sweep w = settings(quick);
  const io::field spec = io::root(info.spec, info.name);
  const any_curve<double, Dim> c = io::curve_from_spec<double, Dim>(spec);
  case_reference<Dim> ref(spec);
  record_sink k(info);
  sweep_length<Dim>(k, c, ref, w);
  sweep_s_of_u<Dim>(k, c, ref, w);
  sweep_u_of_s<Dim>(k, c, ref, w);
  sweep_eval<Dim>(k, c, ref, w, info.spec);
  json properties, channel;
  if constexpr (Dim == 2) properties = sweep_audit(info);
  if (info.spec.value("type", "") == "channel") channel = sweep_channel(k, info, w);
  json peer_records = json::array();
  if (peers != nullptr) {
    if constexpr (Dim == 2) peer_records = peers->dim2(info, c, ref, w);
    if constexpr (Dim == 3) peer_records = peers->dim3(info, c, ref, w);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {{"records", k.records()},
          {"orders", k.orders()},
          {"peer_records", std::move(peer_records)},
          {"case",
           {{"name", info.name},
            {"group", info.group},
            {"reason", info.reason},
            {"family", c.family()},
            {"dimension", Dim},
            {"segments", c.breakpoints().size() - 1},
            {"reference_length", ref.length_text()},
            {"reference_error", ref.length_error()},
            {"speed_minima", ref.speed_minima()},
            {"properties", properties},
            {"channel", channel},
            {"seconds", seconds}}}};
}

}  // namespace

std::string compiler_id() {
#if defined(__clang__)
  return "clang " + std::to_string(__clang_major__) + "." + std::to_string(__clang_minor__) + "." +
         std::to_string(__clang_patchlevel__);
#elif defined(__GNUC__)
  return "gcc " + std::to_string(__GNUC__) + "." + std::to_string(__GNUC_MINOR__) + "." +
         std::to_string(__GNUC_PATCHLEVEL__);
#elif defined(__VERSION__)
  return __VERSION__;
#else
  return "unknown";
#endif
}

namespace {

// A glTF rotation case: a quaternion over time, which has no curve view (so no length, s(u), u(s)
// or eval records), measured by sweep_rotation alone.
json run_rotation(const case_info& info, bool quick) {
  const auto t0 = std::chrono::steady_clock::now();
  record_sink k(info);
  json channel = sweep_rotation(k, info, settings(quick));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return {{"records", k.records()},
          {"orders", k.orders()},
          {"peer_records", json::array()},
          {"case",
           {{"name", info.name},
            {"group", info.group},
            {"reason", info.reason},
            {"family", "channel"},
            {"dimension", info.dimension},
            {"segments", channel["keys"].get<std::size_t>() - 1},
            {"channel", channel},
            {"seconds", seconds}}}};
}

}  // namespace

json run_case(const case_info& c, bool quick, const peer_sweeps* peers) {
  if (c.spec.value("type", "") == "channel" && io::is_gltf_rotation(io::root(c.spec, c.name)))
    return run_rotation(c, quick);
  switch (c.dimension) {
    case 2: return run_dim<2>(c, quick, peers);
    case 3: return run_dim<3>(c, quick, peers);
    default:
      throw invalid_input(c.file + ": the accuracy runner takes 2D and 3D cases, this one is " +
                          std::to_string(c.dimension) + "D");
  }
}

int run_accuracy(const accuracy_options& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  check_results_path(opt.out);  // before minutes of work, not after
  // A run with a failed case is not the suite: it goes beside --out, never over an earlier good run.
  const std::string partial = partial_path(opt.out);
  check_results_path(partial);
  std::vector<case_info> all = load_cases(opt.cases_dir);
  std::vector<case_info> cases;
  for (auto& c : all)
    if ((opt.only.empty() || c.name.find(opt.only) != std::string::npos) && !(opt.quick && !c.quick))
      cases.push_back(std::move(c));
  if (cases.empty()) throw invalid_input("--only " + opt.only + ": no case matches");
  // The most expensive cases first, so that the cores stay busy to the end.
  std::vector<std::size_t> order(cases.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return !cases[a].quick && cases[b].quick; });
  std::vector<json> results(cases.size());
  std::vector<std::string> failures(cases.size());
  const unsigned threads = pool_threads(opt.threads, cases.size());
  run_pool(
      order, threads,
      [&](std::size_t i) {
        try {
          results[i] = run_case(cases[i], opt.quick, opt.peers);
        } catch (const std::exception& e) {
          failures[i] = cases[i].name + ": " + e.what();
        }
      },
      [&](std::size_t i, std::size_t finished) {
        if (opt.quiet) return;
        const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::cerr << "accuracy: case " << finished << " of " << cases.size() << " (" << 100 * finished / cases.size()
                  << "%, " << std::setprecision(3) << elapsed << " s elapsed) " << cases[i].name
                  << (failures[i].empty() ? "" : " FAILED: " + failures[i]) << " ("
                  << (results[i].is_null() ? 0.0 : results[i]["case"]["seconds"].get<double>()) << " s)\n";
      });

  json out{{"schema", 1},
           {"suite", {{"name", suite_name}, {"version", suite_version}, {"cases", cases.size()}}},
           {"records", json::array()},
           {"orders", json::array()},
           {"peer_records", json::array()},
           {"cases", json::array()}};
  for (std::size_t i = 0; i < cases.size(); ++i) {
    if (!failures[i].empty()) continue;
    for (auto& r : results[i]["records"]) out["records"].push_back(std::move(r));
    for (auto& o : results[i]["orders"]) out["orders"].push_back(std::move(o));
    for (auto& p : results[i]["peer_records"]) out["peer_records"].push_back(std::move(p));
    out["cases"].push_back(results[i]["case"]);
  }
  const char* revision = std::getenv("CURVEBENCH_REVISION");
  out["context"] = {{"revision", revision ? revision : "unknown"},
                    {"compiler", compiler_id()},
                    {"flags", CURVEBENCH_FLAGS},
                    {"quick", opt.quick},
                    {"threads", threads},
                    {"peers", opt.peers != nullptr ? opt.peers->versions() : json::object()},
                    {"seconds", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()}};
  std::size_t failed = 0;
  for (const auto& f : failures)
    if (!f.empty()) {
      std::cerr << "accuracy: case failed: " << f << "\n";
      ++failed;
    }
  out["context"]["failed_cases"] = failed;
  write_results(out, failed == 0 ? opt.out : partial);
  std::cerr << "accuracy: " << out["records"].size() << " records, " << out["orders"].size() << " orders from "
            << cases.size() - failed << " cases in " << std::setprecision(3) << out["context"]["seconds"].get<double>()
            << " s -> " << (failed == 0 ? opt.out : partial) << "\n";
  if (failed > 0)
    std::cerr << "accuracy: " << failed << (failed == 1 ? " case" : " cases") << " failed: " << opt.out
              << " is left as it was; the cases that ran are in " << partial << "\n";
  return failed == 0 ? 0 : 1;
}

}  // namespace curvebench::harness
