// Two-wheeled self-balancing robot in the sagittal plane: a wheeled inverted pendulum
// (paper 002, section 3; Newton-Euler / Lagrange as in Grasser et al. 2002, the paper's
// ref. [10]). Derivation and parameter set: docs/algorithms/balancing.md.
//
// Coordinates: x, wheel-axle travel (m, forward positive); theta, body tilt from the
// vertical (rad, leaning forward positive). The motors apply T = T_L + T_R between body
// and wheels (wheels forward, body backward for T > 0). With
//   a = m_b + m_w + I_w / r^2,   b = m_b l,   c = I_b + m_b l^2
// the Lagrange equations are
//   a x''             + b cos(theta) theta'' - b sin(theta) theta'^2 = T / r
//   b cos(theta) x''  + c theta''            - b g sin(theta)        = -T
// and eliminating x'' gives the paper's eq. (10):
//   theta'' = (alpha2 sin(2 theta) theta'^2 + alpha3 sin(theta) + k_T (1 + alpha4 cos(theta)) T)
//             / (1 - alpha1 cos^2(theta))
// with alpha1 = b^2 / (a c), alpha2 = -b^2 / (2 a c), alpha3 = b g / c, alpha4 = b / (a r)
// and the torque gain k_T = -1 / c. (The paper prints the torque term without k_T: its
// torque is in units of -c rad/s^2; the coefficient is kept explicit here.)
// Linearised at theta = 0 (paper eq. (11)): theta'' = (alpha3 theta + k_T (1 + alpha4) T) / (1 - alpha1).
// The first equation gives the axle acceleration from theta'' (not in the paper; needed
// for what the accelerometer sees):
//   x'' = beta2 T + beta1 (sin(theta) theta'^2 - cos(theta) theta''),  beta1 = b / a, beta2 = 1 / (a r).
#pragma once

#include <Eigen/Core>

namespace plexus::algorithms {

/// Physical parameters (SI). Defaults: a small self-balancing robot of the HiBot's class
/// (the paper gives none; docs/algorithms/balancing.md states the choice).
struct WheeledPendulumParams {
  double body_mass = 3.0;          ///< m_b, kg, > 0
  double com_height = 0.12;        ///< l, axle to body centre of mass, m, > 0
  double body_inertia = 0.03;      ///< I_b, about the body's centre of mass (pitch), kg m^2, >= 0
  double wheel_mass = 0.6;         ///< m_w, both wheels, kg, >= 0
  double wheel_radius = 0.04;      ///< r, m, > 0
  double wheel_inertia = 0.00048;  ///< I_w, both wheels about the axle, kg m^2, >= 0
  double gravity = 9.81;           ///< g, m/s^2, > 0
  double max_torque = 4.0;         ///< |T_L + T_R| saturation, N m, > 0 (infinity: none)
};

/// The coefficients of the paper's eq. (10) derived from the physical parameters.
struct PendulumCoefficients {
  double alpha1 = 0.0;       ///< b^2 / (a c), in (0, 1)
  double alpha2 = 0.0;       ///< -b^2 / (2 a c)
  double alpha3 = 0.0;       ///< b g / c, 1/s^2
  double alpha4 = 0.0;       ///< b / (a r)
  double torque_gain = 0.0;  ///< k_T = -1 / c, 1/(kg m^2)
  double beta1 = 0.0;        ///< b / a, m
  double beta2 = 0.0;        ///< 1 / (a r), 1/(kg m)

  /// theta'' of eq. (10) at (theta, theta_dot) under total torque T.
  double tilt_acceleration(double theta, double theta_dot, double torque) const;
  /// theta'' of the linearised eq. (11).
  double linear_tilt_acceleration(double theta, double torque) const;
  /// x'' given theta'' (the wheel equation).
  double axle_acceleration(double theta, double theta_dot, double theta_ddot, double torque) const;
};

struct WheeledPendulumState {
  double x = 0.0;          ///< axle travel, m
  double v = 0.0;          ///< axle speed, m/s
  double theta = 0.0;      ///< tilt, rad
  double theta_dot = 0.0;  ///< tilt rate, rad/s
};

struct WheeledPendulumAccelerations {
  double x_ddot = 0.0;      ///< m/s^2
  double theta_ddot = 0.0;  ///< rad/s^2
};

class WheeledInvertedPendulum {
 public:
  /// Validates the parameters; throws std::invalid_argument naming the first bad one.
  explicit WheeledInvertedPendulum(const WheeledPendulumParams& params);

  /// Accelerations from the full 2x2 Lagrange equations (torque saturated).
  WheeledPendulumAccelerations accelerations(const WheeledPendulumState& s, double torque) const;

  /// Advances `s` by h seconds with the torque held (classical RK4 over `substeps`
  /// equal sub-steps). Returns the accelerations at the end of the step. No allocation.
  WheeledPendulumAccelerations step(WheeledPendulumState& s, double torque, double h, int substeps = 4) const;

  /// Torque after saturation.
  double saturate(double torque) const;

  const PendulumCoefficients& coefficients() const { return coeffs_; }
  const WheeledPendulumParams& params() const { return params_; }

  /// Linearisation at the upright equilibrium: d/dt [x, v, theta, theta_dot] = A s + B T.
  Eigen::Matrix4d linear_a() const;
  Eigen::Vector4d linear_b() const;

 private:
  WheeledPendulumParams params_;
  PendulumCoefficients coeffs_;
  double a_, b_, c_;
};

}  // namespace plexus::algorithms
