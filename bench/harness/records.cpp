#include "harness/records.hpp"

#include "harness/order_fit.hpp"

#include "curvebench/arclength/result.hpp"
#include "curvebench/core/error.hpp"

#include <cmath>
#include <limits>

namespace curvebench::harness {

namespace {
nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(); }
}  // namespace

void record_sink::push(std::string_view quantity, std::string_view method, const std::string& setting, double error,
                       double estimate, double evaluations, std::string_view status) {
  nlohmann::json r{{"case", case_.name},
                   {"group", case_.group},
                   {"quantity", std::string(quantity)},
                   {"method", std::string(method)},
                   {"setting", setting},
                   {"error", finite_or_null(error)},
                   {"estimate", finite_or_null(estimate)},
                   {"evaluations", evaluations},
                   {"status", std::string(status)}};
  r["bounded"] = std::isfinite(estimate) && std::isfinite(error) ? nlohmann::json(estimate >= error) : nlohmann::json();
  records_.push_back(std::move(r));
  series_.emplace_back(evaluations, error);
}

void record_sink::add(const vocab::quantity& q, const vocab::method& m, const std::string& setting, double error,
                      double estimate, double evaluations, std::string_view status) {
  push(q.id, m.id, setting, error, estimate, evaluations, status);
}

void record_sink::add_eval(std::string_view algorithm, double error, double evaluations) {
  push(vocab::quantities::eval.id, algorithm, std::string(), error, std::numeric_limits<double>::quiet_NaN(),
       evaluations, arclength::to_string(arclength::result_status::not_guaranteed));
}

void record_sink::annotate(const nlohmann::json& fields) {
  if (records_.empty()) throw invalid_input("record_sink::annotate: no record yet");
  for (const auto& [key, value] : fields.items()) records_.back()[key] = value.is_number() ? finite_or_null(value.get<double>()) : value;
}

void record_sink::end(const vocab::quantity& q, const vocab::method& m) {
  if (m.theory > 0) {
    const double order = fit_order(series_, order_floor, order_ceiling);
    if (std::isfinite(order))
      orders_.push_back({{"case", case_.name},
                         {"group", case_.group},
                         {"quantity", std::string(q.id)},
                         {"method", std::string(m.id)},
                         {"observed", order},
                         {"theory", m.theory}});
  }
  series_.clear();
}

}  // namespace curvebench::harness
