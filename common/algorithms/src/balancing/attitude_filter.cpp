#include "plexus/algorithms/balancing/attitude_filter.hpp"

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {

constexpr const char* kWhereAttitudeFilter = "attitude_filter";

UkfOptions ukf_options(const AttitudeFilterParams& p) {
  UkfOptions o;
  o.sigma = p.sigma;
  return o;
}

const AttitudeFilterParams& validated(const AttitudeFilterParams& p) {
  validation::require_non_negative(kWhereAttitudeFilter, "q_theta", p.q_theta);
  validation::require_non_negative(kWhereAttitudeFilter, "q_rate", p.q_rate);
  validation::require_non_negative(kWhereAttitudeFilter, "q_drift", p.q_drift);
  validation::require_positive(kWhereAttitudeFilter, "r_tilt", p.r_tilt);
  validation::require_positive(kWhereAttitudeFilter, "r_gyro", p.r_gyro);
  validation::require_positive(kWhereAttitudeFilter, "initial_theta_std", p.initial_theta_std);
  validation::require_positive(kWhereAttitudeFilter, "initial_rate_std", p.initial_rate_std);
  validation::require_positive(kWhereAttitudeFilter, "initial_drift_std", p.initial_drift_std);
  // The UKF weights are validated (for their own L) by the filter constructors.
  return p;
}

}  // namespace

AttitudeFilter::AttitudeFilter(const AttitudeFilterParams& params)
    : params_(validated(params)),
      model_(params.model),
      aug1_(ukf_options(params)),
      aug2_(ukf_options(params)),
      add_(ukf_options(params)),
      ekf_() {
  Q_ = Eigen::Vector3d(params.q_theta * params.q_theta, params.q_rate * params.q_rate, params.q_drift * params.q_drift)
           .asDiagonal();
  reset(State::Zero());
}

void AttitudeFilter::reset(const State& x0) {
  const Eigen::Matrix3d P0 = Eigen::Vector3d(params_.initial_theta_std * params_.initial_theta_std,
                                             params_.initial_rate_std * params_.initial_rate_std,
                                             params_.initial_drift_std * params_.initial_drift_std)
                                 .asDiagonal();
  aug1_.reset(x0, P0);
  aug2_.reset(x0, P0);
  add_.reset(x0, P0);
  ekf_.reset(x0, P0);
  predicted_once_ = false;
}

bool AttitudeFilter::step(double torque, double acc_tilt, double gyro) {
  if (!std::isfinite(torque) || !std::isfinite(acc_tilt) || !std::isfinite(gyro)) return false;
  const bool paper = params_.measurement == AttitudeMeasurementForm::kPaper;
  const bool predict = predicted_once_;
  predicted_once_ = true;
  const double Ra = params_.r_tilt * params_.r_tilt, Rg = params_.r_gyro * params_.r_gyro;
  using V1 = Eigen::Matrix<double, 1, 1>;
  using V2 = Eigen::Vector2d;
  const AttitudeModel& m = model_;
  auto f_add = [&](const State& x) -> State { return m.predict(x, torque); };
  auto f_aug = [&](const State& x, const Eigen::Vector3d& w) -> State { return m.predict(x, torque) + w; };
  auto h1 = [](const State& x) -> V1 { return V1(x(0)); };
  auto h2 = [&](const State& x) -> V2 { return {m.accelerometer_tilt(x, torque), m.gyro(x)}; };
  const V1 z1(acc_tilt);
  const V2 z2(acc_tilt, gyro);

  switch (params_.kind) {
    case AttitudeFilterKind::kUkfAugmented:
      // The augmented form draws its points at predict time; with no predict yet (first
      // sample) it draws them with zero process noise around the prior.
      {
        const Eigen::Matrix3d Qk = predict ? Q_ : Eigen::Matrix3d::Zero();
        auto f = [&](const State& x, const Eigen::Vector3d& w) -> State {
          return predict ? f_aug(x, w) : State(x + w);
        };
        if (paper) {
          if (!aug1_.predict(f, Qk, V1(Ra))) return false;
          return aug1_.update<1>(z1, [&](const State& x, const V1& v) -> V1 { return h1(x) + v; });
        }
        if (!aug2_.predict(f, Qk, V2(Ra, Rg).asDiagonal().toDenseMatrix())) return false;
        return aug2_.update<2>(z2, [&](const State& x, const V2& v) -> V2 { return h2(x) + v; });
      }
    case AttitudeFilterKind::kUkfAdditive:
      if (predict && !add_.predict(f_add, Q_)) return false;
      return paper ? add_.update<1>(z1, h1, V1(Ra)) : add_.update<2>(z2, h2, V2(Ra, Rg).asDiagonal().toDenseMatrix());
    case AttitudeFilterKind::kEkf: {
      if (predict && !ekf_.predict(
                         [&](const State& x, Eigen::Matrix3d& F) -> State {
                           F = m.jacobian(x, torque);
                           return m.predict(x, torque);
                         },
                         Q_)) {
        return false;
      }
      if (paper) {
        return ekf_.update<1>(
            z1,
            [](const State& x, Eigen::Matrix<double, 1, 3>& H) -> V1 {
              H << 1.0, 0.0, 0.0;
              return V1(x(0));
            },
            V1(Ra));
      }
      return ekf_.update<2>(
          z2,
          [&](const State& x, Eigen::Matrix<double, 2, 3>& H) -> V2 {
            const double g = m.gyro_slope(x);
            H.row(0) = m.accelerometer_tilt_gradient(x, torque);
            H.row(1) << 0.0, g, g;
            return h2(x);
          },
          V2(Ra, Rg).asDiagonal().toDenseMatrix());
    }
  }
  return false;
}

