// curvebench_peer_2geom: the native lib2geom peer (Inkscape's 2Geom: arc length and point at
// arc length as a vector editor computes them), answering a "curvebench-shipped-request-1" with a
// "curvebench-shipped-driver-1" document (format: scripts/peers/shipped_results.py).
//
//   curvebench_peer_2geom --request REQ.json --out OUT.json [--quick]
//
// --quick: one timing pass per quantity instead of five (for tests and smoke runs).
//
// Input: each case's SVG path data "d" parsed by lib2geom's own parser, Geom::parse_svg_path
// (svg-path-parser.h) into a PathVector: lines, quadratic and cubic Beziers (BezierCurveN<1..3>) and
// elliptical arcs (EllipticalArc); a closed subpath's closing segment is part of its Path.
//
// What lib2geom computes (installed 1.2.2 headers in /usr/include/2geom-1.2.2/2geom, and the
// library's sources of that generation, read for the facts):
//  - Curve::length(tolerance = 0.01) (curve.h: "tolerance: maximum allowed error"). A line segment:
//    the distance of its ends. QuadraticBezier/CubicBezier: Geom::bezier_length(points, tolerance)
//    (bezier-curve.h): the chord (a lower bound) and the control polygon (an upper bound); when they
//    differ by at most 2 x tolerance (absolute, in path units) the mean of the two is returned,
//    otherwise the curve is split in halves by de Casteljau and both halves measured, at most 8 levels
//    (256 pieces). Any other curve (EllipticalArc has no override): the base Curve::length, i.e.
//    Geom::length(toSBasis(), tolerance) below on the arc's S-basis approximation.
//  - Geom::length(Piecewise<D2<SBasis>>, tol = 0.01) (sbasis-geometric.h): per piece, GSL's adaptive
//    gsl_integration_qag with the 21-point Gauss-Kronrod rule on sqrt(x'(t)^2 + y'(t)^2) over [0, 1],
//    absolute tolerance 0, relative tolerance tol, a workspace of at most 20 subintervals; the
//    result is used whatever GSL's status (GSL errors are reported to its error handler, whose default
//    aborts the process: this driver installs a handler that records them; they appear in the note).
//  - arc_length_parametrization(Piecewise<D2<SBasis>>, order = 3, tol = 0.01) (sbasis-geometric.h):
//    the speed as a piecewise S-basis (sqrt of x'^2 + y'^2 to tol, degree 3), integrated to the arc
//    length s(t); per piece the inverse t(s) by compose_inverse (order 3, tol) and the path composed
//    with it: a Piecewise<D2<SBasis>> on [0, L_param] whose value at s is the point at arc length s.
//    All of it in double.
//
// Runs (peer ids and settings):
//  - peer_2geom, settings "" (tolerance 0.01, the default), "tolerance=1e-04", "tolerance=1e-08":
//    length = the sum of Curve::length(tolerance) over the PathVector's curves (with its documented
//    bound, n_curves x tolerance, as "documented_length_tolerance"); points and spaced =
//    arc_length_parametrization(path.toPwSb(), 3, tolerance) evaluated at s (an s beyond its own
//    domain end L_param asked at L_param) and at k L_param / (n - 1).
//  - peer_2geom, settings "sbasis" (tol 0.01) and "sbasis,tolerance=1e-08": length =
//    Geom::length(path.toPwSb(), tol); no points (lib2geom's point at length is the parametrization
//    above, reported under the same tolerance in the first group).
//
// Each case and setting is measured in a forked child (peers::run_isolated, bench/peers/common/
// peer_driver.hpp, with the lib2geom call in progress named as its stage): lib2geom crashed
// (arc_length_parametrization at tolerance 1e-8 on a cubic of extent 1e4: SIGSEGV) and threw
// ("Invariants violation" at exact cusps); a crash, a throw, a non-finite answer or a call over 60 s
// is a "skipped" entry naming the lib2geom call, never a garbage number or the end of the driver.
//
// Times (ns, best of five passes after a warm-up, each pass repeated until it lasts >= 20 us, per
// call; fewer passes for slow calls; one with --quick): ns_build = parse_svg_path (+ toPwSb for the
// sbasis settings; + toPwSb and arc_length_parametrization, the object the points are read from, for
// the others); ns_length = the length call(s) on the built object; ns_point = one evaluation of the
// parametrization at s, averaged over the request's s.
#include "common/peer_driver.hpp"

#include <nlohmann/json.hpp>

