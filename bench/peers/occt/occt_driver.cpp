// curvebench_peer_occt: the native OpenCASCADE peer (arc length and point at arc length as a CAD
// kernel computes them), answering a "curvebench-shipped-request-1" with a
// "curvebench-shipped-driver-1" document (format: scripts/peers/shipped_results.py): its "cases"
// (SVG path segments as 2D Geom curves) and its "splines" (B-spline and NURBS curves, below).
//
//   curvebench_peer_occt --request REQ.json --out OUT.json [--quick]
//
// --quick: one timing pass per quantity instead of five (for tests and smoke runs).
//
// What is built. Each subpath segment of a request case becomes one 2D Geom curve and one
// Geom2dAdaptor_Curve over it: a line, quadratic or cubic as a Geom2d_BezierCurve on its 2, 3 or 4
// control points (degree 1, 2, 3); an arc, from the request's centre form
// c + R(phi) (rx cos th, ry sin th), th from theta1 to theta1 + dtheta, as a Geom2d_Circle (rx == ry)
// or Geom2d_Ellipse (major radius on the local X direction, so for rx < ry the axes are swapped and
// the parameter shifted by pi/2) trimmed by a Geom2d_TrimmedCurve to that range; a negative dtheta is
// taken by an indirect axis placement (gp_Ax22d with Y = -R(phi) e_y), so the trimmed curve runs
// from the arc's first to its last point with increasing parameter. Coordinates are the SVG numbers
// as they stand (y down is only a coordinate convention). A segment whose control points all
// coincide (a zero-length closing line) is not built: OCCT refuses a curve of zero length.
//
// What OCCT computes (read from the installed 7.6 headers, /usr/include/opencascade):
//  - GCPnts_AbscissaPoint::Length(adaptor) and Length(adaptor, tol): the integral of |C'(u)| over the
//    adaptor's range, in double. CPnts_AbscissaPoint/CPnts_MyGaussFunction and
//    math_GaussSingleIntegration: Gauss-Legendre with a fixed number of points ("Order") on the
//    function |C'|; without a tolerance one fixed-order rule per continuity interval of the curve
//    (Bezier: the whole curve; the order follows the curve's degree, a cubic Bezier gets 6 points —
//    the reading of the sources); with a tolerance the integration is repeated with more
//    points/subintervals until successive results agree to that tolerance.
//  - GCPnts_AbscissaPoint(adaptor, abscissa, U0) and (tol, adaptor, abscissa, U0): the parameter u
//    with Integral(U0, u) |C'| = abscissa, found by a Newton-type iteration (CPnts_MyRootFunction:
//    "a function for the Newton algorithm to find the solution of Integral(F) = L", its derivative
//    |C'|); IsDone() false when it does not converge. The point is adaptor.Value(u).
//  - GCPnts_UniformAbscissa(adaptor, n[, tol]): n parameters equally spaced by arc length from the
//    first to the last point (its tolerance "used for more precise calculation of curve length",
//    Precision::Confusion() = 1e-7 by default).
//
// Settings measured (the run's "setting"): "" = the user's default calls (Length without a
// tolerance, AbscissaPoint without a tolerance, UniformAbscissa with its default tolerance);
// "tolerance=1e-06" and "tolerance=1e-10" = the same calls with that tolerance; on paths with a
// quadratic segment, "parabola" and "parabola, tolerance=..." = the same with each quadratic as the
// arc of a Geom2d_Parabola (parabola_of: the same curve, OCCT's analytic conic and its own length
// code; the issue cites OCCT's own -3.1 % on a wide parabola). Per peer id
// peer_occt_gcpnts. A path of several segments: its length is the sum of the segments' lengths; the
// point at s is AbscissaPoint on the segment holding s (by the segments' lengths of the same
// setting, computed once) from its first parameter; spaced points of a multi-segment path are those
// points at k L_occt / (n - 1) (UniformAbscissa takes one curve), of a single segment
// UniformAbscissa's. An s beyond OCCT's own length is asked at its length.
//
// Splines (request["splines"], when present: curvebench's bspline and nurbs cases, same peer id and
// settings). Each is one 3D Geom_BSplineCurve on the request's points (gp_Pnt, z = 0 for a 2D case;
// rational with the request's weights when it has them) and OCCT's distinct knots + multiplicities:
// clamped: 0 .. n - degree, the end knots of multiplicity degree + 1; uniform: 0 .. n + degree, all
// simple, non-periodic (OCCT's curve then lies on [FlatKnots(degree + 1), FlatKnots(n + 1)], its
// First/LastParameter); periodic: Periodic = true on the n + 1 knots 0 .. n, all simple, measured on a
// GeomAdaptor_Curve over [u0, u0 + Period()] with u0 the knot whose point is the request's "start"
// (so s = 0 is there); given: the full vector folded into distinct knots + multiplicities. The
// curve's point at the adaptor's first and last parameter must be the request's "start" and "end"
// within 1e-12 x the diagonal of the points' bounding box, else the case is skipped (OCCT's knot vector
// would not be curvebench's). Length: GCPnts_AbscissaPoint::Length on the 3D adaptor; points:
// GCPnts_AbscissaPoint from the first parameter, then Value; spaced: GCPnts_UniformAbscissa on the
// adaptor; points written with 2 or 3 coordinates as the request's "dim". ns_build there = building
// the curve and adaptor, including the start check (and the periodic start search).
//
// Times (ns, best of five passes after a warm-up, each pass repeated until it lasts >= 20 us, per
// call; one pass with --quick): ns_build = building all the case's Geom curves and adaptors;
// ns_length = the path's length (all its segments' Length calls); ns_point = one point at length
// (segment lookup, AbscissaPoint, Value), averaged over the request's s.
#include "common/peer_driver.hpp"

