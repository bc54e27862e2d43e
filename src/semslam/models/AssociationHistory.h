#pragma once
// AssociationHistory: a data-association history β_1:k (paper A, eq. 5): for each time step, the landmark id each
// detection of that step is associated with (−1: a dropped detection).
//
// A hybrid belief holds many histories that share their past: at every step each component's history is its
// parent's extended by one step. Stored as vectors, C components over K steps cost O(C · K) per step and, kept
// for every step, O(C · K²) over a run. Here a history is an immutable linked list of per-step nodes shared
// between all histories with the same past (a persistent list, as the ancestry of a particle filter): extending
// is O(1) and copying copies a pointer.
//
// Invariants: a node's `beta` is β_k of step k = size() − 1, `parent` holds β_1:k−1 (null for k = 0); `hash`
// is a function of the contents only (equal histories have equal hashes, whichever nodes hold them). Equality
// compares contents and stops at the first node the two share: O(1) for histories made from the same nodes by
// HistoryInterner, at most O(k · n) otherwise.

#include <cstddef>
#include <initializer_list>
#include <map>
#include <memory>
#include <ostream>
#include <utility>
#include <vector>

namespace semslam {

class AssociationHistory {
 public:
  /// The empty history β_1:0.
  AssociationHistory() = default;
  /// From its steps, β_1 first.
  AssociationHistory(std::initializer_list<std::vector<int>> steps);
  explicit AssociationHistory(const std::vector<std::vector<int>>& steps);

  /// β_1:k+1: this history followed by `beta`; shares this history's nodes.
  AssociationHistory extended(std::vector<int> beta) const;

  /// k: the number of steps.
  std::size_t size() const { return node_ ? node_->steps : 0; }
  bool empty() const { return !node_; }
  /// β_k of the last step; requires !empty().
  const std::vector<int>& back() const { return node_->beta; }
  /// β_1:k−1; requires !empty().
  AssociationHistory parent() const { return AssociationHistory(node_->parent); }
  /// Every step, β_1 first: O(k · n).
  std::vector<std::vector<int>> steps() const;

  std::size_t hash() const { return node_ ? node_->hash : 0; }
  friend bool operator==(const AssociationHistory& a, const AssociationHistory& b);
  friend bool operator!=(const AssociationHistory& a, const AssociationHistory& b) { return !(a == b); }
  /// Whether the two are the same nodes (equal without comparing contents).
  bool sharesNodesWith(const AssociationHistory& other) const { return node_ == other.node_; }

 private:
  struct Node {
    std::vector<int> beta;
    mutable std::shared_ptr<const Node> parent;  // mutable only for the destructor
    std::size_t steps = 0;
    std::size_t hash = 0;
    ~Node();  // unlinks a chain iteratively: a long history must not recurse once per step
  };
  explicit AssociationHistory(std::shared_ptr<const Node> node) : node_(std::move(node)) {}

  std::shared_ptr<const Node> node_;
};

/// {{1, 2}, {1}}: for test failure messages.
std::ostream& operator<<(std::ostream& out, const AssociationHistory& history);

struct AssociationHistoryHash {
  std::size_t operator()(const AssociationHistory& history) const { return history.hash(); }
};

/// Makes equal histories share their nodes: the extensions of one history by equal β are the same history
/// (`extend` returns the one made first). One interner per step, used while the step's children are made; a
/// belief whose histories come only from an interner compares every pair of histories in O(1).
class HistoryInterner {
 public:
  AssociationHistory extend(const AssociationHistory& parent, const std::vector<int>& beta);

 private:
  // Keyed by the parent's hash and β; equal keys are checked against the parent itself.
  std::multimap<std::pair<std::size_t, std::vector<int>>, std::pair<AssociationHistory, AssociationHistory>> made_;
};

}  // namespace semslam
