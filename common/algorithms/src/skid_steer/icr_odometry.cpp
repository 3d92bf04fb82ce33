#include "plexus/algorithms/skid_steer/icr_odometry.hpp"

namespace plexus::algorithms {

RevisableIcrOdometry::RevisableIcrOdometry(int capacity) : history_(capacity, "icr_odometry") {}

void RevisableIcrOdometry::reset(const Pose2& pose) {
  odo_.reset(pose);
  history_.clear();
}

bool RevisableIcrOdometry::step(const TrackSpeeds& u, const IcrParams& icr, double h, double t) {
  const Pose2 before = odo_.pose();
  if (!odo_.step(u, icr, h)) return false;
  if (history_.capacity() > 0) history_.push() = {before, u, h, t};
  return true;
}

int RevisableIcrOdometry::revise(double since, const IcrParams& icr) {
  if (!(icr.y_l > icr.y_r)) return 0;
  int age = -1;  // the oldest kept step starting at or after `since`
  for (int a = 0; a < history_.size(); ++a) {
    const Record& r = history_.at(a);
    if (r.t + 0.5 * r.h < since) break;
    age = a;
  }
  if (age < 0) return 0;
  odo_.reset(history_.at(age).before);
  for (int a = age; a >= 0; --a) {
    Record& r = history_.at(a);
    r.before = odo_.pose();
    odo_.step(r.u, icr, r.h);
  }
  return age + 1;
}

}  // namespace plexus::algorithms
