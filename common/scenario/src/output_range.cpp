#include "plexus/scenario/output_range.hpp"

#include <cmath>
#include <limits>

#include "plexus/msg/registry.hpp"

namespace plexus::scenario {

OutputRange::OutputRange(const OutputPort& port) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const msg::WireType* type = port.message().empty() ? nullptr : msg::find_wire_type(port.message());
  for (const std::string& field : port.fields()) {
    double lo = -kInf, hi = kInf;
    if (type)
      for (const msg::WireSlot& slot : type->slots)
        if (slot.field == field) lo = slot.min, hi = slot.max;
    min_.push_back(lo);
    max_.push_back(hi);
  }
}

int OutputRange::first_violation(const OutputPort& port) const {
  const auto& v = port.sample().values;
  for (std::size_t i = 0; i < min_.size(); ++i)
    if (!std::isfinite(v[i]) || v[i] < min_[i] || v[i] > max_[i]) return static_cast<int>(i);
  return -1;
}

}  // namespace plexus::scenario
