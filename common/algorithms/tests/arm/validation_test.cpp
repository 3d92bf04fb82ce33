// Every parameter check of the arm family names the parameter and the offending value.
#include <gtest/gtest.h>

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "arm_test_helpers.hpp"
#include "plexus/algorithms/arm/ct_pd_controller.hpp"
#include "plexus/algorithms/arm/flexible_joint_ekf.hpp"
#include "plexus/algorithms/arm/flexible_joint_plant.hpp"
#include "plexus/algorithms/arm/sine_reference.hpp"
#include "plexus/algorithms/arm/vdc_controller.hpp"

namespace plexus::algorithms {
namespace {

using testing::invalid_argument_message;
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

template <class Params>
struct Case {
  std::string expected;  // substring of the message
  std::function<void(Params&)> mutate;
};

TEST(ArmValidation, DefaultsAreValid) {
  EXPECT_EQ(invalid_argument_message<FlexibleJointArmPlant>(FlexibleJointArmParams{}), "");
  EXPECT_EQ(invalid_argument_message<VdcController>(VdcParams::paper_2dof()), "");
  EXPECT_EQ(invalid_argument_message<FlexibleJointEkf>(FlexibleJointEkfParams{}), "");
  EXPECT_EQ(invalid_argument_message<CtPdController>(CtPdParams::paper_2dof()), "");
  EXPECT_EQ(invalid_argument_message<ArmSineReference>(ArmSineReferenceParams::paper(2)), "");
}

TEST(ArmValidation, ModelErrors) {
  const std::vector<Case<ArmModel>> cases = {
      {"arm_model: links must be a list of at least one link (got 0)", [](ArmModel& m) { m.links.clear(); }},
      {"arm_model: joints must be as many as links (2) (got 1)", [](ArmModel& m) { m.joints.pop_back(); }},
      {"arm_model: links[0].length must be finite and >= 0 (got -1)", [](ArmModel& m) { m.links[0].length = -1; }},
      {"arm_model: links[1].com must be finite (got nan)", [](ArmModel& m) { m.links[1].com = kNan; }},
      {"arm_model: links[1].mass must be finite and > 0 (got 0)", [](ArmModel& m) { m.links[1].mass = 0; }},
      {"arm_model: links[0].twist must be finite (got inf)",
       [](ArmModel& m) { m.links[0].twist = std::numeric_limits<double>::infinity(); }},
      {"arm_model: links[0].inertia_o must be finite and > mass * com^2 = 0.625 (got 0.5)",
       [](ArmModel& m) { m.links[0].inertia_o = 0.5; }},
      {"arm_model: links[0].inertia_xx must be finite (got nan)", [](ArmModel& m) { m.links[0].inertia_xx = kNan; }},
      {"arm_model: links[0].inertia_yy must be finite (got nan)", [](ArmModel& m) { m.links[0].inertia_yy = kNan; }},
      {"arm_model: links[1].inertia_xx must be such that the central inertias satisfy the triangle inequality (got 1)",
       [](ArmModel& m) { m.links[1].inertia_xx = 1.0; }},
      {"arm_model: joints[0].motor_inertia must be finite and > 0 (got -2)",
       [](ArmModel& m) { m.joints[0].motor_inertia = -2; }},
      {"arm_model: joints[1].friction must be finite and >= 0 (got -0.5)",
       [](ArmModel& m) { m.joints[1].friction = -0.5; }},
      {"arm_model: joints[1].stiffness must be finite and > 0 (got 0)", [](ArmModel& m) { m.joints[1].stiffness = 0; }},
      {"arm_model: gravity must be finite (got nan)", [](ArmModel& m) { m.gravity.y() = kNan; }},
      {"arm_model: payload_mass must be finite and >= 0 (got -1)", [](ArmModel& m) { m.payload_mass = -1; }},
  };
  for (const auto& c : cases) {
    ArmModel m = ArmModel::paper_2dof();
    c.mutate(m);
    EXPECT_EQ(invalid_argument_message<ArmRigidBodyDynamics>(m), c.expected);
    EXPECT_EQ(invalid_argument_message<FlexibleJointArmPlant>(FlexibleJointArmParams{m, 1e-4}), c.expected);
  }
  EXPECT_EQ(invalid_argument_message<FlexibleJointArmPlant>(FlexibleJointArmParams{ArmModel::paper_2dof(), 0.0}),
            "flexible_joint_arm: max_substep must be finite and > 0 (got 0)");
  FlexibleJointArmPlant plant({});
  const Eigen::VectorXd three = Eigen::VectorXd::Zero(3), two = Eigen::VectorXd::Zero(2);
  try {
    plant.reset({three, two, two, two});
    ADD_FAILURE() << "reset accepted a wrong size";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "flexible_joint_arm: state size must be the number of joints 2 (got 3)");
  }
}

TEST(ArmValidation, VdcErrors) {
  using P = VdcParams;
  const std::vector<Case<P>> cases = {
      {"vdc_controller: k_b size must be the joint count 2 (got 3)", [](P& p) { p.k_b = Eigen::Vector3d(1, 1, 1); }},
      {"vdc_controller: k_b[1] must be finite and > 0 (got 0)", [](P& p) { p.k_b(1) = 0; }},
      {"vdc_controller: rho[0] must be finite and >= 0 (got -1)", [](P& p) { p.rho(0) = -1; }},
      {"vdc_controller: lambda[0] must be finite and > 0 (got -20)", [](P& p) { p.lambda(0) = -20; }},
      {"vdc_controller: k_p[1] must be finite and > 0 (got nan)", [](P& p) { p.k_p(1) = kNan; }},
      {"vdc_controller: k_i[0] must be finite and >= 0 (got -1)", [](P& p) { p.k_i(0) = -1; }},
      {"vdc_controller: ts_min[0] must be finite and < 0 (got 1)", [](P& p) { p.ts_min(0) = 1; }},
      {"vdc_controller: ts_max[1] must be finite and > 0 (got -1)", [](P& p) { p.ts_max(1) = -1; }},
      {"vdc_controller: lambda_q[0] must be finite and > 0 (got 0)", [](P& p) { p.lambda_q(0) = 0; }},
      {"vdc_controller: lambda_phi[1] must be finite and > 0 (got 0)", [](P& p) { p.lambda_phi(1) = 0; }},
      {"vdc_controller: lambda_tau[0] must be finite and > 0 (got 0)", [](P& p) { p.lambda_tau(0) = 0; }},
      {"vdc_controller: k_phi[0] must be finite and > 0 (got 0)", [](P& p) { p.k_phi(0) = 0; }},
      {"vdc_controller: k_tau[1] must be finite and > 0 (got 0)", [](P& p) { p.k_tau(1) = 0; }},
      {"vdc_controller: theta_lower must be in (0, 1) (got 1.5)", [](P& p) { p.theta_lower = 1.5; }},
      {"vdc_controller: theta_upper must be finite and >= 1 (got 0.9)", [](P& p) { p.theta_upper = 0.9; }},
      {"vdc_controller: theta_initial must be in [theta_lower, theta_upper] = [0.6, 1.8] (got 2)",
       [](P& p) { p.theta_initial = 2.0; }},
      {"vdc_controller: derivative_step must be finite and > 0 (got 0)", [](P& p) { p.derivative_step = 0; }},
      {"vdc_controller: step must be finite and > 0 (got -0.001)", [](P& p) { p.step = -1e-3; }},
      {"arm_model: links[0].mass must be finite and > 0 (got 0)", [](P& p) { p.model.links[0].mass = 0; }},
  };
  for (const auto& c : cases) {
    P p = P::paper_2dof();
    c.mutate(p);
    EXPECT_EQ(invalid_argument_message<VdcController>(p), c.expected);
  }
}

TEST(ArmValidation, EkfErrors) {
  using P = FlexibleJointEkfParams;
  const std::vector<Case<P>> cases = {
      {"flexible_joint_ekf: q must be finite and > 0 (got 0)", [](P& p) { p.q = 0; }},
      {"flexible_joint_ekf: r must be finite and > 0 (got -0.1)", [](P& p) { p.r = -0.1; }},
      {"flexible_joint_ekf: p0 must be finite and > 0 (got nan)", [](P& p) { p.p0 = kNan; }},
      {"flexible_joint_ekf: substeps must be >= 1 (got 0)", [](P& p) { p.substeps = 0; }},
      {"flexible_joint_ekf: step must be finite and > 0 (got 0)", [](P& p) { p.step = 0; }},
      {"flexible_joint_ekf: accel_filter_hz must be finite and > 0 (got 0)", [](P& p) { p.accel_filter_hz = 0; }},
      {"flexible_joint_ekf: fd_step must be finite and > 0 (got 0)", [](P& p) { p.fd_step = 0; }},
      {"arm_model: joints[0].stiffness must be finite and > 0 (got 0)", [](P& p) { p.model.joints[0].stiffness = 0; }},
  };
  for (const auto& c : cases) {
    P p;
    c.mutate(p);
    EXPECT_EQ(invalid_argument_message<FlexibleJointEkf>(p), c.expected);
  }
  FlexibleJointEkf ekf({});
  try {
    ekf.reset(Eigen::VectorXd::Zero(3));
    ADD_FAILURE() << "reset accepted a wrong size";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "flexible_joint_ekf: x0 size must be 4 n = 8 (got 3)");
  }
}

