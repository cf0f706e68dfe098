// The arc-length parameterization of a curve: s(u), u(s) and constant-speed sampling.
//
// Built once: the cumulative segment lengths (adaptive Gauss-Kronrod) and, unless the method is
// Newton, a table of u_j = u(s_j) on a uniform grid s_j = j L / M with slopes du/ds = 1 / |P'(u_j)|,
// the nodes solved in a chain, each relative to the previous one. s(u): from the nearest known
// point at or left of u, one recursive Gauss-Kronrod integral. u(s): (a) linear_table, O(1),
// error O(ds^2); (b) hermite_table, O(1), cubic Hermite of u(s) with Fritsch-Carlson limited
// slopes, cells split at the arc-length positions of knots (where u'' or u' jumps), error O(ds^4);
// (c) newton (newton_inversion.hpp). (a) and (b) may add one safeguarded Newton polish over one
// panel of the short-step rule. M is given, or doubled from 16 per segment until the Hermite
// table's measured midpoint error is below table_tolerance * L (or the resolution of u in Real, far
// from 0: rounding_limited), or the construction's evaluation budget (2^25) would be passed (cap_hit).
// Degenerate curves (length 0 or rounding noise of their size) have s(u) but no u(s).
// s(u)'s estimate, and with it invert()'s, includes the curve's own rounding (length.hpp,
// evaluation_error); table_error() is the Hermite interpolation's measured error only.
// Sources: seed 002 (arc-length table, u = U(s) by lookup); Eberly (2008); Fritsch & Carlson (1980).
// Cost: construction O(M) Newton solves, at most max_evaluations; u(s) O(1) (+15 or 31 with the polish);
// s(u) O(log M) + one integral. Holds a copy of the curve; const members are thread-safe.
#pragma once

#include "curvebench/arclength/gauss_kronrod.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/newton_inversion.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace curvebench::arclength {

/// How u(s) is computed.
enum class inversion_method {
  linear_table,   ///< (a) uniform s-grid, linear interpolation, O(1)
  hermite_table,  ///< (b) uniform s-grid, cubic Hermite with du/ds = 1/|P'|, O(1)
  newton          ///< (c) Newton from the segment bracket, no table
};

template <class Real>
struct parameterization_options {
  inversion_method method{inversion_method::hermite_table};
  /// One Newton step after the table lookup (methods a and b).
  bool newton_polish{false};
  /// Number of s-grid intervals; 0 = grow by doubling until the measured Hermite error is below
  /// table_tolerance * L (or max_table_intervals is reached: table_status() says cap_hit).
  std::size_t table_intervals{0};
  std::size_t max_table_intervals{std::size_t(1) << 16};
  /// Target of the Hermite table's |ds| error, relative to L: max(32 eps, 1e-15).
  Real table_tolerance{std::max(Real(32) * epsilon<Real>(), Real(1) / Real(1000000000000000LL))};
  /// Newton inversion (method c, table nodes, polish) and segment lengths; see newton_options.
  newton_options<Real> newton{};
  /// Total curve-derivative evaluations of the construction (segment lengths, knots, table). The
  /// segment lengths get at most half; each table node gets its share of what is left (never below
  /// min_node_evaluations); a doubling whose projected cost (twice the last table's) would pass the
  /// budget is not started. The table stops there: table_status() cap_hit (not_guaranteed when no
  /// finer table measured the first one).
  std::size_t max_evaluations{std::size_t(1) << 25};
};

/// The fewest evaluations a table node's Newton solve is given however the budget is shared: one
/// short-step integral and its speed.
inline constexpr std::size_t min_node_evaluations = 64;

/// A curve whose length is at most this many eps of its size (the largest |P| at its breakpoints)
/// has a length made of rounding noise: nothing of it can be told apart in arc length.
inline constexpr int degenerate_length_eps = 64;

template <curve C>
class parameterization {
 public:
  using curve_type = C;
  using real_type = typename C::real_type;
  using point_type = typename C::point_type;
  using Real = real_type;

