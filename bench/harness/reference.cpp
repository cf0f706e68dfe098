// The one translation unit that instantiates curve families at 50 digits (see reference.hpp).
#include "harness/reference.hpp"

#include "curvebench/core/error.hpp"
#include "curvebench/io/spec.hpp"
#include "curvebench/reference/arc_length.hpp"
#include "curvebench/reference/multiprecision.hpp"

#include <algorithm>
#include <iomanip>
#include <map>
#include <sstream>
#include <utility>
#include <vector>

namespace curvebench::harness {

template <int Dim>
struct case_reference<Dim>::impl {
  using curve_q = any_curve<real50, Dim>;
  explicit impl(const io::field& spec) : ref(io::curve_from_spec<real50, Dim>(spec)), L(ref.length()) {}
  reference::reference_arc_length<curve_q> ref;
  real50 L;
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
