// Joint-space sinusoidal reference (paper 004, eq. (59)):
//   q_d,i(t) = offset_i + amplitude_i sin(2 pi f_i t + phase_i)
// with its first three derivatives (the VDC law needs q_d''' for tau_od'). paper() gives eq. (59):
//   q_d = (1 / 2 pi) [sin(2 pi t) + 0.088] rad for every joint.
#pragma once

#include <Eigen/Core>

namespace plexus::algorithms {

struct ArmSineReferenceParams {
  Eigen::VectorXd amplitude, frequency_hz, offset, phase;  ///< one entry per joint
  /// Eq. (59) for n joints.
  static ArmSineReferenceParams paper(int n);
};

struct ArmReferenceSample {
  Eigen::VectorXd q, qd, qdd, qddd;  ///< q_d and its first three derivatives
};

class ArmSineReference {
 public:
  /// Validates: four vectors of the same non-zero size, finite, frequency >= 0.
  explicit ArmSineReference(const ArmSineReferenceParams& params);
  int dof() const { return static_cast<int>(params_.amplitude.size()); }
  /// Writes q_d, q_d', q_d'', q_d''' at time t into `out` (sized by the caller or on first use).
  void sample(double t, ArmReferenceSample& out) const;

 private:
  ArmSineReferenceParams params_;
};

}  // namespace plexus::algorithms