  /// Precomputes the segment lengths and, for methods a and b, the s-grid table. Throws
  /// invalid_input for bad options, a length that is not finite, and for a degenerate curve (length 0, or at most
  /// degenerate_length_eps eps of its size: rounding noise) unless the method is newton: such a
  /// curve has s(u) (within its noise) but no u(s), which then throws invalid_input.
  explicit parameterization(C c, const parameterization_options<Real>& opt = {}) : curve_(std::move(c)), opt_(opt) {
    detail::check_newton_options(opt_.newton);
    validate::positive("table_tolerance", opt_.table_tolerance);
    adaptive_options<Real> seg_opt = segment_lengths<Real>::default_options();
    seg_opt.gauss_points = opt_.newton.gauss_points;
    seg_opt.max_evaluations = std::min(seg_opt.max_evaluations, opt_.max_evaluations / 2);
    // The length prefix serves Newton's brackets; the table methods chain their nodes instead.
    segments_ = segment_lengths<Real>(
        curve_, seg_opt,
        opt_.method == inversion_method::newton ? segment_lengths<Real>::newton_prefix_panels : std::size_t(0));
    if (!is_finite(segments_.length()))
      validate::fail("curve length = " + to_text(segments_.length()) +
                     ": not finite (the speed |P'| overflowed or is not a number somewhere on the curve); an "
                     "arc-length parameterization needs a finite length");
    measure_degeneracy();
    if (opt_.method != inversion_method::newton) {
      require_length();
      collect_knots();
      build_table();
    }
  }

  /// Whether the length is 0 or rounding noise (see degenerate_length_eps): no u(s).
  [[nodiscard]] bool degenerate() const { return !(length() > noise_length_); }
  /// The curve's size: the largest |P|_inf at its breakpoints.
  [[nodiscard]] Real size() const { return size_; }

  [[nodiscard]] const C& curve() const { return curve_; }
  [[nodiscard]] const parameterization_options<Real>& options() const { return opt_; }
  [[nodiscard]] interval<Real> domain() const { return interval<Real>(curve_.domain()); }
  /// Total arc length L.
  [[nodiscard]] Real length() const { return segments_.length(); }
  /// L with its error estimate, evaluations and status.
  [[nodiscard]] const quadrature_result<Real>& length_result() const { return segments_.total(); }
  [[nodiscard]] const segment_lengths<Real>& segments() const { return segments_; }

  /// Arc length from u0 to u. Throws std::domain_error outside the domain.
  [[nodiscard]] Real s(const Real& u) const { return s_result(u).value; }

  /// s(u) with its error estimate, evaluations and status.
  [[nodiscard]] quadrature_result<Real> s_result(const Real& u) const {
    using std::max;
    check_parameter(u, domain());
    Real u_known, s_known, e_known;
    nearest_known(u, u_known, s_known, e_known);
    quadrature_result<Real> q;
    // A degenerate curve's s(u) is wanted to its noise level only (its length is noise).
    if (u > u_known)
      q = integrate_recursive(
          [this](const Real& x) { return speed(curve_, x); }, u_known, u,
          max(Real(opt_.newton.relative_tolerance * length() / Real(8)), degenerate() ? noise_length_ : Real(0)),
          gauss_kronrod<Real>(opt_.newton.gauss_points), opt_.newton.max_depth, opt_.newton.max_evaluations);
    add_evaluation_error(q, evaluation_error(curve_, u_known, u), opt_.newton.relative_tolerance * length());
    q.value += s_known;
    q.error_estimate += e_known;
    if (!is_finite(q.error_estimate) || !is_finite(rounding_bound(curve_, 1))) {  // no bound known (core/curve.hpp)
      q.error_estimate = no_bound<Real>();
      q.status = result_status::not_guaranteed;
    }
    return q;
  }

  /// u(s) by the configured method. Throws std::domain_error for s outside [0, L] or NaN.
  [[nodiscard]] Real u(const Real& s) const { return u(s, opt_.method); }

