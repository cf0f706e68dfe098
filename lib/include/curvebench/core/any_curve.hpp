// any_curve<Real, Dim>: a type-erased curve, for code that holds curves of different families
// side by side (the case suite, the command-line tool, the accuracy runner).
//
// It wraps any type satisfying `curvebench::curve` with the same Real and Dim, and itself
// satisfies the concept. Cost: one virtual call per evaluation (measured by the harness next to
// direct calls); copies share the immutable wrapped curve. Accuracy: exactly the wrapped curve's.
#pragma once

#include "curvebench/core/curve.hpp"

#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <utility>

namespace curvebench {

template <class Real, int Dim>
class any_curve {
 public:
  using real_type = Real;
  using point_type = point<Real, Dim>;
  static constexpr int dimension = Dim;

  template <class C>
  requires(!std::same_as<std::remove_cvref_t<C>, any_curve> && curve<std::remove_cvref_t<C>> &&
           std::same_as<typename std::remove_cvref_t<C>::real_type, Real> && std::remove_cvref_t<C>::dimension == Dim)
      any_curve(C&& c, std::string family = {})  // NOLINT(google-explicit-constructor): a wrapper, like std::function
      : self_(std::make_shared<model<std::remove_cvref_t<C>>>(std::forward<C>(c))), family_(std::move(family)) {}

  [[nodiscard]] interval<Real> domain() const { return self_->domain(); }
  [[nodiscard]] point_type operator()(const Real& u) const { return self_->value(u); }
  [[nodiscard]] point_type derivative(const Real& u, int order) const { return self_->derivative(u, order); }
  [[nodiscard]] std::span<const Real> breakpoints() const { return self_->breakpoints(); }
  /// The wrapped curve's curvebench::value_from_left(c, u) (core/curve.hpp): P(u-), c(u) for a
  /// continuous one.
  [[nodiscard]] point_type value_from_left(const Real& u) const { return self_->value_from_left(u); }
  /// The wrapped curve's curvebench::declared_rounding_bound(c, order) (core/curve.hpp).
  [[nodiscard]] Real rounding_bound(int order) const { return self_->rounding_bound(order); }
  /// The family name given at construction (may be empty).
  [[nodiscard]] const std::string& family() const { return family_; }

  /// The same curve (shared) under another family name.
  [[nodiscard]] any_curve renamed(std::string family) const {
    any_curve c = *this;
    c.family_ = std::move(family);
    return c;
  }

  /// The wrapped curve when it is a C, else nullptr.
  template <class C>
  [[nodiscard]] const C* target() const {
    auto* m = dynamic_cast<const model<C>*>(self_.get());
    return m ? &m->c : nullptr;
  }

 private:
  struct concept_base {
    virtual ~concept_base() = default;
    [[nodiscard]] virtual interval<Real> domain() const = 0;
    [[nodiscard]] virtual point_type value(const Real& u) const = 0;
    [[nodiscard]] virtual point_type derivative(const Real& u, int order) const = 0;
    [[nodiscard]] virtual std::span<const Real> breakpoints() const = 0;
    [[nodiscard]] virtual point_type value_from_left(const Real& u) const = 0;
    [[nodiscard]] virtual Real rounding_bound(int order) const = 0;
  };
  template <class C>
  struct model final : concept_base {
    explicit model(C curve_) : c(std::move(curve_)) {}
    [[nodiscard]] interval<Real> domain() const override { return c.domain(); }
    [[nodiscard]] point_type value(const Real& u) const override { return c(u); }
    [[nodiscard]] point_type derivative(const Real& u, int order) const override { return c.derivative(u, order); }
    [[nodiscard]] std::span<const Real> breakpoints() const override { return c.breakpoints(); }
    [[nodiscard]] point_type value_from_left(const Real& u) const override { return curvebench::value_from_left(c, u); }
    [[nodiscard]] Real rounding_bound(int order) const override {
      return curvebench::declared_rounding_bound(c, order);
    }
    C c;
  };

  std::shared_ptr<const concept_base> self_;
  std::string family_;
};

}  // namespace curvebench
