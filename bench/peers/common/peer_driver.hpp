// What the native peer drivers share (bench/peers/{qt,occt,lib2geom}): the machine and
// package facts they record beside their numbers (cpu_model, debian_version), their timing loop
// (best_ns), the all-or-nothing write of their output (write_json) and the measuring of one call of
// a peer library in a forked child under a time limit (run_isolated), so that a crash, a hang or a
// throw of the peer becomes a skip reason instead of the end of the driver. Header-only: each driver
// is one executable with its own link line; include it as "common/peer_driver.hpp" (the drivers'
// CMakeLists add bench/peers to their include path).
#pragma once

#include <nlohmann/json.hpp>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <string>

namespace curvebench::peers {

using json = nlohmann::json;

// ---- facts about the machine ----------------------------------------------------------------------

// The output of the shell command `cmd` (popen), trailing newlines and spaces removed; "" when it
// cannot be run.
inline std::string run_command(const std::string& cmd) {
  std::string out;
  if (FILE* p = popen(cmd.c_str(), "r")) {
    char buf[256];
    while (std::fgets(buf, sizeof buf, p)) out += buf;
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == ' ')) out.pop_back();
  return out;
}

// The first "model name" of /proc/cpuinfo (recorded with every timed run), or "unknown".
inline std::string cpu_model() {
  std::ifstream f("/proc/cpuinfo");
  std::string line;
  while (std::getline(f, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) {
        std::string v = line.substr(colon + 1);
        v.erase(0, v.find_first_not_of(" \t"));
        return v;
      }
    }
  }
  return "unknown";
}

// The installed version of a Debian package (dpkg-query), or "" when it is not installed or there
// is no dpkg.
inline std::string debian_version(const std::string& package) {
  return run_command("dpkg-query -W -f='${Version}' " + package + " 2>/dev/null");
}

// ---- timing ---------------------------------------------------------------------------------------

inline double elapsed_ns(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
}

// How many timing passes best_ns makes. With the defaults: `passes` passes. budget_ns > 0: as many
// as fit that budget at the length of one pass, clamped to [min_passes, passes] (min_passes <=
// passes). slow_pass_ns > 0: a pass longer than that cuts the passes to at most slow_passes.
struct Timing {
  int passes = 5;
  int min_passes = 1;
  double budget_ns = 0;
  double slow_pass_ns = 0;
  int slow_passes = 2;
  double min_pass_ns = 20000.0;  // a pass repeats the call until it lasts at least this long

  // The OCCT and lib2geom drivers': five passes (one with --quick), two when a pass lasts > 20 ms.
  static Timing fixed(bool quick) {
    Timing t;
    t.passes = quick ? 1 : 5;
    t.slow_pass_ns = 2e7;
    return t;
  }
  // The Qt driver's: the passes that fit 150 ms, 3 to 30 (20 ms, 3 to 5 with --quick).
  static Timing budgeted(bool quick) {
    Timing t;
    t.passes = quick ? 5 : 30;
    t.min_passes = 3;
    t.budget_ns = quick ? 2e7 : 1.5e8;
    return t;
  }
};

// The best time in ns of one of the `calls` operations that one call of f makes. f returns a number
// for a sink (so that the optimiser keeps the work). Contract: one warm-up call of f; then passes
// of r calls each, r the first power of two (at most 2^22) whose pass lasts >= t.min_pass_ns (the
// pass that finds r is the first timed pass); the number of passes as Timing says, from that pass's
// length; the result is min over the passes of (pass ns / r) / calls.
inline double best_ns(const std::function<double()>& f, double calls, const Timing& t) {
  volatile double sink = 0;
  sink = sink + f();
  const auto pass = [&](long reps) {
    const auto t0 = std::chrono::steady_clock::now();
    for (long r = 0; r < reps; ++r) sink = sink + f();
    return elapsed_ns(t0);
  };
  long reps = 1;
  double dt = pass(reps);
  while (dt < t.min_pass_ns && reps < (1L << 22)) {
    reps *= 2;
    dt = pass(reps);
  }
  int passes = t.passes;
  if (t.budget_ns > 0) passes = std::clamp(static_cast<int>(t.budget_ns / std::max(dt, 1.0)), t.min_passes, t.passes);
  if (t.slow_pass_ns > 0 && dt > t.slow_pass_ns) passes = std::min(passes, t.slow_passes);
  double best = dt / static_cast<double>(reps);
  for (int p = 1; p < passes; ++p) best = std::min(best, pass(reps) / static_cast<double>(reps));
  return best / calls;
}

