#include "harness/pool.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

namespace curvebench::harness {

unsigned pool_threads(unsigned requested, std::size_t jobs) {
  const unsigned wanted = requested ? requested : std::thread::hardware_concurrency();
  return std::max(1u, static_cast<unsigned>(std::min<std::size_t>(wanted, jobs)));
}

void run_pool(const std::vector<std::size_t>& order, unsigned threads, const std::function<void(std::size_t)>& job,
              const std::function<void(std::size_t, std::size_t)>& done) {
  std::atomic<std::size_t> next{0};
  std::size_t finished = 0;
  std::mutex lock;
  std::exception_ptr first_error;
  const auto worker = [&] {
    for (std::size_t i; (i = next.fetch_add(1)) < order.size();) {
      std::exception_ptr error;
      try {
        job(order[i]);
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard<std::mutex> guard(lock);
      if (error && !first_error) first_error = error;
      done(order[i], ++finished);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::max(1u, threads); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace curvebench::harness
