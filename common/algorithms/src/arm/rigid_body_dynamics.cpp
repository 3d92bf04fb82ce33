#include "plexus/algorithms/arm/rigid_body_dynamics.hpp"

#include <kdl/chain.hpp>
#include <kdl/chaindynparam.hpp>
#include <kdl/chainidsolver_recursive_newton_euler.hpp>
#include <kdl/jntarray.hpp>
#include <kdl/jntspaceinertiamatrix.hpp>

#include <stdexcept>
#include <vector>

namespace plexus::algorithms {
namespace {

// KDL expresses a segment's inertia in its tip frame, and the segment's joint turns the
// tip. So segment i carries link i: its joint axis passes through the tip of link i-1
// (origin (l_{i-1}, 0, 0), axis RotX(twist_{i-1}) z in {B_{i-1}}), its tip frame is {B_i}
// = Frame(RotX(twist_{i-1}), (l_{i-1}, 0, 0)) turned by q_i, and its inertia sits at
// (com_i, 0, 0) in {B_i}. Segment 0 turns about the base z axis.
KDL::Chain build_chain(const ArmModel& model) {
  KDL::Chain chain;
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const ArmLink& l = model.links[i];
    KDL::RigidBodyInertia inertia(
        l.mass, KDL::Vector(l.com, 0.0, 0.0),
        KDL::RotationalInertia(l.inertia_xx_com(), l.inertia_yy_com(), l.inertia_zz_com(), 0.0, 0.0, 0.0));
    if (i + 1 == model.links.size() && model.payload_mass > 0.0) {
      inertia = inertia + KDL::RigidBodyInertia(model.payload_mass, KDL::Vector(l.length, 0.0, 0.0));
    }
    const double prev_length = i == 0 ? 0.0 : model.links[i - 1].length;
    const double prev_twist = i == 0 ? 0.0 : model.links[i - 1].twist;
    const KDL::Frame to_joint(KDL::Rotation::RotX(prev_twist), KDL::Vector(prev_length, 0.0, 0.0));
    const KDL::Joint joint(to_joint.p, to_joint.M * KDL::Vector(0.0, 0.0, 1.0), KDL::Joint::RotAxis);
    chain.addSegment(KDL::Segment(joint, to_joint, inertia));
  }
  return chain;
}

}  // namespace

struct ArmRigidBodyDynamics::Kdl {
  Kdl(const ArmModel& model, unsigned int nj)
      : chain(build_chain(model)),
        gravity(model.gravity.x(), model.gravity.y(), model.gravity.z()),
        dyn(chain, gravity),
        rne(chain, gravity),
        q(nj),
        qd(nj),
        qdd(nj),
        tau(nj),
        m(nj),
        no_wrenches(chain.getNrOfSegments(), KDL::Wrench::Zero()) {}

  void load(const Eigen::VectorXd& v, KDL::JntArray& out) const {
    for (unsigned int i = 0; i < out.rows(); ++i) out(i) = v(i);
  }
  void rne_torques(const Eigen::VectorXd& q_in, const Eigen::VectorXd& qd_in, const Eigen::VectorXd* qdd_in) {
    load(q_in, q);
    load(qd_in, qd);
    if (qdd_in)
      load(*qdd_in, qdd);
    else
      qdd.data.setZero();
    rne.CartToJnt(q, qd, qdd, no_wrenches, tau);
  }

  KDL::Chain chain;
  // KDL's convention: the gravity vector as it acts on the bodies (e.g. (0, 0, -9.81)).
  KDL::Vector gravity;
  KDL::ChainDynParam dyn;
  KDL::ChainIdSolver_RNE rne;
  KDL::JntArray q, qd, qdd, tau;
  KDL::JntSpaceInertiaMatrix m;
  KDL::Wrenches no_wrenches;
};

ArmRigidBodyDynamics::ArmRigidBodyDynamics(const ArmModel& model) : model_(model), n_(model.dof()) {
  model_.validate();
  kdl_ = std::make_unique<Kdl>(model_, static_cast<unsigned int>(n_));
  mass_ = Eigen::MatrixXd::Zero(n_, n_);
  h_ = Eigen::VectorXd::Zero(n_);
  llt_ = Eigen::LLT<Eigen::MatrixXd>(n_);
}

ArmRigidBodyDynamics::~ArmRigidBodyDynamics() = default;

const KDL::Chain& ArmRigidBodyDynamics::chain() const { return kdl_->chain; }

void ArmRigidBodyDynamics::mass_matrix(const Eigen::VectorXd& q, Eigen::MatrixXd& m) {
  kdl_->load(q, kdl_->q);
  kdl_->dyn.JntToMass(kdl_->q, kdl_->m);
  m = kdl_->m.data;
}

void ArmRigidBodyDynamics::bias(const Eigen::VectorXd& q, const Eigen::VectorXd& qd, Eigen::VectorXd& h) {
  kdl_->rne_torques(q, qd, nullptr);
  h = kdl_->tau.data;
}

void ArmRigidBodyDynamics::inverse_dynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                            const Eigen::VectorXd& qdd, Eigen::VectorXd& tau) {
  kdl_->rne_torques(q, qd, &qdd);
  tau = kdl_->tau.data;
}

void ArmRigidBodyDynamics::forward_dynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qd,
                                            const Eigen::VectorXd& tau, Eigen::VectorXd& qdd) {
  mass_matrix(q, mass_);
  bias(q, qd, h_);
  llt_.compute(mass_);
  h_ = tau - h_;
  qdd = llt_.solve(h_);
}

}  // namespace plexus::algorithms
