// SVG path data (the "d" attribute of <path>): the whole grammar of SVG 1.1 (section 8.3.9) and
// SVG 2 (section 9.3.9) to a list of subpaths of line, quadratic, cubic and elliptical-arc segments
// in absolute coordinates.
//
// Grammar: moveto (M/m) first; lineto L/l, H/h, V/v; cubic C/c, S/s; quadratic Q/q, T/t; arc A/a;
// closepath Z/z. A command's argument group may repeat without repeating its letter (after M/m the
// repeats are implicit L/l). Arguments are separated by white space (space, tab, LF, FF, CR) and at
// most one comma, or by nothing where the grammar allows it: "M0.5.5" is two numbers (a second '.'
// ends the first), "M1-2" too (a sign ends a number), and an arc's flags are single characters
// ("a1 1 0 00.5.5" is rx 1, ry 1, rotation 0, flags 0 and 0, then .5 .5). Numbers: sign, digits with
// an optional fraction, or a fraction alone, and an optional exponent (e or E, sign, digits).
// Relative commands are relative to the current point; S and T reflect the previous segment's last
// control point about the current point when the previous command was C/c/S/s (resp. Q/q/T/t), and
// use the current point otherwise. After Z the current point is the subpath's start, where a next
// subpath starts when no moveto follows.
//
// Arcs: SVG's endpoint form (rx, ry, x-axis rotation in degrees, large-arc and sweep flags, the
// end point) is kept as written; center_form<Real> converts it to the centre form in Real by SVG's
// implementation notes (SVG 1.1 appendix F.6.5 and F.6.6, SVG 2 section 9.5), so that a 50-digit
// twin of the path converts its own: negative radii count by their absolute value, the rotation is
// taken modulo 360 degrees, and radii too small to reach the end point are scaled up by
// sqrt(Lambda) (Lambda = x1'^2 / rx^2 + y1'^2 / ry^2 > 1), which makes the arc half the ellipse
// with its centre exactly at the chord's midpoint.
// The parser decides the two degenerate cases on the data as given: an arc whose endpoints
// coincide is omitted, one with rx = 0 or ry = 0 is a straight line. The centre form is
// c + R(phi) (rx cos theta, ry sin theta) for theta from theta1 to theta1 + dtheta (arc_point).
//
// Errors: SVG renders a path up to its first error; curvebench refuses it instead, never measuring
// a silently shortened path. parse_path throws invalid_input naming the character offset (from 0),
// the character found there (or the end of the data) and what the grammar expected; a number past
// double's range is refused the same way (one below it is 0, as it rounds).
// A relative point past double's range and more than max_segments segments are refused the same way.
// The centre form is computed without squaring a radius (see center_form), so no radius from the
// smallest to the largest double overflows it where the arc itself is representable.
// Cost: O(length of d). No allocation beyond the segments.
#pragma once

#include "curvebench/core/error.hpp"
#include "curvebench/core/point.hpp"
#include "curvebench/core/real.hpp"