  /// u(s) by the given method (a table method needs the object built with a table method,
  /// otherwise std::logic_error).
  [[nodiscard]] Real u(const Real& s, inversion_method m) const {
    require_length();
    check_arc_length(s, length());
    if (m == inversion_method::newton) return newton_invert(curve_, segments_, s, opt_.newton).u;
    require_table();
    std::size_t evaluations = 0;
    return table_u(s, m, evaluations);
  }

  /// u(s) with its residual s(u) - s (computed: costs an integral for the table methods), error
  /// estimate, evaluations and status. For the table methods the status is converged when the
  /// estimate meets newton.relative_tolerance * L, otherwise not_guaranteed.
  [[nodiscard]] inversion_result<Real> invert(const Real& s, inversion_method m) const {
    require_length();
    check_arc_length(s, length());
    if (m == inversion_method::newton) return newton_invert(curve_, segments_, s, opt_.newton);
    using std::abs;
    require_table();
    inversion_result<Real> r;
    std::size_t polish_evaluations = 0;
    r.u = table_u(s, m, polish_evaluations);
    const quadrature_result<Real> q = s_result(r.u);
    r.residual = q.value - s;
    r.s_error_estimate = abs(r.residual) + q.error_estimate;
    r.evaluations = q.evaluations + polish_evaluations;
    r.status = r.s_error_estimate <= opt_.newton.relative_tolerance * length() ? result_status::converged
                                                                               : result_status::not_guaranteed;
    return r;
  }

  /// The parameters of n >= 2 points equally spaced in arc length (s_i = i L / (n - 1)), written
  /// to out (size n), by the configured method.
  void constant_speed_parameters(std::span<Real> out) const {
    validate::count_at_least("constant-speed samples", out.size(), 2, "both ends are sampled");
    const Real n1 = static_cast<Real>(static_cast<long long>(out.size() - 1));
    for (std::size_t i = 0; i < out.size(); ++i) {
      const Real si = i + 1 == out.size() ? length() : length() * Real(static_cast<long long>(i)) / n1;
      out[i] = u(si);
    }
  }
  [[nodiscard]] std::vector<Real> constant_speed_parameters(std::size_t n) const {
    std::vector<Real> out(n);
    constant_speed_parameters(std::span<Real>(out));
    return out;
  }

  /// Number of s-grid intervals M (0 for the Newton method).
  [[nodiscard]] std::size_t table_intervals() const { return nodes_u_.empty() ? 0 : nodes_u_.size() - 1; }
  /// Measured bound of the Hermite table's |ds| error (the coarser table's midpoint error when the
  /// size was found by doubling; +inf when the size was given and not measured).
  [[nodiscard]] Real table_error() const { return table_error_; }
  /// converged (table_error <= table_tolerance * L), rounding_limited (table_error is at the
  /// resolution of u in Real, 8 eps max|u| max|P'|, above that target: a domain far from 0),
  /// cap_hit (max_table_intervals or max_evaluations reached first, or a node's Newton solve ran
  /// out of its share; table_error then includes the worst node's bound), not_guaranteed (size
  /// given by the caller, or the budget allowed no finer table to measure it: no bound).
  [[nodiscard]] result_status table_status() const { return table_status_; }
  /// The s-grid nodes u_j (size M + 1).
  [[nodiscard]] std::span<const Real> table_parameters() const { return nodes_u_; }
  /// Curve-derivative evaluations spent building segments and table.
  [[nodiscard]] std::size_t construction_evaluations() const {
    return build_evaluations_ + segments_.total().evaluations + segments_.prefix_evaluations();
  }

 private:
  struct cubic {
    Real c0, c1, c2, c3;
    [[nodiscard]] Real eval(const Real& t) const { return c0 + t * (c1 + t * (c2 + t * c3)); }
  };

