// ICR EKF (paper 001 section 3.1; docs/algorithms/skid_steer.md).
#include "plexus/algorithms/skid_steer/icr_ekf.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

namespace {
constexpr const char* kWhereIcrEkf = "icr_ekf";
constexpr double kDeg3 = 3.0 * std::numbers::pi / 180.0;

template <int N>
void require_diag(const char* name, const Eigen::Matrix<double, N, 1>& d, bool allow_zero) {
  for (int i = 0; i < N; ++i) {
    const std::string n = std::string(name) + "[" + std::to_string(i) + "]";
    if (allow_zero) {
      validation::require_non_negative(kWhereIcrEkf, n, d(i));
    } else {
      validation::require_positive(kWhereIcrEkf, n, d(i));
    }
  }
}
}  // namespace

ProcessNoiseModel process_noise_model_from_string(const std::string& name) {
  if (name == "dt_squared") return ProcessNoiseModel::kDtSquared;
  if (name == "continuous") return ProcessNoiseModel::kContinuous;
  if (name == "per_step") return ProcessNoiseModel::kPerStep;
  throw std::invalid_argument("icr_ekf: process_noise must be dt_squared, continuous or per_step (got '" + name + "')");
}

IcrVector IcrEkfParams::paper_q() {
  IcrVector q;
  q << 0.3 * 0.3, 0.3 * 0.3, kDeg3 * kDeg3, 0.01 * 0.01, 0.01 * 0.01, 0.01 * 0.01;  // eq. (21)
  return q;
}

Eigen::Vector3d IcrEkfParams::paper_r() { return {0.01 * 0.01, 0.01 * 0.01, kDeg3 * kDeg3}; }  // eq. (21)

IcrVector IcrEkfParams::paper_p_b() {
  IcrVector p;
  p << 0.3 * 0.3, 0.3 * 0.3, kDeg3 * kDeg3, 0.5 * 0.5, 0.5 * 0.5, 0.5 * 0.5;  // eq. (22)
  return p;
}

IcrEkf::IcrEkf(const IcrEkfParams& params) : params_(params) {
  require_diag("q_diag", params.q_diag, true);
  require_diag("r_diag", params.r_diag, false);
  require_diag("p0_diag", params.p0_diag, false);
  require_diag("p_b_diag", params.p_b_diag, false);
  validate_icr("icr_ekf: initial_icr", params.initial_icr);
  validation::require_positive(kWhereIcrEkf, "min_track_separation", params.min_track_separation);
  validation::require_non_negative(kWhereIcrEkf, "track_side_margin", params.track_side_margin);
  if (params.enforce_track_sides &&
      !(params.initial_icr.y_l >= params.track_side_margin && params.initial_icr.y_r <= -params.track_side_margin)) {
    throw std::invalid_argument(
        "icr_ekf: initial_icr must have y_l >= track_side_margin and y_r <= -track_side_margin "
        "when enforce_track_sides is on");
  }
  p0_ = params.p0_diag.asDiagonal();
  p_b_ = params.p_b_diag.asDiagonal();
  r_ = params.r_diag.asDiagonal();
  reset({});
}

void IcrEkf::reset(const Pose2& pose) {
  IcrVector x;
  x << pose.x, pose.y, pose.theta, params_.initial_icr.y_l, params_.initial_icr.y_r, params_.initial_icr.x_G;
  ekf_.reset(x, p0_);
}

void IcrEkf::reset_covariance_to_p_b() { ekf_.reset_covariance(p_b_); }

void IcrEkf::reset_to_prior(const IcrParams& icr, const Eigen::Vector3d& sd) {
  set_icrs(icr, sd, p_b_.topLeftCorner<3, 3>());
}

void IcrEkf::replace_icrs(const IcrParams& icr, const Eigen::Vector3d& sd) {
  set_icrs(icr, sd, ekf_.covariance().topLeftCorner<3, 3>());
}

void IcrEkf::set_icrs(const IcrParams& icr, const Eigen::Vector3d& sd, const Eigen::Matrix3d& pose_covariance) {
  IcrVector x = ekf_.state();
  x(3) = icr.y_l;
  x(4) = icr.y_r;
  x(5) = icr.x_G;
  IcrMatrix p = IcrMatrix::Zero();
  p.topLeftCorner<3, 3>() = pose_covariance;
  p.bottomRightCorner<3, 3>() = sd.cwiseProduct(sd).asDiagonal();
  ekf_.reset(x, p);
}