// ---- output ---------------------------------------------------------------------------------------

// doc as indented JSON at path, written to path.tmp and renamed over path (an interrupted run never
// leaves a half-written file); std::runtime_error or std::filesystem::filesystem_error otherwise.
inline void write_json(const std::string& path, const json& doc) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp);
    if (!f) throw std::runtime_error("cannot write " + tmp);
    f << doc.dump(1) << "\n";
    if (!f) throw std::runtime_error("cannot write " + tmp);
  }
  std::filesystem::rename(tmp, path);
}

// ---- the shipped request and the driver output (scripts/peers/shipped_request.py, shipped_results.py)

// The command line of a driver answering the shipped request: --request REQ.json --out OUT.json
// [--quick]. Anything else prints the usage (naming program) and gives std::nullopt.
struct ShippedArgs {
  std::string request, out;
  bool quick = false;
};

inline std::optional<ShippedArgs> shipped_args(int argc, char** argv, const std::string& program) {
  ShippedArgs a;
  bool bad = false;
  for (int i = 1; i < argc && !bad; ++i) {
    const std::string arg = argv[i];
    if (arg == "--request" && i + 1 < argc)
      a.request = argv[++i];
    else if (arg == "--out" && i + 1 < argc)
      a.out = argv[++i];
    else if (arg == "--quick")
      a.quick = true;
    else
      bad = true;
  }
  if (bad || a.request.empty() || a.out.empty()) {
    std::cerr << "usage: " << program << " --request REQ.json --out OUT.json [--quick]\n";
    return std::nullopt;
  }
  return a;
}

// The request at path, checked to be a "curvebench-shipped-request-1"; std::runtime_error naming the
// file otherwise.
inline json read_shipped_request(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  json req;
  f >> req;
  if (req.value("format", "") != "curvebench-shipped-request-1")
    throw std::runtime_error(path + ": not a curvebench-shipped-request-1");
  return req;
}