  // One Hermite piece of u(s) on [s0, s0 + 1/inv_w]: u = c(t), t = (s - s0) inv_w. `split` is the
  // start of the next piece of the same cell (+inf for a cell's last piece), `next` its index in
  // hermite_table::extra. 64 bytes in double: one cache line per query.
  struct alignas(64) piece {
    Real s0, inv_w;
    cubic c;
    Real split;
    std::size_t next;
  };
  // A knot (interior breakpoint) at arc length s, parameter u, with the speeds just left and right
  // of it (they differ where the curve is only C0).
  struct knot {
    Real s, u, speed_left, speed_right;
  };
  // The Hermite table: cell j's first piece is cells[j], one per cell unless the arc-length
  // position of a knot falls inside the cell; then the cell is split there, so that no piece
  // straddles a knot, where u(s) has a jump in u'' (C1 curves) or in u' (C0 curves), and the
  // further pieces are chained in `extra`. A query reads one record (O(1), no search) unless its
  // cell is split.
  struct hermite_table {
    std::vector<piece> cells;
    std::vector<piece> extra;
    [[nodiscard]] Real eval(const Real& s, std::size_t j) const {
      const piece* p = &cells[j];
      while (!(s < p->split)) [[unlikely]] p = &extra[p->next];
      Real t = (s - p->s0) * p->inv_w;
      if (t < Real(0)) t = Real(0);  // floor(s / ds) rounded up across a node
      if (t > Real(1)) t = Real(1);
      return p->c.eval(t);
    }
  };

  static std::size_t to_index(const Real& x) {
    using std::floor;
    return static_cast<std::size_t>(static_cast<long long>(floor(x)));
  }

  // The noise level and the size (positions at the breakpoints: their evaluations are counted).
  void measure_degeneracy() {
    using std::abs;
    using std::max;
    Real size(0);
    for (const Real& b : segments_.parameters()) {
      const point_type p = curve_(b);
      for (int d = 0; d < p.size(); ++d) size = max(size, Real(abs(p[d])));
      ++build_evaluations_;
    }
    size_ = size;
    noise_length_ = Real(degenerate_length_eps) * epsilon<Real>() * size;
  }

  void require_length() const {
    if (degenerate()) [[unlikely]]
      fail_degenerate();
  }

  [[noreturn]] void fail_degenerate() const {
    validate::fail("curve length = " + to_text(length()) +
                   (length() == Real(0) ? std::string()
                                        : " is rounding noise (at most " + std::to_string(degenerate_length_eps) +
                                              " eps of the curve's size " + to_text(size_) + ")") +
                   ": an arc-length parameterization needs a curve of positive length");
  }

  void require_table() const {
    if (nodes_u_.empty())
      throw std::logic_error("parameterization: a table method needs the object built with a table method");
  }

  // j = floor(s / ds) clamped to [0, M - 1], t = s / ds - j in [0, 1].
  void locate(const Real& s, std::size_t& j, Real& t) const {
    const Real x = s * inv_ds_;
    const std::size_t m = nodes_u_.size() - 1;
    j = x > Real(0) ? std::min(to_index(x), m - 1) : 0;
    t = x - Real(static_cast<long long>(j));
    if (t > Real(1)) t = Real(1);
    if (t < Real(0)) t = Real(0);
  }

  // The known point at or left of u nearest to it: a table node or a segment start.
  void nearest_known(const Real& u, Real& uk, Real& sk, Real& ek) const {
    const std::size_t i = segments_.segment_for_u(u);
    uk = segments_.parameters()[i];
    sk = segments_.cumulative()[i];
    ek = segments_.cumulative_error()[i];
    if (!nodes_u_.empty()) {
      if (!(u < nodes_u_.front())) {
        const std::size_t j = curvebench::detail::breakpoint_at_or_below<Real>(nodes_u_, u);
        if (nodes_u_[j] > uk) {
          uk = nodes_u_[j];
          sk = nodes_s_[j];
          ek = nodes_err_[j];
        }
      }
    }
  }

