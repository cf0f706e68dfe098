// The arc-length parameterization of a curve: s(u), u(s) and constant-speed sampling.
//
// Built once: the cumulative segment lengths (adaptive Gauss-Kronrod) and, unless the method is
// Newton, a table of u_j = u(s_j) with slopes du/ds = 1 / |P'(u_j)|. The table's cells are placed
// per segment: segment i has m_i cells of equal arc length, so no cell straddles a knot (where u''
// or u' of u(s) jumps), and its nodes are solved in a chain, each relative to the previous one.
// s(u): from the nearest known point at or left of u, one recursive Gauss-Kronrod integral. u(s):
// (a) linear_table, O(1), error O(ds^2); (b) hermite_table, O(1), cubic Hermite of u(s) with
// Fritsch-Carlson limited slopes, error O(ds^4); (c) newton (newton_inversion.hpp). (a) and (b)
// may add one safeguarded Newton polish over one panel of the short-step rule. The cell of s is
// found in O(1): a uniform index of 2M buckets over [0, L] names the first cell of each bucket.
// The size M = sum m_i is given (shared by length, no cell wider than L / M), or found per
// segment: each starts at 16 cells, is halved once to measure its table's midpoint error (of the
// method the table is built for), and the segment with the largest measured error is halved next
// (best first) until every segment's error is below table_tolerance * L (or at the resolution of u
// in Real, far from 0: rounding_limited), or max_table_intervals or the construction's evaluation
// budget (2^25) stops it (cap_hit). Formerly M was global and uniform, doubled for the
// hardest segment, and capped at 2^16: a 1000-segment centripetal Catmull-Rom stopped at 4e-9 L
// (measured 2.2e-10 L); per segment it reaches 1e-12 L.
// Degenerate curves (length 0 or rounding noise of their size) have s(u) but no u(s).
// s(u)'s estimate, and with it invert()'s, includes the curve's own rounding (length.hpp,
// evaluation_error); table_error() is the table interpolation's measured error only.
// Sources: seed 002 (arc-length table, u = U(s) by lookup); Eberly (2008); Fritsch & Carlson (1980).
// Cost: construction O(M) Newton solves (each node solved once: a halving adds the midpoints), at
// most max_evaluations; u(s) O(1) (+15 or 31 with the polish); s(u) O(log M) + one integral.
// Memory per cell in double: about 100 bytes on one segment, 230 on many (the cells by bucket, two
// 64-byte copies per cell, make a query read two lines at once instead of one after the other).
// Holds a copy of the curve; const members are thread-safe.
#pragma once

#include "curvebench/arclength/gauss_kronrod.hpp"
#include "curvebench/arclength/length.hpp"
#include "curvebench/arclength/newton_inversion.hpp"
#include "curvebench/arclength/result.hpp"
#include "curvebench/core/curve.hpp"
#include "curvebench/core/detail/segment_lookup.hpp"
#include "curvebench/core/error.hpp"

#include <algorithm>
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
  linear_table,   ///< (a) s-grid per segment, linear interpolation, O(1)
  hermite_table,  ///< (b) s-grid per segment, cubic Hermite with du/ds = 1/|P'|, O(1)
  newton          ///< (c) Newton from the segment bracket, no table
};

template <class Real>
struct parameterization_options {
  inversion_method method{inversion_method::hermite_table};
  /// One Newton step after the table lookup (methods a and b).
  bool newton_polish{false};
  /// Number of cells M, shared by the segments in proportion to their lengths (ceil(M len_i / L)
  /// each, so the table has up to one more per segment); 0 = sized per segment until the measured
  /// error of the table's method is below table_tolerance * L (see the header).
  std::size_t table_intervals{0};
  /// The most cells the automatic size may reach (table_status() cap_hit when it stops there):
  /// about 240 MB in double on a curve of many segments.
  std::size_t max_table_intervals{std::size_t(1) << 20};
  /// Target of the table's |ds| error (of the method it is built for), relative to L: max(32 eps,
  /// 1e-15).
  Real table_tolerance{std::max(Real(32) * epsilon<Real>(), Real(1) / Real(1000000000000000LL))};
  /// Newton inversion (method c, table nodes, polish) and segment lengths; see newton_options.
  newton_options<Real> newton{};
  /// Total curve-derivative evaluations of the construction (segment lengths, table). The segment
  /// lengths get at most half; each table node gets its share of what is left (never below
  /// min_node_evaluations); a segment's halving whose projected cost (twice its last step's) would
  /// pass the budget is not started. The table stops there: table_status() cap_hit (not_guaranteed
  /// when a segment could not be halved once to measure it).
  std::size_t max_evaluations{std::size_t(1) << 25};
};

