// 6-D spatial vectors of virtual decomposition control (paper 004, section 2; Zhu 2010).
//
// A generalized velocity is V = [v; w] (linear, angular) and a generalized force
// F = [f; m] (force, moment), both expressed in a frame {A}. For two frames {A}, {B} of
// one rigid body, with R = A_R_B and r the origin of {B} in {A}:
//
//   A_U_B = [ R      0 ]       B_V = A_U_B^T A_V     (paper 004, eq. (2))
//           [ r^ R   R ]       A_F = A_U_B  B_F      (paper 004, eq. (3))
//
// The rigid-body dynamics of a link in its own (moving) frame is eq. (7):
//   M_B d/dt(V) + C_B(V) V + G_B = F*,
// with M_B = [m I, -m c^; m c^, I_O] (c: centre of mass, I_O: inertia about the frame
// origin), G_B = M_B [-g_B; 0] (g_B: gravity in {B}) and the skew-symmetric
//   C_B(V) = crf(V) M_B + M_B crm(V),   crm(V) = [w^ v^; 0 w^],  crf(V) = -crm(V)^T,
// which gives C_B(V) V = crf(V) M_B V (the Newton-Euler velocity terms) and
// (V_r - V)^T C_B (V_r - V) = 0, the property step 1 of the paper's proof uses.
//
// The 13 parameters of Zhu's regressor (eq. (8), Y_B in R^{6x13}):
//   theta = [m, m cx, m cy, m cz, m cx^2, m cy^2, m cz^2, m cx cy, m cx cz, m cy cz,
//            Ixx_c, Iyy_c, Izz_c]
// so that I_O = diag(I_c) + m (|c|^2 I - c c^T) is linear in theta.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross()

namespace plexus::algorithms::spatial {

using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using Vector13 = Eigen::Matrix<double, 13, 1>;
using Regressor = Eigen::Matrix<double, 6, 13>;

inline Eigen::Matrix3d skew(const Eigen::Vector3d& a) {
  Eigen::Matrix3d s;
  s << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return s;
}

/// A rigid transform between two frames of one body: A_R_B and the origin of {B} in {A}.
struct Transform {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
};

/// A_U_B (eq. (3)) as a 6x6 matrix; used by tests (the hot path applies the two products below).
Matrix6 force_transform(const Transform& a_b);

/// B_V = A_U_B^T A_V  (eq. (2)): v_B = R^T (v_A + w_A x r),  w_B = R^T w_A.
inline Vector6 velocity_to_child(const Transform& a_b, const Vector6& v_a) {
  Vector6 out;
  out.head<3>() = a_b.rotation.transpose() * (v_a.head<3>() + v_a.tail<3>().cross(a_b.origin));
  out.tail<3>() = a_b.rotation.transpose() * v_a.tail<3>();
  return out;
}

/// A_F = A_U_B B_F  (eq. (3)): f_A = R f_B,  m_A = R m_B + r x (R f_B).
inline Vector6 force_to_parent(const Transform& a_b, const Vector6& f_b) {
  Vector6 out;
  out.head<3>() = a_b.rotation * f_b.head<3>();
  out.tail<3>() = a_b.rotation * f_b.tail<3>() + a_b.origin.cross(out.head<3>());
  return out;
}

/// crm(V) X: motion cross product [w x xv + v x xw; w x xw].
inline Vector6 cross_motion(const Vector6& v, const Vector6& x) {
  Vector6 out;
  out.head<3>() = v.tail<3>().cross(x.head<3>()) + v.head<3>().cross(x.tail<3>());
  out.tail<3>() = v.tail<3>().cross(x.tail<3>());
  return out;
}

/// crf(V) F: force cross product [w x f; w x m + v x f].
inline Vector6 cross_force(const Vector6& v, const Vector6& f) {
  Vector6 out;
  out.head<3>() = v.tail<3>().cross(f.head<3>());
  out.tail<3>() = v.tail<3>().cross(f.tail<3>()) + v.head<3>().cross(f.head<3>());
  return out;
}

/// M_B(theta): the 6x6 spatial inertia about the frame origin from the 13 parameters.
Matrix6 spatial_inertia(const Vector13& theta);

/// W(x) with W(x) theta = M_B(theta) x (linear in theta).
Regressor inertia_regressor(const Vector6& x);

/// The regressor of eq. (8):  Y theta = M_B (dVr - [g_B; 0]) + C_B(V) V_r, i.e.
///   Y = W(dVr - [g_B; 0] + crm(V) V_r) + crf(V) W(V_r).
Regressor link_regressor(const Vector6& dvr, const Vector6& vr, const Vector6& v, const Eigen::Vector3d& gravity_b);

/// Zhu's 13 parameters of a body of mass m, centre of mass c and central principal
/// inertias (Ixx_c, Iyy_c, Izz_c) along the frame axes.
Vector13 link_parameters(double mass, const Eigen::Vector3d& com, const Eigen::Vector3d& central_inertia);

}  // namespace plexus::algorithms::spatial
