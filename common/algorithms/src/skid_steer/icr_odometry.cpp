#include "plexus/algorithms/skid_steer/icr_odometry.hpp"

#include <algorithm>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {

RevisableIcrOdometry::RevisableIcrOdometry(int capacity) {
  if (capacity < 0) validation::fail("icr_odometry", "revision capacity", ">= 0", capacity);
  history_.resize(static_cast<std::size_t>(capacity));
}

void RevisableIcrOdometry::reset(const Pose2& pose) {
  odo_.reset(pose);
  kept_ = 0;
}

bool RevisableIcrOdometry::step(const TrackSpeeds& u, const IcrParams& icr, double h, double t) {
  const Pose2 before = odo_.pose();
  if (!odo_.step(u, icr, h)) return false;
  if (!history_.empty()) {
    head_ = (head_ + 1) % static_cast<int>(history_.size());
    kept_ = std::min(kept_ + 1, static_cast<int>(history_.size()));
    history_[static_cast<std::size_t>(head_)] = {before, u, h, t};
  }
  return true;
}

int RevisableIcrOdometry::revise(double since, const IcrParams& icr) {
  if (!(icr.y_l > icr.y_r)) return 0;
  const int n = static_cast<int>(history_.size());
  int age = -1;  // the oldest kept step starting at or after `since`
  for (int a = 0; a < kept_; ++a) {
    const Record& r = history_[static_cast<std::size_t>((head_ - a + n) % n)];
    if (r.t + 0.5 * r.h < since) break;
    age = a;
  }
  if (age < 0) return 0;
  odo_.reset(history_[static_cast<std::size_t>((head_ - age + n) % n)].before);
  for (int a = age; a >= 0; --a) {
    Record& r = history_[static_cast<std::size_t>((head_ - a + n) % n)];
    r.before = odo_.pose();
    odo_.step(r.u, icr, r.h);
  }
  return age + 1;
}

}  // namespace plexus::algorithms
