// Trajectory references for unicycle tracking (paper 000, section 6, eqs. (51)-(52)).
//
// A reference is sampled into a ReferenceSample (position, velocity, acceleration);
// the tracking controller consumes only samples, so any reference with known first
// and second derivatives can be used (paper 000, assumption 1).
#pragma once

#include <cmath>
#include <numbers>

#include <Eigen/Core>

namespace plexus::algorithms {

/// Reference position and its first two time derivatives at one instant.
struct ReferenceSample {
  Eigen::Vector2d p = Eigen::Vector2d::Zero();    ///< (x_r, y_r), m
  Eigen::Vector2d dp = Eigen::Vector2d::Zero();   ///< (x_r', y_r'), m/s
  Eigen::Vector2d ddp = Eigen::Vector2d::Zero();  ///< (x_r'', y_r''), m/s^2
};

struct FigureEightParams {
  double h1 = 5.0;   ///< m, amplitude (paper 000, section 6: 5), > 0
  double h2 = 0.02;  ///< rad/s, angular rate (paper 000: 0.02), > 0
  /// s, reference clock offset: the curve is evaluated at t + t0. The paper states
  /// (x_r(0), y_r(0)) = (0, -5), which eq. (51) reaches at h2 t = 3 pi / 2, so the
  /// default is paper_t0(0.02) = 75 pi s (our reading; docs/papers.md, paper 000).
  double t0 = 1.5 * std::numbers::pi / 0.02;

  /// t0 that starts the figure-eight at its bottom point (0, -h1): 3 pi / (2 h2).
  static double paper_t0(double h2) { return 1.5 * std::numbers::pi / h2; }
};

/// x_r = h1 sin(2 h2 (t + t0)),  y_r = h1 sin(h2 (t + t0))   (paper 000, eq. (51)
/// with the clock offset t0), derivatives as in eq. (52).
class FigureEightReference {
 public:
  /// Validates h1 > 0, h2 > 0, t0 finite; throws std::invalid_argument.
  explicit FigureEightReference(const FigureEightParams& params);

  /// Position, velocity and acceleration at time t (paper 000, eq. (52)).
  ReferenceSample sample(double t) const {
    const double h1 = params_.h1, h2 = params_.h2;
    const double a = h2 * (t + params_.t0);
    const double s1 = std::sin(a), c1 = std::cos(a);
    const double s2 = std::sin(2.0 * a), c2 = std::cos(2.0 * a);
    ReferenceSample r;
    r.p = {h1 * s2, h1 * s1};
    r.dp = {2.0 * h1 * h2 * c2, h1 * h2 * c1};
    r.ddp = {-4.0 * h1 * h2 * h2 * s2, -h1 * h2 * h2 * s1};
    return r;
  }

  /// Reference speed v_r(t) = h1 h2 sqrt(4 cos^2(2 h2 (t+t0)) + cos^2(h2 (t+t0)))  (eq. (52)).
  double speed(double t) const { return sample(t).dp.norm(); }

  /// v_rm = min_t v_r(t), analytic. With c = cos^2(h2 t), v_r^2 / (h1 h2)^2 = 16 c^2 - 15 c + 4,
  /// minimal at c = 15/32 (inside [0, 1]) where it equals 31/64: v_rm = h1 h2 sqrt(31) / 8
  /// (0.0696 m/s for h1 = 5, h2 = 0.02; docs/papers.md, paper 000).
  double min_speed() const { return params_.h1 * params_.h2 * std::sqrt(31.0) / 8.0; }

  /// v_rM = max_t v_r(t) = h1 h2 sqrt(5), at c = 1.
  double max_speed() const { return params_.h1 * params_.h2 * std::sqrt(5.0); }

  const FigureEightParams& params() const { return params_; }

 private:
  FigureEightParams params_;
};

}  // namespace plexus::algorithms
