#include "signal_codec.hpp"

#include <algorithm>
#include <cmath>

namespace plexus::distributed::detail {

void to_message(const scenario::SignalSample& s, std::size_t width, int64_t step_ns, msg::Signal& m) {
  m.header().origin_time_ns(0);
  m.header().data_time_ns(s.step * step_ns);
  m.step_index(s.step);
  m.count(static_cast<uint16_t>(width));
  std::copy_n(s.values.begin(), width, m.field_values().begin());
  std::fill(m.field_values().begin() + static_cast<std::ptrdiff_t>(width), m.field_values().end(), 0.0);
}

Rejection from_message(const msg::Signal& m, std::size_t width, scenario::SignalSample& s, std::size_t& bad_field) {
  if (m.count() != width) return Rejection::wrong_width;
  if (m.step_index() < 0) return Rejection::negative_step;
  for (std::size_t i = 0; i < width; ++i)
    if (!std::isfinite(m.field_values()[i])) {
      bad_field = i;
      return Rejection::non_finite;
    }
  s.step = m.step_index();
  std::copy_n(m.field_values().begin(), width, s.values.begin());
  std::fill(s.values.begin() + static_cast<std::ptrdiff_t>(width), s.values.end(), 0.0);
  return Rejection::none;
}

}  // namespace plexus::distributed::detail
