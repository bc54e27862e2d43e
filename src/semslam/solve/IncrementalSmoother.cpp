#include "semslam/solve/IncrementalSmoother.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <unordered_set>

#include "semslam/solve/ConstrainedOrdering.h"
#include "semslam/solve/SymbolicElimination.h"
#include "semslam/solve/UnconstrainedSystem.h"

namespace semslam {

namespace {

/// `lists` resized to `count` empty lists, keeping the storage of those that existed.
std::vector<std::vector<int>>& reuseLists(std::vector<std::vector<int>>& lists, int count) {
  lists.resize(count);
  for (int i = 0; i < count; ++i) lists[i].clear();
  return lists;
}

}  // namespace

IncrementalSmoother::IncrementalSmoother(IncrementalSmootherParams params) : params_(params) {}

// ---- bookkeeping -------------------------------------------------------------------------------------------

void IncrementalSmoother::validate(const FactorGraph& newFactors, const Values& newValues,
                                   const std::vector<FactorIndex>& removed) const {
  std::unordered_set<FactorIndex> seen;
  for (FactorIndex index : removed) {
    if (index >= slots_.size() || !slots_[index].factor || !seen.insert(index).second) {
      throw std::invalid_argument("IncrementalSmoother::update: no factor with index " + std::to_string(index));
    }
  }
  for (const auto& [key, value] : newValues) {
    if (variableIds_.count(key)) {
      throw std::invalid_argument("IncrementalSmoother::update: variable " + keyToString(key) + " exists");
    }
  }
  for (const auto& factor : newFactors) {
    if (!factor) throw std::invalid_argument("IncrementalSmoother::update: null factor");
    std::vector<Key> keys = factor->keys();
    for (Key key : keys) {
      if (!variableIds_.count(key) && !newValues.exists(key)) {
        throw std::invalid_argument("IncrementalSmoother::update: a new factor names variable " + keyToString(key) +
                                    ", which has no value");
      }
    }
    std::sort(keys.begin(), keys.end());
    if (std::adjacent_find(keys.begin(), keys.end()) != keys.end()) {
      throw std::invalid_argument("IncrementalSmoother::update: a factor names one variable twice");
    }
  }
}

int IncrementalSmoother::addVariable(Key key, const Value& value) {
  const int id = static_cast<int>(variables_.size());
  Variable variable;
  variable.key = key;
  variable.dimension = semslam::dimension(value);
  variable.offset = static_cast<int>(delta_.size());
  variables_.push_back(std::move(variable));
  variableIds_.emplace(key, id);
  theta_.insert(key, value);
  thetaById_.push_back(value);
  estimate_.insert(key, value);
  estimateSlots_.push_back(const_cast<Value*>(&estimate_.value(key)));  // std::map nodes never move
  delta_.resize(delta_.size() + variables_.back().dimension, 0.0);
  deltaAtMixtureCheck_.resize(delta_.size(), 0.0);
  isStale_.push_back(0);
  isCandidate_.push_back(0);
  return id;
}

void IncrementalSmoother::attach(int slot) {
  const std::vector<int>& joined = slots_[slot].variables;
  for (int v : joined) {
    variables_[v].factors.push_back(slot);
    const int partner = joined.size() == 1 ? v : joined.size() == 2 ? joined[joined[0] == v ? 1 : 0] : -1;
    variables_[v].partners.push_back(partner);
  }
}

void IncrementalSmoother::detach(int slot) {
  for (int v : slots_[slot].variables) {
    auto& list = variables_[v].factors;
    const auto at = std::find(list.begin(), list.end(), slot);
    variables_[v].partners.erase(variables_[v].partners.begin() + (at - list.begin()));
    list.erase(at);
  }
}

double IncrementalSmoother::deltaNorm(int variable) const {
  const Variable& v = variables_[variable];
  double norm = 0.0;
  for (int i = 0; i < v.dimension; ++i) norm = std::max(norm, std::abs(delta_[v.offset + i]));
  return norm;
}

void IncrementalSmoother::relinearize(int variable) {
  Variable& v = variables_[variable];
  Eigen::Map<Vector> delta(delta_.data() + v.offset, v.dimension);
  thetaById_[variable] = retract(thetaById_[variable], delta);
  theta_.update(v.key, thetaById_[variable]);
  delta.setZero();
  // Its factors are linearized afresh at θ_v, which is the estimate now: its mixtures choose there.
  std::fill_n(deltaAtMixtureCheck_.begin() + v.offset, v.dimension, 0.0);
  for (int slot : v.factors) slots_[slot].linearization.reset();
}

void IncrementalSmoother::markStale(int variable) const {
  if (!isStale_[variable]) {
    isStale_[variable] = 1;
    staleEstimates_.push_back(variable);
  }
}

int IncrementalSmoother::allocateClique() {
  if (!freeCliques_.empty()) {
    const int id = freeCliques_.back();
    freeCliques_.pop_back();
    return id;
  }
  cliques_.emplace_back();
  return static_cast<int>(cliques_.size()) - 1;
}

void IncrementalSmoother::freeClique(int id) {
  Clique& clique = cliques_[id];
  factorEntries_ -= entries(clique);
  // Emptied, not destroyed: the next clique to take this id reuses the lists' storage.
  clique.frontals.clear();
  clique.separator.clear();
  clique.children.clear();
  clique.parent = -1;
  clique.conditional.reset();
  freeCliques_.push_back(id);
}

std::size_t IncrementalSmoother::entries(const Clique& clique) const {
  if (!clique.conditional) return 0;
  const std::size_t nf = clique.conditional->R.rows();
  const std::size_t ns = clique.conditional->T.cols();
  return nf * (nf + 1) / 2 + nf * ns;
}

// ---- update ------------------------------------------------------------------------------------------------

std::vector<FactorIndex> IncrementalSmoother::update(const FactorGraph& newFactors, const Values& newValues,
                                                     const std::vector<FactorIndex>& removed) {
  validate(newFactors, newValues, removed);
  lastUpdate_ = UpdateStatistics();
  for (const auto& [key, value] : newValues) addVariable(key, value);

  MarkedVariables marked;
  marked.isMarked.assign(variables_.size(), 0);
  for (int v : pendingMarked_) marked.mark(v);
  pendingMarked_.clear();
  for (FactorIndex index : removed) {
    Slot& slot = slots_[index];
    for (int v : slot.variables) marked.mark(v);
    detach(static_cast<int>(index));
    slot = Slot();
  }
  std::vector<FactorIndex> indices;
  std::vector<bool> constrainedLast(variables_.size(), false);
  for (const auto& factor : newFactors) {
    const int index = static_cast<int>(slots_.size());
    indices.push_back(index);
    Slot slot;
    slot.factor = factor;
    for (Key key : factor->keys()) slot.variables.push_back(variableIds_.at(key));
    slots_.push_back(std::move(slot));
    attach(index);
    for (int v : slots_[index].variables) {
      marked.mark(v);
      constrainedLast[v] = true;
    }
  }

  // Fluid relinearization (iSAM2 Alg. 6, steps 4–5).
  const bool checkRelinearization =
      forceFull_ || (params_.relinearizeSkip > 0 && updates_ % params_.relinearizeSkip == 0);
  if (checkRelinearization) {
    // Only a variable whose Δ changed since its last check can have crossed the threshold.
    std::vector<int> candidates;
    if (forceFull_) {
      candidates.resize(variables_.size());
      std::iota(candidates.begin(), candidates.end(), 0);
    } else {
      candidates.swap(relinearizationCandidates_);
    }
    for (int v : candidates) isCandidate_[v] = 0;
    relinearizationCandidates_.clear();
    for (int v : candidates) {
      if (variables_[v].clique < 0) continue;
      const double norm = deltaNorm(v);
      if (forceFull_ ? norm > 0.0 : norm > params_.relinearizeThreshold) relinearizeAndMark(v, marked);
    }
  }
  ++updates_;

  // Mixtures entering the graph choose at the estimate (class comment, step 0).
  std::vector<int> entering;
  entering.swap(pendingReplaced_);
  if (params_.maxSwitchRounds > 0 && !forceFull_) {
    entering.insert(entering.end(), indices.begin(), indices.end());
    relinearizeMixtures(switchedMixtures(entering, true), marked);
  }

  // Need-based reordering, or convergeAll(): the whole tree.
  const std::size_t treeVariables = variables_.size();
  const bool fillGrew = params_.reorderFillGrowth > 0.0 && entriesPerVariableAtReorder_ > 0.0 &&
                        static_cast<double>(factorEntries_) / static_cast<double>(treeVariables) >
                            params_.reorderFillGrowth * entriesPerVariableAtReorder_;
  const bool full = forceFull_ || fillGrew;
  if (full) {
    for (int v = 0; v < static_cast<int>(variables_.size()); ++v) {
      if (!variables_[v].factors.empty() || variables_[v].clique >= 0) marked.mark(v);
    }
    if (forceFull_) std::fill(constrainedLast.begin(), constrainedLast.end(), false);
  }
  lastUpdate_.fullReordering = full;

  scratch_.linearizedMixtures.clear();
  scratch_.changedVariables.clear();
  const std::vector<int> newCliques = reeliminate(marked.list, constrainedLast);
  if (full || entriesPerVariableAtReorder_ == 0.0) {
    entriesPerVariableAtReorder_ = static_cast<double>(factorEntries_) / static_cast<double>(treeVariables);
  }
  const double wildfireThreshold = forceFull_ ? 0.0 : params_.wildfireThreshold;
  backSubstitute(newCliques, wildfireThreshold);
  if (params_.maxSwitchRounds > 0) settleMixtures(constrainedLast, wildfireThreshold);
  return indices;
}

void IncrementalSmoother::relinearizeAndMark(int variable, MarkedVariables& marked) {
  relinearize(variable);
  ++lastUpdate_.relinearizedVariables;
  for (int slot : variables_[variable].factors) {
    for (int u : slots_[slot].variables) marked.mark(u);
  }
}

std::vector<int> IncrementalSmoother::reeliminate(const std::vector<int>& marked,
                                                  const std::vector<bool>& constrainedLast) {
  ReeliminatedPart part = detachTop(marked);
  const std::vector<int>& eliminated = part.variables;
  lastUpdate_.reeliminatedVariables += static_cast<int>(eliminated.size());
  const int m = static_cast<int>(eliminated.size());
  if (m == 0) {
    if (!part.orphans.empty()) throw std::logic_error("IncrementalSmoother: orphans without a re-eliminated parent");
    return {};
  }

  // Local numbering of the re-eliminated variables (localIndexOf), for the phases below.
  std::vector<int>& localIndex = scratch_.localIndex;
  localIndex.resize(variables_.size(), -1);
  for (int i = 0; i < m; ++i) localIndex[eliminated[i]] = i;
  struct ResetLocal {  // leaves the scratch all −1 however this function exits
    std::vector<int>& index;
    const std::vector<int>& variables;
    ~ResetLocal() {
      for (int v : variables) index[v] = -1;
    }
  } resetLocal{localIndex, eliminated};

  const std::vector<int> gathered = gatherFactorsInside(eliminated);
  linearizeStale(gathered);
  const std::vector<int> order = orderPart(part, gathered, constrainedLast);
  std::vector<int> rank(m);  // local index -> position in the elimination order
  for (int k = 0; k < m; ++k) rank[order[k]] = k;
  const std::vector<int> cliqueIds = buildCliques(part, order, rank);
  eliminateCliques(cliqueIds, gathered, rank);
  return cliqueIds;
}

// Step 2: removes the cliques of the marked variables and their ancestors. The variables to re-eliminate are the
// frontals of the removed cliques and the marked variables outside the tree, less those that lost all their
// factors (they leave the tree at their estimate); the orphans are the removed cliques' children that stay.
IncrementalSmoother::ReeliminatedPart IncrementalSmoother::detachTop(const std::vector<int>& marked) {
  std::vector<int> removedCliques;
  std::vector<char> isRemoved(cliques_.size(), 0);
  for (int v : marked) {
    for (int c = variables_[v].clique; c >= 0 && !isRemoved[c]; c = cliques_[c].parent) {
      isRemoved[c] = 1;
      removedCliques.push_back(c);
    }
  }
  ReeliminatedPart part;
  std::vector<int>& eliminated = part.variables;
  for (int c : removedCliques) {
    for (int v : cliques_[c].frontals) eliminated.push_back(v);
  }
  for (int v : marked) {
    if (variables_[v].clique < 0) eliminated.push_back(v);
  }
  for (int c : removedCliques) {
    for (int child : cliques_[c].children) {
      if (!isRemoved[child]) part.orphans.push_back(child);
    }
  }
  roots_.erase(std::remove_if(roots_.begin(), roots_.end(), [&](int c) { return isRemoved[c] != 0; }),
               roots_.end());
  for (int c : removedCliques) freeClique(c);
  for (int v : eliminated) variables_[v].clique = -1;
  eliminated.erase(std::remove_if(eliminated.begin(), eliminated.end(),
                                  [&](int v) {
                                    if (!variables_[v].factors.empty()) return false;
                                    relinearize(v);
                                    markStale(v);
                                    return true;
                                  }),
                   eliminated.end());
  return part;
}

// Step 3, gathering: the factors whose variables all lie in the re-eliminated part, each once, in order of first
// touch by `eliminated` (the others are summarised in the orphans' marginals).
std::vector<int> IncrementalSmoother::gatherFactorsInside(const std::vector<int>& eliminated) {
  std::vector<int> gathered;
  std::vector<int>& seen = scratch_.slotStamp;
  seen.resize(slots_.size(), 0);
  const int stamp = ++scratch_.stamp;
  for (int v : eliminated) {  // v is inside: a factor is when its partner is (or, of 3+ variables, all of them are)
    const Variable& variable = variables_[v];
    for (std::size_t i = 0; i < variable.factors.size(); ++i) {
      const int slot = variable.factors[i], partner = variable.partners[i];
      if (partner >= 0 && localIndexOf(partner) < 0) continue;
      if (seen[slot] == stamp) continue;
      seen[slot] = stamp;
      bool inside = true;
      if (partner < 0) {
        for (int u : slots_[slot].variables) inside = inside && localIndexOf(u) >= 0;
      }
      if (inside) gathered.push_back(slot);
    }
  }
  return gathered;
}

// Step 3, relinearization: each stale factor's information form at θ, JᵀJ and −Jᵀr over its stacked variables.
void IncrementalSmoother::linearizeStale(const std::vector<int>& slots) {
  for (int slot : slots) {
    Slot& s = slots_[slot];
    if (!s.linearization) {
      LinearizedFactor& lin = scratch_.linearized;
      s.factor->linearize(theta_, lin);
      auto contribution = std::make_shared<FactorContribution>();
      int total = 0;
      for (const Matrix& J : lin.jacobians) {
        contribution->offsets.push_back(total);
        total += static_cast<int>(J.cols());
      }
      Matrix J(lin.whitenedError.size(), total);
      for (std::size_t p = 0; p < lin.jacobians.size(); ++p) {
        J.middleCols(contribution->offsets[p], lin.jacobians[p].cols()) = lin.jacobians[p];
      }
      contribution->information.noalias() = J.transpose() * J;
      contribution->vector.noalias() = -(J.transpose() * lin.whitenedError);
      s.linearization = std::move(contribution);
      if (params_.maxSwitchRounds > 0) {  // the mixtures' rule only (class comment); off, nothing is recorded
        s.component = s.factor->activeComponent(theta_);
        if (s.component >= 0) scratch_.linearizedMixtures.push_back(slot);
      }
    }
  }
}

// Step 3, ordering: the part's adjacency (gathered factors and orphan separators, in scratch_.neighbours, which
// buildCliques reads) ordered by CAMD with the variables of the new factors last; returns order[k] = the local
// index eliminated k-th.
std::vector<int> IncrementalSmoother::orderPart(const ReeliminatedPart& part, const std::vector<int>& gathered,
                                                const std::vector<bool>& constrainedLast) {
  const int m = static_cast<int>(part.variables.size());
  std::vector<std::vector<int>>& neighbours = reuseLists(scratch_.neighbours, m);
  const auto connect = [&](const std::vector<int>& variables) {
    for (std::size_t p = 1; p < variables.size(); ++p) {
      const int a = localIndexOf(variables[p]);
      for (std::size_t q = 0; q < p; ++q) neighbours[a].push_back(localIndexOf(variables[q]));
    }
  };
  for (int slot : gathered) connect(slots_[slot].variables);
  for (int orphan : part.orphans) connect(cliques_[orphan].separator);
  std::vector<bool> last(m);
  for (int i = 0; i < m; ++i) last[i] = constrainedLast[part.variables[i]];
  return constrainedOrdering(neighbours, last);
}

// Step 4a: symbolic elimination in rank space (SymbolicElimination.h, left in scratch_.symbolic): column
// structures, elimination tree, cliques. Allocates the new cliques, links them into the tree (roots, parents,
// children) and hangs each orphan below the clique of its first-ordered separator variable; returns their ids,
// indexed like scratch_.symbolic's cliques.
std::vector<int> IncrementalSmoother::buildCliques(const ReeliminatedPart& part, const std::vector<int>& order,
                                                   const std::vector<int>& rank) {
  const int m = static_cast<int>(part.variables.size());
  const std::vector<std::vector<int>>& neighbours = scratch_.neighbours;
  std::vector<std::vector<int>>& later = reuseLists(scratch_.later, m);
  for (int a = 0; a < m; ++a) {
    for (int b : neighbours[a]) {
      const int ra = rank[a];
      const int rb = rank[b];
      if (ra < rb) {
        later[ra].push_back(rb);
      } else if (rb < ra) {
        later[rb].push_back(ra);
      }
    }
  }
  SymbolicElimination& symbolic = scratch_.symbolic;
  symbolic.eliminate(later, params_.relaxedCliqueFrontals, params_.relaxedCliqueZeros);
  const int newCount = symbolic.cliqueCount();
  lastUpdate_.reeliminatedCliques += newCount;
  std::vector<int> cliqueIds(newCount);
  for (int i = 0; i < newCount; ++i) cliqueIds[i] = allocateClique();
  const auto globalOfRank = [&](int r) { return part.variables[order[r]]; };
  for (int i = 0; i < newCount; ++i) {
    Clique& clique = cliques_[cliqueIds[i]];
    for (int r : symbolic.frontals(i)) {
      clique.frontals.push_back(globalOfRank(r));
      variables_[globalOfRank(r)].clique = cliqueIds[i];
    }
    for (int r : symbolic.separator(i)) clique.separator.push_back(globalOfRank(r));
    if (symbolic.parent(i) < 0) {
      roots_.push_back(cliqueIds[i]);
    } else {
      clique.parent = cliqueIds[symbolic.parent(i)];
    }
  }
  for (int i = 0; i < newCount; ++i) {
    const int id = cliqueIds[i];
    if (cliques_[id].parent >= 0) cliques_[cliques_[id].parent].children.push_back(id);
  }
  for (int orphan : part.orphans) {
    int first = m;
    for (int v : cliques_[orphan].separator) first = std::min(first, rank[localIndexOf(v)]);
    const int id = cliqueIds[symbolic.cliqueOf(first)];
    cliques_[orphan].parent = id;
    cliques_[id].children.push_back(orphan);
  }
  return cliqueIds;
}

// Step 4b: numeric elimination of the new cliques, children before parents: by increasing last frontal (a child's
// last frontal precedes its parent variable, which is a frontal of the parent clique). Each gathered factor goes
// to the clique of its first-ordered variable; each clique's dense system is the extend-add of its factors'
// information and its children's marginals, and its conditional comes from CliqueConditional::eliminate.
void IncrementalSmoother::eliminateCliques(const std::vector<int>& cliqueIds, const std::vector<int>& gathered,
                                           const std::vector<int>& rank) {
  const SymbolicElimination& symbolic = scratch_.symbolic;
  const int m = static_cast<int>(rank.size());
  const int newCount = static_cast<int>(cliqueIds.size());
  std::vector<std::vector<int>>& factorsOfClique = reuseLists(scratch_.factorsOfClique, newCount);
  for (int slot : gathered) {
    int first = m;
    for (int v : slots_[slot].variables) first = std::min(first, rank[localIndexOf(v)]);
    factorsOfClique[symbolic.cliqueOf(first)].push_back(slot);
  }
  std::vector<int> byLastFrontal(newCount);
  std::iota(byLastFrontal.begin(), byLastFrontal.end(), 0);
  std::sort(byLastFrontal.begin(), byLastFrontal.end(),
            [&](int a, int b) { return symbolic.frontals(a).back() < symbolic.frontals(b).back(); });
  std::vector<int>& scalarOffset = scratch_.scalarOffset;
  scalarOffset.resize(variables_.size());
  for (int i : byLastFrontal) {
    Clique& clique = cliques_[cliqueIds[i]];
    int n = 0;
    for (int v : clique.frontals) {
      scalarOffset[v] = n;
      n += variables_[v].dimension;
    }
    const int nf = n;
    for (int v : clique.separator) {
      scalarOffset[v] = n;
      n += variables_[v].dimension;
    }
    std::vector<double>& storage = scratch_.cliqueSystem;
    if (storage.size() < static_cast<std::size_t>(n) * (n + 1)) storage.resize(static_cast<std::size_t>(n) * (n + 1));
    std::fill(storage.begin(), storage.begin() + static_cast<std::ptrdiff_t>(n) * (n + 1), 0.0);
    Eigen::Map<Matrix> A(storage.data(), n, n);
    Eigen::Map<Vector> b(storage.data() + static_cast<std::ptrdiff_t>(n) * n, n);
    // Extend-add: each factor's information and each child's marginal, scattered scalar by scalar through the
    // positions of their variables in this clique.
    std::vector<int>& positions = scratch_.positions;
    const auto scatter = [&](const std::vector<int>& variables, Eigen::Ref<const Matrix> information,
                             Eigen::Ref<const Vector> vector) {
      positions.clear();
      for (int v : variables) {
        for (int d = 0; d < variables_[v].dimension; ++d) positions.push_back(scalarOffset[v] + d);
      }
      const int size = static_cast<int>(positions.size());
      for (int c = 0; c < size; ++c) {
        double* column = A.data() + static_cast<Eigen::Index>(positions[c]) * n;
        const double* source = information.data() + static_cast<Eigen::Index>(c) * information.outerStride();
        for (int r = 0; r < size; ++r) column[positions[r]] += source[r];
        b[positions[c]] += vector[c];
      }
    };
    for (int slot : factorsOfClique[i]) {
      const Slot& s = slots_[slot];
      scatter(s.variables, s.linearization->information, s.linearization->vector);
    }
    for (int child : clique.children) {
      const Clique& c = cliques_[child];
      scatter(c.separator, c.conditional->marginalInformation, c.conditional->marginalVector);
    }
    auto conditional = std::make_shared<CliqueConditional>();
    if (!CliqueConditional::eliminate(A, b, nf, *conditional)) throwUnconstrained(factors(), theta_);
    clique.conditional = std::move(conditional);
    factorEntries_ += entries(clique);
  }
}

void IncrementalSmoother::backSubstitute(const std::vector<int>& newCliques, double wildfireThreshold) {
  std::vector<char> isNew(cliques_.size(), 0);
  for (int c : newCliques) isNew[c] = 1;
  std::vector<char> moved(variables_.size(), 0);
  std::vector<int> stack;
  for (int root : roots_) {
    if (isNew[root]) stack.push_back(root);
  }
  std::vector<double>& buffer = scratch_.solveBuffer;
  while (!stack.empty()) {
    const int id = stack.back();
    stack.pop_back();
    const Clique& clique = cliques_[id];
    ++lastUpdate_.solvedCliques;
    const int nfTotal = static_cast<int>(clique.conditional->R.rows());
    const int nsTotal = static_cast<int>(clique.conditional->T.cols());
    if (buffer.size() < static_cast<std::size_t>(nfTotal + nsTotal)) buffer.resize(nfTotal + nsTotal);
    double* gathered = buffer.data() + nfTotal;
    for (int v : clique.separator) {
      const Variable& variable = variables_[v];
      std::copy(delta_.begin() + variable.offset, delta_.begin() + variable.offset + variable.dimension, gathered);
      gathered += variable.dimension;
    }
    Eigen::Map<Vector> frontalDelta(buffer.data(), nfTotal);
    clique.conditional->solve(Eigen::Map<const Vector>(buffer.data() + nfTotal, nsTotal), frontalDelta);
    int nf = 0;
    for (int v : clique.frontals) {
      const Variable& variable = variables_[v];
      Eigen::Map<Vector> delta(delta_.data() + variable.offset, variable.dimension);
      const auto updated = frontalDelta.segment(nf, variable.dimension);
      const double change = (updated - delta).cwiseAbs().maxCoeff();
      if (change > wildfireThreshold) moved[v] = 1;
      if (change > 0.0) {
        delta = updated;
        markStale(v);
        scratch_.changedVariables.push_back(v);
        if (!isCandidate_[v]) {
          isCandidate_[v] = 1;
          relinearizationCandidates_.push_back(v);
        }
      }
      nf += variable.dimension;
    }
    // A child's separator lies in this clique's variables: if none of them moved, only new children need solving.
    bool anyMoved = false;
    for (int v : clique.frontals) anyMoved = anyMoved || moved[v];
    for (int v : clique.separator) anyMoved = anyMoved || moved[v];
    for (int child : clique.children) {
      bool visit = isNew[child] != 0;
      if (!anyMoved && !visit) continue;
      for (std::size_t i = 0; !visit && i < cliques_[child].separator.size(); ++i) {
        visit = moved[cliques_[child].separator[i]] != 0;
      }
      if (visit) stack.push_back(child);
    }
  }
}

void IncrementalSmoother::replaceFactor(FactorIndex index, FactorPtr factor) {
  if (index >= slots_.size() || !slots_[index].factor) {
    throw std::invalid_argument("IncrementalSmoother::replaceFactor: no factor with index " + std::to_string(index));
  }
  if (!factor) throw std::invalid_argument("IncrementalSmoother::replaceFactor: null factor");
  std::vector<int> variables;
  for (Key key : factor->keys()) {
    const auto it = variableIds_.find(key);
    if (it == variableIds_.end()) {
      throw std::invalid_argument("IncrementalSmoother::replaceFactor: the factor names variable " +
                                  keyToString(key) + ", which has no value");
    }
    variables.push_back(it->second);
  }
  Slot& slot = slots_[index];
  pendingMarked_.insert(pendingMarked_.end(), slot.variables.begin(), slot.variables.end());
  pendingMarked_.insert(pendingMarked_.end(), variables.begin(), variables.end());
  pendingReplaced_.push_back(static_cast<int>(index));
  detach(static_cast<int>(index));
  slot.factor = std::move(factor);
  slot.variables = std::move(variables);
  slot.linearization.reset();
  attach(static_cast<int>(index));
}

// ---- queries -----------------------------------------------------------------------------------------------

const Values& IncrementalSmoother::estimate() const {
  for (int v : staleEstimates_) {
    const Variable& variable = variables_[v];
    *estimateSlots_[v] =
        retract(thetaById_[v], Eigen::Map<const Vector>(delta_.data() + variable.offset, variable.dimension));
    isStale_[v] = 0;
  }
  staleEstimates_.clear();
  return estimate_;
}

FactorGraph IncrementalSmoother::factors() const {
  FactorGraph graph;
  for (const Slot& slot : slots_) {
    if (slot.factor) graph.add(slot.factor);
  }
  return graph;
}

FactorPtr IncrementalSmoother::factor(FactorIndex index) const { return slots_.at(index).factor; }

std::unique_ptr<Smoother> IncrementalSmoother::fork() const {
  std::unique_ptr<IncrementalSmoother> copy(new IncrementalSmoother(*this));
  // The copy's estimate is a new map: point its slots at its own nodes.
  for (std::size_t v = 0; v < variables_.size(); ++v) {
    copy->estimateSlots_[v] = const_cast<Value*>(&copy->estimate_.value(variables_[v].key));
  }
  return copy;
}

JointMarginal IncrementalSmoother::jointMarginal(const std::vector<Key>& keys) const {
  std::vector<int> requested;
  std::vector<int> dimensions;
  for (Key key : keys) {
    const auto it = variableIds_.find(key);
    if (it == variableIds_.end() || variables_[it->second].clique < 0) {
      throw std::out_of_range("jointMarginal: variable " + keyToString(key) + " is not in the system");
    }
    requested.push_back(it->second);
    dimensions.push_back(variables_[it->second].dimension);
  }
  {
    std::vector<int> sorted = requested;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) {
      throw std::invalid_argument("jointMarginal: a key is repeated");
    }
  }
  // The cliques on the paths from the keys to the root, with their depths. L⁻¹ e_j is zero outside the path of
  // e_j's clique, and the back-substitution for a clique needs only its ancestors.
  std::unordered_map<int, int> depth;
  std::vector<int> path;
  for (int v : requested) {
    path.clear();
    int c = variables_[v].clique;
    while (c >= 0 && !depth.count(c)) {
      path.push_back(c);
      c = cliques_[c].parent;
    }
    int d = (c >= 0) ? depth.at(c) : -1;
    for (auto it = path.rbegin(); it != path.rend(); ++it) depth.emplace(*it, ++d);
  }
  std::vector<int> cliques;
  for (const auto& [c, d] : depth) cliques.push_back(c);
  std::sort(cliques.begin(), cliques.end(), [&](int a, int b) {
    const int da = depth.at(a);
    const int db = depth.at(b);
    return da != db ? da > db : a < b;
  });  // deepest first: children before parents
  std::unordered_map<int, int> row;  // variable -> first row in Y
  int rows = 0;
  for (int c : cliques) {
    for (int v : cliques_[c].frontals) {
      row.emplace(v, rows);
      rows += variables_[v].dimension;
    }
  }
  const int k = std::accumulate(dimensions.begin(), dimensions.end(), 0);
  Matrix Y = Matrix::Zero(rows, k);
  int column = 0;
  for (std::size_t i = 0; i < requested.size(); ++i) {
    Y.block(row.at(requested[i]), column, dimensions[i], dimensions[i]).setIdentity();
    column += dimensions[i];
  }
  // Forward: Rᵀ y = e, bottom-up.
  for (int c : cliques) {
    const Clique& clique = cliques_[c];
    const CliqueConditional& conditional = *clique.conditional;
    const int first = row.at(clique.frontals.front());
    const int nf = static_cast<int>(conditional.R.rows());
    auto yF = Y.middleRows(first, nf);
    conditional.R.transpose().triangularView<Eigen::Lower>().solveInPlace(yF);
    int offset = 0;
    for (int v : clique.separator) {
      const int d = variables_[v].dimension;
      Y.middleRows(row.at(v), d).noalias() -= conditional.T.middleCols(offset, d).transpose() * yF;
      offset += d;
    }
  }
  // Backward: R x = y, top-down.
  for (auto it = cliques.rbegin(); it != cliques.rend(); ++it) {
    const Clique& clique = cliques_[*it];
    const CliqueConditional& conditional = *clique.conditional;
    const int first = row.at(clique.frontals.front());
    const int nf = static_cast<int>(conditional.R.rows());
    auto xF = Y.middleRows(first, nf);
    int offset = 0;
    for (int v : clique.separator) {
      const int d = variables_[v].dimension;
      xF.noalias() -= conditional.T.middleCols(offset, d) * Y.middleRows(row.at(v), d);
      offset += d;
    }
    conditional.R.triangularView<Eigen::Upper>().solveInPlace(xF);
  }
  Matrix covariance(k, k);
  column = 0;
  for (std::size_t i = 0; i < requested.size(); ++i) {
    covariance.middleRows(column, dimensions[i]) = Y.middleRows(row.at(requested[i]), dimensions[i]);
    column += dimensions[i];
  }
  covariance = 0.5 * (covariance + covariance.transpose()).eval();
  return JointMarginal(keys, std::move(dimensions), std::move(covariance));
}

