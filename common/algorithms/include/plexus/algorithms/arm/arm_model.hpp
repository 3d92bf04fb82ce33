// Physical description of an n-DoF serial arm with flexible revolute joints (paper 004,
// section 3 and Tables 1-2; Spong's reduced model).
//
//   M(q) q'' + C(q, q') q' + G(q) = tau                 link side, tau = K (phi - q)
//   J phi'' + F phi' + tau = u + u_d                      motor side (paper 004, eqs. (16)-(17))
//
// Geometry (our choice; paper 004 is silent, see docs/algorithms/arm.md):
// - every joint turns about the z axis of its link frame {B_i}, whose origin is on the joint;
// - link i's tip frame {T_{i+1}} sits at (length_i, 0, 0) in {B_i}, rotated by `twist_i`
//   about x (0 for a planar arm: then every joint axis is parallel); {B_{i+1}} is {T_{i+1}}
//   turned by q_{i+1} about z;
// - the centre of mass lies at (com_i, 0, 0) in {B_i}; `inertia_o_i` is the moment of
//   inertia about the joint axis (I_O of Table 1), so the central inertia about z is
//   I_O - m d^2; the central x and y inertias default to the same value (they only
//   matter for twisted links);
// - base frame = {B_1} at q_1 = 0. Gravity is a vector in the base frame; the default
//   (9.81, 0, 0) makes the base x axis point down, so q = 0 is the arm hanging at rest.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "plexus/algorithms/arm/spatial.hpp"

namespace plexus::algorithms {

/// One rigid link (paper 004, Table 1).
struct ArmLink {
  double length = 0.5;       ///< l_i, m: joint i to joint i+1 along x of {B_i}
  double com = 0.25;         ///< d_i, m: centre of mass on x of {B_i}
  double mass = 10.0;        ///< m_i, kg, > 0
  double inertia_o = 1.0;    ///< I_O_i, kg m^2: about the joint axis; must exceed mass * com^2
  double twist = 0.0;        ///< rad: rotation of the tip frame about x (0: planar arm)
  double inertia_xx = -1.0;  ///< central inertia about x, kg m^2; < 0: same as the central z inertia
  double inertia_yy = -1.0;  ///< central inertia about y, kg m^2; < 0: same as the central z inertia

  /// Central inertia about z: I_O - m d^2.
  double inertia_zz_com() const { return inertia_o - mass * com * com; }
  double inertia_xx_com() const { return inertia_xx < 0.0 ? inertia_zz_com() : inertia_xx; }
  double inertia_yy_com() const { return inertia_yy < 0.0 ? inertia_zz_com() : inertia_yy; }
};

/// One flexible joint with its motor (paper 004, Table 2), reduced to the link side.
struct ArmJoint {
  double motor_inertia = 2.0;  ///< J_i (I_i in the paper), kg m^2, > 0
  double friction = 1.0;       ///< F_i (f_i), N m s, >= 0
  double stiffness = 1e4;      ///< K_i (k_i^f), N m / rad, > 0
};

struct ArmModel {
  std::vector<ArmLink> links;
  std::vector<ArmJoint> joints;
  Eigen::Vector3d gravity{9.81, 0.0, 0.0};  ///< m/s^2, in the base frame
  double payload_mass = 0.0;                ///< kg, point mass at the tip of the last link (>= 0)

  int dof() const { return static_cast<int>(links.size()); }

  /// The constant part of {B_{i-1}} -> {B_i} (the joint angle q_i turns about z after it):
  /// RotX(twist_{i-1}) and the origin (length_{i-1}, 0, 0); for i = 0, RotX(0) at the base.
  spatial::Transform fixed_link_frame(int i) const;

  /// Throws std::invalid_argument ("arm_model: links[1].mass must be finite and > 0 (got -1)")
  /// unless: at least one link, as many joints as links, finite positive masses, lengths >= 0,
  /// I_O > m d^2, central inertias >= 0 and physically consistent (triangle inequality),
  /// positive J and K, F >= 0, finite gravity, payload >= 0.
  void validate() const;

  /// The 2-DoF arm of paper 004, Tables 1-2.
  static ArmModel paper_2dof();
  /// n identical links scaled from link 2 of the paper (4 kg, 0.5 m) and joint 2, used for
  /// the n-DoF tests and the VDC cost benchmark.
  static ArmModel uniform_chain(int n);
};

}  // namespace plexus::algorithms
