#include "semslam/solve/UnconstrainedSystem.h"

#include <Eigen/Eigenvalues>

#include <map>
#include <numeric>
#include <set>
#include <vector>

namespace semslam {
namespace {

constexpr std::size_t kNamesShown = 8;
constexpr double kSingularRatio = 1e-12;

const char* const kPrefix = "the system cannot be solved: ";

std::string keyList(const std::vector<Key>& keys) {
  std::string text;
  for (std::size_t i = 0; i < keys.size() && i < kNamesShown; ++i) text += (i ? ", " : "") + keyToString(keys[i]);
  if (keys.size() > kNamesShown) text += " and " + std::to_string(keys.size() - kNamesShown) + " more";
  return text;
}

/// Union-find over variable indices.
struct Components {
  std::vector<std::size_t> parent;
  explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  std::size_t find(std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
};

/// Every variable some factor names.
std::set<Key> namedVariables(const FactorGraph& graph) {
  std::set<Key> named;
  for (const FactorPtr& factor : graph) named.insert(factor->keys().begin(), factor->keys().end());
  return named;
}

std::string unusedVariables(const FactorGraph& graph, const Values& values) {
  const std::set<Key> named = namedVariables(graph);
  std::vector<Key> unused;
  for (Key key : values.keys()) {
    if (!named.count(key)) unused.push_back(key);
  }
  if (unused.empty()) return {};
  return std::string(kPrefix) + "no factor names " + (unused.size() == 1 ? "variable " : "the variables ") +
         keyList(unused) + ", so nothing determines " + (unused.size() == 1 ? "its value" : "their values") +
         ". Add a measurement (an edge or a detection) that involves " + (unused.size() == 1 ? "it" : "them") +
         ", or leave " + (unused.size() == 1 ? "it" : "them") + " out.";
}

std::string unanchoredParts(const FactorGraph& graph, const Values& values) {
  const std::set<Key> named = namedVariables(graph);  // only variables some factor names are in the system
  std::vector<Key> keys;
  for (Key key : values.keys()) {
    if (named.count(key)) keys.push_back(key);
  }
  std::map<Key, std::size_t> index;
  for (std::size_t i = 0; i < keys.size(); ++i) index[keys[i]] = i;
  Components components(keys.size());
  std::vector<char> anchoredVariable(keys.size(), 0);
  for (const FactorPtr& factor : graph) {
    const std::vector<Key>& fk = factor->keys();
    if (fk.size() == 1) {
      if (index.count(fk[0])) anchoredVariable[index[fk[0]]] = 1;
      continue;
    }
    for (std::size_t j = 1; j < fk.size(); ++j) {
      if (index.count(fk[0]) && index.count(fk[j])) components.join(index[fk[0]], index[fk[j]]);
    }
  }
  std::map<std::size_t, std::vector<Key>> parts;  // root → its variables, in key order
  std::set<std::size_t> anchoredRoots;
  for (std::size_t i = 0; i < keys.size(); ++i) {
    const std::size_t root = components.find(i);
    parts[root].push_back(keys[i]);
    if (anchoredVariable[i]) anchoredRoots.insert(root);
  }
  std::vector<std::vector<Key>> free;
  for (const auto& [root, members] : parts) {
    if (!anchoredRoots.count(root)) free.push_back(members);
  }
  if (free.empty()) return {};
  // The part holding the first variable is named first (the order of key numbers).
  const std::vector<Key>& part = free.front();
  std::string text = std::string(kPrefix) + "nothing holds " +
                     (part.size() == 1 ? "variable " + keyList(part)
                                       : "the " + std::to_string(part.size()) + " variables " + keyList(part)) +
                     " in place: " +
                     (part.size() == 1 ? "no prior is on it"
                                       : "they are measured relative to each other only, with no prior on any of "
                                         "them") +
                     " and no factor joins " + (part.size() == 1 ? "it" : "them") +
                     " to a variable that has one. Add a prior (an anchor) on one of them, or a measurement joining "
                     "them to the rest of the graph.";
  if (free.size() > 1) text += " (" + std::to_string(free.size() - 1) + " more such part(s).)";
  return text;
}

std::string underconstrainedVariable(const FactorGraph& graph, const Values& values) {
  std::map<Key, Matrix> blocks;  // Σ Jᵀ J of each variable's own factors
  LinearizedFactor linearized;
  std::map<Key, int> factorCount;
  for (const FactorPtr& factor : graph) {
    factor->linearize(values, linearized);
    const std::vector<Key>& fk = factor->keys();
    for (std::size_t j = 0; j < fk.size() && j < linearized.jacobians.size(); ++j) {
      const Matrix& J = linearized.jacobians[j];
      auto [it, inserted] = blocks.try_emplace(fk[j], Matrix::Zero(J.cols(), J.cols()));
      if (it->second.rows() == J.cols()) it->second += J.transpose() * J;
      ++factorCount[fk[j]];
    }
  }
  for (const auto& [key, block] : blocks) {
    if (block.rows() == 0) continue;
    const Eigen::SelfAdjointEigenSolver<Matrix> eigen(block);
    const Vector& lambda = eigen.eigenvalues();
    if (!lambda.allFinite()) {
      return std::string(kPrefix) + "a factor on variable " + keyToString(key) +
             " has a non-finite Jacobian at the current values; check its measurement and initial value.";
    }
    const double largest = lambda.maxCoeff();
    const int free = static_cast<int>((lambda.array() <= kSingularRatio * std::max(largest, 1e-300)).count());
    if (free > 0) {
      const int n = factorCount[key];
      return std::string(kPrefix) + "variable " + keyToString(key) + " has " + std::to_string(block.rows()) +
             " dimensions but its " + std::to_string(n) + " factor" + (n == 1 ? "" : "s") + " fix only " +
             std::to_string(block.rows() - free) + " of them (" + std::to_string(free) +
             " direction(s) left free, e.g. a landmark measured from a single place by a sensor that does not "
             "observe all of its coordinates). Add measurements of it from other places, or a prior on it.";
    }
  }
  return {};
}

}  // namespace

std::string describeUnconstrained(const FactorGraph& graph, const Values& values) {
  // Unused variables last: the batch solvers leave them out of the system (harmless there), the incremental
  // smoother keeps them (fatal there).
  for (auto cause : {unanchoredParts, underconstrainedVariable, unusedVariables}) {
    std::string text = cause(graph, values);
    if (!text.empty()) return text;
  }
  return std::string(kPrefix) +
         "the factors leave a combination of several variables free (every variable is measured and every part "
         "of the graph has a prior, but together they do not fix all directions, e.g. landmarks seen only along "
         "one line of sight). Add independent measurements or priors; `semslam check` lists what a log holds.";
}

void throwUnconstrained(const FactorGraph& graph, const Values& values) {
  throw UnconstrainedSystemError(describeUnconstrained(graph, values));
}

}  // namespace semslam
