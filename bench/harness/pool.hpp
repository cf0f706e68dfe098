// The accuracy runner's worker pool: independent jobs (one case each) on a few threads.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace curvebench::harness {

/// The thread count for `jobs` jobs: `requested` (0: std::thread::hardware_concurrency()), at most
/// one per job, at least 1.
unsigned pool_threads(unsigned requested, std::size_t jobs);

/// Runs job(i) for every i of `order` on `threads` threads, each thread taking the next index of
/// `order` when it is free (put the longest jobs first to keep the threads busy to the end). After
/// each job, done(i, finished) is called under one lock (finished: jobs completed so far, this one
/// included), e.g. to print progress. An exception escaping a job is rethrown here after all
/// threads have joined (the first one; the other jobs still run).
void run_pool(const std::vector<std::size_t>& order, unsigned threads, const std::function<void(std::size_t)>& job,
              const std::function<void(std::size_t, std::size_t)>& done);

}  // namespace curvebench::harness