// A driver's start: its arguments and its request into args and req; 0, or the exit status after
// printing why (2: the usage; 1: the request could not be read, naming program and the file).
inline int start_shipped_driver(int argc, char** argv, const std::string& program, ShippedArgs& args, json& req) {
  const std::optional<ShippedArgs> a = shipped_args(argc, argv, program);
  if (!a) return 2;
  args = *a;
  try {
    req = read_shipped_request(args.request);
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}

// One "skipped" entry: the peer, the case and why, prefixed by the setting ("default setting" for "").
inline json skipped_entry(const std::string& peer, const json& c, const std::string& setting, const std::string& why) {
  return {{"peer", peer},
          {"case", c.at("case")},
          {"reason", (setting.empty() ? std::string("default setting") : setting) + ": " + why}};
}

// The driver output ("curvebench-shipped-driver-1") written to path, with a one-line summary on
// stderr; the exit status (1 naming program and the error when it cannot be written).
inline int write_shipped_output(const std::string& path, const std::string& driver, const json& versions,
                                const json& runs, const json& skipped, const std::string& program) {
  const json out = {{"driver", driver},     {"format", "curvebench-shipped-driver-1"},
                    {"versions", versions}, {"cpu", cpu_model()},
                    {"runs", runs},         {"skipped", skipped}};
  try {
    write_json(path, out);
  } catch (const std::exception& e) {
    std::cerr << program << ": " << e.what() << "\n";
    return 1;
  }
  std::cerr << program << ": " << runs.size() << " runs, " << skipped.size() << " skipped -> " << path << "\n";
  return 0;
}

// ---- one measurement in a child process under a time limit ------------------------------------------

namespace detail {

inline int g_isolated_fd = -1;        // in run_isolated's child: the pipe to the parent
inline std::string g_isolated_stage;  // in that child: the stage last named

inline bool write_all(int fd, const std::string& text) {
  size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = write(fd, text.data() + done, text.size() - done);
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

}  // namespace detail

// What run_isolated's child gave: ok and its JSON, or why not.
struct Isolated {
  bool ok = false;
  json value;
  std::string reason;
};

// In run_isolated's child: from now on the child is in `what` (named in the reason of a timeout or
// a crash). limit_s > 0 also restarts the time limit: the child must answer or reach its next
// limited stage within limit_s seconds (a tighter limit for one call). Outside such a child it only
// records the name.
inline void isolated_stage(const std::string& what, unsigned limit_s = 0) {
  detail::g_isolated_stage = what;
  if (detail::g_isolated_fd < 0) return;
  std::string line = "S" + std::to_string(limit_s) + " " + what;
  std::replace(line.begin(), line.end(), '\n', ' ');
  if (!detail::write_all(detail::g_isolated_fd, line + "\n")) _exit(3);
  if (limit_s > 0) alarm(limit_s);
}

// The stage the child last named ("" before any).
inline const std::string& isolated_stage_name() { return detail::g_isolated_stage; }

// work() in a forked child process that has limit_s seconds (alarm(); the parent kills it 10 s after
// its limit should the alarm not end it). Returns {true, its JSON, ""} or {false, null, reason}, the
// reason one of: "no answer within N s[ in STAGE] (killed)" (N the limit in force), "the measuring
// process died of signal N (NAME)[ in STAGE]", the message of what work() threw, or "the measuring
// process exited with status N and no answer[ in STAGE]". std::runtime_error when pipe or fork fail.
inline Isolated run_isolated(const std::function<json()>& work, unsigned limit_s) {
  using clock = std::chrono::steady_clock;
  constexpr unsigned kGraceS = 10;
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = fork();
  if (pid < 0) {
    close(fds[0]);
    close(fds[1]);
    throw std::runtime_error("fork failed");
  }
  if (pid == 0) {
    close(fds[0]);
    detail::g_isolated_fd = fds[1];
    std::signal(SIGALRM, SIG_DFL);  // the alarm ends the child; the parent sees SIGALRM
    alarm(limit_s);
    std::string answer;
    try {
      answer = "R" + work().dump() + "\n";
    } catch (const std::exception& e) {
      answer = "E" + json(e.what()).dump() + "\n";
    }
    alarm(0);
    _exit(detail::write_all(fds[1], answer) ? 0 : 3);
  }
  close(fds[1]);
  // Lines from the child: "S<limit> <stage>" as it names a stage, then one "R<json>" or "E<json string>".
  unsigned limit = limit_s;
  std::string stage, answer, pending;
  auto deadline = clock::now() + std::chrono::seconds(limit + kGraceS);
  bool killed = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - clock::now()).count();
    if (left <= 0) {
      kill(pid, SIGKILL);
      killed = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left)) <= 0) continue;
    char chunk[65536];
    const ssize_t n = read(fds[0], chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    pending.append(chunk, static_cast<size_t>(n));
    size_t start = 0;
    for (size_t end; (end = pending.find('\n', start)) != std::string::npos; start = end + 1) {
      const std::string line = pending.substr(start, end - start);
      if (line.empty() || line[0] != 'S') {
        answer = line;
        continue;
      }
      const size_t space = line.find(' ');
      const unsigned new_limit = static_cast<unsigned>(std::stoul(line.substr(1, space - 1)));
      stage = space == std::string::npos ? "" : line.substr(space + 1);
      if (new_limit > 0) {
        limit = new_limit;
        deadline = clock::now() + std::chrono::seconds(limit + kGraceS);
      }
    }
    pending.erase(0, start);
  }
  close(fds[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!killed && !answer.empty()) {
    const json value = json::parse(answer.substr(1), nullptr, false);
    if (!value.is_discarded()) {
      if (answer[0] == 'R') return {true, value, ""};
      if (answer[0] == 'E' && value.is_string()) return {false, nullptr, value.get<std::string>()};
    }
  }
  const std::string in = stage.empty() ? "" : " in " + stage;
  if (killed || (WIFSIGNALED(status) && WTERMSIG(status) == SIGALRM))
    return {false, nullptr, "no answer within " + std::to_string(limit) + " s" + in + " (killed)"};
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    return {false, nullptr,
            "the measuring process died of signal " + std::to_string(sig) + " (" + strsignal(sig) + ")" + in};
  }
  return {false, nullptr,
          "the measuring process exited with status " + std::to_string(WEXITSTATUS(status)) + " and no answer" + in};
}

}  // namespace curvebench::peers