  // The table value of u(s) in cell j (O(1)), polished when the options say so; evaluations are
  // added to `evaluations`.
  [[nodiscard]] Real table_u(const Real& s, inversion_method m, std::size_t& evaluations) const {
    std::size_t j;
    Real t;
    locate(s, j, t);
    const Real uu =
        m == inversion_method::linear_table ? nodes_u_[j] + t * (nodes_u_[j + 1] - nodes_u_[j]) : hermite_.eval(s, j);
    return opt_.newton_polish ? polish(s, uu, j, evaluations) : uu;
  }

  // s(x) - s for x in cell j, integrated from the nearer cell end by one panel of the short-step
  // rule (detail::short_step_rule, G7-K15); err gets the panel's estimate |G - K| + rounding floor. The node's own
  // error (nodes_err_, a loose bound that includes the segment lengths' estimates) is left out: it biases r0 and r1
  // alike, and a step can only end as close to s as the node is, which the table value is no closer than.
  [[nodiscard]] Real cell_residual(const Real& s, const Real& x, std::size_t j, Real& err,
                                   std::size_t& evaluations) const {
    const gauss_kronrod_rule<Real>& rule = detail::short_step_rule<Real>();
    auto f = [this](const Real& v) { return speed(curve_, v); };
    const bool from_left = x - nodes_u_[j] <= nodes_u_[j + 1] - x;
    const kronrod_panel<Real> p = from_left ? rule.apply(f, nodes_u_[j], x) : rule.apply(f, x, nodes_u_[j + 1]);
    evaluations += p.evaluations;
    err = p.error_estimate;
    return from_left ? (nodes_s_[j] - s) + p.kronrod : (nodes_s_[j + 1] - s) - p.kronrod;
  }

  // The safeguarded Newton polish of the table value uu in cell j, whose bracket [u_j, u_{j+1}]
  // contains u(s) (s(u) is monotone). The step is tried only when the residual r0 = s(uu) - s is
  // above its own error estimate e0 (otherwise it is quadrature noise and a step would follow the
  // panel's error, not the table's), must stay inside the bracket, and is kept only when its
  // residual bound |r1| + e1 is below the table value's lower bound |r0| - e0; otherwise the table
  // value stands. Without these checks a step follows the panel's error wherever the table is
  // already better than one panel (on the s-grid, next to a kink). Integrating from the nearer
  // end halves the panel. Cost: 15 evaluations when the residual is noise, 31 when a step is tried.
  [[nodiscard]] Real polish(const Real& s, const Real& uu, std::size_t j, std::size_t& evaluations) const {
    using std::abs;
    Real e0, e1;
    const Real r0 = cell_residual(s, uu, j, e0, evaluations);
    if (!(abs(r0) > e0)) return uu;
    const Real sp = speed(curve_, uu);
    ++evaluations;
    if (!(sp > Real(0))) return uu;
    const Real next = uu - r0 / sp;
    if (!(next >= nodes_u_[j] && next <= nodes_u_[j + 1])) return uu;
    const Real r1 = cell_residual(s, next, j, e1, evaluations);
    return abs(r1) + e1 < abs(r0) - e0 ? next : uu;
  }

