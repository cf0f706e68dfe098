// curvebench_peer_qt: Qt 5's arc length, point at length and easing curves as peers.
//
// Usage
//   curvebench_peer_qt paths  --request REQ.json --out OUT.json [--quick]
//       REQ.json: scripts/peers/shipped_request.py's "curvebench-shipped-request-1"; OUT.json: a
//       "curvebench-shipped-driver-1" document (driver "qt") for scripts/peers/shipped_results.py.
//   curvebench_peer_qt easing --cases bench/cases --out OUT.json [--quick]
//       every case file with "type": "channel", "tool": "css" and "easing": "cubic-bezier(x1, y1,
//       x2, y2)" evaluated at the accuracy runner's sample fractions (257, 65 with --quick); OUT.json
//       in the format of scripts/peers/easing_driver.mjs (driver "qt_easing") for
//       scripts/peers/easing_results.py.
//   curvebench_peer_qt tcb --cases bench/cases [--spec FILE]... --out OUT.json [--quick]
//       every case file of DIR (and every --spec FILE) with "type": "kochanek_bartels" that an
//       easing curve can hold (2D, open, no knots or uniform ones, x strictly increasing from key to
//       key, first and last y different; the others named in "notes" with the reason) as a
//       QEasingCurve TCB spline: its Bezier segments (toCubicSpline) and valueForProgress at the
//       sample fractions; OUT.json (driver "qt_tcb") for scripts/peers/tcb_results.py.
//   --quick: fewer and shorter timing passes (paths), 65 instead of 257 times (easing, tcb).
// Neither mode creates a QGuiApplication: QPainterPath, QTransform and QEasingCurve are plain
// geometry and need no platform plugin, so the program runs without a display.
//
// Peers (Qt 5.15 as Debian ships it; qreal is double on x86_64, so every computation is in double)
// peer_qt_painterpath: a QPainterPath built from each request case's segments: moveTo(start),
//   lineTo, quadTo, cubicTo, closeSubpath() after a closed subpath's closing segment. Facts read
//   from Qt's qpainterpath.h and its sources (qpainterpath.cpp, qbezier.cpp, qstroker.cpp):
//   - A path holds only lines and cubics: quadTo stores the equivalent cubic (inner points 2/3 of
//     the way to the control point). arcTo(rect, startAngle, sweep) takes degrees, counter-clockwise
//     with y down (the point at angle a is the rect's centre + (rx cos a, -ry sin a), a the
//     parametric angle of the ellipse), adds a lineTo to the arc's start when the path is not there,
//     and then cubics: one per quarter of the ellipse with inner points at kappa = 0.5522847498 of
//     the radii, a partial quarter cut at the Bezier t approximating the angle. So an SVG arc is
//     Qt's cubic approximation of the ellipse, not the ellipse: the arc's error is part of Qt's
//     answer. An arc of the request (its centre form c + R(phi)(rx cos th, ry sin th)) is
//     arcTo(rect of (cx, cy, rx, ry), -theta1, -dtheta) when phi = 0; a rotated one (phi != 0) is
//     built about the origin in a separate path (arcMoveTo, arcTo), mapped by the QTransform
//     R(phi) + c, and its cubics appended with cubicTo (the first starts at the path's current
//     point, within rounding of the mapped start).
//   - length(): the sum over the elements of each line's length and of QBezier::length() of each
//     cubic: the cubic is halved (de Casteljau) recursively until its control polygon's length
//     minus its chord is <= 0.01, an absolute tolerance in path units with no depth limit, and
//     the polygon lengths are summed (an upper bound of the cubic's length). Qt 5 does not cache
//     it (the path's private data has no length field; Qt 6.10 added caching): every call walks
//     the path again, and percentAtLength and pointAtPercent call it too.
//   - percentAtLength(s): length() of the path (s beyond it gives 1), then walks the elements: in
//     a line it returns s / total; in a cubic, QBezier::tAtLength(s - before): bisection on t
//     where every step measures the left part with QBezier::length(), until that length is within
//     0.01 (absolute) of the wanted one, in a loop with no iteration cap (where the measured left
//     length jumps over the 0.01 window as t moves, the loop never ends: this driver runs every
//     call under a time limit); it returns (t x cubic length + before) / total.
//   - pointAtPercent(p): length() again, the element where the running length / total reaches p
//     (each cubic measured again), and that Bezier at t = (total p - before) / its length clamped
//     to [0, 1]: linear in t inside a cubic (a line is a cubic with inner points at its thirds,
//     so linear in length there); p outside [0, 1] gives a warning and (0, 0).
//   The point at s is pointAtPercent(percentAtLength(min(s, Qt's length))); the n spaced points
//   are the points at k Lq / (n - 1), Lq = length(), k = 0 .. n - 1. One setting: Qt's defaults
//   (the 0.01 tolerances are not parameters of the public API).
// peer_qt_easing_curve: QEasingCurve(QEasingCurve::BezierSpline) with one
//   addCubicBezierSegment((x1, y1), (x2, y2), (1, 1)); valueForProgress(x) clamps x to [0, 1],
//   finds the segment holding x and solves x(t) = x in closed form (a cube root by a bit trick
//   refined with one Halley step, polynomial approximations of cos(acos(v) / 3) for three real
//   roots, a root accepted in [-0.01, 1.01]), then evaluates y(t); all in double.
// peer_qt_easing_curve (tcb mode): QEasingCurve(QEasingCurve::TCBSpline) with one
//   addTCBSegment(key, t, c, b) per key, the first at (0, 0) and the last at (1, 1) (Qt's documented
//   requirement; the keys are mapped affinely into the unit square, x' = (x - x0) / (xn - x0),
//   y' = (y - y0) / (yn - y0), the map recorded). Adding (1, 1) converts the keys into one cubic
//   Bezier per pair of keys (toCubicSpline(): inner point, inner point, end per segment, in double;
//   an inner key's outgoing and incoming tangents weighted by (1 - t)(1 +- c)(1 +- b) / 2 on its
//   arriving and leaving chords, the first and last key's tangent from their only chord), and
//   valueForProgress evaluates that Bezier spline as above (the same approximate x(t) = x solve).
//   A run records the map, the unit-square keys and their t, c, b, toCubicSpline()'s points, the
//   values at the sample fractions and (key_values) at the keys' own x.
//
// Time limit: every phase of a case runs in a forked child process (peers::run_isolated,
// bench/peers/common/peer_driver.hpp) with kPhaseLimit seconds, and every percentAtLength call in it
// under its own limit of kCallLimit seconds; a call that has not returned by then ends the child, and
// the case is listed in "skipped" with "points: no answer within N s in percentAtLength at s=...
// (killed)", its length (which always returns) still written as a run with no points. A crash of the
// child is skipped likewise.
//
// The limit itself is checked with CURVEBENCH_PEER_QT_SELFTEST_HANG=CASE in the environment: the
// points of that case then wait forever (pause()) at its third s instead of calling Qt.
//
// Times (peers::best_ns with Timing::budgeted: std::chrono::steady_clock, in the child, after one
// warm-up call): the best of the passes that fit 150 ms, 3 to 30 (20 ms, 3 to 5 with --quick), each
// pass repeating the operation until it lasts >= 20 us, divided by the repeats:
// ns_build = building the QPainterPath from the parsed segments; ns_length = one length() call
// (no cache to clear in Qt 5); ns_point = one percentAtLength + pointAtPercent, averaged over the
// request's s; ns_per_op (easing, tcb) = one valueForProgress, averaged over the times.
#include "common/peer_driver.hpp"