bool AttitudeFilter::predict(double torque) {
  if (!std::isfinite(torque)) return false;
  if (!predicted_once_) return true;  // nothing to predict from yet
  const AttitudeModel& m = model_;
  const double Ra = params_.r_tilt * params_.r_tilt, Rg = params_.r_gyro * params_.r_gyro;
  switch (params_.kind) {
    case AttitudeFilterKind::kUkfAugmented: {
      // The points drawn here are drawn again by the next step()'s predict, from this estimate.
      auto f = [&](const State& x, const Eigen::Vector3d& w) -> State { return m.predict(x, torque) + w; };
      if (params_.measurement == AttitudeMeasurementForm::kPaper)
        return aug1_.predict(f, Q_, Eigen::Matrix<double, 1, 1>(Ra));
      return aug2_.predict(f, Q_, Eigen::Vector2d(Ra, Rg).asDiagonal().toDenseMatrix());
    }
    case AttitudeFilterKind::kUkfAdditive:
      return add_.predict([&](const State& x) -> State { return m.predict(x, torque); }, Q_);
    case AttitudeFilterKind::kEkf:
      return ekf_.predict(
          [&](const State& x, Eigen::Matrix3d& F) -> State {
            F = m.jacobian(x, torque);
            return m.predict(x, torque);
          },
          Q_);
  }
  return false;
}

const AttitudeFilter::State& AttitudeFilter::state() const {
  switch (params_.kind) {
    case AttitudeFilterKind::kUkfAugmented:
      return params_.measurement == AttitudeMeasurementForm::kPaper ? aug1_.state() : aug2_.state();
    case AttitudeFilterKind::kUkfAdditive: return add_.state();
    case AttitudeFilterKind::kEkf: break;
  }
  return ekf_.state();
}

const Eigen::Matrix3d& AttitudeFilter::covariance() const {
  switch (params_.kind) {
    case AttitudeFilterKind::kUkfAugmented:
      return params_.measurement == AttitudeMeasurementForm::kPaper ? aug1_.covariance() : aug2_.covariance();
    case AttitudeFilterKind::kUkfAdditive: return add_.covariance();
    case AttitudeFilterKind::kEkf: break;
  }
  return ekf_.covariance();
}

int AttitudeFilter::sigma_points() const {
  switch (params_.kind) {
    case AttitudeFilterKind::kUkfAugmented:
      return params_.measurement == AttitudeMeasurementForm::kPaper ? AugmentedUkf<3, 3, 1>::kSigmaPoints
                                                                    : AugmentedUkf<3, 3, 2>::kSigmaPoints;
    case AttitudeFilterKind::kUkfAdditive: return AdditiveUkf<3>::kSigmaPoints;
    case AttitudeFilterKind::kEkf: break;
  }
  return 0;
}

}  // namespace plexus::algorithms