  // Nodes u_j = u(j L / m), j = 0..m, each by Newton from the previous node (the nearest known
  // point) when it is in the same segment. Chained, the arc lengths are taken relative to the
  // previous node s_{j-1}: the bracket's lower end is the previous node's computed residual
  // s(u_{j-1}) - s_{j-1}, the target ds. Every sum is then of the size ds and rounds by ~eps ds; in
  // absolute s each node inherited the previous one's rounding of eps s, a random walk that grew
  // like sqrt(M) eps L (1.2e-14 L at M = 32768 on a 4-segment Catmull-Rom) and kept the automatic
  // sizing from ever meeting 32 eps L.
  // Each node's Newton solve gets its share of the budget left (never below min_node_evaluations);
  // the status returned is the worst of the nodes' (cap_hit when a share ran out).
  result_status compute_nodes(std::size_t m, std::vector<Real>& us, std::vector<Real>& ss, std::vector<Real>& es,
                              std::vector<Real>& sp) {
    const Real len = length();
    const Real tol = opt_.newton.relative_tolerance * len;
    us.assign(m + 1, Real(0));
    ss.assign(m + 1, Real(0));
    es.assign(m + 1, Real(0));
    sp.assign(m + 1, Real(0));
    const auto p = segments_.parameters();
    const auto cum = segments_.cumulative();
    const auto err = segments_.cumulative_error();
    us[0] = p.front();
    us[m] = p.back();
    ss[m] = len;
    es[m] = err.back();
    Real carried(0);  // s(u_{j-1}) - s_{j-1} as computed along the chain
    result_status status = result_status::converged;
    for (std::size_t j = 1; j < m; ++j) {
      const Real sj = len * Real(static_cast<long long>(j)) / Real(static_cast<long long>(m));
      ss[j] = sj;
      const std::size_t i = segments_.segment_for_s(sj);
      newton_bracket<Real> br{p[i], cum[i], err[i], p[i + 1], cum[i + 1], err[i + 1], segments_.guess(i, sj)};
      Real target = sj, inherited(0);
      if (us[j - 1] > br.u_lo && us[j - 1] < br.u_hi) {
        const Real base = ss[j - 1];
        br.u_lo = us[j - 1];
        br.s_lo = carried;
        // The previous node's error bound is added to this node's afterwards, not handed to Newton:
        // summed along the chain it outgrows the tolerance near a segment's end, and Newton then
        // bisected to rounding (rounding_limited, 160 instead of 35 evaluations per node at
        // M = 65536 on the 4-segment Catmull-Rom).
        br.s_lo_error = Real(0);
        inherited = es[j - 1];
        br.s_hi = cum[i + 1] - base;
        target = sj - base;  // exact (Sterbenz) for j >= 2; j = 1 never chains (u_0 is a segment start)
      }
      newton_options<Real> node_opt = opt_.newton;
      node_opt.final_step = true;  // nodes are interpolated by every query: polish them to rounding level
      const std::size_t share = budget_left() > m + 1 ? (budget_left() - (m + 1)) / (m - j) : 0;
      node_opt.max_evaluations = std::min(node_opt.max_evaluations, std::max(min_node_evaluations, share));
      const inversion_result<Real> r = newton_invert(curve_, target, br, tol, node_opt);
      build_evaluations_ += r.evaluations;
      if (r.status == result_status::cap_hit) status = result_status::cap_hit;
      us[j] = r.u;
      es[j] = r.s_error_estimate + inherited;
      carried = r.residual;
    }
    for (std::size_t j = 0; j <= m; ++j) sp[j] = speed(curve_, us[j]);
    build_evaluations_ += m + 1;
    return status;
  }

  [[nodiscard]] std::size_t budget_left() const {
    const std::size_t spent = construction_evaluations();
    return opt_.max_evaluations > spent ? opt_.max_evaluations - spent : 0;
  }

  // What the table can resolve in arc length: 8 eps max|u| max|P'| (u is a Real: one ulp of u
  // moves s by |P'| ulp(u); the Hermite evaluation adds a few ulps). Far from 0 (a domain [1e8,
  // 1e8 + 1]) this is far above table_tolerance * L.
  [[nodiscard]] Real resolution(const std::vector<Real>& sp) const {
    using std::abs;
    using std::max;
    Real top(0);
    for (const Real& v : sp) top = max(top, v);
    const Real umax = max(Real(abs(domain().lo)), Real(abs(domain().hi)));
    return Real(8) * epsilon<Real>() * umax * top;
  }

  // The worst node bound of a table, added to its measured error when a node's solve was capped.
  [[nodiscard]] static Real worst_node_error(const std::vector<Real>& es) {
    Real w(0);
    for (const Real& e : es) w = e > w ? e : w;
    return w;
  }