#include <boost/math/constants/constants.hpp>

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace curvebench::io::svg {

/// A point of path data, absolute.
struct xy {
  double x = 0, y = 0;
  friend bool operator==(const xy&, const xy&) = default;
};

enum class segment_kind { line, quadratic, cubic, arc };

/// An elliptical arc's arguments as written (SVG's endpoint form, without its end point).
struct arc_arguments {
  double rx = 0, ry = 0;
  double rotation = 0;  ///< the x-axis rotation, degrees
  bool large = false;   ///< large-arc-flag
  bool sweep = false;   ///< sweep-flag: 1 is the direction of increasing angle
};

/// One segment: its control points p[0..points) (line 2, quadratic 3, cubic 4, arc its 2 ends),
/// and for an arc its arguments.
struct segment {
  segment_kind kind = segment_kind::line;
  std::array<xy, 4> p{};
  int points = 2;
  arc_arguments arc{};
  std::size_t offset = 0;  ///< the offset in d of the command (or repeated argument group) it came from
  [[nodiscard]] const xy& start() const { return p[0]; }
  [[nodiscard]] const xy& end() const { return p[static_cast<std::size_t>(points - 1)]; }
};

/// A subpath: from a moveto (or the point a closepath returned to) to the next.
struct subpath {
  xy start;
  std::vector<segment> segments;  ///< may be empty ("M1 1" alone)
  bool closed = false;            ///< ended by Z/z (its closing line, when not of zero length, is the last segment)
};

/// An elliptical arc in centre form: c + R(phi) (rx cos theta, ry sin theta) for theta from theta1
/// to theta1 + dtheta.
template <class Real>
struct arc_center {
  Real cx{0}, cy{0};
  Real rx{0}, ry{0};  ///< after the out-of-range correction, > 0
  Real phi{0};        ///< the x-axis rotation, radians, in [0, 2 pi)
  Real theta1{0};     ///< the start angle, radians
  Real dtheta{0};     ///< the sweep, radians: > 0 with sweep-flag 1, < 0 with 0; |dtheta| <= 2 pi
  /// (cos theta1, sin theta1), computed without the angle: the start point relative to the centre
  /// in the unit circle's frame. Pieces of the arc are built from it and the written end points,
  /// never as c + (a point relative to c), which loses everything when |c| dwarfs the arc.
  Real ux{1}, uy{0};
};

/// The centre form of arc segment s, computed in Real (SVG 1.1 F.6.5 and F.6.6; see the header).
/// No intermediate can overflow or underflow where the result is representable: the F.6.5 radicand
/// is taken in the unit circle's frame, X = x1' / rx and Y = y1' / ry (its terms divided by
/// rx^2 ry^2, so no fourth power of a radius is formed), and the radii scaled up by sqrt(Lambda)
/// are hypot(x1', y1' rx / ry) and hypot(x1' ry / rx, y1'). A result that is not finite in Real (a
/// centre or radii past its range, a ratio of radii past it) throws invalid_input naming it.
template <class Real>
[[nodiscard]] arc_center<Real> center_form(const segment& s) {
  using std::abs, std::atan2, std::cos, std::fmod, std::sin, std::sqrt;
  const auto hypot = [](const Real& p, const Real& q) { return safe_norm(point<Real, 2>(p, q)); };
  if (s.kind != segment_kind::arc) throw invalid_input("svg center_form: the segment is not an arc");
  const Real pi = boost::math::constants::pi<Real>();
  const Real x1s(s.p[0].x), y1s(s.p[0].y), x2(s.p[1].x), y2(s.p[1].y);
  Real rx = abs(Real(s.arc.rx)), ry = abs(Real(s.arc.ry));
  if (!(rx > Real(0)) || !(ry > Real(0)))
    throw invalid_input("svg center_form: an arc with a zero radius is a line (the parser makes it one)");
  Real degrees = fmod(Real(s.arc.rotation), Real(360));
  if (degrees < Real(0)) degrees += Real(360);
  arc_center<Real> a;
  a.phi = degrees * pi / Real(180);
  const Real cp = cos(a.phi), sp = sin(a.phi);
  // Halves first: x1s / 2 - x2 / 2 cannot overflow where x1s - x2 would (halving is exact).
  const Real dx = x1s / Real(2) - x2 / Real(2), dy = y1s / Real(2) - y2 / Real(2);
  // |x1'| and |y1'| are at most hypot(dx, dy) <= sqrt(2) max(|dx|, |dy|); computed as below each
  // term is at most max(|dx|, |dy|), so only a rotated half chord past Real's range overflows.
  const Real x1 = cp * dx + sp * dy, y1 = -sp * dx + cp * dy;
  const Real X = x1 / rx, Y = y1 / ry;  // the half chord in the unit circle's frame; may be +-inf
  const Real h = hypot(X, Y);           // sqrt(Lambda), without squaring
  Real ux, uy;
  if (h > Real(1)) {
    // Radii too small to reach the end: scaled by sqrt(Lambda), the arc is half the ellipse, its
    // centre the chord's midpoint exactly (F.6.6's radicand is 0 there; computed after the scaling it
    // is rounding noise of either sign, and its square root would move the centre by about sqrt(eps)
    // of the radii: 5e-8 in the length of a 30-degree arc, different between two builds).
    const Real q = ry / rx;
    if (!is_finite(q) || !(q > Real(0)))
      throw invalid_input("svg arc: the ratio of its radii ry / rx = " + to_text(ry) + " / " + to_text(rx) +
                          " is past the range of the arithmetic");
    const Real rx2 = hypot(x1, y1 / q), ry2 = hypot(x1 * q, y1);
    rx = rx2;
    ry = ry2;
    ux = x1 / rx;
    uy = y1 / ry;
    // Unit up to rounding; normalised so that the pieces built from it are exact to the arithmetic.
    const Real n = hypot(ux, uy);
    ux /= n;
    uy /= n;
  } else {
    // F.6.5.2 divided by rx^2 ry^2: coef^2 = (1 - Lambda) / Lambda, with 1 - Lambda = (1 - h)(1 + h)
    // (no cancellation beyond that of 1 - h itself). The centre in the primed frame is
    // coef (rx Y, -ry X); the start point relative to it, in the unit frame, is
    // u = (X - coef Y, Y + coef X), a unit vector; coef is +-inf only when h is 0, which the parser
    // excludes (coincident end points are no arc).
    // Formed as h e + sgn c (-e_y, e_x), e = (X, Y) / h and c = |coef| h = sqrt(1 - h^2), so that
    // nothing overflows when h is tiny (a huge radius over a short chord).
    const Real ex = X / h, ey = Y / h;
    const Real c = sqrt((Real(1) - h) * (Real(1) + h));
    const Real sgn = s.arc.large == s.arc.sweep ? Real(-1) : Real(1);
    ux = h * ex - sgn * c * ey;
    uy = h * ey + sgn * c * ex;
  }
  // The end relative to the centre, in the unit frame: -u on the half ellipse; else v = u - 2 (X, Y)
  // (the chord is -2 (x1', y1') in the primed frame).
  const Real vx = h > Real(1) ? Real(-ux) : Real(ux - Real(2) * X);
  const Real vy = h > Real(1) ? Real(-uy) : Real(uy - Real(2) * Y);
  a.rx = rx;
  a.ry = ry;
  a.ux = ux;
  a.uy = uy;
  a.theta1 = atan2(uy, ux);
  Real dtheta = atan2(ux * vy - uy * vx, ux * vx + uy * vy);
  if (!s.arc.sweep && dtheta > Real(0)) dtheta -= Real(2) * pi;
  if (s.arc.sweep && dtheta < Real(0)) dtheta += Real(2) * pi;
  a.dtheta = dtheta;
  // The centre: on the half ellipse the chord's midpoint, exactly; else the start point minus A u,
  // A = R(phi) diag(rx, ry).
  if (h > Real(1)) {
    a.cx = x1s / Real(2) + x2 / Real(2);
    a.cy = y1s / Real(2) + y2 / Real(2);
  } else {
    const Real ax = rx * ux, ay = ry * uy;
    a.cx = x1s - (cp * ax - sp * ay);
    a.cy = y1s - (sp * ax + cp * ay);
  }
  for (const Real* v : {&a.cx, &a.cy, &a.rx, &a.ry})
    if (!is_finite(*v))
      throw invalid_input("svg arc: its centre form is past the range of the arithmetic (radii " + to_text(rx) + ", " +
                          to_text(ry) + ")");
  return a;
}

/// The point of the arc at angle theta: {x, y}.
template <class Real>
[[nodiscard]] std::array<Real, 2> arc_point(const arc_center<Real>& a, const Real& theta) {
  using std::cos, std::sin;
  const Real c = cos(a.phi), s = sin(a.phi);
  const Real x = a.rx * cos(theta), y = a.ry * sin(theta);
  return {a.cx + c * x - s * y, a.cy + s * x + c * y};
}

/// The segments one path's data may draw: past it parse_path refuses the data before building more
/// (a segment is about 120 bytes here and a few hundred in a curve, so a million is a few hundred MB).
inline constexpr std::size_t max_segments = 1000000;

namespace detail {

class path_reader {
 public:
  explicit path_reader(std::string_view d) : d_(d) {}

  std::vector<subpath> read() {
    skip_wsp();
    if (at_end()) fail("a moveto command (M or m): the path data is empty");
    if (peek() != 'M' && peek() != 'm') fail("a moveto command (M or m) first");
    while (true) {
      skip_wsp();
      if (at_end()) break;
      const std::size_t at = pos_;
      const char c = peek();
      if (!is_command(c)) fail("a path command (one of MmZzLlHhVvCcSsQqTtAa)");
      ++pos_;
      command(c, at);
    }
    return std::move(out_);
  }

 private:
  std::string_view d_;
  std::size_t pos_ = 0;
  std::vector<subpath> out_;
  std::size_t segments_ = 0;
  xy current_{}, start_{};
  bool open_ = false;  // a subpath is being written (a moveto started it)
  char previous_ = 0;  // the previous command's letter, upper case
  xy last_control_{};  // the previous C/S's second control point, or Q/T's control point

  [[nodiscard]] bool at_end() const { return pos_ >= d_.size(); }
  [[nodiscard]] char peek() const { return d_[pos_]; }
  static bool is_wsp(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\f' || c == '\r'; }
  static bool is_digit(char c) { return c >= '0' && c <= '9'; }
  static bool is_command(char c) { return std::string_view("MmZzLlHhVvCcSsQqTtAa").find(c) != std::string_view::npos; }
  void skip_wsp() {
    while (!at_end() && is_wsp(peek())) ++pos_;
  }
  // comma-wsp?: white space with at most one comma in it.
  void skip_separator() {
    skip_wsp();
    if (!at_end() && peek() == ',') {
      ++pos_;
      skip_wsp();
    }
  }
  // Whether a number (an argument) starts here, after white space: the start of an implicit repeat.
  [[nodiscard]] bool number_follows() {
    std::size_t p = pos_;
    while (p < d_.size() && is_wsp(d_[p])) ++p;
    if (p < d_.size() && d_[p] == ',') {
      // A comma before the next group is allowed only between arguments: treat it as the start of
      // one, so that "L1 2, 3 4" repeats and "L1 2,Z" fails at the comma's successor.
      return true;
    }
    return p < d_.size() && (is_digit(d_[p]) || d_[p] == '.' || d_[p] == '-' || d_[p] == '+');
  }

  [[noreturn]] void fail(std::string_view expected) const {
    std::string found = at_end() ? std::string("the end of the data") : "'" + std::string(1, d_[pos_]) + "'";
    throw invalid_input("svg path data: at offset " + std::to_string(pos_) + " (" + found + "): expected " +
                        std::string(expected));
  }

  double number(std::string_view what) {
    skip_wsp();
    const std::size_t begin = pos_;
    std::size_t p = pos_;
    bool negative = false;
    if (p < d_.size() && (d_[p] == '+' || d_[p] == '-')) negative = d_[p++] == '-';
    const std::size_t mantissa = p;
    std::size_t int_digits = 0, leading_zeros = 0, frac_digits = 0, frac_zeros = 0;
    bool nonzero = false;
    while (p < d_.size() && is_digit(d_[p])) {
      if (!nonzero && d_[p] == '0')
        ++leading_zeros;
      else
        nonzero = true;
      ++int_digits, ++p;
    }
    if (p < d_.size() && d_[p] == '.') {
      ++p;
      while (p < d_.size() && is_digit(d_[p])) {
        if (!nonzero && d_[p] == '0')
          ++frac_zeros;
        else
          nonzero = true;
        ++frac_digits, ++p;
      }
    }
    if (int_digits + frac_digits == 0) {
      pos_ = begin;
      fail(what);
    }
    long long exponent = 0;
    if (p < d_.size() && (d_[p] == 'e' || d_[p] == 'E')) {
      // An exponent needs digits: "1e" and "1e+" are errors (SVG's grammar; no browser reads "1e" as 1).
      std::size_t q = p + 1;
      bool exp_negative = false;
      if (q < d_.size() && (d_[q] == '+' || d_[q] == '-')) exp_negative = d_[q++] == '-';
      if (q >= d_.size() || !is_digit(d_[q])) {
        pos_ = q;
        fail("the exponent's digits of a number");
      }
      while (q < d_.size() && is_digit(d_[q])) {
        if (exponent < 100000) exponent = exponent * 10 + (d_[q] - '0');
        ++q;
      }
      if (exp_negative) exponent = -exponent;
      p = q;
    }
    double value = 0;
    const auto r = std::from_chars(d_.data() + mantissa, d_.data() + p, value, std::chars_format::general);
    if (r.ec == std::errc::result_out_of_range) {
      // Past double's range when the number's decimal magnitude is positive, else below it (0).
      const long long magnitude = int_digits > leading_zeros
                                      ? static_cast<long long>(int_digits - leading_zeros) + exponent
                                      : exponent - static_cast<long long>(frac_zeros);
      if (nonzero && magnitude > 0) {
        pos_ = begin;
        fail("a number within double's range (this one overflows)");
      }
      value = 0;
    } else if (r.ec != std::errc() || r.ptr != d_.data() + p) {
      pos_ = begin;
      fail(what);
    }
    pos_ = p;
    return negative ? -value : value;
  }

  bool flag() {
    skip_wsp();
    if (at_end() || (peek() != '0' && peek() != '1')) fail("an arc flag, 0 or 1");
    return d_[pos_++] == '1';
  }

  xy pair(bool relative) {
    const std::size_t at = pos_;
    const double x = number("a number (the x coordinate)");
    skip_separator();
    const double y = number("a number (the y coordinate)");
    return relative ? absolute(xy{current_.x + x, current_.y + y}, at) : xy{x, y};
  }

  // A relative coordinate added to the current point may pass double's range: refused where it was
  // written, never carried on as inf.
  xy absolute(const xy& p, std::size_t at) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      pos_ = at;
      fail("a relative point whose absolute coordinates stay within double's range (this one overflows)");
    }
    return p;
  }

  void add(segment s, std::size_t at) {
    if (++segments_ > max_segments) {
      pos_ = at;
      fail("at most " + std::to_string(max_segments) + " segments in one path's data (the limit of a path)");
    }
    s.offset = at;
    s.p[0] = current_;
    out_.back().segments.push_back(s);
    current_ = s.end();
  }

  void move_to(const xy& p) {
    out_.push_back(subpath{p, {}, false});
    current_ = start_ = p;
    open_ = true;
  }

  // A subpath after Z without a moveto starts at the closed subpath's start.
  void ensure_open() {
    if (!open_) move_to(start_);
  }

  void command(char c, std::size_t at) {
    const bool relative = c >= 'a';
    const char upper = relative ? static_cast<char>(c - 'a' + 'A') : c;
    if (upper == 'Z') {
      if (open_) {
        subpath& sp = out_.back();
        if (!(current_ == start_)) {
          segment s;
          s.kind = segment_kind::line;
          s.points = 2;
          s.p[1] = start_;
          add(s, at);
        }
        sp.closed = true;
        current_ = start_;
        open_ = false;
      }
      previous_ = 'Z';
      skip_wsp();
      if (!at_end() && !is_command(peek())) fail("a command after closepath (Z takes no arguments)");
      return;
    }
    bool first = true;
    do {
      if (!first) skip_separator();
      const std::size_t group = first ? at : pos_;
      argument_group(upper, relative, first, group);
      first = false;
    } while (number_follows());
  }

  void argument_group(char upper, bool relative, bool first, std::size_t at) {
    segment s;
    switch (upper) {
      case 'M': {
        // A first "m" of the data is from the origin, i.e. absolute, as SVG says; after Z it is
        // relative to the closed subpath's start, the current point.
        const xy p = pair(relative);
        if (first) {  // the pairs after it are implicit linetos
          move_to(p);
          previous_ = 'M';
          return;
        }
        s.kind = segment_kind::line;
        s.p[1] = p;
        upper = 'L';
        break;
      }
      case 'L':
        s.kind = segment_kind::line;
        s.p[1] = pair(relative);
        break;
      case 'H': {
        const double x = number("a number (the x coordinate)");
        s.kind = segment_kind::line;
        s.p[1] = absolute({relative ? current_.x + x : x, current_.y}, at);
        break;
      }
      case 'V': {
        const double y = number("a number (the y coordinate)");
        s.kind = segment_kind::line;
        s.p[1] = absolute({current_.x, relative ? current_.y + y : y}, at);
        break;
      }
      case 'C':
        s.kind = segment_kind::cubic;
        s.points = 4;
        s.p[1] = pair(relative);
        skip_separator();
        s.p[2] = pair(relative);
        skip_separator();
        s.p[3] = pair(relative);
        break;
      case 'S':
        s.kind = segment_kind::cubic;
        s.points = 4;
        s.p[1] = previous_ == 'C' || previous_ == 'S' ? absolute(reflect(last_control_), at) : current_;
        s.p[2] = pair(relative);
        skip_separator();
        s.p[3] = pair(relative);
        break;
      case 'Q':
        s.kind = segment_kind::quadratic;
        s.points = 3;
        s.p[1] = pair(relative);
        skip_separator();
        s.p[2] = pair(relative);
        break;
      case 'T':
        s.kind = segment_kind::quadratic;
        s.points = 3;
        s.p[1] = previous_ == 'Q' || previous_ == 'T' ? absolute(reflect(last_control_), at) : current_;
        s.p[2] = pair(relative);
        break;
      case 'A': {
        arc_arguments args;
        args.rx = number("a number (the arc's rx)");
        skip_separator();
        args.ry = number("a number (the arc's ry)");
        skip_separator();
        args.rotation = number("a number (the arc's x-axis rotation, degrees)");
        skip_separator();
        args.large = flag();
        skip_separator();
        args.sweep = flag();
        skip_separator();
        const xy end = pair(relative);
        ensure_open();
        previous_ = 'A';
        arc_to(args, end, at);
        return;
      }
      default: fail("a path command");
    }
    ensure_open();
    if (s.kind == segment_kind::cubic) last_control_ = s.p[2];
    if (s.kind == segment_kind::quadratic) last_control_ = s.p[1];
    previous_ = upper;
    add(s, at);
  }

  [[nodiscard]] xy reflect(const xy& control) const { return {2 * current_.x - control.x, 2 * current_.y - control.y}; }

  // An arc: omitted between coincident endpoints, a line with a zero radius (decided on the data
  // as written), else kept in its endpoint form (center_form converts it).
  void arc_to(const arc_arguments& args, const xy& end, std::size_t at) {
    if (current_ == end) return;
    segment s;
    s.p[1] = end;
    s.kind = args.rx == 0 || args.ry == 0 ? segment_kind::line : segment_kind::arc;
    s.arc = args;
    add(s, at);
  }
};

}  // namespace detail

/// The subpaths of SVG path data d (see the header); invalid_input naming the offset, the character
/// there and what was expected when d is not path data.
[[nodiscard]] inline std::vector<subpath> parse_path(std::string_view d) { return detail::path_reader(d).read(); }

}  // namespace curvebench::io::svg
