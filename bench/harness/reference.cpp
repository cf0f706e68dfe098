// The one translation unit that instantiates curve families at 50 digits (see reference.hpp).
#include "harness/reference.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <iomanip>
#include <limits>
#include <map>
#include <optional>
#include <queue>
#include <sstream>
#include <utility>
#include <vector>

namespace curvebench::harness {

template <int Dim>
struct case_reference<Dim>::impl {
  using curve_q = any_curve<real50, Dim>;
  explicit impl(const io::field& given)
      : ref(io::curve_from_spec<real50, Dim>(given)), L(ref.length()), spec(given.value) {}
  reference::reference_arc_length<curve_q> ref;
  real50 L;
  nlohmann::json spec;                         // for the double twin of nearest()'s scan
  std::optional<any_curve<double, Dim>> twin;  // built on nearest()'s first call
  // nearest()'s scan index, built with the twin: per segment the box of its samples and its
  // longest chord between neighbouring samples, and a tree of boxes over runs of segments.
  struct scan_box {
    point<double, Dim> lo, hi;
    double reach = 0;                 // the longest chord between neighbouring samples inside
    std::size_t first = 0, last = 0;  // the segments [first, last)
    std::size_t left = 0, right = 0;  // the children (a leaf: last == first + 1)
  };
  std::vector<scan_box> boxes;                          // the leaves (segment k at k), then the tree
  std::size_t scan_root = 0;                            // the index of the tree's root in boxes
  double scan_size = 0;                                 // the largest sampled coordinate magnitude
  std::vector<real50> s_ref;                            // s(u_j) of set_s_parameters
  std::map<double, std::pair<real50, real50>> anchors;  // target s -> (u, s(u))
  std::vector<point<real50, Dim>> exact;                // P(u_j) of set_eval_parameters
  real50 scale{1};
  std::vector<std::pair<double, real50>> s_cache;  // (u, s(u)) of cache_s, u increasing