#include <nlohmann/json.hpp>

#include <GCPnts_AbscissaPoint.hxx>
#include <GCPnts_UniformAbscissa.hxx>
#include <Geom2dAdaptor_Curve.hxx>
#include <Geom2d_BezierCurve.hxx>
#include <Geom2d_Circle.hxx>
#include <Geom2d_Ellipse.hxx>
#include <Geom2d_Parabola.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <Standard_Version.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <gp_Ax22d.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

using nlohmann::json;
namespace peers = curvebench::peers;

namespace {

struct Setting {
  std::string name;
  bool has_tol;
  double tol;
  bool parabola = false;  // quadratic segments as Geom2d_Parabola (on paths that have one)
};

const std::vector<Setting> kSettings = {{"", false, 0.0},
                                        {"tolerance=1e-06", true, 1e-6},
                                        {"tolerance=1e-10", true, 1e-10},
                                        {"parabola", false, 0.0, true},
                                        {"parabola, tolerance=1e-06", true, 1e-6, true},
                                        {"parabola, tolerance=1e-10", true, 1e-10, true}};

// A quadratic Bezier A, B, C as the arc of a Geom2d_Parabola (OCCT's analytic conic, whose length
// has its own code path): P(t) = V + w tau + D tau^2 with D = A - 2B + C, tau = t - t_v, t_v the
// vertex's parameter (P'(t_v) . D = 0), V = P(t_v), w = P'(t_v) / 2... so with OCCT's parabola
// V + u^2 / (4F) X + u Y (X = D / |D|, Y = w / |w|): u = |w| tau and F = |w|^2 / (4 |D|); the arc is
// u from -|w| t_v to |w| (1 - t_v). A quadratic whose points are collinear is no parabola (refused).
Handle(Geom2d_Curve) parabola_of(const gp_Pnt2d& a, const gp_Pnt2d& b, const gp_Pnt2d& c) {
  const gp_Vec2d d(a.X() - 2 * b.X() + c.X(), a.Y() - 2 * b.Y() + c.Y()), ab(a, b);
  const double dd = d.SquareMagnitude();
  if (!(dd > 0)) throw std::runtime_error("a quadratic with A - 2B + C = 0 is a line, not a parabola");
  const double tv = -ab.Dot(d) / dd;
  // P(t) = A + 2 (B - A) t + D t^2; P'(t) / 2 = (B - A) + D t, so w = 2 ((B - A) + D t_v).
  const gp_Vec2d w = 2.0 * (ab + tv * d);
  const double wm = w.Magnitude();
  if (!(wm > 1e-12 * std::sqrt(dd))) throw std::runtime_error("collinear control points: not a parabola's arc");
  const gp_Pnt2d v(a.X() + 2 * ab.X() * tv + d.X() * tv * tv, a.Y() + 2 * ab.Y() * tv + d.Y() * tv * tv);
  const double focal = wm * wm / (4 * std::sqrt(dd));
  Handle(Geom2d_Parabola) parabola = new Geom2d_Parabola(gp_Ax22d(v, gp_Dir2d(d), gp_Dir2d(w)), focal);
  return new Geom2d_TrimmedCurve(parabola, -wm * tv, wm * (1 - tv), Standard_True, Standard_True);
}

struct Segment {
  Handle(Geom2d_Curve) curve;
  Handle(Geom2dAdaptor_Curve) adaptor;
};

gp_Pnt2d pnt(const json& p) { return gp_Pnt2d(p.at(0).get<double>(), p.at(1).get<double>()); }

// One request segment as a Geom curve; a null handle for a zero-length one. With parabola, a
// quadratic is a Geom2d_Parabola's arc instead of a Geom2d_BezierCurve.
Handle(Geom2d_Curve) build_segment(const json& seg, bool parabola = false) {
  const std::string kind = seg.at("kind").get<std::string>();
  const json& pts = seg.at("points");
  if (kind == "arc") {
    const json& c = seg.at("center");
    const double cx = c.at("cx").get<double>(), cy = c.at("cy").get<double>();
    const double rx = c.at("rx").get<double>(), ry = c.at("ry").get<double>(), phi = c.at("phi").get<double>();
    const double th1 = c.at("theta1").get<double>(), dth = c.at("dtheta").get<double>();
    if (rx == 0.0 || ry == 0.0 || dth == 0.0) throw std::runtime_error("degenerate arc (zero radius or sweep)");
    const gp_Dir2d ex(std::cos(phi), std::sin(phi)), ey(-std::sin(phi), std::cos(phi));
    const double sgn = dth < 0 ? -1.0 : 1.0;
    Handle(Geom2d_Conic) conic;
    double u1 = 0, u2 = 0;
    const gp_Pnt2d centre(cx, cy);
    if (rx >= ry) {
      // P(u) = c + rx cos u ex + ry sin u (sgn ey), u = sgn th.
      gp_Ax22d ax(centre, ex, gp_Dir2d(sgn * ey.X(), sgn * ey.Y()));
      if (rx == ry)
        conic = new Geom2d_Circle(ax, rx);
      else
        conic = new Geom2d_Ellipse(ax, rx, ry);
      u1 = sgn * th1;
      u2 = sgn * (th1 + dth);
    } else {
      // Major axis along ey: P(u) = c + ry cos u ey + rx sin u (-sgn ex), u = sgn (th - pi/2).
      gp_Ax22d ax(centre, ey, gp_Dir2d(-sgn * ex.X(), -sgn * ex.Y()));
      conic = new Geom2d_Ellipse(ax, ry, rx);
      u1 = sgn * (th1 - std::numbers::pi / 2);
      u2 = sgn * (th1 + dth - std::numbers::pi / 2);
    }
    return new Geom2d_TrimmedCurve(conic, u1, u2, Standard_True, Standard_True);
  }
  const int n = static_cast<int>(pts.size());
  bool all_same = true;
  for (int i = 1; i < n; ++i) all_same = all_same && pts.at(static_cast<size_t>(i)) == pts.at(0);
  if (all_same) return Handle(Geom2d_Curve)();
  if (parabola && kind == "quadratic") return parabola_of(pnt(pts.at(0)), pnt(pts.at(1)), pnt(pts.at(2)));
  TColgp_Array1OfPnt2d poles(1, n);
  for (int i = 0; i < n; ++i) poles.SetValue(i + 1, pnt(pts.at(static_cast<size_t>(i))));
  return new Geom2d_BezierCurve(poles);
}

std::vector<Segment> build_path(const json& c, bool parabola = false) {
  std::vector<Segment> out;
  for (const json& sub : c.at("segments"))
    for (const json& seg : sub.at("segments")) {
      Handle(Geom2d_Curve) curve = build_segment(seg, parabola);
      if (curve.IsNull()) continue;
      out.push_back({curve, new Geom2dAdaptor_Curve(curve)});
    }
  return out;
}

// GCPnts_AbscissaPoint::Length over the adaptor's range (a 2D or a 3D adaptor), with the setting's
// tolerance if it has one.
template <class Adaptor>
double adaptor_length(const Adaptor& a, const Setting& st) {
  return st.has_tol ? GCPnts_AbscissaPoint::Length(a, st.tol) : GCPnts_AbscissaPoint::Length(a);
}

// The parameter at arc length `abscissa` from the adaptor's first parameter (GCPnts_AbscissaPoint).
template <class Adaptor>
double adaptor_param(const Adaptor& a, double abscissa, const Setting& st) {
  const double u0 = a.FirstParameter();
  if (st.has_tol) {
    GCPnts_AbscissaPoint ap(st.tol, a, abscissa, u0);
    if (!ap.IsDone()) throw std::runtime_error("GCPnts_AbscissaPoint: IsDone() false");
    return ap.Parameter();
  }
  GCPnts_AbscissaPoint ap(a, abscissa, u0);
  if (!ap.IsDone()) throw std::runtime_error("GCPnts_AbscissaPoint: IsDone() false");
  return ap.Parameter();
}

double seg_length(const Segment& s, const Setting& st) { return adaptor_length(*s.adaptor, st); }

gp_Pnt2d seg_point(const Segment& s, double abscissa, const Setting& st) {
  return s.adaptor->Value(adaptor_param(*s.adaptor, abscissa, st));
}

// The point at path arc length s (clamped to [0, total]) from the segments' lengths of this setting.
gp_Pnt2d path_point(const std::vector<Segment>& segs, const std::vector<double>& lens, double total, double s,
                    const Setting& st) {
  s = std::clamp(s, 0.0, total);
  double before = 0;
  size_t k = 0;
  for (; k + 1 < segs.size(); ++k) {
    if (s <= before + lens[k]) break;
    before += lens[k];
  }
  return seg_point(segs[k], std::min(s - before, lens[k]), st);
}

json xy(const gp_Pnt2d& p) {
  if (!std::isfinite(p.X()) || !std::isfinite(p.Y())) throw std::runtime_error("a non-finite point");
  return json::array({p.X(), p.Y()});
}

const char* kPeer = "peer_occt_gcpnts";

bool has_quadratic(const json& c) {
  for (const json& sub : c.at("segments"))
    for (const json& seg : sub.at("segments"))
      if (seg.at("kind") == "quadratic") return true;
  return false;
}

// One run of a case and setting; throws (the caller records a skip) on a failure of OCCT.
json run_case(const json& c, const Setting& st, const peers::Timing& timing) {
  std::vector<Segment> segs = build_path(c, st.parabola);
  if (segs.empty()) throw std::runtime_error("no segment of non-zero length");
  std::vector<double> lens;
  double total = 0;
  for (const Segment& s : segs) {
    lens.push_back(seg_length(s, st));
    if (!std::isfinite(lens.back())) throw std::runtime_error("Length is not finite");
    total += lens.back();
  }
  const std::vector<double> s_list = c.at("s").get<std::vector<double>>();
  const int n_spaced = c.at("spaced").get<int>();
  json points = json::array(), spaced = json::array();
  bool clamped = false;
  for (double s : s_list) {
    clamped = clamped || s > total;
    points.push_back(xy(path_point(segs, lens, total, s, st)));
  }
  const bool single = segs.size() == 1;
  if (single) {
    GCPnts_UniformAbscissa ua(*segs[0].adaptor, n_spaced, st.has_tol ? st.tol : -1.0);
    if (!ua.IsDone() || ua.NbPoints() != n_spaced)
      throw std::runtime_error("GCPnts_UniformAbscissa: not done or " + std::to_string(ua.NbPoints()) + " points");
    for (int i = 1; i <= n_spaced; ++i) spaced.push_back(xy(segs[0].adaptor->Value(ua.Parameter(i))));
  } else {
    for (int k = 0; k < n_spaced; ++k)
      spaced.push_back(xy(path_point(segs, lens, total, total * k / (n_spaced - 1), st)));
  }

  const double ns_build =
      peers::best_ns([&] { return static_cast<double>(build_path(c, st.parabola).size()); }, 1, timing);
  const double ns_length = peers::best_ns(
      [&] {
        double t = 0;
        for (const Segment& s : segs) t += seg_length(s, st);
        return t;
      },
      1, timing);
  const double ns_point = peers::best_ns(
      [&] {
        double sum = 0;
        for (double s : s_list) sum += path_point(segs, lens, total, s, st).X();
        return sum;
      },
      static_cast<double>(s_list.size()), timing);

  std::string note = std::string("GCPnts_AbscissaPoint::Length") + (st.has_tol ? "(adaptor, tol)" : "(adaptor)") +
                     " summed over " + std::to_string(segs.size()) + " Geom2d segment(s)" +
                     (st.parabola ? " (quadratics as Geom2d_Parabola arcs)" : "") + "; point: AbscissaPoint" +
                     (st.has_tol ? " with tol" : "") + " on the segment holding s";
  note += single ? "; spaced: GCPnts_UniformAbscissa(adaptor, n)"
                 : "; spaced: point at k L/(n-1) (UniformAbscissa takes one curve)";
  if (clamped) note += "; s beyond OCCT's own length asked at its length";
  return {{"peer", kPeer},        {"case", c.at("case")}, {"setting", st.name},     {"length", total},
          {"points", points},     {"spaced", spaced},     {"ns_length", ns_length}, {"ns_point", ns_point},
          {"ns_build", ns_build}, {"note", note}};
}

// ---- the request's "splines": curvebench's bspline and nurbs cases as Geom_BSplineCurve ----------

struct Spline {
  Handle(Geom_BSplineCurve) curve;
  Handle(GeomAdaptor_Curve) adaptor;  // on [u0, u1]: s = 0 at the request's "start"
  int dim = 2;
};

gp_Pnt pnt3(const json& p) {
  return gp_Pnt(p.at(0).get<double>(), p.at(1).get<double>(), p.size() > 2 ? p.at(2).get<double>() : 0.0);
}

// A full non-decreasing knot vector as OCCT's distinct knots and multiplicities.
void distinct_knots(const std::vector<double>& flat, std::vector<double>& knots, std::vector<int>& mults) {
  for (size_t i = 0; i < flat.size(); ++i) {
    if (i > 0 && flat[i] < flat[i - 1]) throw std::runtime_error("the given knot vector decreases");
    if (!knots.empty() && flat[i] == knots.back())
      ++mults.back();
    else {
      knots.push_back(flat[i]);
      mults.push_back(1);
    }
  }
}

// The request's spline as a Geom_BSplineCurve and an adaptor on the range from its "start" to its
// "end"; std::runtime_error (a skip) when OCCT's curve does not start and end there.
Spline build_spline(const json& c) {
  const json& pts = c.at("points");
  const int n = static_cast<int>(pts.size());
  const int degree = c.at("degree").get<int>();
  const std::string kind = c.at("knot_vector").get<std::string>();
  std::vector<double> knots;
  std::vector<int> mults;
  bool periodic = false;
  if (kind == "clamped") {
    if (n < degree + 1) throw std::runtime_error("fewer points than degree + 1");
    for (int i = 0; i <= n - degree; ++i) {
      knots.push_back(i);
      mults.push_back(i == 0 || i == n - degree ? degree + 1 : 1);
    }
  } else if (kind == "uniform") {
    for (int i = 0; i <= n + degree; ++i) {
      knots.push_back(i);
      mults.push_back(1);
    }
  } else if (kind == "periodic") {
    periodic = true;
    for (int i = 0; i <= n; ++i) {
      knots.push_back(i);
      mults.push_back(1);
    }
  } else if (kind == "given") {
    distinct_knots(c.at("knots").get<std::vector<double>>(), knots, mults);
  } else {
    throw std::runtime_error("knot_vector " + kind + " unknown to this driver");
  }
  TColgp_Array1OfPnt poles(1, n);
  double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
  for (int i = 0; i < n; ++i) {
    const gp_Pnt p = pnt3(pts.at(static_cast<size_t>(i)));
    poles.SetValue(i + 1, p);
    for (int d = 0; d < 3; ++d) {
      lo[d] = i == 0 ? p.Coord(d + 1) : std::min(lo[d], p.Coord(d + 1));
      hi[d] = i == 0 ? p.Coord(d + 1) : std::max(hi[d], p.Coord(d + 1));
    }
  }
  const double size = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  const int nk = static_cast<int>(knots.size());
  TColStd_Array1OfReal k(1, nk);
  TColStd_Array1OfInteger m(1, nk);
  for (int i = 0; i < nk; ++i) {
    k.SetValue(i + 1, knots[static_cast<size_t>(i)]);
    m.SetValue(i + 1, mults[static_cast<size_t>(i)]);
  }
  Spline out;
  out.dim = c.at("dim").get<int>();
  const json& w = c.at("weights");
  if (w.is_null()) {
    out.curve = new Geom_BSplineCurve(poles, k, m, degree, periodic);
  } else {
    if (static_cast<int>(w.size()) != n) throw std::runtime_error("not one weight per point");
    TColStd_Array1OfReal weights(1, n);
    for (int i = 0; i < n; ++i) weights.SetValue(i + 1, w.at(static_cast<size_t>(i)).get<double>());
    out.curve = new Geom_BSplineCurve(poles, weights, k, m, degree, periodic);
  }
  const gp_Pnt start = pnt3(c.at("start")), end = pnt3(c.at("end"));
  const double eps = 1e-12 * size;
  double u0 = out.curve->FirstParameter(), u1 = out.curve->LastParameter();
  if (periodic) {
    // s = 0 at the request's start: the knot of OCCT's periodic curve whose point it is.
    bool found = false;
    for (int i = 1; i < nk && !found; ++i)
      if (out.curve->Value(k.Value(i)).Distance(start) <= eps) {
        u0 = k.Value(i);
        found = true;
      }
    if (!found) throw std::runtime_error("no knot of OCCT's periodic curve is at the request's start");
    u1 = u0 + out.curve->Period();
  }
  const double d0 = out.curve->Value(u0).Distance(start), d1 = out.curve->Value(u1).Distance(end);
  if (d0 > eps || d1 > eps) {
    char msg[200];
    std::snprintf(msg, sizeof msg, "OCCT's curve starts %.3g and ends %.3g from curvebench's start and end", d0, d1);
    throw std::runtime_error(std::string(msg) + " (not curvebench's knot vector)");
  }
  out.adaptor = new GeomAdaptor_Curve(out.curve, u0, u1);
  return out;
}

json coords(const gp_Pnt& p, int dim) {
  if (!std::isfinite(p.X()) || !std::isfinite(p.Y()) || !std::isfinite(p.Z()))
    throw std::runtime_error("a non-finite point");
  return dim == 3 ? json::array({p.X(), p.Y(), p.Z()}) : json::array({p.X(), p.Y()});
}

json run_spline(const json& c, const Setting& st, const peers::Timing& timing) {
  const Spline sp = build_spline(c);
  const GeomAdaptor_Curve& a = *sp.adaptor;
  const double total = adaptor_length(a, st);
  if (!std::isfinite(total)) throw std::runtime_error("Length is not finite");
  const std::vector<double> s_list = c.at("s").get<std::vector<double>>();
  const int n_spaced = c.at("spaced").get<int>();
  json points = json::array(), spaced = json::array();
  bool clamped = false;
  const auto point_at = [&](double s) { return a.Value(adaptor_param(a, std::clamp(s, 0.0, total), st)); };
  for (double s : s_list) {
    clamped = clamped || s > total;
    points.push_back(coords(point_at(s), sp.dim));
  }
  GCPnts_UniformAbscissa ua(a, n_spaced, st.has_tol ? st.tol : -1.0);
  if (!ua.IsDone() || ua.NbPoints() != n_spaced)
    throw std::runtime_error("GCPnts_UniformAbscissa: not done or " + std::to_string(ua.NbPoints()) + " points");
  for (int i = 1; i <= n_spaced; ++i) spaced.push_back(coords(a.Value(ua.Parameter(i)), sp.dim));

  const double ns_build = peers::best_ns([&] { return build_spline(c).adaptor->FirstParameter(); }, 1, timing);
  const double ns_length = peers::best_ns([&] { return adaptor_length(a, st); }, 1, timing);
  const double ns_point = peers::best_ns(
      [&] {
        double sum = 0;
        for (double s : s_list) sum += point_at(s).X();
        return sum;
      },
      static_cast<double>(s_list.size()), timing);
  std::string note = "Geom_BSplineCurve (degree " + std::to_string(c.at("degree").get<int>()) + ", " +
                     c.at("knot_vector").get<std::string>() + " knots" +
                     (c.at("weights").is_null() ? "" : ", rational") + ") on a GeomAdaptor_Curve over [" +
                     std::to_string(a.FirstParameter()) + ", " + std::to_string(a.LastParameter()) +
                     "]; GCPnts_AbscissaPoint::Length" + (st.has_tol ? "(adaptor, tol)" : "(adaptor)") +
                     "; point: AbscissaPoint" + (st.has_tol ? " with tol" : "") +
                     "; spaced: GCPnts_UniformAbscissa(adaptor, n)";
  if (clamped) note += "; s beyond OCCT's own length asked at its length";
  return {{"peer", kPeer},        {"case", c.at("case")}, {"setting", st.name},     {"length", total},
          {"points", points},     {"spaced", spaced},     {"ns_length", ns_length}, {"ns_point", ns_point},
          {"ns_build", ns_build}, {"note", note}};
}

}  // namespace

