#pragma once
// Exceptions must not leave an OpenMP region (that would terminate the program): each
// iteration runs through ParallelErrors, which keeps the first exception and rethrows it
// after the loop.
#include <atomic>
#include <exception>
#include <mutex>

namespace bemcontact {

class ParallelErrors {
 public:
  template <class Body>
  void run(Body&& body) {
    try {
      body();
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!first_) first_ = std::current_exception();
      failed_ = true;
    }
  }
  bool failed() const { return failed_.load(std::memory_order_relaxed); }
  void rethrow() const {
    if (first_) std::rethrow_exception(first_);
  }

 private:
  std::mutex mutex_;
  std::exception_ptr first_;
  std::atomic<bool> failed_{false};
};

}  // namespace bemcontact