  // The Hermite cubic on a piece of arc-length width w from (u0, |P'| = sp0) to (u1, sp1): slopes
  // du/ds = 1/|P'| scaled by w, the secant where |P'| = 0, limited for monotonicity
  // (Fritsch-Carlson: the slopes' vector scaled to length <= 3 secants).
  static cubic hermite_cubic(const Real& u0, const Real& u1, const Real& sp0, const Real& sp1, const Real& w) {
    using std::sqrt;
    const Real du = u1 - u0;  // the secant times w
    Real d0 = sp0 > Real(0) ? w / sp0 : du;
    Real d1 = sp1 > Real(0) ? w / sp1 : du;
    if (!is_finite(d0)) d0 = du;
    if (!is_finite(d1)) d1 = du;
    if (du > Real(0)) {
      const Real a = d0 / du, b = d1 / du, r2 = a * a + b * b;
      if (r2 > Real(9)) {
        const Real tau = Real(3) / sqrt(r2);
        d0 *= tau;
        d1 *= tau;
      }
    } else {
      d0 = Real(0);
      d1 = Real(0);
    }
    // u(t) = u0 + d0 t + (3 du - 2 d0 - d1) t^2 + (d0 + d1 - 2 du) t^3
    return cubic{u0, d0, Real(3) * du - Real(2) * d0 - d1, d0 + d1 - Real(2) * du};
  }

