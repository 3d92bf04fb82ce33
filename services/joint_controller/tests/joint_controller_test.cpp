// joint_controller: arm_ct_pd, arm_vdc (controllers) and arm_ekf (estimator) of paper 004.
// JointReference + LinkJointState in -> edge check -> control law -> JointCommand out;
// JointState + JointCommand in -> edge check -> EKF update -> LinkJointState out.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "plexus/algorithms/arm/ct_pd_controller.hpp"
#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"
#include "plexus/algorithms/arm/rigid_body_dynamics.hpp"
#include "plexus/algorithms/arm/vdc_controller.hpp"
#include "service_harness.hpp"

namespace plexus::services_test {
namespace {

// The component types of services/joint_controller/ whose data path this file tests.
const Covers kCovers{"arm_ct_pd", "arm_vdc", "arm_ekf"};

namespace alg = plexus::algorithms;
using Eigen::Vector2d;

msg::JointReference joint_reference(const ServiceUnderTest& s, int64_t k, Vector2d q, Vector2d dq, Vector2d ddq,
                                    Vector2d dddq) {
  auto m = s.stamped<msg::JointReference>(k);
  m.count(2);
  for (int i = 0; i < 2; ++i) {
    m.position()[i] = q(i), m.velocity()[i] = dq(i), m.acceleration()[i] = ddq(i), m.jerk()[i] = dddq(i);
  }
  return m;
}

struct Estimate {
  Vector2d q{0, 0}, dq{0, 0}, ddq{0, 0}, dddq{0, 0}, tau{0, 0}, dtau{0, 0}, phi{0, 0}, dphi{0, 0};
};

msg::LinkJointState link_state(const ServiceUnderTest& s, int64_t k, const Estimate& e) {
  auto m = s.stamped<msg::LinkJointState>(k);
  m.count(2);
  for (int i = 0; i < 2; ++i) {
    m.position()[i] = e.q(i), m.velocity()[i] = e.dq(i), m.acceleration()[i] = e.ddq(i), m.jerk()[i] = e.dddq(i);
    m.torque()[i] = e.tau(i), m.torque_rate()[i] = e.dtau(i);
    m.motor_position()[i] = e.phi(i), m.motor_velocity()[i] = e.dphi(i);
  }
  return m;
}

alg::ArmFeedback feedback_of(const Estimate& e) { return {e.q, e.dq, e.ddq, e.tau, e.dtau, e.phi, e.dphi, e.dddq}; }

alg::ArmReferenceSample reference_of(Vector2d q, Vector2d dq, Vector2d ddq, Vector2d dddq) {
  return {q, dq, ddq, dddq};
}

// A reference and an estimate that move with k (the controllers' inputs of one run).
Estimate estimate_at(int64_t k) {
  const double t = 0.001 * static_cast<double>(k);
  Estimate e;
  e.q = {0.1 + 0.2 * t, -0.1 + t};
  e.dq = {0.2, 1.0};
  e.ddq = {0.0, -0.5};
  e.tau = {30.0, 5.0};
  e.dtau = {1.0, -2.0};
  e.phi = e.q + e.tau / 1e4;
  e.dphi = e.dq + e.dtau / 1e4;
  return e;
}

void feed_controller(ServiceUnderTest& s, int64_t k) {
  const double t = 0.001 * static_cast<double>(k);
  ASSERT_EQ(s.deliver("r4/reference", joint_reference(s, k, {0.12 + t, -0.08}, {0.3, 0.9}, {0.1, -0.4}, {0.0, 0.2})),
            Rejection::none);
  ASSERT_EQ(s.deliver("r4/estimate", link_state(s, k, estimate_at(k))), Rejection::none);
}

std::vector<BadSample> bad_controller_inputs() {
  return {
      {"reference jerk 1e11 rad/s^3",
       [](ServiceUnderTest& s, int64_t k) {
         return s.deliver("r4/reference", joint_reference(s, k, {0, 0}, {0, 0}, {0, 0}, {0, 1e11}));
       },
       Rejection::out_of_range},
      {"reference for 3 joints",
       [](ServiceUnderTest& s, int64_t k) {
         auto m = joint_reference(s, k, {0, 0}, {0, 0}, {0, 0}, {0, 0});
         m.count(3);
         return s.deliver("r4/reference", m);
       },
       Rejection::wrong_count},
      {"estimate torque NaN",
       [](ServiceUnderTest& s, int64_t k) {
         Estimate e = estimate_at(k);
         e.tau(1) = kNaN;
         return s.deliver("r4/estimate", link_state(s, k, e));
       },
       Rejection::non_finite},
      {"estimate for 17 joints",
       [](ServiceUnderTest& s, int64_t k) {
         auto m = link_state(s, k, estimate_at(k));
         m.count(17);
         return s.deliver("r4/estimate", m);
       },
       Rejection::wrong_count},
      {"estimate before the epoch",
       [](ServiceUnderTest& s, int64_t) { return s.deliver("r4/estimate", link_state(s, -2, estimate_at(0))); },
       Rejection::negative_time},
  };
}

// --- arm_ct_pd --------------------------------------------------------------------------

const std::string kCtPd = R"(name: ctl_part
step: 0.001
services:
  ctl: {type: arm_ct_pd, robot: r4}
)";

TEST(ArmCtPd, ZeroCommandUntilBothInputsExist) {
  ServiceUnderTest s(kCtPd);
  EXPECT_EQ(s.message_type("r4/reference"), "JointReference");
  EXPECT_EQ(s.message_type("r4/estimate"), "LinkJointState");
  s.deliver("r4/reference", joint_reference(s, 0, {0.1, 0.1}, {0, 0}, {0, 0}, {0, 0}));
  s.step(0);
  const auto m = s.published<msg::JointCommand>("r4/cmd");
  EXPECT_EQ(m.count(), 2);
  EXPECT_EQ(m.effort()[0], 0.0);
  EXPECT_EQ(m.effort()[1], 0.0);
}

TEST(ArmCtPd, HangingArmIsPurePdByHand) {
  // At q = q' = 0 the arm hangs along gravity ([9.81, 0, 0]): G = 0, C q' = 0, and with
  // q_d'' = 0, phi' = 0, eq. (60) (motor velocity) is u = K_p q_d + K_v q_d', with the
  // paper's K_p = diag(1900, 500), K_v = diag(500, 150):
  // u = (1900 0.01 + 500 0.1, 500 (-0.02) + 150 0.2) = (69, 20).
  ServiceUnderTest s(kCtPd);
  s.deliver("r4/reference", joint_reference(s, 0, {0.01, -0.02}, {0.1, 0.2}, {0, 0}, {0, 0}));
  s.deliver("r4/estimate", link_state(s, 0, Estimate{}));
  s.step(0);
  const auto m = s.published<msg::JointCommand>("r4/cmd");
  EXPECT_NEAR(m.effort()[0], 69.0, 1e-9);
  EXPECT_NEAR(m.effort()[1], 20.0, 1e-9);
  EXPECT_EQ(s.check_output("r4/cmd"), Rejection::none);
}

TEST(ArmCtPd, MatchesTheAlgorithm) {
  ServiceUnderTest s(kCtPd);
  alg::CtPdParams p = alg::CtPdParams::paper_2dof();
  p.velocity = alg::CtPdVelocity::kMotor;  // the service's default
  alg::CtPdController ref(p);
  for (int64_t k = 0; k < 3; ++k) {
    feed_controller(s, k);
    s.step(k);
    const double t = 0.001 * static_cast<double>(k);
    const auto& u =
        ref.step(reference_of({0.12 + t, -0.08}, {0.3, 0.9}, {0.1, -0.4}, {0.0, 0.2}), feedback_of(estimate_at(k)));
    EXPECT_NEAR(s.out("r4/cmd", "u1"), u(0), 1e-9 * std::abs(u(0)) + 1e-12) << k;
    EXPECT_NEAR(s.out("r4/cmd", "u2"), u(1), 1e-9 * std::abs(u(1)) + 1e-12) << k;
  }
  EXPECT_GT(std::abs(s.out("r4/cmd", "u1")), 1.0);
}

TEST(ArmCtPd, BadSamplesAreRefusedAndLeaveTheCommandAlone) {
  expect_refused_without_effect(kCtPd, {}, {"r4/cmd"}, 6, 3, feed_controller, bad_controller_inputs());
}

TEST(ArmCtPd, BadParametersAreConfigurationErrors) {
  expect_config_errors(kCtPd, {
                                  {"services.ctl.k_p=[1900]", {"services.ctl.k_p", "2 numbers"}},
                                  {"services.ctl.k_v=[-1, 1]", {"services.ctl", "k_v"}},
                                  {"services.ctl.velocity=both", {"services.ctl.velocity"}},
                                  {"services.ctl.model=paper_3dof", {"services.ctl.model"}},
                                  {"services.ctl.stiffness=[0, 1e4]", {"services.ctl", "stiffness"}},
                              });
}

// --- arm_vdc ----------------------------------------------------------------------------

// `tuning: paper`: eqs. (18)-(23) as printed, VdcParams::paper_2dof(); the default (robust)
// is checked by ArmVdc.DefaultIsTheRobustTuning.
const std::string kVdc = R"(name: ctl_part
step: 0.001
services:
  ctl: {type: arm_vdc, robot: r4, tuning: paper}
)";

