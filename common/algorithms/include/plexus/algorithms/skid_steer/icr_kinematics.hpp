// Skid-steer kinematics from the instantaneous centres of rotation (ICRs).
//
// Paper 001 (Wu et al. 2015, docs/papers.md), eqs. (3)-(5). In the body
// frame (x forward, y left) the left track, right track and body ICRs are y_l, y_r, x_G.
// With track speeds v_l, v_r:
//   v_x = (v_r y_l - v_l y_r) / (y_l - y_r)
//   v_y = (v_r - v_l) x_G / (y_l - y_r)
//   omega = (v_r - v_l) / (y_l - y_r)
//   X' = v_x cos(theta) - v_y sin(theta),  Y' = v_x sin(theta) + v_y cos(theta),  theta' = omega
// The no-slip (NS) model of a vehicle of track width B is y_l = B/2, y_r = -B/2, x_G = 0.
//
// icr_pose_step() integrates the pose exactly for body velocities held over the step (the
// body turns at a constant rate while its body-frame velocity is constant): the plant uses
// it. icr_euler_step() is the Euler discretisation the EKF's prediction uses (section 3.1).
#pragma once

#include <cmath>
#include <string_view>

#include "plexus/algorithms/core/angles.hpp"
#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

/// ICR coordinates in the body frame, m. Valid when finite and y_l > y_r.
struct IcrParams {
  double y_l = 0.2;   ///< left-track ICR, lateral coordinate, m
  double y_r = -0.2;  ///< right-track ICR, lateral coordinate, m
  double x_G = 0.0;   ///< body ICR, longitudinal coordinate, m
};

/// Throws std::invalid_argument naming `where` unless the ICRs are finite and y_l > y_r.
inline void validate_icr(std::string_view where, const IcrParams& icr) {
  validation::require_finite(where, "y_l", icr.y_l);
  validation::require_finite(where, "y_r", icr.y_r);
  validation::require_finite(where, "x_G", icr.x_G);
  if (!(icr.y_l > icr.y_r)) validation::fail(where, "y_l - y_r", "> 0 (y_l left of y_r)", icr.y_l - icr.y_r);
}

/// The no-slip model of a vehicle with track width `track_width` (> 0): (B/2, -B/2, 0).
inline IcrParams no_slip_icr(double track_width) {
  validation::require_positive("no_slip_icr", "track_width", track_width);
  return {0.5 * track_width, -0.5 * track_width, 0.0};
}

struct TrackSpeeds {
  double v_l = 0.0;  ///< left track speed, m/s
  double v_r = 0.0;  ///< right track speed, m/s
};

struct BodyVelocity {
  double v_x = 0.0;    ///< forward, m/s
  double v_y = 0.0;    ///< lateral (left), m/s
  double omega = 0.0;  ///< yaw rate, rad/s
};

struct Pose2 {
  double x = 0.0;      ///< m
  double y = 0.0;      ///< m
  double theta = 0.0;  ///< rad, continuous (not wrapped)
};

/// Paper 001 eqs. (3)-(5). Requires y_l != y_r.
inline BodyVelocity icr_body_velocity(const IcrParams& icr, const TrackSpeeds& u) {
  const double inv = 1.0 / (icr.y_l - icr.y_r);
  return {(u.v_r * icr.y_l - u.v_l * icr.y_r) * inv, (u.v_r - u.v_l) * icr.x_G * inv, (u.v_r - u.v_l) * inv};
}

/// Exact pose update over `h` s for body velocities held constant: the body-frame
/// displacement is (v_x, v_y) h integrated along an arc of turn omega h, evaluated at the
/// mid-heading with sinc (smooth through omega = 0).
inline Pose2 icr_pose_step(const Pose2& p, const BodyVelocity& b, double h) {
  const double half = 0.5 * b.omega * h;
  const double s = h * sinc(half);
  const double mid = p.theta + half;
  const double c = std::cos(mid), sn = std::sin(mid);
  return {p.x + s * (b.v_x * c - b.v_y * sn), p.y + s * (b.v_x * sn + b.v_y * c), p.theta + b.omega * h};
}

/// Euler step of the world-frame kinematics (paper 001 eq. (7) without noise).
inline Pose2 icr_euler_step(const Pose2& p, const BodyVelocity& b, double h) {
  const double c = std::cos(p.theta), s = std::sin(p.theta);
  return {p.x + h * (b.v_x * c - b.v_y * s), p.y + h * (b.v_x * s + b.v_y * c), p.theta + h * b.omega};
}

}  // namespace plexus::algorithms