#include <2geom/bezier-curve.h>
#include <2geom/curve.h>
#include <2geom/path.h>
#include <2geom/pathvector.h>
#include <2geom/piecewise.h>
#include <2geom/sbasis-geometric.h>
#include <2geom/svg-path-parser.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_version.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using nlohmann::json;
namespace peers = curvebench::peers;

namespace {

std::set<std::string> g_gsl_errors;  // GSL errors since the last reset (the handler below)

std::string fmt(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string fmt_tol(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

void record_gsl_error(const char* reason, const char* /*file*/, int /*line*/, int gsl_errno) {
  g_gsl_errors.insert(std::string(reason ? reason : "?") + " (gsl_errno " + std::to_string(gsl_errno) + ")");
}

struct Setting {
  std::string name;
  double tol;
  bool sbasis;  // Geom::length of the S-basis form instead of Curve::length (+ the parametrization)
};

const std::vector<Setting> kSettings = {{"", 0.01, false},
                                        {"tolerance=1e-04", 1e-4, false},
                                        {"tolerance=1e-08", 1e-8, false},
                                        {"sbasis", 0.01, true},
                                        {"sbasis,tolerance=1e-08", 1e-8, true}};

const char* kPeer = "peer_2geom";

Geom::Piecewise<Geom::D2<Geom::SBasis>> to_pw(const Geom::PathVector& pv) {
  Geom::Piecewise<Geom::D2<Geom::SBasis>> pw;
  for (const Geom::Path& p : pv) {
    Geom::Piecewise<Geom::D2<Geom::SBasis>> one = p.toPwSb();
    if (one.empty()) continue;
    if (pw.empty())
      pw = one;
    else
      pw.concat(one);
  }
  return pw;
}

double curves_length(const Geom::PathVector& pv, double tol) {
  double total = 0;
  for (const Geom::Path& p : pv)
    for (const Geom::Curve& c : p) total += c.length(tol);
  return total;
}

json xy(const Geom::Point& p) {
  if (!std::isfinite(p[Geom::X]) || !std::isfinite(p[Geom::Y])) throw std::runtime_error("a non-finite point");
  return json::array({p[Geom::X], p[Geom::Y]});
}

std::string gsl_note() {
  if (g_gsl_errors.empty()) return "";
  std::string s = "; GSL reported (its default handler would abort): ";
  bool first = true;
  for (const std::string& e : g_gsl_errors) {
    s += (first ? "" : ", ") + e;
    first = false;
  }
  return s;
}

json run_case(const json& c, const Setting& st, const peers::Timing& timing) {
  // Each lib2geom call is named as the measuring child's stage, so that a crash or a throw names it.
  const std::string d = c.at("d").get<std::string>();
  g_gsl_errors.clear();
  peers::isolated_stage("parse_svg_path");
  const Geom::PathVector pv = Geom::parse_svg_path(d.c_str());
  size_t n_curves = 0;
  for (const Geom::Path& p : pv) n_curves += p.size();
  if (n_curves == 0) throw std::runtime_error("parse_svg_path gave no curve");
  peers::isolated_stage("Path::toPwSb");
  const auto pw = to_pw(pv);
  json run = {{"peer", kPeer}, {"case", c.at("case")}, {"setting", st.name}};

  if (st.sbasis) {
    peers::isolated_stage("Geom::length(Piecewise<D2<SBasis>>)");
    const double length = Geom::length(pw, st.tol);
    if (!std::isfinite(length)) throw std::runtime_error("Geom::length is not finite" + gsl_note());
    const std::string note_gsl = gsl_note();
    peers::isolated_stage("timing");
    run["length"] = length;
    run["points"] = nullptr;
    run["spaced"] = nullptr;
    run["ns_build"] =
        peers::best_ns([&] { return static_cast<double>(to_pw(Geom::parse_svg_path(d.c_str())).size()); }, 1, timing);
    run["ns_length"] = peers::best_ns([&] { return Geom::length(pw, st.tol); }, 1, timing);
    run["ns_point"] = nullptr;
    run["note"] = "Geom::length(Piecewise<D2<SBasis>>, " + fmt_tol(st.tol) +
                  ") (GSL qag GK21 per piece) on the parsed path's toPwSb(); no points (lib2geom's point at length is "
                  "arc_length_parametrization, reported under peer_2geom at the same tolerance)" +
                  note_gsl;
    return run;
  }

  peers::isolated_stage("Curve::length");
  const double length = curves_length(pv, st.tol);
  if (!std::isfinite(length)) throw std::runtime_error("Curve::length is not finite" + gsl_note());
  peers::isolated_stage("arc_length_parametrization");
  const auto param = Geom::arc_length_parametrization(pw, 3, st.tol);
  if (param.empty()) throw std::runtime_error("arc_length_parametrization gave an empty function");
  const double l_param = param.cuts.back();
  if (!std::isfinite(l_param)) throw std::runtime_error("arc_length_parametrization: non-finite domain");
  const std::vector<double> s_list = c.at("s").get<std::vector<double>>();
  const int n_spaced = c.at("spaced").get<int>();
  json points = json::array(), spaced = json::array();
  bool clamped = false;
  for (double s : s_list) {
    clamped = clamped || s > l_param;
    points.push_back(xy(param.valueAt(std::clamp(s, 0.0, l_param))));
  }
  for (int k = 0; k < n_spaced; ++k)
    spaced.push_back(xy(param.valueAt(k == n_spaced - 1 ? l_param : l_param * k / (n_spaced - 1))));
  const std::string note_gsl = gsl_note();
  peers::isolated_stage("timing");

  run["length"] = length;
  // curve.h documents Curve::length's tolerance as the maximum allowed error, per curve: the path's
  // length (their sum) is then within n_curves x tolerance, absolute. shipped_results.py reports a
  // length outside that bound as a finding.
  run["documented_length_tolerance"] = static_cast<double>(n_curves) * st.tol;
  run["points"] = points;
  run["spaced"] = spaced;
  run["ns_build"] = peers::best_ns(
      [&] { return Geom::arc_length_parametrization(to_pw(Geom::parse_svg_path(d.c_str())), 3, st.tol).cuts.back(); },
      1, timing);
  run["ns_length"] = peers::best_ns([&] { return curves_length(pv, st.tol); }, 1, timing);
  run["ns_point"] = peers::best_ns(
      [&] {
        double sum = 0;
        for (double s : s_list) sum += param.valueAt(std::clamp(s, 0.0, l_param))[Geom::X];
        return sum;
      },
      static_cast<double>(s_list.size()), timing);
  std::string note = "sum of Curve::length(" + fmt_tol(st.tol) + ") over " + std::to_string(n_curves) +
                     " parsed curve(s) (Beziers: bezier_length); points: arc_length_parametrization(toPwSb, 3, tol) "
                     "at s, its own length " +
                     fmt(l_param) +
                     "; spaced at k L_param/(n-1); ns_build includes the "
                     "parametrization";
  if (clamped) note += "; s beyond the parametrization's own length asked at its length";
  run["note"] = note + note_gsl;
  return run;
}

// run_case in a child process: a crash (lib2geom's recursion overflowing the stack was seen) or a call
// running past kTimeLimitS is the reason of a skip instead of the end of the driver; a throw's reason
// names the lib2geom call it came from.
constexpr unsigned kTimeLimitS = 60;

peers::Isolated run_isolated(const json& c, const Setting& st, const peers::Timing& timing) {
  return peers::run_isolated(
      [&] {
        try {
          return run_case(c, st, timing);
        } catch (const std::exception& e) {
          const std::string& where = peers::isolated_stage_name();
          throw std::runtime_error((where.empty() ? "?" : where) + ": " + e.what());
        }
      },
      kTimeLimitS);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string program = "curvebench_peer_2geom";
  peers::ShippedArgs args;
  json req;
  if (const int status = peers::start_shipped_driver(argc, argv, program, args, req)) return status;
  gsl_set_error_handler(&record_gsl_error);
  const bool verbose = std::getenv("CURVEBENCH_PEER_VERBOSE") != nullptr;
  const peers::Timing timing = peers::Timing::fixed(args.quick);
  json runs = json::array(), skipped = json::array();
  for (const json& c : req.at("cases")) {
    for (const Setting& st : kSettings) {
      std::string why;
      if (verbose) std::cerr << c.at("case").get<std::string>() << " [" << st.name << "]\n";
      try {
        peers::Isolated run = run_isolated(c, st, timing);
        if (run.ok)
          runs.push_back(std::move(run.value));
        else
          why = run.reason;
      } catch (const std::exception& e) {
        why = e.what();
      }
      if (!why.empty()) skipped.push_back(peers::skipped_entry(kPeer, c, st.name, why));
    }
  }
  return peers::write_shipped_output(args.out, "lib2geom",
                                     {{"lib2geom", peers::debian_version("lib2geom-dev")},
                                      {"2geom.pc", CURVEBENCH_2GEOM_PKG_VERSION},
                                      {"gsl", GSL_VERSION}},
                                     runs, skipped, program);
}