TEST(ArmVdc, MatchesTheAlgorithmStepByStep) {
  // VDC adapts (theta^, t_s): three steps in a row, each against the algorithm.
  ServiceUnderTest s(kVdc);
  alg::VdcParams p = alg::VdcParams::paper_2dof();
  p.step = 0.001;
  alg::VdcController ref(p);
  for (int64_t k = 0; k < 3; ++k) {
    feed_controller(s, k);
    s.step(k);
    const double t = 0.001 * static_cast<double>(k);
    const auto& u =
        ref.step(reference_of({0.12 + t, -0.08}, {0.3, 0.9}, {0.1, -0.4}, {0.0, 0.2}), feedback_of(estimate_at(k)));
    const auto m = s.published<msg::JointCommand>("r4/cmd");
    EXPECT_NEAR(m.effort()[0], u(0), 1e-9 * std::abs(u(0)) + 1e-12) << k;
    EXPECT_NEAR(m.effort()[1], u(1), 1e-9 * std::abs(u(1)) + 1e-12) << k;
  }
  EXPECT_GT(std::abs(s.out("r4/cmd", "u1")), 1.0);
}

TEST(ArmVdc, DefaultIsTheRobustTuning) {
  // Without `tuning`, the controller feeds half of the observer's model residual forward
  // (issue 18; docs/algorithms/arm.md "Model error").
  ServiceUnderTest s(R"(name: ctl_part
step: 0.001
services:
  ctl: {type: arm_vdc, robot: r4}
)");
  alg::VdcParams p = alg::VdcParams::paper_2dof();
  p.step = 0.001;
  p.disturbance_compensation = alg::VdcParams::kRobustDisturbanceCompensation;
  alg::VdcController ref(p), paper(alg::VdcParams::paper_2dof());
  for (int64_t k = 0; k < 3; ++k) {
    feed_controller(s, k);
    s.step(k);
    const double t = 0.001 * static_cast<double>(k);
    const auto sample = reference_of({0.12 + t, -0.08}, {0.3, 0.9}, {0.1, -0.4}, {0.0, 0.2});
    const auto& u = ref.step(sample, feedback_of(estimate_at(k)));
    const auto& u_paper = paper.step(sample, feedback_of(estimate_at(k)));
    const auto m = s.published<msg::JointCommand>("r4/cmd");
    EXPECT_NEAR(m.effort()[0], u(0), 1e-9 * std::abs(u(0)) + 1e-12) << k;
    EXPECT_NEAR(m.effort()[1], u(1), 1e-9 * std::abs(u(1)) + 1e-12) << k;
    EXPECT_GT(std::abs(u(0) - u_paper(0)), 1e-6) << k;  // the compensation is on
  }
}