#include <QtCore/QEasingCurve>
#include <QtCore/QPointF>
#include <QtCore/QRectF>
#include <QtCore/QtGlobal>
#include <QtGui/QPainterPath>
#include <QtGui/QTransform>

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <numbers>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

namespace peers = curvebench::peers;
using json = nlohmann::json;

constexpr unsigned kCallLimit = 5;    // seconds for one percentAtLength call
constexpr unsigned kPhaseLimit = 60;  // seconds for a whole phase (build and length, points, timing)
constexpr double kInvPhi = 0.6180339887498949;

// ---- the request's geometry ---------------------------------------------------------------------

struct Segment {
  std::string kind;  // line, quadratic, cubic, arc
  std::vector<QPointF> points;
  double cx = 0, cy = 0, rx = 0, ry = 0, phi = 0, theta1 = 0, dtheta = 0;  // arcs' centre form
};

struct Subpath {
  QPointF start;
  bool closed = false;
  std::vector<Segment> segments;
};

struct Case {
  std::string name;
  std::vector<Subpath> subpaths;
  std::vector<double> s;
  int spaced = 0;
};

QPointF point_of(const json &p) { return {p.at(0).get<double>(), p.at(1).get<double>()}; }

Case case_of(const json &c) {
  Case out;
  out.name = c.at("case").get<std::string>();
  for (const auto &sp : c.at("segments")) {
    Subpath sub;
    sub.start = point_of(sp.at("start"));
    sub.closed = sp.value("closed", false);
    for (const auto &seg : sp.at("segments")) {
      Segment g;
      g.kind = seg.at("kind").get<std::string>();
      for (const auto &p : seg.at("points")) g.points.push_back(point_of(p));
      if (g.kind == "arc") {
        const json &ctr = seg.at("center");
        g.cx = ctr.at("cx").get<double>();
        g.cy = ctr.at("cy").get<double>();
        g.rx = ctr.at("rx").get<double>();
        g.ry = ctr.at("ry").get<double>();
        g.phi = ctr.at("phi").get<double>();
        g.theta1 = ctr.at("theta1").get<double>();
        g.dtheta = ctr.at("dtheta").get<double>();
      }
      sub.segments.push_back(std::move(g));
    }
    out.subpaths.push_back(std::move(sub));
  }
  for (const auto &v : c.at("s")) out.s.push_back(v.get<double>());
  out.spaced = c.value("spaced", 0);
  return out;
}

