#include "harness/records.hpp"

#include "harness/order_fit.hpp"

#include "curvebench/arclength/result.hpp"
#include "curvebench/core/error.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace curvebench::harness {

void record_sink::push(std::string_view quantity, std::string_view method, const std::string& setting, double error,
                       double estimate, double evaluations, std::string_view status) {
  records_.push_back(
      record::measured(case_.name, case_.group, quantity, method, setting, error, estimate, evaluations, status));
  series_.emplace_back(evaluations, error);
}

nlohmann::json record_sink::records() const {
  nlohmann::json out = nlohmann::json::array();
  for (const record& r : records_) out.push_back(to_json(r));
  return out;
}

void record_sink::add(const vocab::quantity& q, const vocab::method& m, const std::string& setting, double error,
                      double estimate, double evaluations, std::string_view status, std::string reason) {
  push(q.id, m.id, setting, error, estimate, evaluations, status);
  records_.back().reason = std::move(reason);
}

void record_sink::add_eval(std::string_view algorithm, double error, double evaluations) {
  push(vocab::quantities::eval.id, algorithm, std::string(), error, std::numeric_limits<double>::quiet_NaN(),
       evaluations, arclength::to_string(arclength::result_status::not_guaranteed));
}

void record_sink::annotate(const nlohmann::json& fields) {
  if (records_.empty()) throw invalid_input("record_sink::annotate: no record yet");
  for (const auto& [key, value] : fields.items()) records_.back().extra[key] = value;
}

void record_sink::end(const vocab::quantity& q, const vocab::method& m) {
  if (m.theory > 0) {
    const order_fit fit = fit_order(series_, order_floor, order_ceiling);
    if (std::isfinite(fit.order))
      orders_.push_back({{"case", case_.name},
                         {"group", case_.group},
                         {"quantity", std::string(q.id)},
                         {"method", std::string(m.id)},
                         {"observed", fit.order},
                         {"theory", m.theory},
                         {"points", fit.used},
                         {"excluded", fit.excluded}});
  }
  series_.clear();
}

}  // namespace curvebench::harness