TEST(ArmVdc, CommandOutOfRangeIsZeroAndRestartsTheController) {
  // An estimate inside LinkJointState's range but moving at 1e4 rad/s asks for torques far
  // beyond JointCommand's 1e7 N m: the controller publishes zero torque instead, and
  // restarts, so that its next command is the fresh algorithm's on the same inputs.
  ServiceUnderTest s(kVdc);
  feed_controller(s, 0);
  s.step(0);
  Estimate wild = estimate_at(1);
  wild.dq = {1e4, -1e4};
  wild.dphi = wild.dq;
  wild.ddq = {1e7, 1e7};
  ASSERT_EQ(s.deliver("r4/reference", joint_reference(s, 1, {0.12, -0.08}, {0.3, 0.9}, {0.1, -0.4}, {0.0, 0.2})),
            Rejection::none);
  ASSERT_EQ(s.deliver("r4/estimate", link_state(s, 1, wild)), Rejection::none);
  s.step(1);
  EXPECT_EQ(s.out("r4/cmd", "u1"), 0.0);
  EXPECT_EQ(s.out("r4/cmd", "u2"), 0.0);
  alg::VdcParams p = alg::VdcParams::paper_2dof();
  p.step = 0.001;
  alg::VdcController fresh(p), unreset(p);
  (void)unreset.step(reference_of({0.12, -0.08}, {0.3, 0.9}, {0.1, -0.4}, {0.0, 0.2}), feedback_of(estimate_at(0)));
  feed_controller(s, 2);
  s.step(2);
  const auto sample = reference_of({0.122, -0.08}, {0.3, 0.9}, {0.1, -0.4}, {0.0, 0.2});
  const auto& u = fresh.step(sample, feedback_of(estimate_at(2)));
  const auto& u_unreset = unreset.step(sample, feedback_of(estimate_at(2)));
  EXPECT_NEAR(s.out("r4/cmd", "u1"), u(0), 1e-9 * std::abs(u(0)) + 1e-12);
  EXPECT_NEAR(s.out("r4/cmd", "u2"), u(1), 1e-9 * std::abs(u(1)) + 1e-12);
  EXPECT_GT(std::abs(u(0) - u_unreset(0)), 1e-9);  // the restart is what makes it match
}