namespace {

/// The Euler transition's pose rows and the top three rows of its Jacobian (header
/// comment), from one evaluation of the body velocities and one sincos; the ICR rows of F
/// are the identity (random walks).
struct IcrStep {
  Eigen::Vector3d pose;
  Eigen::Matrix<double, 3, 6> F_top;
};

IcrStep icr_step(const IcrVector& x, const TrackSpeeds& u, double dt) {
  const double yl = x(3), yr = x(4), xg = x(5);
  const double d = yl - yr;
  const double dv = u.v_r - u.v_l;
  const double d2 = d * d;
  const BodyVelocity b = icr_body_velocity({yl, yr, xg}, u);
  const double c = std::cos(x(2)), s = std::sin(x(2));
  IcrStep out;
  out.pose = {x(0) + dt * (b.v_x * c - b.v_y * s), x(1) + dt * (b.v_x * s + b.v_y * c),
              x(2) + dt * b.omega};  // eq. (7)
  // Partial derivatives of the body velocities (header comment).
  const double dvx_dyl = -yr * dv / d2, dvx_dyr = yl * dv / d2;
  const double dvy_dyl = -xg * dv / d2, dvy_dyr = xg * dv / d2, dvy_dxg = dv / d;
  const double dw_dyl = -dv / d2, dw_dyr = dv / d2;
  auto& F = out.F_top;
  F.setZero();
  F(0, 0) = F(1, 1) = F(2, 2) = 1.0;
  F(0, 2) = -dt * (b.v_x * s + b.v_y * c);
  F(1, 2) = dt * (b.v_x * c - b.v_y * s);
  F(0, 3) = dt * (c * dvx_dyl - s * dvy_dyl);
  F(0, 4) = dt * (c * dvx_dyr - s * dvy_dyr);
  F(0, 5) = dt * (-s * dvy_dxg);
  F(1, 3) = dt * (s * dvx_dyl + c * dvy_dyl);
  F(1, 4) = dt * (s * dvx_dyr + c * dvy_dyr);
  F(1, 5) = dt * (c * dvy_dxg);
  F(2, 3) = dt * dw_dyl;
  F(2, 4) = dt * dw_dyr;
  return out;
}

}  // namespace

IcrVector IcrEkf::transition(const IcrVector& x, const TrackSpeeds& u, double dt) {
  IcrVector out = x;
  out.head<3>() = icr_step(x, u, dt).pose;
  return out;
}

IcrMatrix IcrEkf::jacobian(const IcrVector& x, const TrackSpeeds& u, double dt) {
  IcrMatrix F = IcrMatrix::Identity();
  F.topRows<3>() = icr_step(x, u, dt).F_top;
  return F;
}

bool IcrEkf::predict(const TrackSpeeds& u, double dt) {
  const IcrVector& x = ekf_.state();
  if (!(dt > 0.0) || !std::isfinite(dt) || !std::isfinite(u.v_l) || !std::isfinite(u.v_r) ||
      !(x(3) - x(4) > params_.min_track_separation)) {
    ++rejected_;
    return false;
  }
  double scale = 1.0;                                                           // L Q L^T with L = I * sqrt(scale)
  if (params_.process_noise == ProcessNoiseModel::kDtSquared) scale = dt * dt;  // eq. (12): L = I dt
  if (params_.process_noise == ProcessNoiseModel::kContinuous) scale = dt;
  const IcrVector q = scale * params_.q_diag;  // Q is diagonal
  const IcrStep step = icr_step(x, u, dt);
  IcrVector x_pred = x;
  x_pred.head<3>() = step.pose;
  // The ICR rows of F are the identity: the shared EKF's structured prediction (ekf.hpp).
  if (!ekf_.predict_partial<3>(x_pred, step.F_top, q)) {
    ++rejected_;
    return false;
  }
  return true;
}

bool IcrEkf::update(const Pose2& z) {
  // H = [I3 0] (eq. (14)): the pose is measured directly, the EKF's structured update.
  const Eigen::Vector3d zm(z.x, z.y, z.theta);
  if (!ekf_.update_segment<3>(zm, 0, r_, AngularMask{1u << 2})) return false;  // heading residual wrapped
  if (params_.enforce_track_sides) {
    const double m = params_.track_side_margin;
    if (ekf_.state()(3) < m || ekf_.state()(4) > -m) {
      IcrVector clamped = ekf_.state();
      clamped(3) = std::max(clamped(3), m);
      clamped(4) = std::min(clamped(4), -m);
      ekf_.reset(clamped, ekf_.covariance());
      ++clamps_;
    }
  }
  return true;
}

}  // namespace plexus::algorithms
