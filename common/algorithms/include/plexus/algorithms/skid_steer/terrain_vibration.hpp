// Terrain-induced vertical vibration of a skid-steer body (the z-acceleration an IMU sees).
//
// Paper 001 classifies terrain from the IMU z-acceleration recorded on the real robot; a
// simulator has to synthesise it (docs/papers.md, paper 001). The model, chosen here and
// documented in docs/algorithms/skid_steer.md:
//
//   a_z(t) = g + gain(s) * ( sum_j r_j(t) + floor_rms * e_0(t) ),
//   gain(s) = (s / reference_speed)^speed_exponent,   s = (|v_l| + |v_r|) / 2
//
// Each resonance j of the current terrain is a damped second-order oscillator (natural
// frequency f_j, damping ratio zeta_j) driven by white noise and discretised exactly at
// the sample period h as the AR(2) process
//   r[n] = a1 r[n-1] + a2 r[n-2] + b e_j[n],  a1 = 2 rho cos(w_d h),  a2 = -rho^2,
//   rho = exp(-zeta w0 h),  w0 = 2 pi f,  w_d = w0 sqrt(1 - zeta^2),
// with b chosen so that r has the stationary RMS `rms` (at gain 1):
//   var(r) / b^2 = (1 - a2) / ((1 + a2) ((1 - a2)^2 - a1^2)).
// Its PSD peaks near f_j with a width ~ 2 zeta f_j, so terrains with different
// resonances have different spectra; the gain scales the whole spectrum with speed
// (a robot at rest does not vibrate). Every terrain's oscillators run all the time (no
// start-up transient at a terrain change); only the current terrain's reach a_z. All
// draws come from the caller's Rng (core/random.hpp), in a fixed order, so a seed fixes
// the signal.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "plexus/algorithms/core/random.hpp"

namespace plexus::algorithms {

struct VibrationResonance {
  double frequency_hz = 10.0;  ///< natural frequency, > 0 and below the Nyquist frequency
  double damping_ratio = 0.1;  ///< in (0, 1)
  double rms = 0.5;            ///< stationary RMS at gain 1, m/s^2, >= 0
};

/// The vibration signature of one terrain.
struct VibrationSpectrum {
  std::vector<VibrationResonance> resonances;
  double floor_rms = 0.05;  ///< white broadband floor at gain 1, m/s^2, >= 0
};

struct TerrainVibrationParams {
  std::vector<VibrationSpectrum> spectra;  ///< one per terrain (index = terrain id), >= 1
  double sample_period = 0.01;             ///< s, > 0 (the plant step)
  double reference_speed = 0.5;            ///< m/s, > 0: speed at which gain = 1
  double speed_exponent = 1.0;             ///< >= 0: 0 makes the gain 1 at every speed > 0
  double gravity = 9.81;                   ///< m/s^2, finite: added to a_z
};

class TerrainVibration {
 public:
  /// Validates every field; throws std::invalid_argument naming it (e.g.
  /// "terrain_vibration: spectra[1].resonances[0].frequency_hz must be ...").
  explicit TerrainVibration(const TerrainVibrationParams& params);

  /// Advances every oscillator one sample and returns a_z for `terrain` at track speed
  /// `speed` (m/s, the mean absolute track speed). terrain must be in [0, terrain_count()).
  /// Draws one normal per oscillator of every terrain plus one per terrain floor. No allocation.
  double sample(int terrain, double speed, Rng& rng);

  /// gain(s) of the model above.
  double gain(double speed) const;

  std::size_t terrain_count() const { return params_.spectra.size(); }
  const TerrainVibrationParams& params() const { return params_; }

 private:
  struct Oscillator {
    double a1, a2, b;
    double r1 = 0.0, r2 = 0.0;  // r[n-1], r[n-2]
  };
  TerrainVibrationParams params_;
  std::vector<std::vector<Oscillator>> oscillators_;  // [terrain][resonance]
};

}  // namespace plexus::algorithms
