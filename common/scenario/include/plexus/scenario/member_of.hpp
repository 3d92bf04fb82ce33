// Which message member a signal field fills: a field may have several names (IDL aliases:
// Imu's `az`, `acc_z` and `a_z` are all linear_acceleration[2]), so two components, or a
// component and a bridge frame, that name one member differently still meet.
#pragma once

#include <string>

namespace plexus::scenario {

/// The member a field of `message` fills ("linear_acceleration[2]"), or "" when the type or
/// the field is unknown.
std::string member_of(const std::string& message, const std::string& field);

}  // namespace plexus::scenario
