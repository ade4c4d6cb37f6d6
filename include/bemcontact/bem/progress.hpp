#pragma once
// Progress of long phases, reported to whoever listens (the command line prints it on a
// terminal); the numerics never print.
#include <algorithm>
#include <functional>
#include <mutex>
#include <string>

#include "bemcontact/operators/progress.hpp"

namespace bemcontact::bem {

// phase name, fraction done in [0, 1]
using ProgressCallback = std::function<void(const std::string& phase, double fraction)>;

// One phase's reports to a ProgressCallback: increasing (a fraction not above the last one
// reported, from a slower thread say, is dropped), in steps of at least 1/1000 so that a
// listener is called a few hundred times whatever the source's rate, and 1 once, by
// finish(). Callable from several threads: the listener is called under a lock.
class PhaseProgress {
 public:
  PhaseProgress(const ProgressCallback& listener, std::string phase) : listener_(listener), phase_(std::move(phase)) {}
  explicit operator bool() const { return static_cast<bool>(listener_); }

  void report(double fraction) {
    if (!listener_) return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    std::lock_guard<std::mutex> lock(mutex_);
    if (fraction <= last_ || (fraction < 1.0 && last_ >= 0.0 && fraction < last_ + 1e-3)) return;
    last_ = fraction;
    listener_(phase_, fraction);
  }
  void start() { report(0.0); }
  void finish() { report(1.0); }
  // For the operators' layer (hierarchical matrices, LU), which knows no phase names; an
  // empty function when nobody listens, so the operator skips its bookkeeping.
  operators::FractionCallback fractions() {
    if (!listener_) return {};
    return [this](double fraction) { report(fraction); };
  }

 private:
  ProgressCallback listener_;
  std::string phase_;
  std::mutex mutex_;
  double last_ = -1.0;
};

}  // namespace bemcontact::bem
