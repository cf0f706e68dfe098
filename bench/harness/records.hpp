// The records of one case and the orders fitted over its sweeps (formats: harness/gate.hpp; the
// record type and its JSON writer: harness/record.hpp).
// Quantities and methods are vocabulary objects (harness/vocabulary.hpp), settings come from
// harness/setting.hpp, statuses are result_status names (arclength/result.hpp): every id a record
// carries is declared once. Eval records name the evaluation algorithm (vocab::methods::eval_default
// or one of the family's algorithms), have the setting "" and the status "not_guaranteed" (an
// evaluation reports no error estimate of its own).
#pragma once

#include "harness/cases.hpp"
#include "harness/record.hpp"
#include "harness/vocabulary.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvebench::harness {

class record_sink {
 public:
  explicit record_sink(const case_info& info) : case_(info) {}

  /// One record of a method of the vocabulary. error and estimate are relative (see accuracy.hpp);
  /// estimate is NaN (or infinite) when the method gives none; status is a result_status name;
  /// reason why it is not converged (arclength::to_text of the result's reason), "" for none.
  void add(const vocab::quantity& q, const vocab::method& m, const std::string& setting, double error, double estimate,
           double evaluations, std::string_view status, std::string reason = {});
  /// One eval record of an evaluation algorithm (vocab::methods::eval_default.id or a family's).
  void add_eval(std::string_view algorithm, double error, double evaluations);

  /// Adds fields to the last record (a quantity's extra figures, named in its vocabulary doc).
  void annotate(const nlohmann::json& fields);

  /// Opens a series: forgets the (cost, error) points added so far.
  void begin() { series_.clear(); }
  /// Closes the series of method m: when m.theory > 0, records the order fitted over it, with the
  /// points fitted ("points") and those left out at the rounding floor ("excluded"), when at least
  /// 3 points spanning a factor 4 in cost are left (harness/order_fit.hpp). Then opens a new series.
  void end(const vocab::quantity& q, const vocab::method& m);

  /// The records as accuracy.json holds them (harness/record.hpp's writer).
  [[nodiscard]] nlohmann::json records() const;
  [[nodiscard]] const nlohmann::json& orders() const { return orders_; }

 private:
  void push(std::string_view quantity, std::string_view method, const std::string& setting, double error,
            double estimate, double evaluations, std::string_view status);
  const case_info& case_;
  std::vector<record> records_;
  nlohmann::json orders_ = nlohmann::json::array();
  std::vector<std::pair<double, double>> series_;  // (cost, error) of the open series
};

}  // namespace curvebench::harness
