#include "plexus/algorithms/skid_steer/icr_terrain_reset.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "plexus/algorithms/core/validation.hpp"

namespace plexus::algorithms {
namespace {

const IcrTerrainResetOptions& validated(const IcrTerrainResetOptions& o) {
  constexpr const char* kWhere = "icr_terrain_reset";
  if (o.check_updates < 1) validation::fail(kWhere, "check_updates", ">= 1", o.check_updates);
  validation::require_positive(kWhere, "decisive", o.decisive);
  validation::require_non_negative(kWhere, "lead", o.lead);
  if (o.rewind_steps < 0) validation::fail(kWhere, "rewind_steps", ">= 0", o.rewind_steps);
  if (o.max_candidates < 1) validation::fail(kWhere, "max_candidates", ">= 1", o.max_candidates);
  return o;
}

}  // namespace

IcrTerrainResetFilter::IcrTerrainResetFilter(const IcrEkfParams& ekf, const IcrTerrainResetOptions& options)
    : options_(validated(options)),
      ekf_(ekf),
      shadow_(ekf_),
      trial_(ekf_),
      best_(ekf_),
      history_(options.rewind_steps, "icr_terrain_reset"),
      older_(static_cast<std::size_t>(options.rewind_steps)) {}

void IcrTerrainResetFilter::start(const Pose2& z) {
  ekf_.reset(z);
  started_ = true;
  history_.clear();
  checking_ = 0;
  steps_ = since_prior_ = since_paper_ = 0;
}

bool IcrTerrainResetFilter::step(const TrackSpeeds* u, double dt, const Pose2* z) {
  if (!started_) return false;
  ++steps_;
  Record* r = nullptr;
  if (history_.capacity() > 0) {
    r = &history_.push();
    r->x = ekf_.state();
    r->p = ekf_.covariance();
    r->predicted = u != nullptr;
    r->u = u ? *u : TrackSpeeds{};
    r->dt = dt;
    r->updated = false;
    r->z = z ? *z : Pose2{};
    r->neg2ll = 0.0;
  }
  if (u) {
    ekf_.predict(*u, dt);
    if (checking_ > 0) shadow_.predict(*u, dt);
  }
  if (!z || !ekf_.update(*z)) return false;
  if (r) {
    r->updated = true;
    r->neg2ll = ekf_.last_neg2_log_likelihood();
  }
  if (checking_ > 0 && shadow_.update(*z)) check_prior();
  return true;
}

void IcrTerrainResetFilter::terrain_changed(const TerrainIcrPrior* prior) {
  ++resets_;
  last_rewind_ = 0;
  checking_ = 0;
  if (kept_updates() == 0) {  // nothing kept: the reset at the confirmation
    if (!prior) {
      ekf_.reset_covariance_to_p_b();  // paper 001 eq. (22)
      since_prior_ = steps_;
      return;
    }
    since_prior_ = since_paper_ = steps_;
    shadow_ = ekf_;
    shadow_.reset_covariance_to_p_b();  // the paper's hypothesis, run beside the prior
    ekf_.reset_to_prior(prior->mean, prior->sd);
    neg2ll_prior_ = neg2ll_paper_ = 0.0;
    checking_ = options_.check_updates;
    return;
  }
  if (!prior) {  // paper 001 eq. (22), at the estimated switch
    last_rewind_ = best_change(Hypothesis::kPaper, nullptr, ekf_).age;
    since_prior_ = steps_ - last_rewind_;
    return;
  }
  // Each hypothesis at its own most likely change time; both scores cover the same kept
  // updates, so their difference starts the check. The paper's hypothesis here widens the
  // ICR block only (P_B's), keeping the pose covariance as the prior does: the two differ
  // only in the ICRs, and the likelihoods compare the ICRs, not P_B's wider pose block.
  const Change p = best_change(Hypothesis::kPrior, prior, ekf_);
  const Change q = best_change(Hypothesis::kPaperIcrs, nullptr, shadow_);
  last_rewind_ = p.age;
  since_prior_ = steps_ - p.age;
  since_paper_ = steps_ - q.age;
  neg2ll_prior_ = p.score;
  neg2ll_paper_ = q.score;
  checking_ = options_.check_updates;
}

double IcrTerrainResetFilter::refilter(IcrEkf& f, int age) const {
  double sum = 0.0;
  for (int a = age; a >= 0; --a) {
    const Record& r = history_.at(a);
    if (r.predicted) f.predict(r.u, r.dt);
    if (r.updated && f.update(r.z)) sum += f.last_neg2_log_likelihood();
  }
  return sum;
}

int IcrTerrainResetFilter::kept_updates() const {
  int updates = 0;
  for (int a = 0; a < history_.size(); ++a) updates += history_.at(a).updated ? 1 : 0;
  return updates;
}

void IcrTerrainResetFilter::apply(IcrEkf& f, Hypothesis h, const TerrainIcrPrior* prior) {
  switch (h) {
    case Hypothesis::kPrior: f.replace_icrs(prior->mean, prior->sd); break;
    case Hypothesis::kPaper: f.reset_covariance_to_p_b(); break;
    case Hypothesis::kPaperIcrs: f.replace_icrs(f.icr(), f.params().p_b_diag.tail<3>().cwiseSqrt()); break;
  }
}

IcrTerrainResetFilter::Change IcrTerrainResetFilter::best_change(Hypothesis h, const TerrainIcrPrior* prior,
                                                                 IcrEkf& out) {
  // older_[a]: the recorded -2 log likelihoods of the kept updates older than step age a.
  double sum = 0.0;
  for (int a = history_.size() - 1; a >= 0; --a) {
    older_[static_cast<std::size_t>(a)] = sum;
    if (history_.at(a).updated) sum += history_.at(a).neg2ll;
  }
  Change best{0, std::numeric_limits<double>::infinity()};
  const auto try_at = [&](int a) {
    const Record& r = history_.at(a);
    trial_.restore(r.x, r.p);
    apply(trial_, h, prior);
    const double score = older_[static_cast<std::size_t>(a)] + refilter(trial_, a);
    if (score < best.score) {
      best = {a + 1, score};
      best_ = trial_;
    }
  };
  // Coarse: the kept GPS updates, at most max_candidates of them spread evenly from the
  // oldest to the newest. Fine: every step between the GPS updates either side of the best
  // (a switch between two GPS samples changes the prediction of the next one).
  const int stride = (kept_updates() + options_.max_candidates - 1) / options_.max_candidates;
  int seen = 0;
  for (int a = history_.size() - 1; a >= 0; --a)
    if (history_.at(a).updated && seen++ % stride == 0) try_at(a);
  const int coarse = best.age - 1;
  int older = coarse + 1, newer = coarse - 1;
  while (older < history_.size() - 1 && !history_.at(older).updated) ++older;
  while (newer > 0 && !history_.at(newer).updated) --newer;
  for (int a = std::min(older, history_.size() - 1); a >= std::max(newer, 0); --a)
    if (a != coarse) try_at(a);
  out = best_;
  return best;
}

void IcrTerrainResetFilter::check_prior() {
  neg2ll_prior_ += ekf_.last_neg2_log_likelihood();
  neg2ll_paper_ += shadow_.last_neg2_log_likelihood();
  const double d = neg2ll_prior_ - neg2ll_paper_;
  if (--checking_ > 0 && std::abs(d) < options_.decisive) return;
  checking_ = 0;
  if (d > 0.0) {
    ekf_ = shadow_;
    since_prior_ = since_paper_;
    ++fallbacks_;
  }
}

bool IcrTerrainResetFilter::publishing_paper() const {
  return checking_ > 0 && neg2ll_paper_ + options_.lead < neg2ll_prior_;
}

const IcrEkf& IcrTerrainResetFilter::published() const { return publishing_paper() ? shadow_ : ekf_; }

long IcrTerrainResetFilter::published_model_steps() const {
  return steps_ - (publishing_paper() ? since_paper_ : since_prior_);
}

}  // namespace plexus::algorithms