double degrees(double radians) { return radians * (180.0 / std::numbers::pi); }

// An arc of the request appended to `path` (whose current point is the arc's start).
void add_arc(QPainterPath &path, const Segment &g) {
  // Qt's angle a is at (rx cos a, -ry sin a) from the centre (y down), the request's theta at
  // (rx cos th, ry sin th): a = -theta.
  const double start = -degrees(g.theta1);
  const double sweep = -degrees(g.dtheta);
  if (g.phi == 0.0) {
    path.arcTo(QRectF(g.cx - g.rx, g.cy - g.ry, 2 * g.rx, 2 * g.ry), start, sweep);
    return;
  }
  const QRectF about_origin(-g.rx, -g.ry, 2 * g.rx, 2 * g.ry);
  QPainterPath local;
  local.arcMoveTo(about_origin, start);
  local.arcTo(about_origin, start, sweep);
  // QTransform(m11, m12, m21, m22, dx, dy) maps (x, y) to (m11 x + m21 y + dx, m12 x + m22 y + dy).
  const double c = std::cos(g.phi), s = std::sin(g.phi);
  const QPainterPath mapped = QTransform(c, s, -s, c, g.cx, g.cy).map(local);
  for (int i = 1; i < mapped.elementCount(); ++i) {
    const QPainterPath::Element e = mapped.elementAt(i);
    if (e.isCurveTo()) {
      path.cubicTo(QPointF(e), QPointF(mapped.elementAt(i + 1)), QPointF(mapped.elementAt(i + 2)));
      i += 2;
    } else if (e.isLineTo()) {
      path.lineTo(QPointF(e));
    }
  }
}