TEST(ArmVdc, BadSamplesAreRefusedAndLeaveTheCommandAlone) {
  expect_refused_without_effect(kVdc, {}, {"r4/cmd"}, 6, 3, feed_controller, bad_controller_inputs());
}

TEST(ArmVdc, BadParametersAreConfigurationErrors) {
  expect_config_errors(kVdc, {
                                 {"services.ctl.k_b=[1, 2, 3]", {"services.ctl.k_b", "2 numbers"}},
                                 {"services.ctl.theta_lower=2", {"services.ctl", "theta"}},
                                 {"services.ctl.rho=[-1, 1]", {"services.ctl", "rho"}},
                             });
  EXPECT_EQ(config_error(kVdc, {"services.ctl.model=uniform"}), "no error");
}

// --- arm_ekf ----------------------------------------------------------------------------

// `tuning: paper`: Q = 4 I, no model-error states (FlexibleJointEkfParams{}); the default
// (robust) is checked by ArmEkf.DefaultIsTheRobustTuning.
const std::string kEkf = R"(name: ekf_part
step: 0.001
services:
  ekf: {type: arm_ekf, robot: r4, tuning: paper}
)";

msg::JointState encoders(const ServiceUnderTest& s, int64_t k, Vector2d phi, Vector2d dphi) {
  auto m = s.stamped<msg::JointState>(k);
  m.count(2);
  for (int i = 0; i < 2; ++i) m.position()[i] = phi(i), m.velocity()[i] = dphi(i);
  return m;
}

msg::JointCommand joint_command(const ServiceUnderTest& s, int64_t k, Vector2d u) {
  auto m = s.stamped<msg::JointCommand>(k);
  m.count(2);
  m.effort()[0] = u(0), m.effort()[1] = u(1);
  return m;
}

Vector2d phi_at(int64_t k) { return {0.1 + 0.001 * static_cast<double>(k), -0.2 + 0.0005 * static_cast<double>(k)}; }
Vector2d dphi_at(int64_t) { return {1.0, 0.5}; }
const Vector2d kU{40.0, -3.0};

void feed_ekf(ServiceUnderTest& s, int64_t k) {
  ASSERT_EQ(s.deliver("r4/joint_states", encoders(s, k, phi_at(k), dphi_at(k))), Rejection::none);
  ASSERT_EQ(s.deliver("r4/cmd", joint_command(s, k, kU)), Rejection::none);
}

TEST(ArmEkf, FirstSampleStartsInSteadyMotion) {
  // x^ = [C(phi, phi') phi' + G(phi), 0, phi, phi']: the motor side is the measurement, the
  // torque rate zero, the torque the rigid-body bias, and q = phi - tau / K (K = 1e4).
  ServiceUnderTest s(kEkf);
  EXPECT_EQ(s.message_type("r4/joint_states"), "JointState");
  EXPECT_EQ(s.message_type("r4/estimate"), "LinkJointState");
  s.step(0);  // no encoder sample yet: the estimate stays zero
  EXPECT_EQ(s.out("r4/estimate", "phi1"), 0.0);
  feed_ekf(s, 1);
  s.step(1);
  alg::ArmRigidBodyDynamics dyn(alg::ArmModel::paper_2dof());
  Eigen::VectorXd tau(2);
  dyn.bias(phi_at(1), dphi_at(1), tau);
  const auto m = s.published<msg::LinkJointState>("r4/estimate");
  EXPECT_EQ(m.count(), 2);
  for (int i = 0; i < 2; ++i) {
    EXPECT_DOUBLE_EQ(m.motor_position()[i], phi_at(1)(i)) << i;
    EXPECT_DOUBLE_EQ(m.motor_velocity()[i], dphi_at(1)(i)) << i;
    EXPECT_EQ(m.torque_rate()[i], 0.0) << i;
    EXPECT_NEAR(m.torque()[i], tau(i), 1e-9) << i;
    EXPECT_NEAR(m.position()[i], phi_at(1)(i) - tau(i) / 1e4, 1e-12) << i;
  }
  EXPECT_GT(std::abs(m.torque()[0]), 1.0);  // gravity and the Coriolis terms are not zero here
}