int main(int argc, char** argv) {
  const std::string program = "curvebench_peer_occt";
  peers::ShippedArgs args;
  json req;
  if (const int status = peers::start_shipped_driver(argc, argv, program, args, req)) return status;
  const peers::Timing timing = peers::Timing::fixed(args.quick);
  json runs = json::array(), skipped = json::array();
  std::vector<std::pair<const json*, bool>> all;  // (case, is a spline)
  for (const json& c : req.at("cases")) all.emplace_back(&c, false);
  if (req.contains("splines"))
    for (const json& c : req.at("splines")) all.emplace_back(&c, true);
  for (const auto& [cp, is_spline] : all) {
    const json& c = *cp;
    for (const Setting& st : kSettings) {
      if (st.parabola && (is_spline || !has_quadratic(c))) continue;  // only paths with a quadratic
      std::string why;
      try {
        runs.push_back(is_spline ? run_spline(c, st, timing) : run_case(c, st, timing));
      } catch (const Standard_Failure& e) {
        why = std::string("OCCT raised ") + e.DynamicType()->Name() + ": " +
              (e.GetMessageString() ? e.GetMessageString() : "");
      } catch (const std::exception& e) {
        why = e.what();
      }
      if (!why.empty()) skipped.push_back(peers::skipped_entry(kPeer, c, st.name, why));
    }
  }
  return peers::write_shipped_output(args.out, "occt",
                                     {{"opencascade", OCC_VERSION_COMPLETE},
                                      {"libocct-foundation-dev", peers::debian_version("libocct-foundation-dev")}},
                                     runs, skipped, program);
}
