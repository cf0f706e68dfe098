// The fuzz targets' shared check (tests/fuzz/): runs one step of a target and sorts what it throws
// into documented refusals (returns false) and violations (aborts, see targets.hpp).
#pragma once

#include "targets.hpp"

#include "curvebench/core/error.hpp"

#include <exception>
#include <new>
#include <stdexcept>
#include <string>
#include <string_view>
#include <typeinfo>

namespace curvebench::fuzz {

/// Whether a documented exception's message is one a user can read: not empty, bounded.
inline void check_message(std::string_view target, std::string_view step, const char* what) {
  const std::string_view m(what);
  if (m.empty()) violation(target, "clear error", std::string(step) + ": an exception with an empty message");
  if (m.size() > max_message)
    violation(target, "bounded error message",
              std::string(step) + ": a message of " + std::to_string(m.size()) + " bytes (at most " +
                  std::to_string(max_message) + "), starting " + std::string(m.substr(0, 200)));
}

/// Where std::domain_error is a documented refusal of the step (a parameter the caller gave outside
/// a domain), or a violation (the target only asks for parameters inside the domain, so a
/// domain_error there is an internal error reaching the user).
enum class domain_errors { refusal, violation };

/// Runs f(); true when it returned, false when it threw invalid_input (io::spec_error included) or,
/// where allowed, std::domain_error. Any other exception is a violation naming its type and `step`.
template <class F>
bool run_step(std::string_view target, std::string_view step, domain_errors domain, F&& f) {
  try {
    f();
    return true;
  } catch (const invalid_input& e) {
    check_message(target, step, e.what());
  } catch (const std::domain_error& e) {
    if (domain == domain_errors::violation)
      violation(target, "no internal domain error",
                std::string(step) + ": std::domain_error for a request inside the domain: " + e.what());
    check_message(target, step, e.what());
  } catch (const std::bad_alloc& e) {
    violation(target, "documented exceptions only", std::string(step) + ": std::bad_alloc (" + e.what() + ")");
  } catch (const std::exception& e) {
    violation(
        target, "documented exceptions only",
        std::string(step) + ": " + typeid(e).name() + ": " + std::string(std::string_view(e.what()).substr(0, 300)));
  } catch (...) {
    violation(target, "documented exceptions only", std::string(step) + ": a non-std exception");
  }
  return false;
}

}  // namespace curvebench::fuzz
