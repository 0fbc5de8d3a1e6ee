// parallel_runs.hpp (private): run(k) for k = 0 … count - 1 on up to `jobs` threads, each taking
// the next k as it finishes one. The first exception thrown stops the taking and is rethrown here
// once every thread has ended.
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace rodshape::sim_detail {

template <class Run>
void parallel_runs(int count, int jobs, const Run& run) {
  const int threads = std::max(1, std::min(jobs, count));
  if (threads == 1) {
    for (int k = 0; k < count; ++k) run(k);
    return;
  }
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  const auto work = [&] {
    for (int k = next++; k < count; k = next++) {
      try {
        run(k);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = count;  // stop taking runs
      }
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(work);
  work();
  for (std::thread& thread : pool) thread.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rodshape::sim_detail
