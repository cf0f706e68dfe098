// Measures the hand-written Catmull-Rom and chord table (keys.hpp) against curvebench's 50-digit
// reference on the installed cases catmull_rom_uniform_2d (alpha 0) and catmull_rom_centripetal_2d
// (alpha 1/2), writes the results (accuracy.json's format, for `curvebench gate` and the report)
// and gates them on thresholds.json: exit 1 naming every breach.
//   own_measure CASES_DIR THRESHOLDS OUT.json [--with-methods]
#include "keys.hpp"

#include <harness/subject.hpp>
#include <harness/writers.hpp>

#include <cstdio>
#include <exception>
#include <string>

int main(int argc, char** argv) {
  namespace h = curvebench::harness;
  if (argc < 4) {
    std::fprintf(stderr, "usage: own_measure CASES_DIR THRESHOLDS OUT.json [--with-methods]\n");
    return 2;
  }
  try {
    h::subject_options o;
    o.quick = true;
    o.with_methods = argc > 4 && std::string(argv[4]) == "--with-methods";
    nlohmann::json results;
    for (const auto& [case_name, alpha] :
         {std::pair{"catmull_rom_uniform_2d", 0.0}, std::pair{"catmull_rom_centripetal_2d", 0.5}}) {
      auto spline = h::measure_case(argv[1], case_name, own::spline_subject(alpha), o);
      // curvebench's own methods once per case are enough.
      h::subject_options table_options = o;
      table_options.with_methods = false;
      const auto table = h::measure_case(argv[1], case_name, own::table_subject(alpha), table_options);
      results = results.is_null() ? h::merge_results(spline, table)
                                  : h::merge_results(h::merge_results(results, spline), table);
    }
    h::write_results(results, argv[3]);
    for (const auto& r : results["records"])
      if (r.value("subject", false))
        std::printf("%-28s %-8s %-16s error %.3g\n", r["case"].get<std::string>().c_str(),
                    r["quantity"].get<std::string>().c_str(), r["method"].get<std::string>().c_str(),
                    r["error"].is_number() ? r["error"].get<double>() : -1.0);
    const auto breaches = h::subject_gate(results, argv[2]);
    for (const auto& b : breaches) std::fprintf(stderr, "own_measure: gate: %s\n", b.c_str());
    if (!breaches.empty()) return 1;
    std::printf("own_measure: gate passed (%s)\n", argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "own_measure: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
