// The ICR EKF's reaction to a confirmed terrain change (paper 001 section 3.2, eq. (22), and
// plexus's prior reset; docs/algorithms/skid_steer.md "Prior reset").
//
// Paper 001 resets P to P_B around the old terrain's ICRs. The prior reset starts the ICRs
// from the new terrain's learned values (a TerrainIcrLibrary entry) instead; a wrong label
// gives a wrong prior, so the paper's reset runs beside it as a second hypothesis (the shadow)
// for `check_updates` GPS updates, and the hypothesis whose innovations are less likely
// (summed NIS + log det S) is dropped, as soon as the sums differ by `decisive` or at the end.
// The published estimate is the prior's until the paper's hypothesis leads by `lead`.
//
// Rewind. The change is confirmed one to two classifier windows after the switch. Until
// then the filter predicts with the old terrain's ICRs, and its heading drifts from the truth
// at the difference of the two models' turn rates, which the GPS heading (R: 3 deg) corrects
// only slowly: 10-20 deg by the confirmation when the ICRs jump by 0.3-0.5 m (measured,
// issue 29). Starting the prior there, with the pose block of P_B (3 deg), made the correct
// prior less likely than the paper's reset, whose wide ICRs absorb the heading error, and the
// wrong hypothesis won. So the prior hypothesis restarts at the switch instead of at the
// confirmation: the filter keeps its last `rewind_steps` steps (the state and covariance
// before each, its inputs, its GPS pose and that update's -2 log likelihood), and the switch
// time is estimated as a change point: for each GPS update k in that history, the prior is
// applied to the state before k (ICRs replaced, their covariance diag(sd^2), the pose and its
// covariance kept) and the steps from k on are filtered again; the score of k is the sum of
// the recorded -2 log likelihoods before k and the re-filtered ones from k (all candidates
// are scored on the same updates), and the lowest score wins (a generalised likelihood ratio
// over the change time). The paper's reset, the shadow, is applied at the same change time
// and filtered again over the same steps, so the check compares the two hypotheses on the
// same updates from the change time on.
//
// Fixed-size storage allocated at construction; no allocation per step or per reset.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "plexus/algorithms/core/history_ring.hpp"
#include "plexus/algorithms/skid_steer/icr_ekf.hpp"
#include "plexus/algorithms/skid_steer/terrain_icr_library.hpp"

namespace plexus::algorithms {

struct IcrTerrainResetOptions {
  int check_updates = 60;   ///< GPS updates the prior and the paper's reset are compared, >= 1
  double decisive = 10.0;   ///< summed -2 log likelihoods this far apart end the check (e^5), > 0
  double lead = 2.0;        ///< the paper's hypothesis is published once it leads by this, >= 0
  int rewind_steps = 0;     ///< filter steps kept to restart the reset at the switch, >= 0 (0: at the confirmation)
  int max_candidates = 60;  ///< GPS updates tried as change times (spread evenly over those kept), >= 1;
                            ///< then every step between the best one's neighbours
};

class IcrTerrainResetFilter {
 public:
  /// Validates both; throws std::invalid_argument naming the entry.
  IcrTerrainResetFilter(const IcrEkfParams& ekf, const IcrTerrainResetOptions& options);

  /// Starts the filter at the first GPS pose (x = pose and the initial ICRs, P = P_0).
  void start(const Pose2& z);
  bool started() const { return started_; }

  /// One filter step: predict over dt with u (when u != nullptr), then update with z (when
  /// z != nullptr). Returns whether z was applied. No allocation.
  bool step(const TrackSpeeds* u, double dt, const Pose2* z);

  /// A confirmed change of terrain: paper 001's covariance reset (prior == nullptr), or the
  /// prior reset with its check (above). No allocation.
  void terrain_changed(const TerrainIcrPrior* prior);

  /// The estimate to publish: the prior's, or the paper's hypothesis while it leads a check.
  const IcrEkf& published() const;
  const IcrEkf& filter() const { return ekf_; }
  long resets() const { return resets_; }
  /// Prior resets whose check the paper's hypothesis won.
  long fallbacks() const { return fallbacks_; }
  /// Steps the last reset moved the prior (or P_B) back by (0: applied at the confirmation).
  int last_rewind_steps() const { return last_rewind_; }
  /// Filter steps since the published estimate's model applies: since the switch time its
  /// reset placed it at (rewound resets re-estimate it), or since start() before any reset.
  long published_model_steps() const;
  bool checking() const { return checking_ > 0; }

 private:
  struct Record {
    IcrVector x;  ///< before the step
    IcrMatrix p;
    TrackSpeeds u;
    double dt = 0.0;
    bool predicted = false;
    bool updated = false;
    Pose2 z;
    double neg2ll = 0.0;  ///< of this step's update
  };
  enum class Hypothesis { kPrior, kPaper, kPaperIcrs };
  struct Change {
    int age = 0;         ///< steps back from the newest (0: none)
    double score = 0.0;  ///< summed -2 log likelihood over every kept update
  };
  int kept_updates() const;
  /// The hypothesis applied at its most likely change time among the kept GPS updates,
  /// written to `out` as filtered again to the newest step.
  Change best_change(Hypothesis h, const TerrainIcrPrior* prior, IcrEkf& out);
  /// kPrior: the prior's ICRs and sd, pose kept; kPaper: P = P_B (eq. (22)); kPaperIcrs:
  /// the ICRs kept with P_B's ICR block, pose kept.
  static void apply(IcrEkf& f, Hypothesis h, const TerrainIcrPrior* prior);
  /// Filters the kept steps from `age` down to the newest into f; the summed -2 log
  /// likelihood of its updates.
  double refilter(IcrEkf& f, int age) const;
  void check_prior();
  bool publishing_paper() const;

  IcrTerrainResetOptions options_;
  IcrEkf ekf_;
  IcrEkf shadow_;
  IcrEkf trial_;
  IcrEkf best_;
  HistoryRing<Record> history_;
  std::vector<double> older_;  ///< best_change's scratch: recorded -2 log likelihoods older than each age
  long steps_ = 0;             ///< steps since start()
  long since_prior_ = 0;       ///< step from which ekf_'s model applies
  long since_paper_ = 0;       ///< step from which shadow_'s model applies
  bool started_ = false;
  long resets_ = 0;
  long fallbacks_ = 0;
  int last_rewind_ = 0;
  int checking_ = 0;
  double neg2ll_prior_ = 0.0;
  double neg2ll_paper_ = 0.0;
};

}  // namespace plexus::algorithms