TEST(ArmEkf, UpdatesMatchTheAlgorithm) {
  ServiceUnderTest s(kEkf);
  alg::FlexibleJointEkfParams p;
  p.step = 0.001;
  alg::FlexibleJointEkf ref(p);
  alg::ArmRigidBodyDynamics dyn(p.model);
  for (int64_t k = 0; k < 4; ++k) {
    feed_ekf(s, k);
    s.step(k);
    Eigen::VectorXd y(4);
    y << phi_at(k), dphi_at(k);
    if (k == 0) {
      Eigen::VectorXd g(2), x0(8);
      dyn.bias(phi_at(0), dphi_at(0), g);
      x0 << g, Eigen::VectorXd::Zero(2), y;
      ref.reset(x0);
    } else {
      ref.update(kU, y, 0.001);
    }
    const auto& fb = ref.feedback();
    for (int i = 0; i < 2; ++i) {
      const std::string j = std::to_string(i + 1);
      EXPECT_NEAR(s.out("r4/estimate", "tau" + j), fb.tau(i), 1e-9 * std::abs(fb.tau(i)) + 1e-12) << k;
      EXPECT_NEAR(s.out("r4/estimate", "dtau" + j), fb.taud(i), 1e-9 * std::abs(fb.taud(i)) + 1e-12) << k;
      EXPECT_NEAR(s.out("r4/estimate", "ddq" + j), fb.qdd(i), 1e-9 * std::abs(fb.qdd(i)) + 1e-12) << k;
      EXPECT_NEAR(s.out("r4/estimate", "phi" + j), fb.phi(i), 1e-12) << k;
    }
  }
  EXPECT_NE(s.out("r4/estimate", "dtau1"), 0.0);  // the update moved the torque rate
}

// Every field of a published estimate is finite and within LinkJointState's @range
// (idl/plexus/msg/estimates.idl), the edge check of a reader in another process.
void expect_within_link_joint_state(const ServiceUnderTest& s, int64_t k) {
  const auto m = s.published<msg::LinkJointState>("r4/estimate");
  for (int i = 0; i < 2; ++i) {
    for (auto [v, bound] : {std::pair{m.position()[i], 1e6},
                            {m.velocity()[i], 1e4},
                            {m.acceleration()[i], 1e7},
                            {m.jerk()[i], 1e10},
                            {m.torque()[i], 1e7},
                            {m.torque_rate()[i], 1e10},
                            {m.motor_position()[i], 1e6},
                            {m.motor_velocity()[i], 1e4}}) {
      ASSERT_TRUE(std::isfinite(v)) << "step " << k << ", joint " << i;
      ASSERT_LE(std::abs(v), bound) << "step " << k << ", joint " << i;
    }
  }
}

TEST(ArmEkf, DivergedEstimateRestartsFromTheLatestSample) {
  // Commands of +-1e7 N m (in JointCommand's range) alternating every step drive the filter
  // at 1 kHz to 1e205 rad/s and then NaN within 6 steps, for good without the restart (the
  // restarted joint controller's failure in fault.kill_each_service_*: docs/testing.md).
  // Each estimate it publishes stays finite and in range; once the commands are sane again
  // the filter follows the encoders.
  ServiceUnderTest s(kEkf);
  for (int64_t k = 0; k < 60; ++k) {
    ASSERT_EQ(s.deliver("r4/joint_states", encoders(s, k, phi_at(k), dphi_at(k))), Rejection::none);
    const double u = (k % 2 ? 1.0 : -1.0) * 1e7;
    ASSERT_EQ(s.deliver("r4/cmd", joint_command(s, k, {u, -u})), Rejection::none);
    s.step(k);
    expect_within_link_joint_state(s, k);
  }
  for (int64_t k = 60; k < 80; ++k) {
    feed_ekf(s, k);
    s.step(k);
    expect_within_link_joint_state(s, k);
  }
  ServiceUnderTest calm(kEkf);
  for (int64_t k = 0; k < 80; ++k) {
    feed_ekf(calm, k);
    calm.step(k);
  }
  // As close to the encoders as a filter that never diverged, on the same inputs since step 60
  // (this test's encoders and command are not one motion, so neither matches them).
  for (auto [f, y] : {std::pair{"phi1", phi_at(79)(0)},
                      {"phi2", phi_at(79)(1)},
                      {"dphi1", dphi_at(79)(0)},
                      {"dphi2", dphi_at(79)(1)}}) {
    EXPECT_LE(std::abs(s.out("r4/estimate", f) - y), std::abs(calm.out("r4/estimate", f) - y) + 1e-6) << f;
  }
}

