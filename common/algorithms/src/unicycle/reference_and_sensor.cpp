// Validation for the small header-defined models: FigureEightReference, PositionSensor.
#include <stdexcept>
#include <string>

#include "plexus/algorithms/core/validation.hpp"
#include "plexus/algorithms/unicycle/figure_eight_reference.hpp"
#include "plexus/algorithms/unicycle/position_sensor.hpp"

namespace plexus::algorithms {

FigureEightReference::FigureEightReference(const FigureEightParams& params) : params_(params) {
  validation::require_positive("figure_eight_reference", "h1", params.h1);
  validation::require_positive("figure_eight_reference", "h2", params.h2);
  validation::require_finite("figure_eight_reference", "t0", params.t0);
}

PositionSensor::PositionSensor(const PositionSensorParams& params) : params_(params) {
  constexpr const char* kWhere = "position_sensor";
  validation::require_non_negative(kWhere, "sigma", params.sigma);
  validation::require_positive(kWhere, "grid_spacing", params.grid_spacing);
  validation::require_finite(kWhere, "grid_origin.x", params.grid_origin.x());
  validation::require_finite(kWhere, "grid_origin.y", params.grid_origin.y());
  validation::require_positive(kWhere, "rate_hz", params.rate_hz);
}

PositionSensorKind position_sensor_kind_from_string(const std::string& name) {
  if (name == "exact") return PositionSensorKind::kExact;
  if (name == "gaussian") return PositionSensorKind::kGaussian;
  if (name == "rfid_grid") return PositionSensorKind::kRfidGrid;
  throw std::invalid_argument("position_sensor: kind must be one of exact, gaussian, rfid_grid (got \"" + name + "\")");
}

}  // namespace plexus::algorithms
