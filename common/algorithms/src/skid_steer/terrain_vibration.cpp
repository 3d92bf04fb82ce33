// Terrain vibration model (docs/algorithms/skid_steer.md, "Vibration model").
#include "plexus/algorithms/skid_steer/terrain_vibration.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

namespace {
constexpr const char* kWhereTerrainVibration = "terrain_vibration";
}  // namespace

TerrainVibration::TerrainVibration(const TerrainVibrationParams& params) : params_(params) {
  using namespace validation;
  if (params.spectra.empty()) throw std::invalid_argument("terrain_vibration: spectra must not be empty");
  require_positive(kWhereTerrainVibration, "sample_period", params.sample_period);
  require_positive(kWhereTerrainVibration, "reference_speed", params.reference_speed);
  require_non_negative(kWhereTerrainVibration, "speed_exponent", params.speed_exponent);
  require_finite(kWhereTerrainVibration, "gravity", params.gravity);
  const double h = params.sample_period;
  const double nyquist = 0.5 / h;
  for (std::size_t t = 0; t < params.spectra.size(); ++t) {
    const VibrationSpectrum& s = params.spectra[t];
    const std::string st = "spectra[" + std::to_string(t) + "]";
    require_non_negative(kWhereTerrainVibration, st + ".floor_rms", s.floor_rms);
    std::vector<Oscillator> bank;
    for (std::size_t j = 0; j < s.resonances.size(); ++j) {
      const VibrationResonance& r = s.resonances[j];
      const std::string sr = st + ".resonances[" + std::to_string(j) + "]";
      require_open_interval(kWhereTerrainVibration, sr + ".frequency_hz", r.frequency_hz, 0.0, nyquist);
      require_open_interval(kWhereTerrainVibration, sr + ".damping_ratio", r.damping_ratio, 0.0, 1.0);
      require_non_negative(kWhereTerrainVibration, sr + ".rms", r.rms);
      const double w0 = 2.0 * std::numbers::pi * r.frequency_hz;
      const double wd = w0 * std::sqrt(1.0 - r.damping_ratio * r.damping_ratio);
      const double rho = std::exp(-r.damping_ratio * w0 * h);
      const double a1 = 2.0 * rho * std::cos(wd * h);
      const double a2 = -rho * rho;
      const double unit_var = (1.0 - a2) / ((1.0 + a2) * ((1.0 - a2) * (1.0 - a2) - a1 * a1));
      bank.push_back({a1, a2, r.rms / std::sqrt(unit_var)});
    }
    oscillators_.push_back(std::move(bank));
  }
}

double TerrainVibration::gain(double speed) const {
  const double s = std::abs(speed);
  if (!(s > 0.0)) return 0.0;  // at rest: no vibration, whatever the exponent
  return std::pow(s / params_.reference_speed, params_.speed_exponent);
}

double TerrainVibration::sample(int terrain, double speed, Rng& rng) {
  double out = 0.0;
  for (std::size_t t = 0; t < oscillators_.size(); ++t) {
    double sum = 0.0;
    for (Oscillator& o : oscillators_[t]) {
      const double r = o.a1 * o.r1 + o.a2 * o.r2 + o.b * rng.normal();
      o.r2 = o.r1;
      o.r1 = r;
      sum += r;
    }
    sum += params_.spectra[t].floor_rms * rng.normal();
    if (static_cast<int>(t) == terrain) out = sum;
  }
  return params_.gravity + gain(speed) * out;
}

}  // namespace plexus::algorithms
