// curvebench's fuzz targets: one function per reader a user's file reaches, each taking
// one input's bytes, running them through that reader the way the `curvebench` tool does, and
// checking properties that must hold for every input.
//
//   spec   io::parse, the family registry's build (curve_from_spec), evaluation, the length
//          methods, s(u) and u(s) (targets_spec.cpp)
//   gate   io::parse of a results and a thresholds file, then harness::check_gate (targets_gate.cpp)
//   csv    harness::parse_csv, the reader of `curvebench check`'s tables (targets_csv.cpp)
//   times  `sample --at / --range / --frames` on a channel spec: the tool's parsers of the option,
//          the spec's tool model and its evaluation at those times (targets_times.cpp)
//   svg    `length --svg`'s reader of SVG files (bench/tool/svg_file.hpp) and the path data parser
//          with the svg_path family's build (targets_svg.cpp)
//   compare   `curvebench compare`'s reader of results files (harness::read_results) and the
//             comparison of two runs, harness::compare_runs (targets_compare.cpp)
//   fidelity  `curvebench fidelity`'s reader of tool recordings, harness::measure_fidelity, with
//             each channel's evaluation as the tool (targets_fidelity.cpp)
//
// A reader may refuse an input only with the exceptions the error policy documents
// (core/error.hpp: invalid_input and its io::spec_error; std::domain_error outside a domain), with a
// non-empty message of bounded size. Anything else, and every broken property, calls violation(),
// which prints "fuzz <target>: property violated: <property>: <details>" on stderr and aborts: under
// libFuzzer that is a crash with the input saved; in the replay test (replay.cpp) a failing test
// naming the file. One property name per class of defect, so that findings sort by name.
//
// The same sources build two ways: with clang and -fsanitize=fuzzer,address,undefined as libFuzzer
// executables (CURVEBENCH_FUZZ, scripts/fuzz.sh), and with the normal compiler into the replay
// driver that the test build runs over tests/fuzz/regressions/ and the seed corpus.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

namespace curvebench::fuzz {

/// Prints "fuzz <target>: property violated: <property>: <details>" and aborts.
[[noreturn]] void violation(std::string_view target, std::string_view property, const std::string& details);

/// The longest exception message a reader may produce (bytes): echoes of the input are cut to a
/// few dozen characters and paths are at most io::max_nesting_depth levels of at most 40-character
/// keys, so a longer message echoes input without bound.
inline constexpr std::size_t max_message = 4096;

int spec_target(const std::uint8_t* data, std::size_t size);
int gate_target(const std::uint8_t* data, std::size_t size);
int csv_target(const std::uint8_t* data, std::size_t size);
int times_target(const std::uint8_t* data, std::size_t size);
int svg_target(const std::uint8_t* data, std::size_t size);
int compare_target(const std::uint8_t* data, std::size_t size);
int fidelity_target(const std::uint8_t* data, std::size_t size);

}  // namespace curvebench::fuzz