// ---- convergence -------------------------------------------------------------------------------------------

OptimizationResult IncrementalSmoother::convergeAll(const OptimizerParams& params) {
  // Batch Gauss-Newton (CHOLMOD) from the estimate, then the tree rebuilt at the optimum: θ ← optimum, Δ ← 0,
  // every factor relinearized, everything re-eliminated and solved exactly (the step from the optimum is ~0).
  const FactorGraph graph = factors();
  if (graph.empty()) return OptimizationResult();
  OptimizationResult result = optimize(graph, estimate(), params);
  for (int v = 0; v < static_cast<int>(variables_.size()); ++v) {
    Variable& variable = variables_[v];
    theta_.update(variable.key, result.values.value(variable.key));
    thetaById_[v] = theta_.value(variable.key);
    std::fill(delta_.begin() + variable.offset, delta_.begin() + variable.offset + variable.dimension, 0.0);
    markStale(v);
  }
  std::fill(deltaAtMixtureCheck_.begin(), deltaAtMixtureCheck_.end(), 0.0);
  for (Slot& slot : slots_) slot.linearization.reset();
  forceFull_ = true;
  try {
    update();
  } catch (...) {
    forceFull_ = false;
    throw;
  }
  forceFull_ = false;
  return result;
}

std::size_t IncrementalSmoother::memoryBytes() const {
  std::size_t bytes = vectorBytes(variables_) + mapBytes(variableIds_) + theta_.memoryBytes() +
                      vectorBytes(thetaById_) + vectorBytes(delta_) + vectorBytes(slots_) +
                      vectorBytes(pendingMarked_) + vectorBytes(pendingReplaced_) + vectorBytes(unsettledMixtures_) +
                      vectorBytes(cliques_) + vectorBytes(freeCliques_) + vectorBytes(roots_) +
                      vectorBytes(relinearizationCandidates_) + vectorBytes(isCandidate_) + estimate_.memoryBytes() +
                      vectorBytes(staleEstimates_) + vectorBytes(isStale_) + vectorBytes(estimateSlots_);
  bytes += vectorBytes(deltaAtMixtureCheck_);
  for (const Variable& v : variables_) bytes += vectorBytes(v.factors) + vectorBytes(v.partners);
  for (const Slot& slot : slots_) {
    bytes += vectorBytes(slot.variables);
    if (slot.linearization) {
      bytes += sizeof(FactorContribution) + denseBytes(slot.linearization->information) +
               denseBytes(slot.linearization->vector) + vectorBytes(slot.linearization->offsets);
    }
  }
  for (const Clique& clique : cliques_) {
    bytes += vectorBytes(clique.frontals) + vectorBytes(clique.separator) + vectorBytes(clique.children);
    if (clique.conditional) bytes += sizeof(CliqueConditional) + clique.conditional->memoryBytes();
  }
  // The scratch of update() (a fork starts with an empty one, so this counts what a used smoother holds).
  bytes += vectorBytes(scratch_.localIndex) + vectorBytes(scratch_.scalarOffset) + vectorBytes(scratch_.slotStamp) +
           vectorBytes(scratch_.positions) + vectorBytes(scratch_.cliqueSystem) +
           nestedVectorBytes(scratch_.neighbours) + nestedVectorBytes(scratch_.later) +
           nestedVectorBytes(scratch_.factorsOfClique) + vectorBytes(scratch_.solveBuffer) +
           vectorBytes(scratch_.changedVariables) + vectorBytes(scratch_.linearizedMixtures);
  return bytes;
}

}  // namespace semslam
