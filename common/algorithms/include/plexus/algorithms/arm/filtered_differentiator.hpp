// Filtered ("dirty") differentiator y = s w / (s + w) x, discretised with the bilinear
// (Tustin) transform at a fixed step h:
//   y_k = a y_{k-1} + b (x_k - x_{k-1}),   a = (2 - w h) / (2 + w h),  b = 2 w / (2 + w h).
// Paper 004 section 4 obtains q'' this way from the observed q' ("a differentiator with a
// low-pass filter"); the VDC controller also uses it for the time derivatives of required
// signals (docs/algorithms/arm.md). Vector-valued; no allocation after construction.
#pragma once

#include <cmath>
#include <numbers>

#include <Eigen/Core>

namespace plexus::algorithms {

class FilteredDifferentiator {
 public:
  FilteredDifferentiator() = default;
  /// size: vector length; cutoff_hz > 0; step: s, > 0 (the caller's fixed period).
  FilteredDifferentiator(int size, double cutoff_hz, double step) { configure(size, cutoff_hz, step); }

  void configure(int size, double cutoff_hz, double step) {
    const double w = 2.0 * std::numbers::pi * cutoff_hz;
    a_ = (2.0 - w * step) / (2.0 + w * step);
    b_ = 2.0 * w / (2.0 + w * step);
    prev_ = Eigen::VectorXd::Zero(size);
    out_ = Eigen::VectorXd::Zero(size);
    started_ = false;
  }
  /// Forgets the history: the next update() starts from derivative 0.
  void reset() {
    started_ = false;
    out_.setZero();
  }

  /// Feeds x_k; returns the filtered derivative estimate.
  const Eigen::VectorXd& update(const Eigen::VectorXd& x) {
    if (!started_) {
      prev_ = x;
      out_.setZero();
      started_ = true;
      return out_;
    }
    out_ = a_ * out_ + b_ * (x - prev_);
    prev_ = x;
    return out_;
  }
  const Eigen::VectorXd& value() const { return out_; }

 private:
  double a_ = 0.0, b_ = 0.0;
  Eigen::VectorXd prev_, out_;
  bool started_ = false;
};

}  // namespace plexus::algorithms
