#include "signal_codec.hpp"

#include <algorithm>

namespace plexus::distributed::detail {

void to_message(const scenario::SignalSample& s, std::size_t width, int64_t step_ns, msg::Signal& m) {
  m.header().origin_time_ns(0);
  m.header().data_time_ns(s.step * step_ns);
  m.step_index(s.step);
  m.count(static_cast<uint16_t>(width));
  std::copy_n(s.values.begin(), width, m.field_values().begin());
  std::fill(m.field_values().begin() + static_cast<std::ptrdiff_t>(width), m.field_values().end(), 0.0);
}

bool from_message(const msg::Signal& m, std::size_t width, scenario::SignalSample& s) {
  if (m.count() != width || m.step_index() < 0) return false;
  s.step = m.step_index();
  std::copy_n(m.field_values().begin(), width, s.values.begin());
  std::fill(s.values.begin() + static_cast<std::ptrdiff_t>(width), s.values.end(), 0.0);
  return true;
}

}  // namespace plexus::distributed::detail