/// The most cells a table may be asked for (table_intervals, max_table_intervals): 2^30, up to
/// 240 GB in double.
inline constexpr std::size_t max_table_cells = std::size_t(1) << 30;

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
    for (const auto& [name, value] : {std::pair{"table_intervals", opt_.table_intervals},
                                      std::pair{"max_table_intervals", opt_.max_table_intervals}})
      if (value > max_table_cells)
        validate::fail(std::string(name) + " = " + std::to_string(value) + ": at most " +
                       std::to_string(max_table_cells) + " cells");
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
      q.reason = global_reason<Real>(is_finite(rounding_bound(curve_, 1)) ? reasons::estimate_not_finite
                                                                          : reasons::no_rounding_bound);
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
    if (r.status != result_status::converged)
      r.reason =
          global_reason(reasons::table_residual, r.s_error_estimate, Real(opt_.newton.relative_tolerance * length()));
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

  /// Number of cells M (0 for the Newton method).
  [[nodiscard]] std::size_t table_intervals() const { return cells_.size(); }
  /// Measured bound of the table's |ds| error, of the method it was built for (the worst over the
  /// segments of each one's coarser table's midpoint error plus the lookup's rounding, 8 eps max|u|
  /// max|P'|, when the size was found automatically; +inf when the size was given and not measured).
  [[nodiscard]] Real table_error() const { return table_error_; }
  /// converged (table_error <= table_tolerance * L), rounding_limited (table_error is at the
  /// resolution of u in Real, 8 eps max|u| max|P'|, above that target: a domain far from 0),
  /// cap_hit (max_table_intervals or max_evaluations reached first, or a node's Newton solve ran
  /// out of its share; table_error then includes the worst node's bound), not_guaranteed (size
  /// given by the caller, or the budget allowed no finer table to measure it: no bound).
  [[nodiscard]] result_status table_status() const { return table_status_; }
  /// Why table_status() is not converged (which cap, which segment); empty when it is.
  [[nodiscard]] const status_reason<Real>& table_reason() const { return table_reason_; }
  /// The table's nodes u_j, ascending (M + 1 of them, more when a segment too short for cells lies
  /// between two that have them).
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

  // One cell of the table, [s0, s_end) in arc length: the Hermite cubic of u(s) over it, u = c(t),
  // t = (s - s0) inv_w (c.c0 is u at s0), and u1, u at its end (the linear table reads c0 and u1).
  // Cells lie within one segment each, so none straddles a knot, where u(s) has a jump in u''
  // (C1 curves) or in u' (C0 curves). The last cell's s_end is +inf. 64 bytes in double: one cache
  // line per query.
  struct alignas(64) piece {
    Real s0, inv_w;
    cubic c;
    Real s_end, u1;
  };

  // The nodes of one segment while the table is built: u, s (the grid, s[0] and s[m] the segment's
  // cumulative lengths), the error bound of s(u) at the node (es) and its residual s(u) - s as
  // computed along the chain (r), and |P'| (one-sided at the segment's ends).
  struct segment_nodes {
    std::size_t index = 0;  // the segment
    std::vector<Real> u, s, es, r, sp;
    Real error = no_bound<Real>();  // the measured error of the table on this segment (+inf: not measured)
    std::size_t last_cost = 0;      // evaluations of its last seeding or refinement
    bool capped = false;            // a node's Newton solve ran out of its share
    bool retired = false;           // at its rounding floor: not refined further
    [[nodiscard]] std::size_t cells() const { return u.size() - 1; }
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
    if (cells_.empty())
      throw std::logic_error("parameterization: a table method needs the object built with a table method");
  }

  // The cell holding s (0 <= s <= L), as its index: floor(s / ds) on a one-segment table, by
  // bisection otherwise (the polish only, which costs 15 evaluations or more).
  [[nodiscard]] std::size_t cell_at(const Real& s) const { return uniform_ ? uniform_cell(s) : cell_by_search(s); }

  // One segment: its cells are equal in s, the cell is floor(s / ds), clamped to the table (t is
  // clamped in the cell).
  [[nodiscard]] std::size_t uniform_cell(const Real& s) const {
    const Real y = s * inv_ds_;
    return y > Real(0) ? std::min(to_index(y), cells_.size() - 1) : 0;
  }

  // The first cell that ends after s (the last one ends at +inf).
  [[nodiscard]] std::size_t cell_by_search(const Real& s) const {
    return static_cast<std::size_t>(
        std::partition_point(cells_.begin(), cells_.end(), [&s](const piece& p) { return !(s < p.s_end); }) -
        cells_.begin());
  }

  // The cell holding s (0 <= s <= L), for the query. On a table of many segments the two copies
  // bucket_cells_[b] and [b + 1] are read together (their addresses follow from s alone, so the two
  // loads overlap, where an index of cell numbers made the cell's load wait for the index's): the
  // first holds s when s is before its end, the second otherwise, wherever bucket b meets at most two
  // cells. The chosen cell is checked to hold s, so rounding at a bucket's ends or a bucket meeting
  // more cells (a short segment refined far more than its neighbours) falls back to the bisection.
  [[nodiscard]] const piece& piece_at(const Real& s) const {
    if (uniform_) return cells_[uniform_cell(s)];
    const Real x = s * inv_bucket_;
    const std::size_t b = x > Real(0) ? std::min(to_index(x), bucket_cells_.size() - 2) : 0;
    const piece& first = bucket_cells_[b];
    const piece& p = s < first.s_end ? first : bucket_cells_[b + 1];
    if (!(s < p.s_end) || s < p.s0) [[unlikely]]
      return cells_[cell_by_search(s)];
    return p;
  }

  // u on cell p at s: its cubic (hermite_table) or its chord (linear_table), t clamped to [0, 1].
  [[nodiscard]] static Real cell_value(const piece& p, const Real& s, inversion_method m) {
    Real t = (s - p.s0) * p.inv_w;
    if (t < Real(0)) t = Real(0);  // s in a segment too short for cells, or rounded across a node
    if (t > Real(1)) t = Real(1);
    return m == inversion_method::linear_table ? p.c.c0 + t * (p.u1 - p.c.c0) : p.c.eval(t);
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

  // The table value of u(s) (O(1)), polished when the options say so; evaluations are added to
  // `evaluations`.
  [[nodiscard]] Real table_u(const Real& s, inversion_method m, std::size_t& evaluations) const {
    if (!opt_.newton_polish) return cell_value(piece_at(s), s, m);
    const std::size_t j = cell_at(s);
    return polish(s, cell_value(cells_[j], s, m), j, evaluations);
  }

  // s(x) - s for x in cell j, integrated from the nearer cell end by one panel of the short-step
  // rule (detail::short_step_rule, G7-K15); err gets the panel's estimate |G - K| + rounding floor. The node's own
  // error (nodes_err_, a loose bound that includes the segment lengths' estimates) is left out: it biases r0 and r1
  // alike, and a step can only end as close to s as the node is, which the table value is no closer than.
  [[nodiscard]] Real cell_residual(const Real& s, const Real& x, std::size_t j, Real& err,
                                   std::size_t& evaluations) const {
    const gauss_kronrod_rule<Real>& rule = detail::short_step_rule<Real>();
    auto f = [this](const Real& v) { return speed(curve_, v); };
    const std::size_t k = cell_node_[j];
    const bool from_left = x - nodes_u_[k] <= nodes_u_[k + 1] - x;
    const kronrod_panel<Real> p = from_left ? rule.apply(f, nodes_u_[k], x) : rule.apply(f, x, nodes_u_[k + 1]);
    evaluations += p.evaluations;
    err = p.error_estimate;
    return from_left ? (nodes_s_[k] - s) + p.kronrod : (nodes_s_[k + 1] - s) - p.kronrod;
  }

  // The safeguarded Newton polish of the table value uu in cell j, whose bracket (its nodes' u)
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
    const std::size_t k = cell_node_[j];
    if (!(next >= nodes_u_[k] && next <= nodes_u_[k + 1])) return uu;
    const Real r1 = cell_residual(s, next, j, e1, evaluations);
    return abs(r1) + e1 < abs(r0) - e0 ? next : uu;
  }

  [[nodiscard]] std::size_t budget_left() const {
    const std::size_t spent = construction_evaluations();
    return opt_.max_evaluations > spent ? opt_.max_evaluations - spent : 0;
  }

  // The Newton options of one table node, `remaining` nodes (this one included) still to solve in
  // this step: its share of the budget left, never below min_node_evaluations.
  [[nodiscard]] newton_options<Real> node_options(std::size_t remaining) const {
    newton_options<Real> o = opt_.newton;
    o.final_step = true;  // nodes are interpolated by every query: polish them to rounding level
    const std::size_t left = budget_left();
    const std::size_t share = left > remaining ? (left - remaining) / remaining : 0;
    o.max_evaluations = std::min(o.max_evaluations, std::max(min_node_evaluations, share));
    return o;
  }

  // Segment i's first m cells: nodes at s_k = cum_i + k len_i / m, each by Newton from the previous
  // node (the nearest known point). Chained, the arc lengths are taken relative to the previous
  // node s_{k-1}: the bracket's lower end is the previous node's computed residual s(u_{k-1}) -
  // s_{k-1}, the target ds. Every sum is then of the size ds and rounds by ~eps ds; in absolute s
  // each node inherited the previous one's rounding of eps s, a random walk that grew like
  // sqrt(M) eps L (1.2e-14 L at M = 32768 on a 4-segment Catmull-Rom) and kept the automatic sizing
  // from ever meeting 32 eps L.
  segment_nodes seed_segment(std::size_t i, std::size_t m) {
    const auto p = segments_.parameters();
    const auto cum = segments_.cumulative();
    const auto err = segments_.cumulative_error();
    const Real tol = opt_.newton.relative_tolerance * length();
    const Real len = cum[i + 1] - cum[i];
    const std::size_t before = construction_evaluations();
    segment_nodes g;
    g.index = i;
    g.u.assign(m + 1, Real(0));
    g.s.assign(m + 1, Real(0));
    g.es.assign(m + 1, Real(0));
    g.r.assign(m + 1, Real(0));
    g.sp.assign(m + 1, Real(0));
    g.u[0] = p[i], g.s[0] = cum[i], g.es[0] = err[i];
    g.u[m] = p[i + 1], g.s[m] = cum[i + 1], g.es[m] = err[i + 1];
    g.sp[0] = segments_.start_speed(i);
    g.sp[m] = segments_.end_speed(i);
    for (std::size_t k = 1; k < m; ++k) {
      g.s[k] = cum[i] + len * Real(static_cast<long long>(k)) / Real(static_cast<long long>(m));
      // The ends' bounds (the cumulative lengths', which add up over the segments before) are added
      // to the node's afterwards, not handed to Newton: above the tolerance (1e5 segments) they kept
      // it from converging, 145 evaluations a node.
      newton_bracket<Real> br{p[i], cum[i], Real(0), p[i + 1], cum[i + 1], Real(0), segments_.guess(i, g.s[k])};
      Real target = g.s[k], inherited = std::max(err[i], err[i + 1]);
      if (k > 1 && g.u[k - 1] > br.u_lo && g.u[k - 1] < br.u_hi) {
        const Real base = g.s[k - 1];
        br.u_lo = g.u[k - 1];
        br.s_lo = g.r[k - 1];
        // The previous node's error bound is added to this node's afterwards, not handed to Newton:
        // summed along the chain it outgrows the tolerance near a segment's end, and Newton then
        // bisected to rounding (rounding_limited, 160 instead of 35 evaluations per node at
        // M = 65536 on the 4-segment Catmull-Rom).
        br.s_lo_error = Real(0);
        inherited = std::max(g.es[k - 1], err[i + 1]);  // Newton integrates from the nearer end
        br.s_hi = cum[i + 1] - base;
        target = g.s[k] - base;  // exact (Sterbenz) where s_k <= 2 s_{k-1}
      }
      const inversion_result<Real> r = newton_invert(curve_, target, br, tol, node_options(m - k));
      build_evaluations_ += r.evaluations;
      if (r.status == result_status::cap_hit) g.capped = true;
      g.u[k] = r.u;
      g.es[k] = r.s_error_estimate + inherited;
      g.r[k] = r.residual;
      g.sp[k] = speed(curve_, g.u[k]);
      ++build_evaluations_;
    }
    g.last_cost = construction_evaluations() - before;
    return g;
  }

  // The coarse table's value of u at s on the cell [k, k + 1] of g, by the method the table is
  // built for (its Hermite cubic or its chord).
  [[nodiscard]] Real coarse_u(const segment_nodes& g, std::size_t k, const Real& s, inversion_method m) const {
    const Real w = g.s[k + 1] - g.s[k];
    const Real t = (s - g.s[k]) / w;
    if (m == inversion_method::linear_table) return g.u[k] + t * (g.u[k + 1] - g.u[k]);
    return hermite_cubic(g.u[k], g.u[k + 1], g.sp[k], g.sp[k + 1], w).eval(t);
  }

  // Halves every cell of g: a node at each cell's midpoint in s, solved by Newton inside the cell
  // (relative to its left node, as the chain is), and g.error set to the coarse table's worst error
  // at those midpoints, |u_coarse - u| |P'|, plus the lookup's rounding (resolution): the table's
  // measured error on this segment.
  void refine_segment(segment_nodes& g) {
    using std::abs;
    using std::max;
    const std::size_t m = g.cells(), i = g.index;
    const Real tol = opt_.newton.relative_tolerance * length();
    const Real scale = segments_.parameters()[i + 1] - segments_.parameters()[i];
    const std::size_t before = construction_evaluations();
    segment_nodes f;
    f.index = i;
    f.u.resize(2 * m + 1), f.s.resize(2 * m + 1), f.es.resize(2 * m + 1), f.r.resize(2 * m + 1), f.sp.resize(2 * m + 1);
    Real worst(0);
    for (std::size_t k = 0; k < m; ++k) {
      const std::size_t a = 2 * k;
      f.u[a] = g.u[k], f.s[a] = g.s[k], f.es[a] = g.es[k], f.r[a] = g.r[k], f.sp[a] = g.sp[k];
      const Real len = g.s[k + 1] - g.s[k];
      const Real sm = g.s[k] + len / Real(2);
      const Real hermite = coarse_u(g, k, sm, inversion_method::hermite_table);
      // The ends' error bounds are added to the node's afterwards, not handed to Newton (as in
      // seed_segment): Newton integrates from the nearer end, whose bound the node inherits; handed
      // over, a bound above the tolerance kept it from converging (180 evaluations a node, not 35).
      newton_bracket<Real> br{g.u[k], g.r[k], Real(0), g.u[k + 1], len + g.r[k + 1], Real(0), hermite, scale};
      const inversion_result<Real> r = newton_invert(curve_, sm - g.s[k], br, tol, node_options(m - k));
      build_evaluations_ += r.evaluations;
      if (r.status == result_status::cap_hit) f.capped = true;
      f.u[a + 1] = r.u, f.s[a + 1] = sm, f.es[a + 1] = r.s_error_estimate + max(g.es[k], g.es[k + 1]);
      f.r[a + 1] = r.residual;
      f.sp[a + 1] = speed(curve_, r.u);
      ++build_evaluations_;
      const Real coarse =
          opt_.method == inversion_method::linear_table ? coarse_u(g, k, sm, inversion_method::linear_table) : hermite;
      worst = max(worst, Real(abs(coarse - r.u) * f.sp[a + 1]));
    }
    f.u[2 * m] = g.u[m], f.s[2 * m] = g.s[m], f.es[2 * m] = g.es[m], f.r[2 * m] = g.r[m], f.sp[2 * m] = g.sp[m];
    f.capped = f.capped || g.capped;
    // The lookup's own rounding is added: on a straight line the measured midpoint error was
    // 1.1e-16 L and the lookups were off by 4.4e-16 L.
    f.error = worst + resolution(f);
    f.last_cost = construction_evaluations() - before;
    g = std::move(f);
  }

  // What the table can resolve in arc length on g: 8 eps max|u| max|P'| (u is a Real: one ulp of u
  // moves s by |P'| ulp(u); the Hermite evaluation adds a few ulps). Far from 0 (a domain [1e8,
  // 1e8 + 1]) this is far above table_tolerance * L.
  [[nodiscard]] Real resolution(const segment_nodes& g) const {
    using std::abs;
    using std::max;
    Real top(0);
    for (const Real& v : g.sp) top = max(top, v);
    const Real umax = max(Real(abs(domain().lo)), Real(abs(domain().hi)));
    return Real(8) * epsilon<Real>() * umax * top;
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

  // The segments that get cells: those longer than detail::knot_gap_eps eps L in arc length. A
  // shorter one (a zero-length segment) has an ambiguous u(s): its arc-length position belongs to
  // the cells around it.
  [[nodiscard]] std::vector<std::size_t> tabled_segments() const {
    const auto cum = segments_.cumulative();
    const Real gap = Real(detail::knot_gap_eps) * epsilon<Real>() * length();
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i + 1 < cum.size(); ++i)
      if (cum[i + 1] - cum[i] > gap) out.push_back(i);
    return out;
  }

  // The most cells segment i can be given: none narrower than knot_gap_eps eps L (the s-grid must
  // stay strictly increasing in Real), at least one.
  [[nodiscard]] std::size_t cells_allowed(std::size_t i, std::size_t want) const {
    const auto cum = segments_.cumulative();
    const Real gap = Real(detail::knot_gap_eps) * epsilon<Real>() * length();
    const Real most = (cum[i + 1] - cum[i]) / gap;
    return most < Real(static_cast<long long>(want)) ? std::max<std::size_t>(1, to_index(most)) : want;
  }

  void build_table() {
    using std::ceil;
    using std::max;
    const Real len = length();
    std::vector<std::size_t> tabled = tabled_segments();
    if (tabled.empty()) tabled.push_back(0);  // unreachable for a length above the noise level; kept safe
    const auto cum = segments_.cumulative();
    std::vector<segment_nodes> segs;
    segs.reserve(tabled.size());
    if (opt_.table_intervals > 0) {
      // The caller's size, shared in proportion to the segments' lengths, ceil(M len_i / L) cells
      // each: no cell is wider than L / M. Not measured: no bound.
      for (const std::size_t i : tabled) {
        const Real want = ceil(Real(static_cast<long long>(opt_.table_intervals)) * (cum[i + 1] - cum[i]) / len);
        segs.push_back(seed_segment(i, cells_allowed(i, std::max<std::size_t>(1, to_index(want)))));
      }
      table_error_ = no_bound<Real>();
      table_status_ = result_status::not_guaranteed;
      table_reason_ = global_reason<Real>(reasons::table_size_given);
    } else {
      size_table(tabled, segs);
    }
    assemble(segs);
  }

  // The automatic size: every segment starts with m0 cells (16, fewer where the cap or the budget
  // could not pay for two per segment at that size), is halved once to measure it, and then the
  // segment whose measured error is largest is halved next (best first) until every segment's error
  // is below table_tolerance L, at its rounding floor, or the cap (max_table_intervals cells) or
  // the budget stops it. Each segment gets as many cells as its own error asks for: a many-segment
  // curve is not sized by its hardest segment.
  void size_table(const std::vector<std::size_t>& tabled, std::vector<segment_nodes>& segs) {
    using std::max;
    const Real target = opt_.table_tolerance * length();
    const std::size_t n = std::max<std::size_t>(1, tabled.size());
    std::size_t m0 = 16;
    while (m0 > 1 && (2 * m0 * n > opt_.max_table_intervals || 2 * m0 * n * min_node_evaluations > budget_left()))
      m0 /= 2;
    std::size_t cells = 0;
    for (const std::size_t i : tabled) {
      segs.push_back(seed_segment(i, cells_allowed(i, m0)));
      cells += segs.back().cells();
    }
    bool capped = false, unmeasured = false;
    // A refinement is started only when the cap and the budget allow it (its projected cost: twice
    // its last step's).
    auto affordable = [&](const segment_nodes& g) {
      return cells + g.cells() <= opt_.max_table_intervals && 2 * g.last_cost <= budget_left() && !g.capped;
    };
    auto can_halve = [&](const segment_nodes& g) { return 2 * g.cells() <= cells_allowed(g.index, 2 * g.cells()); };
    for (segment_nodes& g : segs) {
      if (!can_halve(g)) {
        g.retired = true;  // too short to halve: its cells are at the grid's resolution
        continue;
      }
      if (!affordable(g)) {
        unmeasured = true;
        capped = true;
        continue;
      }
      cells += g.cells();
      refine_segment(g);
    }
    const auto less = [&segs](std::size_t x, std::size_t y) { return segs[x].error < segs[y].error; };
    std::vector<std::size_t> heap;
    for (std::size_t k = 0; k < segs.size(); ++k)
      if (!segs[k].retired && is_finite(segs[k].error)) heap.push_back(k);
    std::make_heap(heap.begin(), heap.end(), less);
    while (!heap.empty()) {
      segment_nodes& g = segs[heap.front()];
      if (g.error <= target) break;  // the worst meets the target: every segment does
      std::pop_heap(heap.begin(), heap.end(), less);
      const std::size_t k = heap.back();
      heap.pop_back();
      if (g.error <= Real(2) * resolution(g) || !can_halve(g)) {  // the measured part is at rounding level
        g.retired = true;
        continue;
      }
      if (!affordable(g)) {
        capped = true;
        break;
      }
      cells += g.cells();
      refine_segment(g);
      heap.push_back(k);
      std::push_heap(heap.begin(), heap.end(), less);
    }
    Real worst(0), worst_node(0);
    bool any_capped_nodes = false, at_floor = false;
    const segment_nodes* worst_segment = nullptr;
    const segment_nodes* unmeasured_segment = nullptr;
    for (const segment_nodes& g : segs) {
      if (g.capped) {
        any_capped_nodes = true;
        for (const Real& e : g.es) worst_node = max(worst_node, e);
      }
      if (g.retired && g.error > target) at_floor = true;
      if (is_finite(g.error) && !(g.error <= worst)) worst = g.error, worst_segment = &g;
      if (!is_finite(g.error) && !g.retired && unmeasured_segment == nullptr) unmeasured_segment = &g;
    }
    const auto pu = segments_.parameters();
    auto reason_at = [&](std::string_view what, const segment_nodes* g, const Real& measured) {
      if (g == nullptr) return global_reason<Real>(what, measured, target);
      return segment_reason<Real>(what, g->index, pu[g->index], pu[g->index + 1], measured, target);
    };
    if (unmeasured || segs.empty()) {
      // A segment the cap or budget allowed no finer table to measure: no bound.
      table_error_ = no_bound<Real>();
      table_status_ = result_status::not_guaranteed;
      table_reason_ = reason_at(reasons::table_unmeasured, unmeasured_segment, Real(0));
      return;
    }
    table_error_ = any_capped_nodes ? worst + worst_node : worst;
    if (any_capped_nodes || (capped && worst > target)) {
      table_status_ = result_status::cap_hit;
      table_reason_ =
          reason_at(any_capped_nodes ? reasons::table_node_cap : reasons::table_cap, worst_segment, table_error_);
    } else if (worst <= target) {
      table_status_ = result_status::converged;
    } else {
      table_status_ = at_floor ? result_status::rounding_limited : result_status::cap_hit;
      table_reason_ = reason_at(at_floor ? reasons::table_at_resolution : reasons::table_cap, worst_segment, worst);
    }
  }

  // The table's cells and nodes from the segments' nodes (ascending), and, for a table of many
  // segments, the cells by bucket: 2 x cells equal buckets over [0, L], bucket b holding a copy of
  // the first cell that ends after its start, and one more bucket holding the last cell (see
  // piece_at).
  void assemble(std::vector<segment_nodes>& segs) {
    const Real none = std::numeric_limits<Real>::infinity();
    for (segment_nodes& g : segs) {
      // A segment's first node is the previous segment's last unless a segment without cells (too
      // short) lies between them.
      const bool shared = !nodes_u_.empty() && !(g.u[0] != nodes_u_.back());
      std::size_t first_node = shared ? nodes_u_.size() - 1 : nodes_u_.size();
      for (std::size_t k = shared ? 1 : 0; k < g.u.size(); ++k) {
        nodes_u_.push_back(g.u[k]);
        nodes_s_.push_back(g.s[k]);
        nodes_err_.push_back(g.es[k]);
      }
      for (std::size_t k = 0; k < g.cells(); ++k) {
        const Real w = g.s[k + 1] - g.s[k];
        cells_.push_back(piece{g.s[k], Real(1) / w, hermite_cubic(g.u[k], g.u[k + 1], g.sp[k], g.sp[k + 1], w),
                               g.s[k + 1], g.u[k + 1]});
        cell_node_.push_back(first_node + k);
      }
      std::vector<Real>().swap(g.u), std::vector<Real>().swap(g.s), std::vector<Real>().swap(g.es);
      std::vector<Real>().swap(g.r), std::vector<Real>().swap(g.sp);
    }
    // One segment with cells spanning [0, L] (the common single-segment curve): its cells are equal,
    // s_k = k L / m, and the cell of s is found without the index (its extra load cost a query 2 ns).
    uniform_ = segs.size() == 1 && cells_.front().s0 == Real(0) && cells_.back().s_end == length();
    inv_ds_ = Real(static_cast<long long>(cells_.size())) / length();
    cells_.back().s_end = none;
    if (uniform_) return;
    const std::size_t k = 2 * cells_.size();
    inv_bucket_ = Real(static_cast<long long>(k)) / length();
    bucket_cells_.reserve(k + 1);
    std::size_t j = 0;
    for (std::size_t b = 0; b < k; ++b) {
      const Real start = Real(static_cast<long long>(b)) / inv_bucket_;
      while (j + 1 < cells_.size() && !(cells_[j].s_end > start)) ++j;
      bucket_cells_.push_back(cells_[j]);
    }
    bucket_cells_.push_back(cells_.back());
  }

  C curve_;
  parameterization_options<Real> opt_;
  segment_lengths<Real> segments_;
  std::vector<Real> nodes_u_, nodes_s_, nodes_err_;
  std::vector<piece> cells_;
  std::vector<std::size_t> cell_node_;  // the node at each cell's start (its end is the next node)
  std::vector<piece> bucket_cells_;     // the cells by bucket, many segments only (see assemble)
  Real inv_bucket_{0};                  // buckets / L (bucket_cells_)
  Real inv_ds_{0};                      // cells / L: the cell of s when uniform_
  bool uniform_ = false;                // one segment has all the cells, equal in s from 0
  Real table_error_{0};
  Real size_{0}, noise_length_{0};
  result_status table_status_{result_status::not_guaranteed};
  status_reason<Real> table_reason_{};
  std::size_t build_evaluations_{0};
};

}  // namespace curvebench::arclength