  /// s(u): from cache_s's table when u is in it, else integrated from the reference's splits.
  [[nodiscard]] real50 s_at(double u) const {
    const auto it = std::lower_bound(s_cache.begin(), s_cache.end(), u,
                                     [](const std::pair<double, real50>& e, double x) { return e.first < x; });
    if (it != s_cache.end() && it->first == u) return it->second;
    return ref.s(real50(u));
  }
};

template <int Dim>
case_reference<Dim>::case_reference(const io::field& spec) : impl_(std::make_unique<impl>(spec)) {}

template <int Dim>
case_reference<Dim>::~case_reference() = default;

template <int Dim>
double case_reference<Dim>::length() const {
  return static_cast<double>(impl_->L);
}

template <int Dim>
std::string case_reference<Dim>::length_text() const {
  std::ostringstream os;
  os << std::setprecision(40) << impl_->L;
  return os.str();
}

template <int Dim>
double case_reference<Dim>::length_error() const {
  return static_cast<double>(impl_->ref.length_error() / impl_->L);
}

template <int Dim>
std::size_t case_reference<Dim>::speed_minima() const {
  return impl_->ref.speed_minima().size();
}

template <int Dim>
double case_reference<Dim>::length_error_of(double value) const {
  using std::abs;
  return static_cast<double>(abs(real50(value) - impl_->L) / impl_->L);
}

template <int Dim>
void case_reference<Dim>::set_s_parameters(std::span<const double> us) {
  impl_->s_ref.resize(us.size());
  for (std::size_t j = 0; j < us.size(); ++j) impl_->s_ref[j] = impl_->ref.s(real50(us[j]));
}

template <int Dim>
double case_reference<Dim>::s_error(std::size_t j, double value) const {
  using std::abs;
  if (j >= impl_->s_ref.size())
    throw invalid_input("case_reference::s_error: j = " + std::to_string(j) + " is not below the " +
                        std::to_string(impl_->s_ref.size()) + " parameters set");
  return static_cast<double>(abs(real50(value) - impl_->s_ref[j])) / static_cast<double>(impl_->L);
}

template <int Dim>
double case_reference<Dim>::ds(double u, double s) {
  using std::abs;
  const real50 uq(u);
  auto& anchors = impl_->anchors;
  const auto it = anchors.find(s);
  const real50 su =
      it == anchors.end() ? impl_->s_at(u) : it->second.second + impl_->ref.s_between(it->second.first, uq);
  if (it == anchors.end()) anchors.emplace(s, std::make_pair(uq, su));
  return static_cast<double>(abs(su - real50(s)) / impl_->L);
}

template <int Dim>
interval<double> case_reference<Dim>::domain() const {
  const interval<real50> d = impl_->ref.curve().domain();
  return {static_cast<double>(d.lo), static_cast<double>(d.hi)};
}

namespace {
template <int Dim>
point<real50, Dim> exact_at(const any_curve<real50, Dim>& c, double u, int order) {
  if (order < 0 || order > 3)
    throw invalid_input("case_reference: derivative order " + std::to_string(order) + " is not in 0..3");
  return order == 0 ? c(real50(u)) : c.derivative(real50(u), order);
}
}  // namespace

template <int Dim>
point<double, Dim> case_reference<Dim>::exact(double u, int order) const {
  const point<real50, Dim> q = exact_at(impl_->ref.curve(), u, order);
  point<double, Dim> p;
  for (int i = 0; i < Dim; ++i) p[i] = static_cast<double>(q[i]);
  return p;
}

template <int Dim>
double case_reference<Dim>::difference(double u, int order, const point<double, Dim>& p) const {
  using std::abs;
  const point<real50, Dim> q = exact_at(impl_->ref.curve(), u, order);
  real50 worst(0);
  for (int i = 0; i < Dim; ++i) worst = std::max(worst, real50(abs(real50(p[i]) - q[i])));
  return static_cast<double>(worst);
}

template <int Dim>
double case_reference<Dim>::length_between(double u0, double u1) const {
  return static_cast<double>(impl_->s_at(u1) - impl_->s_at(u0));
}

template <int Dim>
double case_reference<Dim>::length_between_error(double u0, double u1, double value) const {
  using std::abs;
  return static_cast<double>(abs(real50(value) - (impl_->s_at(u1) - impl_->s_at(u0))));
}

template <int Dim>
void case_reference<Dim>::cache_s(std::span<const double> us,
                                  const std::function<void(std::size_t, std::size_t)>& on_done) {
  std::vector<double> sorted(us.begin(), us.end());
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  auto& cache = impl_->s_cache;
  cache.clear();
  cache.reserve(sorted.size());
  for (const double u : sorted) {
    const real50 uq(u);
    cache.emplace_back(u, cache.empty() ? impl_->ref.s(uq)
                                        : cache.back().second + impl_->ref.s_between(real50(cache.back().first), uq));
    if (on_done) on_done(cache.size(), sorted.size());
  }
}

template <int Dim>
double case_reference<Dim>::distance_at_length(double s, const point<double, Dim>& q) const {
  using std::sqrt;
  // s may be the double nearest L, a rounding above it: that is the end.
  const point<real50, Dim> p = impl_->ref.curve()(impl_->ref.u(std::min(real50(s), impl_->L)));
  real50 d2(0);
  for (int i = 0; i < Dim; ++i) d2 += (real50(q[i]) - p[i]) * (real50(q[i]) - p[i]);
  return static_cast<double>(sqrt(d2));
}

template <int Dim>
typename case_reference<Dim>::nearest_point case_reference<Dim>::nearest(const point<double, Dim>& q,
                                                                         double s_hint) const {
  using std::abs, std::sqrt;
  const any_curve<real50, Dim>& c = impl_->ref.curve();
  // The scan runs on the double twin (a path of 1000 segments is 32000 samples a point), the polish
  // at 50 digits on the candidates the scan cannot rule out.
  if (!impl_->twin) impl_->twin = io::curve_from_spec<double, Dim>(io::field{impl_->spec, "spec"});
  const any_curve<double, Dim>& cd = *impl_->twin;
  point<real50, Dim> qq;
  for (int i = 0; i < Dim; ++i) qq[i] = real50(q[i]);
  // d2(u) on segment [a, b]: at b the limit from the left (the segment's own end).
  auto d2_at = [&](const real50& u, const real50& b) {
    const point<real50, Dim> p = u == b ? c.value_from_left(u) : c(u);
    return real50((p - qq).squaredNorm());
  };
  struct sampled {
    double lo, u, hi, a, b, dist;  // a local minimum of the sampled distance, its neighbours, its segment
    double reach;                  // the longer chord to a neighbour: how much closer the curve may come
    std::size_t segment;           // its segment's index
  };
  const std::span<const double> bp = cd.breakpoints();
  constexpr int samples = 32;
  std::array<double, samples + 1> us{}, ds{};
  std::array<point<double, Dim>, samples + 1> ps{};
  const auto sample = [&](std::size_t k) {
    const double a = bp[k], b = bp[k + 1];
    for (int j = 0; j <= samples; ++j) {
      us[j] = j == samples ? b : a + (b - a) * j / samples;
      ps[j] = j == samples ? cd.value_from_left(b) : cd(us[j]);
    }
  };
  using scan_box = typename impl::scan_box;
  auto& boxes = impl_->boxes;
  if (boxes.empty() && bp.size() >= 2) {
    // Leaves first (segment k at k), then the tree over runs of neighbouring segments: a path's
    // neighbours lie near each other, so a run's box is tight.
    const std::size_t n = bp.size() - 1;
    boxes.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      sample(k);
      scan_box& bx = boxes[k];
      bx.lo = bx.hi = ps[0];
      bx.first = k, bx.last = k + 1;
      for (int j = 0; j <= samples; ++j) {
        bx.lo = bx.lo.cwiseMin(ps[j]), bx.hi = bx.hi.cwiseMax(ps[j]);
        impl_->scan_size = std::max(impl_->scan_size, ps[j].cwiseAbs().maxCoeff());
        if (j > 0) bx.reach = std::max(bx.reach, safe_norm(point<double, Dim>(ps[j] - ps[j - 1])));
      }
    }
    const std::function<std::size_t(std::size_t, std::size_t)> build = [&](std::size_t first, std::size_t last) {
      if (last - first == 1) return first;
      const std::size_t mid = first + (last - first) / 2;
      const std::size_t l = build(first, mid), r = build(mid, last);
      scan_box bx;
      bx.lo = boxes[l].lo.cwiseMin(boxes[r].lo), bx.hi = boxes[l].hi.cwiseMax(boxes[r].hi);
      bx.reach = std::max(boxes[l].reach, boxes[r].reach);
      bx.first = first, bx.last = last, bx.left = l, bx.right = r;
      boxes.push_back(bx);
      return boxes.size() - 1;
    };
    impl_->scan_root = build(0, n);
  }
  const double size = impl_->scan_size;
  // The slack of the candidates' test below (keep), but for the best distance so far.
  const double slack = 1e-9 * static_cast<double>(impl_->L) +
                       1e3 * std::numeric_limits<double>::epsilon() * (size + q.cwiseAbs().maxCoeff());
  // How close a box's samples can come to q, less twice its reach (the test below): an under-
  // estimate (the distance to the box's nearest face, shrunk past its rounding).
  const auto bound = [&](const scan_box& bx) {
    point<double, Dim> gap;
    for (int i = 0; i < Dim; ++i) gap[i] = std::max({bx.lo[i] - q[i], q[i] - bx.hi[i], 0.0});
    return safe_norm(gap) * (1 - 1e-12) - 2 * bx.reach;
  };
  std::vector<sampled> minima;
  double best = std::numeric_limits<double>::infinity();
  std::size_t scanned = 0;
  // Best first over the tree: a box whose bound exceeds 2 best + slack holds no candidate (the
  // test below, whose best can only be smaller), and neither does any box popped after it.
  using entry = std::pair<double, std::size_t>;
  std::priority_queue<entry, std::vector<entry>, std::greater<>> open;
  if (!boxes.empty()) open.emplace(bound(boxes[impl_->scan_root]), impl_->scan_root);
  while (!open.empty()) {
    const auto [key, at] = open.top();
    open.pop();
    if (key > 2 * best + slack) break;
    const scan_box& bx = boxes[at];
    if (bx.last - bx.first > 1) {
      for (const std::size_t child : {bx.left, bx.right}) open.emplace(bound(boxes[child]), child);
      continue;
    }
    const std::size_t k = bx.first;
    ++scanned;
    sample(k);
    for (int j = 0; j <= samples; ++j) ds[j] = safe_norm(point<double, Dim>(ps[j] - q));
    for (int j = 0; j <= samples; ++j) {
      if ((j > 0 && ds[j] > ds[j - 1]) || (j < samples && ds[j] > ds[j + 1])) continue;  // not a local minimum
      const int lo = j > 0 ? j - 1 : 0, hi = j < samples ? j + 1 : samples;
      const double reach =
          std::max(safe_norm(point<double, Dim>(ps[lo] - ps[j])), safe_norm(point<double, Dim>(ps[hi] - ps[j])));
      minima.push_back({us[lo], us[j], us[hi], bp[k], bp[k + 1], ds[j], reach, k});
      best = std::min(best, ds[j]);
    }
  }
  // In the curve's order, as a scan of every segment would list them (ties below go to the first).
  std::stable_sort(minima.begin(), minima.end(),
                   [](const sampled& x, const sampled& y) { return x.segment < y.segment; });
  // Between samples the curve may come closer than a sampled minimum by about the chord to its
  // neighbour (twice that, for the arc's bulge): a minimum that close to twice the best, plus the
  // double rounding of the distances (the curve's size), stays a candidate.
  const double keep = 2 * best + slack;
  struct candidate {
    real50 u, d2;
  };
  std::vector<candidate> found;
  for (const sampled& m : minima) {
    if (m.dist - 2 * m.reach > keep) continue;
    const real50 a(m.a), b(m.b);
    // Safeguarded Newton on g(u) = (P - q) . P' inside [lo, hi], bisection where g' <= 0 or the step
    // leaves the bracket; g(lo) < 0 < g(hi) when the minimum is interior.
    real50 lo(m.lo), hi(m.hi);
    auto g = [&](const real50& u, real50& dg) {
      const point<real50, Dim> p = c(u), d1 = c.derivative(u, 1), d2 = c.derivative(u, 2);
      dg = d1.squaredNorm() + (p - qq).dot(d2);
      return real50((p - qq).dot(d1));
    };
    // At the segment's end b, g is taken just before it: there the curve may already be the next
    // segment's (a breakpoint belongs to the segment on its right).
    const real50 before_b = b - (b - a) * real50(1e-40);
    real50 dg(0);
    const real50 glo = g(lo, dg), ghi = g(hi < b ? hi : before_b, dg);
    real50 u(m.u);
    if (glo < 0 && ghi > 0) {
      for (int it = 0; it < 200 && hi - lo > real50(1e-45) * (abs(a) + abs(b) + 1); ++it) {
        const real50 gu = g(u, dg);
        if (gu == 0) break;
        (gu < 0 ? lo : hi) = u;
        real50 next = dg > 0 ? real50(u - gu / dg) : real50((lo + hi) / 2);
        if (!(next > lo && next < hi)) next = (lo + hi) / 2;
        if (abs(next - u) <= real50(1e-45) * (abs(u) + 1)) {
          u = next;
          break;
        }
        u = next;
      }
    }
    found.push_back({u, d2_at(u, b)});
  }
  real50 least = found.front().d2;
  for (const candidate& f : found) least = std::min(least, f.d2);
  // Branches about as close as the nearest one: the one whose s is nearest the hint.
  const real50 near = 2 * sqrt(least) + real50(1e-12) * impl_->L;
  const bool hinted = !std::isnan(s_hint);
  const candidate* pick = nullptr;
  real50 pick_s(0), pick_key(0);
  for (const candidate& f : found) {
    if (sqrt(f.d2) > near) continue;
    const real50 sf = impl_->ref.s(f.u);
    const real50 key = hinted ? real50(abs(sf - real50(s_hint))) : f.d2;
    if (pick == nullptr || key < pick_key) pick = &f, pick_s = sf, pick_key = key;
  }
  nearest_point r;
  r.u = static_cast<double>(pick->u);
  r.distance = static_cast<double>(sqrt(pick->d2));
  r.s = static_cast<double>(pick_s);
  r.ds = hinted ? static_cast<double>(abs(pick_s - real50(s_hint)) / impl_->L) : 0.0;
  r.scanned = scanned;
  return r;
}

