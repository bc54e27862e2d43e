#include "semslam/association/JointCompatibility.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace semslam {

namespace {

class Search {
 public:
  Search(const std::vector<JointAssignmentRow>& rows, const JointDensity& density, const AssociationGate& gate,
         long maximumEvaluations)
      : rows_(rows), density_(density), gate_(gate), maximumEvaluations_(maximumEvaluations),
        boundOfRest_(rows.size() + 1, 0.0), options_(rows.size()), current_(rows.size(), -1) {
    // boundOfRest_[i]: an upper bound on what rows i… can add (the class comment of the header).
    for (std::size_t i = rows.size(); i-- > 0;) {
      double best = rows[i].unassignedLogLikelihood;
      for (double label : rows[i].labelLogLikelihoods) best = std::max(best, label - rows[i].logNormalizer);
      boundOfRest_[i] = boundOfRest_[i + 1] + best;
    }
    // Each row's options, most likely alone first (its unassigned hypothesis against each pairing's own density and
    // label): good assignments are found early, and the bound then cuts most of the rest.
    for (std::size_t i = 0; i < rows.size(); ++i) {
      std::vector<std::pair<double, int>> alone = {{rows[i].unassignedLogLikelihood, -1}};
      for (std::size_t c = 0; c < rows[i].candidates.size(); ++c) {
        alone.emplace_back(rows[i].pairingLogLikelihoods[c], static_cast<int>(c));
      }
      std::stable_sort(alone.begin(), alone.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
      for (const auto& [value, option] : alone) options_[i].push_back(option);
    }
  }

  /// The score of a complete assignment, or none where its pairings fail the joint gate.
  std::optional<double> score(const std::vector<int>& landmarkOfRow) {
    double total = 0.0, labelRatios = 0.0, density = 0.0;
    std::vector<std::pair<std::size_t, int>> pairings;
    for (std::size_t i = 0; i < rows_.size(); ++i) {
      if (landmarkOfRow[i] < 0) {
        total += rows_[i].unassignedLogLikelihood;
        continue;
      }
      pairings.emplace_back(i, landmarkOfRow[i]);
      const double label = labelOf(i, landmarkOfRow[i]);
      total += label;
      labelRatios += label - rows_[i].labelPriorLogLikelihood;
      const std::optional<double> joint = admissibleDensity(pairings, labelRatios);  // every prefix, as the search
      if (!joint) return std::nullopt;                                               // meets them
      density = *joint;
    }
    return total + density;
  }

  void seed(const std::vector<int>& incumbent, double value) {
    best_ = incumbent;
    bestScore_ = value;
  }

  /// Depth first from row i; `partial` is the score of rows 0…i−1 (their density included).
  void visit(std::size_t i, double partial, std::vector<std::pair<std::size_t, int>>& pairings, double density,
             double labelRatios) {
    if (budgetSpent_) return;
    if (partial + boundOfRest_[i] <= bestScore_) return;  // cannot beat the incumbent
    if (i == rows_.size()) {
      bestScore_ = partial;
      best_ = current_;
      return;
    }
    const JointAssignmentRow& row = rows_[i];
    for (int option : options_[i]) {
      if (option < 0) {
        current_[i] = -1;
        visit(i + 1, partial + row.unassignedLogLikelihood, pairings, density, labelRatios);
        if (budgetSpent_) return;
        continue;
      }
      const std::size_t c = static_cast<std::size_t>(option);
      const int landmark = row.candidates[c];
      if (std::find(current_.begin(), current_.begin() + static_cast<std::ptrdiff_t>(i), landmark) !=
          current_.begin() + static_cast<std::ptrdiff_t>(i)) {
        continue;  // exclusion
      }
      // The pairing's own bound first: a branch that cannot win is not worth a joint density.
      const double label = row.labelLogLikelihoods[c];
      if (partial + label - row.logNormalizer + boundOfRest_[i + 1] <= bestScore_) continue;
      if (evaluations_ >= maximumEvaluations_) {
        budgetSpent_ = true;
        return;
      }
      pairings.emplace_back(i, landmark);
      const double ratios = labelRatios + label - row.labelPriorLogLikelihood;
      const std::optional<double> joint = admissibleDensity(pairings, ratios);
      if (joint) {
        current_[i] = landmark;
        visit(i + 1, partial - density + label + *joint, pairings, *joint, ratios);
        current_[i] = -1;
      }
      pairings.pop_back();
      if (budgetSpent_) return;
    }
  }

  std::vector<int> best_;
  double bestScore_ = -std::numeric_limits<double>::infinity();
  long evaluations_ = 0;
  bool budgetSpent_ = false;

 private:
  double labelOf(std::size_t i, int landmark) const {
    const JointAssignmentRow& row = rows_[i];
    const auto at = std::find(row.candidates.begin(), row.candidates.end(), landmark);
    return row.labelLogLikelihoods[static_cast<std::size_t>(at - row.candidates.begin())];
  }

  /// ln N(ν_P; 0, S_P) where the pairings pass the joint gate (`labelRatios`: Σ ln(P(s_i | j) / P₀(s_i))), else none.
  std::optional<double> admissibleDensity(const std::vector<std::pair<std::size_t, int>>& pairings,
                                          double labelRatios) {
    ++evaluations_;
    const LinearizedLikelihood joint = density_(pairings);
    const double statistic = joint.innovationChi2 - 2.0 * labelRatios;
    if (!(statistic <= gate_.threshold(joint.dimension))) return std::nullopt;  // jointly incompatible
    return joint.logLikelihood;
  }

  const std::vector<JointAssignmentRow>& rows_;
  const JointDensity& density_;
  const AssociationGate& gate_;
  long maximumEvaluations_;
  std::vector<double> boundOfRest_;
  std::vector<std::vector<int>> options_;  // per row: −1 (unassigned) and candidate indices, in the order tried
  std::vector<int> current_;
};

void checkProblem(const std::vector<JointAssignmentRow>& rows, const std::vector<int>& incumbent,
                  long maximumEvaluations) {
  if (maximumEvaluations < 1) throw std::invalid_argument("joint compatibility: the evaluation budget must be >= 1");
  if (incumbent.size() != rows.size()) {
    throw std::invalid_argument("joint compatibility: the incumbent has " + std::to_string(incumbent.size()) +
                                " entries for " + std::to_string(rows.size()) + " rows");
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const JointAssignmentRow& row = rows[i];
    if (row.labelLogLikelihoods.size() != row.candidates.size() ||
        row.pairingLogLikelihoods.size() != row.candidates.size()) {
      throw std::invalid_argument("joint compatibility: row " + std::to_string(i) + " has " +
                                  std::to_string(row.candidates.size()) + " candidates, " +
                                  std::to_string(row.labelLogLikelihoods.size()) + " label log-likelihoods and " +
                                  std::to_string(row.pairingLogLikelihoods.size()) + " pairing log-likelihoods");
    }
    const int given = incumbent[i];
    if (given < 0) continue;
    if (std::find(row.candidates.begin(), row.candidates.end(), given) == row.candidates.end()) {
      throw std::invalid_argument("joint compatibility: the incumbent gives row " + std::to_string(i) +
                                  " landmark " + std::to_string(given) + ", not one of its candidates");
    }
    if (std::count(incumbent.begin(), incumbent.end(), given) > 1) {
      throw std::invalid_argument("joint compatibility: the incumbent gives landmark " + std::to_string(given) +
                                  " twice");
    }
  }
}

}  // namespace

JointAssignment jointlyCompatibleAssignment(const std::vector<JointAssignmentRow>& rows, const JointDensity& density,
                                            const AssociationGate& gate, const std::vector<int>& incumbent,
                                            long maximumEvaluations) {
  checkProblem(rows, incumbent, maximumEvaluations);
  Search search(rows, density, gate, maximumEvaluations);
  // Every row unassigned is always admissible; the incumbent replaces it where admissible and better.
  std::vector<int> none(rows.size(), -1);
  search.seed(none, *search.score(none));
  if (const std::optional<double> given = search.score(incumbent); given && *given >= search.bestScore_) {
    search.seed(incumbent, *given);
  }
  std::vector<std::pair<std::size_t, int>> pairings;
  search.visit(0, 0.0, pairings, 0.0, 0.0);
  JointAssignment result;
  result.landmarkOfRow = search.best_;
  result.logLikelihood = search.bestScore_;
  result.exhaustive = !search.budgetSpent_;
  result.evaluations = search.evaluations_;
  return result;
}

}  // namespace semslam