TEST(ArmValidation, CtPdAndReferenceErrors) {
  const std::vector<Case<CtPdParams>> ct = {
      {"ct_pd_controller: k_p size must be the joint count 2 (got 1)",
       [](CtPdParams& p) { p.k_p = Eigen::VectorXd::Ones(1); }},
      {"ct_pd_controller: k_v[1] must be finite and >= 0 (got -1)", [](CtPdParams& p) { p.k_v(1) = -1; }},
      {"ct_pd_controller: k_d[0] must be finite and >= 0 (got nan)", [](CtPdParams& p) { p.k_d(0) = kNan; }},
  };
  for (const auto& c : ct) {
    CtPdParams p = CtPdParams::paper_2dof();
    c.mutate(p);
    EXPECT_EQ(invalid_argument_message<CtPdController>(p), c.expected);
  }
  using R = ArmSineReferenceParams;
  const std::vector<Case<R>> ref = {
      {"arm_sine_reference: amplitude must be a non-empty list (got 0)", [](R& p) { p = R{}; }},
      {"arm_sine_reference: offset size must be the joint count 2 (got 3)",
       [](R& p) { p.offset = Eigen::Vector3d::Zero(); }},
      {"arm_sine_reference: phase[1] must be finite (got nan)", [](R& p) { p.phase(1) = kNan; }},
      {"arm_sine_reference: frequency_hz[0] must be finite and >= 0 (got -1)", [](R& p) { p.frequency_hz(0) = -1; }},
  };
  for (const auto& c : ref) {
    R p = R::paper(2);
    c.mutate(p);
    EXPECT_EQ(invalid_argument_message<ArmSineReference>(p), c.expected);
  }
}

}  // namespace
}  // namespace plexus::algorithms