template <int Dim>
void case_reference<Dim>::set_eval_parameters(std::span<const double> us) {
  using std::abs;
  impl_->exact.resize(us.size());
  real50 scale(0);
  for (std::size_t j = 0; j < us.size(); ++j) {
    impl_->exact[j] = impl_->ref.curve()(real50(us[j]));
    for (int i = 0; i < Dim; ++i) scale = std::max(scale, real50(abs(impl_->exact[j][i])));
  }
  impl_->scale = scale > 0 ? scale : real50(1);
}

template <int Dim>
double case_reference<Dim>::eval_error(std::span<const point<double, Dim>> p) const {
  using std::abs;
  if (p.size() != impl_->exact.size())
    throw invalid_input("case_reference::eval_error: " + std::to_string(p.size()) + " points for the " +
                        std::to_string(impl_->exact.size()) + " parameters set");
  real50 worst(0);
  for (std::size_t j = 0; j < p.size(); ++j)
    for (int i = 0; i < Dim; ++i) worst = std::max(worst, real50(abs(real50(p[j][i]) - impl_->exact[j][i])));
  return static_cast<double>(worst / (impl_->scale * real50(epsilon<double>())));
}

template class case_reference<1>;
template class case_reference<2>;
template class case_reference<3>;

}  // namespace curvebench::harness
