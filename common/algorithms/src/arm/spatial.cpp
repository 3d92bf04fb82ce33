#include "plexus/algorithms/arm/spatial.hpp"

namespace plexus::algorithms::spatial {

Matrix6 force_transform(const Transform& a_b) {
  Matrix6 u = Matrix6::Zero();
  u.topLeftCorner<3, 3>() = a_b.rotation;
  u.bottomLeftCorner<3, 3>() = skew(a_b.origin) * a_b.rotation;
  u.bottomRightCorner<3, 3>() = a_b.rotation;
  return u;
}

Matrix6 spatial_inertia(const Vector13& th) {
  Matrix6 m = Matrix6::Zero();
  const Eigen::Vector3d mc = th.segment<3>(1);
  m.topLeftCorner<3, 3>() = th(0) * Eigen::Matrix3d::Identity();
  m.topRightCorner<3, 3>() = -skew(mc);
  m.bottomLeftCorner<3, 3>() = skew(mc);
  Eigen::Matrix3d io;
  io << th(10) + th(5) + th(6), -th(7), -th(8),  //
      -th(7), th(11) + th(4) + th(6), -th(9),    //
      -th(8), -th(9), th(12) + th(4) + th(5);
  m.bottomRightCorner<3, 3>() = io;
  return m;
}

Regressor inertia_regressor(const Vector6& x) {
  // M x = [m xv - (m c) x xw ; (m c) x xv + I_O xw] = [m xv + xw^ (m c) ; -xv^ (m c) + I_O xw].
  Regressor w = Regressor::Zero();
  const Eigen::Vector3d xv = x.head<3>();
  const double wx = x(3), wy = x(4), wz = x(5);
  w.block<3, 1>(0, 0) = xv;
  w.block<3, 3>(0, 1) = skew(x.tail<3>());
  w.block<3, 3>(3, 1) = -skew(xv);
  // I_O xw: Ixx = th10 + th5 + th6, Iyy = th11 + th4 + th6, Izz = th12 + th4 + th5,
  // Ixy = -th7, Ixz = -th8, Iyz = -th9 (0-based indices).
  w(4, 4) = wy, w(5, 4) = wz;                   // m cx^2
  w(3, 5) = wx, w(5, 5) = wz;                   // m cy^2
  w(3, 6) = wx, w(4, 6) = wy;                   // m cz^2
  w(3, 7) = -wy, w(4, 7) = -wx;                 // m cx cy
  w(3, 8) = -wz, w(5, 8) = -wx;                 // m cx cz
  w(4, 9) = -wz, w(5, 9) = -wy;                 // m cy cz
  w(3, 10) = wx, w(4, 11) = wy, w(5, 12) = wz;  // central inertias
  return w;
}

Regressor link_regressor(const Vector6& dvr, const Vector6& vr, const Vector6& v, const Eigen::Vector3d& gravity_b) {
  Vector6 a = dvr + cross_motion(v, vr);
  a.head<3>() -= gravity_b;
  Regressor y = inertia_regressor(a);
  const Regressor wr = inertia_regressor(vr);
  // crf(V) W(V_r), column by column (13 fixed-size cross products).
  for (int c = 0; c < 13; ++c) y.col(c) += cross_force(v, wr.col(c));
  return y;
}

Vector13 link_parameters(double mass, const Eigen::Vector3d& c, const Eigen::Vector3d& central) {
  Vector13 th;
  th << mass, mass * c.x(), mass * c.y(), mass * c.z(), mass * c.x() * c.x(), mass * c.y() * c.y(),
      mass * c.z() * c.z(), mass * c.x() * c.y(), mass * c.x() * c.z(), mass * c.y() * c.z(), central.x(), central.y(),
      central.z();
  return th;
}

}  // namespace plexus::algorithms::spatial