  // The knots whose arc-length position is known from the segment lengths, with one-sided speeds
  // (evaluated detail::knot_offset inside each neighbouring segment, as segment_lengths does). A
  // knot closer than detail::knot_gap_eps L to the previous one in s (a zero-length segment) is dropped: u(s) is
  // ambiguous there, and the table keeps the first.
  void collect_knots() {
    using std::abs;
    const auto p = segments_.parameters();
    const auto cum = segments_.cumulative();
    const Real gap = Real(detail::knot_gap_eps) * epsilon<Real>() * length();
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
      if (!(cum[i] > gap && cum[i] < length() - gap)) continue;
      if (!knots_.empty() && !(cum[i] - knots_.back().s > gap)) continue;
      const Real d = detail::knot_offset(Real(abs(p[i - 1]) + abs(p[i + 1])));
      const Real left = p[i] - p[i - 1] > Real(2) * d ? speed(curve_, Real(p[i] - d)) : speed(curve_, p[i]);
      const Real right = p[i + 1] - p[i] > Real(2) * d ? speed(curve_, Real(p[i] + d)) : speed(curve_, p[i]);
      build_evaluations_ += 2;
      knots_.push_back({cum[i], p[i], left, right});
    }
  }

  // The Hermite table on the node set (s_j = j ds, u_j, |P'(u_j)|), cells split at the knots
  // strictly inside them (detail::knot_gap_eps L away from the cell's ends).
  [[nodiscard]] hermite_table make_hermite(const std::vector<Real>& us, const std::vector<Real>& ss,
                                           const std::vector<Real>& sp) const {
    const std::size_t m = us.size() - 1;
    const Real gap = Real(detail::knot_gap_eps) * epsilon<Real>() * length();
    const Real none = std::numeric_limits<Real>::infinity();
    hermite_table h;
    h.cells.reserve(m);
    auto make = [&](const Real& s0, const Real& s1, const Real& u0, const Real& u1, const Real& sp0, const Real& sp1) {
      const Real w = s1 - s0;
      return piece{s0, Real(1) / w, hermite_cubic(u0, u1, sp0, sp1, w), none, 0};
    };
    std::size_t k = 0;  // next knot
    for (std::size_t j = 0; j < m; ++j) {
      while (k < knots_.size() && !(knots_[k].s > ss[j] + gap)) ++k;
      Real s0 = ss[j], u0 = us[j], sp0 = sp[j];
      bool started = false;   // the cell's first piece is in cells
      bool in_extra = false;  // the cell's last piece so far is extra[last_extra], not cells[j]
      std::size_t last_extra = 0;
      auto append = [&](const piece& p) {
        if (!started) {
          h.cells.push_back(p);
          started = true;
          return;
        }
        // chain: the previous piece of the cell ends where this one starts
        piece& prev = in_extra ? h.extra[last_extra] : h.cells.back();
        prev.split = p.s0;
        prev.next = h.extra.size();
        h.extra.push_back(p);
        last_extra = h.extra.size() - 1;
        in_extra = true;
      };
      for (; k < knots_.size() && knots_[k].s < ss[j + 1] - gap; ++k) {
        append(make(s0, knots_[k].s, u0, knots_[k].u, sp0, knots_[k].speed_left));
        s0 = knots_[k].s;
        u0 = knots_[k].u;
        sp0 = knots_[k].speed_right;
      }
      append(make(s0, ss[j + 1], u0, us[j + 1], sp0, sp[j + 1]));
    }
    return h;
  }

  void build_table() {
    using std::abs;
    using std::max;
    const Real len = length();
    std::vector<Real> us, ss, es, sp;
    if (opt_.table_intervals > 0) {
      compute_nodes(opt_.table_intervals, us, ss, es, sp);
      table_error_ = no_bound<Real>();
      table_status_ = result_status::not_guaranteed;
    } else {
      // A power of two, so that doubling can reach a power-of-two cap (5 segments started at 80
      // stopped at 40960 with 65536 allowed).
      std::size_t m = std::bit_ceil(std::max<std::size_t>(16, 16 * segments_.segment_count()));
      m = std::min(m, std::max<std::size_t>(1, opt_.max_table_intervals / 2));
      std::size_t before = construction_evaluations();
      result_status nodes = compute_nodes(m, us, ss, es, sp);
      std::size_t last_cost = construction_evaluations() - before;
      table_status_ = result_status::not_guaranteed;  // until a finer table measures this one
      table_error_ = no_bound<Real>();
      while (true) {
        if (nodes == result_status::cap_hit || 2 * last_cost > budget_left()) {
          if (is_finite(table_error_)) table_status_ = result_status::cap_hit;
          break;
        }
        const hermite_table h = make_hermite(us, ss, sp);
        std::vector<Real> us2, ss2, es2, sp2;
        before = construction_evaluations();
        nodes = compute_nodes(2 * m, us2, ss2, es2, sp2);
        last_cost = construction_evaluations() - before;
        Real worst_err(0);
        for (std::size_t j = 0; j < m; ++j) {
          const Real du = abs(h.eval(ss2[2 * j + 1], j) - us2[2 * j + 1]);
          worst_err = max(worst_err, du * sp2[2 * j + 1]);
        }
        us.swap(us2), ss.swap(ss2), es.swap(es2), sp.swap(sp2);
        m *= 2;
        table_error_ = worst_err;
        if (nodes == result_status::cap_hit) {  // the finer nodes are only as good as their bounds
          table_error_ = worst_err + worst_node_error(es);
          table_status_ = result_status::cap_hit;
          break;
        }
        if (worst_err <= opt_.table_tolerance * len) {
          table_status_ = result_status::converged;
          break;
        }
        if (worst_err <= resolution(sp)) {
          table_status_ = result_status::rounding_limited;
          break;
        }
        table_status_ = result_status::cap_hit;
        if (2 * m > opt_.max_table_intervals) break;
      }
    }
    const std::size_t m = us.size() - 1;
    inv_ds_ = Real(static_cast<long long>(m)) / len;
    hermite_ = make_hermite(us, ss, sp);
    nodes_u_ = std::move(us);
    nodes_s_ = std::move(ss);
    nodes_err_ = std::move(es);
  }

  C curve_;
  parameterization_options<Real> opt_;
  segment_lengths<Real> segments_;
  std::vector<Real> nodes_u_, nodes_s_, nodes_err_;
  std::vector<knot> knots_;
  hermite_table hermite_;
  Real inv_ds_{0};
  Real table_error_{0};
  Real size_{0}, noise_length_{0};
  result_status table_status_{result_status::not_guaranteed};
  std::size_t build_evaluations_{0};
};

}  // namespace curvebench::arclength