TEST(ArmEkf, DefaultIsTheRobustTuning) {
  // Without `tuning`, the observer carries the tip-mass and disturbance states (issue 18).
  ServiceUnderTest s(R"(name: ekf_part
step: 0.001
services:
  ekf: {type: arm_ekf, robot: r4}
)");
  alg::FlexibleJointEkfParams p = alg::FlexibleJointEkfParams::robust();
  p.step = 0.001;
  alg::FlexibleJointEkf ref(p);
  ASSERT_EQ(ref.state_size(), 11);
  alg::ArmRigidBodyDynamics dyn(p.model);
  for (int64_t k = 0; k < 4; ++k) {
    feed_ekf(s, k);
    s.step(k);
    Eigen::VectorXd y(4);
    y << phi_at(k), dphi_at(k);
    if (k == 0) {
      Eigen::VectorXd g(2), x0(8);
      dyn.bias(phi_at(0), dphi_at(0), g);
      x0 << g, Eigen::VectorXd::Zero(2), y;
      ref.reset(x0);
    } else {
      ref.update(kU, y, 0.001);
    }
    const auto& fb = ref.feedback();
    for (int i = 0; i < 2; ++i) {
      const std::string j = std::to_string(i + 1);
      EXPECT_NEAR(s.out("r4/estimate", "dtau" + j), fb.taud(i), 1e-9 * std::abs(fb.taud(i)) + 1e-12) << k;
      EXPECT_NEAR(s.out("r4/estimate", "ddq" + j), fb.qdd(i), 1e-9 * std::abs(fb.qdd(i)) + 1e-12) << k;
    }
  }
}

TEST(ArmEkf, BadSamplesAreRefusedAndLeaveTheEstimateAlone) {
  expect_refused_without_effect(kEkf, {}, {"r4/estimate"}, 6, 3, feed_ekf,
                                {
                                    {"encoders for 3 joints",
                                     [](ServiceUnderTest& s, int64_t k) {
                                       auto m = encoders(s, k, phi_at(k), dphi_at(k));
                                       m.count(3);
                                       return s.deliver("r4/joint_states", m);
                                     },
                                     Rejection::wrong_count},
                                    {"encoder velocity NaN",
                                     [](ServiceUnderTest& s, int64_t k) {
                                       return s.deliver("r4/joint_states", encoders(s, k, phi_at(k), {kNaN, 0}));
                                     },
                                     Rejection::non_finite},
                                    {"encoder angle 1e7 rad",
                                     [](ServiceUnderTest& s, int64_t k) {
                                       return s.deliver("r4/joint_states", encoders(s, k, {1e7, 0}, dphi_at(k)));
                                     },
                                     Rejection::out_of_range},
                                    {"command 1e8 N m",
                                     [](ServiceUnderTest& s, int64_t k) {
                                       return s.deliver("r4/cmd", joint_command(s, k, {1e8, 0}));
                                     },
                                     Rejection::out_of_range},
                                    {"command for 1 joint",
                                     [](ServiceUnderTest& s, int64_t k) {
                                       auto m = joint_command(s, k, kU);
                                       m.count(1);
                                       return s.deliver("r4/cmd", m);
                                     },
                                     Rejection::wrong_count},
                                });
}

TEST(ArmEkf, BadParametersAreConfigurationErrors) {
  expect_config_errors(kEkf, {
                                 {"services.ekf.q=-4", {"services.ekf", "q"}},
                                 {"services.ekf.jacobian=numeric", {"services.ekf.jacobian"}},
                                 {"services.ekf.acceleration=guess", {"services.ekf.acceleration"}},
                                 {"services.ekf.substeps=0", {"services.ekf", "substeps"}},
                                 {"services.ekf.dof=3", {"services.ekf.dof"}},
                             });
}

}  // namespace
}  // namespace plexus::services_test