QPainterPath build(const Case &c) {
  QPainterPath path;
  for (const Subpath &sub : c.subpaths) {
    path.moveTo(sub.start);
    for (const Segment &g : sub.segments) {
      if (g.kind == "line") {
        path.lineTo(g.points.at(1));
      } else if (g.kind == "quadratic") {
        path.quadTo(g.points.at(1), g.points.at(2));
      } else if (g.kind == "cubic") {
        path.cubicTo(g.points.at(1), g.points.at(2), g.points.at(3));
      } else if (g.kind == "arc") {
        add_arc(path, g);
      } else {
        throw std::runtime_error("segment kind " + g.kind + " is not one QPainterPath has");
      }
    }
    if (sub.closed) path.closeSubpath();
  }
  return path;
}

std::string shortest(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// The point at arc length s, as a user asks it (s beyond Qt's own length asked at that length);
// `clamped` counts the percentAtLength answers above 1 (rounding) that pointAtPercent would refuse.
QPointF point_at_length(const QPainterPath &path, double s, int *clamped) {
  const double p = path.percentAtLength(s);
  if (p > 1.0 || p < 0.0) {
    if (clamped) ++*clamped;
    return path.pointAtPercent(std::clamp(p, 0.0, 1.0));
  }
  return path.pointAtPercent(p);
}

// In a child of peers::run_isolated: the points at arcs `at`, each call under its own time limit; {"points": [[x,
// y]...], "clamped": n}.
json points_at(const QPainterPath &path, const std::vector<double> &at, bool selftest_hang) {
  json pts = json::array();
  int clamped = 0;
  for (const double s : at) {
    peers::isolated_stage("percentAtLength at s=" + shortest(s), kCallLimit);
    if (selftest_hang && pts.size() == 2) pause();
    const QPointF q = point_at_length(path, s, &clamped);
    if (!std::isfinite(q.x()) || !std::isfinite(q.y()))
      throw std::runtime_error("pointAtPercent(percentAtLength(" + shortest(s) + ")) is not finite");
    pts.push_back({q.x(), q.y()});
  }
  return {{"points", pts}, {"clamped", clamped}};
}

json versions() {
  json v = {{"Qt", std::string(qVersion())}};
  const std::string deb = peers::debian_version("libqt5gui5");
  if (!deb.empty()) v["libqt5gui5 (Debian)"] = deb;
  return v;
}

// ---- mode 1: paths --------------------------------------------------------------------------------

void run_case(const Case &c, bool quick, json &runs, json &skipped) {
  const std::string peer = "peer_qt_painterpath";
  bool has_arc = false, rotated = false;
  for (const auto &sub : c.subpaths)
    for (const auto &g : sub.segments)
      if (g.kind == "arc") {
        has_arc = true;
        rotated = rotated || g.phi != 0.0;
      }

  const peers::Timing timing = peers::Timing::budgeted(quick);
  // Phase 1: build and length (never expected to hang; limited as a whole).
  const peers::Isolated base = peers::run_isolated(
      [&]() -> json {
        peers::isolated_stage("building the path and length()");
        const QPainterPath path = build(c);
        const double length = path.length();
        if (!std::isfinite(length)) throw std::runtime_error("length() is " + shortest(length));
        peers::isolated_stage("timing the build and length()");
        const double ns_build = peers::best_ns([&] { return static_cast<double>(build(c).elementCount()); }, 1, timing);
        const double ns_length = peers::best_ns([&] { return path.length(); }, 1, timing);
        return {
            {"length", length}, {"ns_build", ns_build}, {"ns_length", ns_length}, {"elements", path.elementCount()}};
      },
      kPhaseLimit);
  if (!base.ok) {
    skipped.push_back({{"peer", peer}, {"case", c.name}, {"reason", base.reason}});
    return;
  }
  const double length = base.value.at("length").get<double>();

  // Phase 2: the points at the request's s; phase 3: the spaced points. Each call has its own limit.
  std::vector<double> at;
  int beyond = 0;
  for (const double s : c.s) {
    at.push_back(std::min(s, length));
    beyond += s > length ? 1 : 0;
  }
  std::vector<double> spaced_at;
  for (int k = 0; k < c.spaced; ++k) spaced_at.push_back(k == c.spaced - 1 ? length : length * k / (c.spaced - 1));
  const char *hang = std::getenv("CURVEBENCH_PEER_QT_SELFTEST_HANG");
  const bool selftest_hang = hang && c.name == hang;
  const peers::Isolated points =
      peers::run_isolated([&] { return points_at(build(c), at, selftest_hang); }, kPhaseLimit);
  const peers::Isolated spaced =
      c.spaced >= 2 ? peers::run_isolated([&] { return points_at(build(c), spaced_at, false); }, kPhaseLimit)
                    : peers::Isolated{false, nullptr, "no spaced points asked"};

  // Phase 4: the time per point (the same calls as phase 2, which returned).
  std::optional<double> ns_point;
  if (points.ok) {
    const peers::Isolated timed = peers::run_isolated(
        [&]() -> json {
          peers::isolated_stage("timing the points");
          const QPainterPath path = build(c);
          return peers::best_ns(
              [&] {
                double sum = 0;
                for (const double s : at) sum += point_at_length(path, s, nullptr).x();
                return sum;
              },
              static_cast<double>(at.size()), timing);
        },
        kPhaseLimit);
    if (timed.ok) ns_point = timed.value.get<double>();
  }

  std::ostringstream note;
  note << "pointAtPercent(percentAtLength(s)) on a QPainterPath with Qt's fixed 0.01 absolute tolerances";
  if (has_arc)
    note << "; arcs through arcTo (Qt's kappa cubics)" << (rotated ? ", rotated ones mapped by a QTransform" : "");
  if (beyond) note << "; " << beyond << " s beyond Qt's own length asked at its length";
  int clamped = 0;
  for (const peers::Isolated *r : {&points, &spaced})
    if (r->ok) clamped += r->value.at("clamped").get<int>();
  if (clamped) note << "; " << clamped << " percentAtLength answers above 1 (rounding) clamped to 1";
  if (!points.ok) note << "; no points: " << points.reason;
  if (!spaced.ok && c.spaced >= 2) note << "; no spaced points: " << spaced.reason;
  json run = {{"peer", peer},
              {"case", c.name},
              {"setting", ""},
              {"length", length},
              {"points", points.ok ? points.value.at("points") : json(nullptr)},
              {"spaced", spaced.ok ? spaced.value.at("points") : json(nullptr)},
              {"ns_length", base.value.at("ns_length")},
              {"ns_point", ns_point ? json(*ns_point) : json(nullptr)},
              {"ns_build", base.value.at("ns_build")},
              {"note", note.str()}};
  runs.push_back(run);
  for (const peers::Isolated *r : {&points, &spaced})
    if (!r->ok && (r == &points || c.spaced >= 2))
      skipped.push_back(
          {{"peer", peer}, {"case", c.name}, {"reason", (r == &points ? "points: " : "spaced points: ") + r->reason}});
}

int paths_mode(const std::string &request_path, const std::string &out_path, bool quick) {
  std::ifstream f(request_path);
  if (!f) throw std::runtime_error("cannot read " + request_path);
  const json request = json::parse(f);
  if (request.value("format", "") != "curvebench-shipped-request-1")
    throw std::runtime_error(request_path + ": not a curvebench-shipped-request-1");
  json runs = json::array(), skipped = json::array();
  for (const auto &jc : request.at("cases")) {
    const Case c = case_of(jc);
    const auto t0 = std::chrono::steady_clock::now();
    run_case(c, quick, runs, skipped);
    std::cerr << "curvebench_peer_qt: " << c.name << " " << std::lround(peers::elapsed_ns(t0) / 1e6) << " ms\n";
  }
  const json doc = {{"driver", "qt"},         {"format", "curvebench-shipped-driver-1"},
                    {"versions", versions()}, {"cpu", peers::cpu_model()},
                    {"quick", quick},         {"runs", runs},
                    {"skipped", skipped}};
  peers::write_json(out_path, doc);
  std::cout << "curvebench_peer_qt: " << runs.size() << " runs, " << skipped.size() << " skipped -> " << out_path
            << "\n";
  return 0;
}

// ---- mode 2: easing -------------------------------------------------------------------------------

// valueForProgress of curve at each of times into run, as easing_driver.mjs writes its runs: "times",
// "values" (null where not finite, each such one listed in "non_finite" as [x, "NaN" | "Infinity" |
// "-Infinity"]) and "ns_per_op" (one call, over the finite ones; null when none is).
void add_progress_values(json &run, const QEasingCurve &curve, const std::vector<double> &times, bool quick) {
  json values = json::array(), bad = json::array();
  std::vector<double> timed;
  for (const double x : times) {
    const double v = curve.valueForProgress(x);
    if (std::isfinite(v)) {
      values.push_back(v);
      timed.push_back(x);
    } else {
      values.push_back(nullptr);
      bad.push_back({x, std::isnan(v) ? "NaN" : v > 0 ? "Infinity" : "-Infinity"});
    }
  }
  run["times"] = times;
  run["values"] = values;
  run["ns_per_op"] = timed.empty() ? json(nullptr)
                                   : json(peers::best_ns(
                                         [&] {
                                           double sum = 0;
                                           for (const double x : timed) sum += curve.valueForProgress(x);
                                           return sum;
                                         },
                                         static_cast<double>(timed.size()), peers::Timing::budgeted(quick)));
  if (!bad.empty()) run["non_finite"] = bad;
}

std::vector<double> sample_fractions(int n) {
  std::vector<double> out;
  for (int j = 0; j < n; ++j)
    out.push_back(j == 0 ? 0.0 : j + 1 == n ? 1.0 : std::fmod(static_cast<double>(j) * kInvPhi, 1.0));
  return out;
}

std::optional<std::array<double, 4>> cubic_bezier(const std::string &easing) {
  static const std::regex re(R"(^\s*cubic-bezier\(([^)]*)\)\s*$)");
  std::smatch m;
  if (!std::regex_match(easing, m, re)) return std::nullopt;
  std::array<double, 4> p{};
  std::stringstream ss(m[1].str());
  std::string item;
  size_t i = 0;
  while (std::getline(ss, item, ',')) {
    if (i >= 4) return std::nullopt;
    try {
      size_t used = 0;
      p[i] = std::stod(item, &used);
      if (item.find_first_not_of(" \t", used) != std::string::npos) return std::nullopt;
    } catch (const std::exception &) {
      return std::nullopt;
    }
    if (!std::isfinite(p[i])) return std::nullopt;
    ++i;
  }
  if (i != 4) return std::nullopt;
  return p;
}

int easing_mode(const std::string &cases_dir, const std::string &out_path, bool quick) {
  const std::vector<double> times = sample_fractions(quick ? 65 : 257);
  std::vector<std::filesystem::path> files;
  for (const auto &e : std::filesystem::directory_iterator(cases_dir))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  json runs = json::array(), notes = json::array();
  for (const auto &file : files) {
    std::ifstream f(file);
    const json spec = json::parse(f);
    if (spec.value("type", "") != "channel" || spec.value("tool", "") != "css") continue;
    const std::string name = file.stem().string();
    const std::string easing =
        spec.contains("easing") && spec["easing"].is_string() ? spec["easing"].get<std::string>() : std::string();
    const auto p = cubic_bezier(easing);
    if (!p) {
      notes.push_back(name + ": easing " + json(easing).dump() +
                      " is not cubic-bezier(); QEasingCurve's BezierSpline peer evaluates only that");
      continue;
    }
    const auto [x1, y1, x2, y2] = *p;
    QEasingCurve curve(QEasingCurve::BezierSpline);
    curve.addCubicBezierSegment(QPointF(x1, y1), QPointF(x2, y2), QPointF(1.0, 1.0));
    json run = {{"case", name}, {"peer", "peer_qt_easing_curve"}, {"easing", {x1, y1, x2, y2}}};
    add_progress_values(run, curve, times, quick);
    runs.push_back(run);
  }
  const json doc = {{"driver", "qt_easing"},     {"quick", quick}, {"versions", versions()},
                    {"cpu", peers::cpu_model()}, {"notes", notes}, {"runs", runs}};
  peers::write_json(out_path, doc);
  std::cout << "curvebench_peer_qt: " << runs.size() << " easing runs -> " << out_path << "\n";
  return 0;
}

// ---- mode 3: tcb ----------------------------------------------------------------------------------

// A spec's per-key tension, continuity or bias: a number for every key, one per key, or 0.
std::vector<double> per_key(const json &spec, const char *key, size_t n) {
  if (!spec.contains(key)) return std::vector<double>(n, 0.0);
  const json &v = spec.at(key);
  if (v.is_number()) return std::vector<double>(n, v.get<double>());
  if (!v.is_array() || v.size() != n)
    throw std::runtime_error(std::string("\"") + key + "\" is neither a number nor one number per key");
  std::vector<double> out;
  for (const auto &e : v) out.push_back(e.get<double>());
  return out;
}

// Why an easing curve cannot hold this kochanek_bartels spec, or "" when it can.
std::string tcb_refusal(const json &spec, const std::vector<QPointF> &keys) {
  if (spec.value("closed", false)) return "a closed loop (an easing curve is open)";
  if (keys.size() < 2) return "fewer than two keys";
  if (spec.contains("knots")) {
    const json &k = spec.at("knots");
    if (!k.is_array() || k.size() != keys.size()) return "knots not one per key";
    const double h = k.at(1).get<double>() - k.at(0).get<double>();
    for (size_t i = 1; i < k.size(); ++i)
      if (k.at(i).get<double>() - k.at(i - 1).get<double>() != h)
        return "non-uniform knots (Qt's TCB spline is uniform: one segment per key pair)";
  }
  for (size_t i = 1; i < keys.size(); ++i)
    if (!(keys[i].x() > keys[i - 1].x())) return "key x not strictly increasing (not an easing curve)";
  if (keys.back().y() == keys.front().y()) return "first and last key at the same y (no map onto (0, 0)-(1, 1))";
  return "";
}

int tcb_mode(const std::string &cases_dir, const std::vector<std::string> &spec_files, const std::string &out_path,
             bool quick) {
  const std::vector<double> times = sample_fractions(quick ? 65 : 257);
  std::vector<std::filesystem::path> files;
  if (!cases_dir.empty())
    for (const auto &e : std::filesystem::directory_iterator(cases_dir))
      if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  for (const auto &f : spec_files) files.emplace_back(f);
  json runs = json::array(), notes = json::array();
  for (const auto &file : files) {
    std::ifstream f(file);
    if (!f) throw std::runtime_error("cannot read " + file.string());
    const json spec = json::parse(f);
    if (spec.value("type", "") != "kochanek_bartels") continue;
    const std::string name = file.stem().string();
    std::vector<QPointF> keys;
    bool planar = true;
    for (const auto &p : spec.at("points")) {
      planar = planar && p.size() == 2;
      if (planar) keys.push_back(point_of(p));
    }
    const std::string refusal = planar ? tcb_refusal(spec, keys) : "not 2D (an easing curve is planar)";
    if (!refusal.empty()) {
      notes.push_back(name + ": " + refusal + "; QEasingCurve's TCB spline cannot hold it");
      continue;
    }
    const size_t n = keys.size();
    const std::vector<double> t = per_key(spec, "tension", n), c = per_key(spec, "continuity", n),
                              b = per_key(spec, "bias", n);
    const double x0 = keys.front().x(), y0 = keys.front().y();
    const double dx = keys.back().x() - x0, dy = keys.back().y() - y0;
    QEasingCurve curve(QEasingCurve::TCBSpline);
    json unit = json::array();
    for (size_t i = 0; i < n; ++i) {
      const QPointF q((keys[i].x() - x0) / dx, (keys[i].y() - y0) / dy);
      unit.push_back({q.x(), q.y()});
      curve.addTCBSegment(q, t[i], c[i], b[i]);
    }
    json bezier = json::array();
    for (const QPointF &q : curve.toCubicSpline()) bezier.push_back({q.x(), q.y()});
    if (bezier.size() != 3 * (n - 1)) {
      notes.push_back(name + ": toCubicSpline() gave " + std::to_string(bezier.size()) + " points for " +
                      std::to_string(n - 1) + " segments (3 each expected); not measured");
      continue;
    }
    json key_values = json::array();  // valueForProgress at the keys' own x (their y is Qt's segment ends)
    for (const auto &q : unit) {
      const double v = curve.valueForProgress(q.at(0).get<double>());
      key_values.push_back(std::isfinite(v) ? json(v) : json(nullptr));
    }
    json run = {{"case", name},
                {"peer", "peer_qt_easing_curve"},
                {"key_values", key_values},
                {"map", {{"x0", x0}, {"y0", y0}, {"dx", dx}, {"dy", dy}}},
                {"keys", unit},
                {"tcb", {{"tension", t}, {"continuity", c}, {"bias", b}}},
                {"bezier", bezier}};
    add_progress_values(run, curve, times, quick);
    runs.push_back(run);
  }
  const json doc = {{"driver", "qt_tcb"},        {"quick", quick}, {"versions", versions()},
                    {"cpu", peers::cpu_model()}, {"notes", notes}, {"runs", runs}};
  peers::write_json(out_path, doc);
  std::cout << "curvebench_peer_qt: " << runs.size() << " tcb runs, " << notes.size() << " notes -> " << out_path
            << "\n";
  return 0;
}

int usage() {
  std::cerr << "usage: curvebench_peer_qt paths --request REQ.json --out OUT.json [--quick]\n"
               "       curvebench_peer_qt easing --cases DIR --out OUT.json [--quick]\n"
               "       curvebench_peer_qt tcb [--cases DIR] [--spec FILE]... --out OUT.json [--quick]\n";
  return 2;
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 2) return usage();
  const std::string mode = argv[1];
  std::string request, cases, out;
  std::vector<std::string> specs;
  bool quick = false;
  for (int i = 2; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--quick") {
      quick = true;
    } else if ((a == "--request" || a == "--cases" || a == "--out") && i + 1 < argc) {
      (a == "--request" ? request : a == "--cases" ? cases : out) = argv[++i];
    } else if (a == "--spec" && i + 1 < argc) {
      specs.emplace_back(argv[++i]);
    } else {
      std::cerr << "curvebench_peer_qt: unknown argument " << a << "\n";
      return usage();
    }
  }
  try {
    if (mode == "paths" && !request.empty() && !out.empty()) return paths_mode(request, out, quick);
    if (mode == "easing" && !cases.empty() && !out.empty()) return easing_mode(cases, out, quick);
    if (mode == "tcb" && (!cases.empty() || !specs.empty()) && !out.empty()) return tcb_mode(cases, specs, out, quick);
  } catch (const std::exception &e) {
    std::cerr << "curvebench_peer_qt: " << e.what() << "\n";
    return 1;
  }
  return usage();
}
