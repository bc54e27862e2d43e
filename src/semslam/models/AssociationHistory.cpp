#include "semslam/models/AssociationHistory.h"

#include <cstdint>

namespace semslam {
namespace {

// splitmix64's finaliser: a well-mixed 64-bit hash of the running value.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

std::size_t stepHash(std::size_t parentHash, const std::vector<int>& beta) {
  std::uint64_t h = mix(static_cast<std::uint64_t>(parentHash) ^ (beta.size() + 1));
  for (int id : beta) h = mix(h ^ static_cast<std::uint32_t>(id));
  return static_cast<std::size_t>(h);
}

}  // namespace

AssociationHistory::Node::~Node() {
  std::shared_ptr<const Node> next = std::move(parent);
  while (next && next.use_count() == 1) next = std::move(next->parent);  // the old `next` dies with no parent
}

AssociationHistory::AssociationHistory(std::initializer_list<std::vector<int>> steps) {
  for (const std::vector<int>& beta : steps) *this = extended(beta);
}

AssociationHistory::AssociationHistory(const std::vector<std::vector<int>>& steps) {
  for (const std::vector<int>& beta : steps) *this = extended(beta);
}

AssociationHistory AssociationHistory::extended(std::vector<int> beta) const {
  auto node = std::make_shared<Node>();
  node->hash = stepHash(hash(), beta);
  node->beta = std::move(beta);
  node->parent = node_;
  node->steps = size() + 1;
  return AssociationHistory(std::move(node));
}

std::vector<std::vector<int>> AssociationHistory::steps() const {
  std::vector<std::vector<int>> out(size());
  std::size_t k = out.size();
  for (const Node* node = node_.get(); node; node = node->parent.get()) out[--k] = node->beta;
  return out;
}

bool operator==(const AssociationHistory& a, const AssociationHistory& b) {
  if (a.size() != b.size() || a.hash() != b.hash()) return false;
  const AssociationHistory::Node* x = a.node_.get();
  const AssociationHistory::Node* y = b.node_.get();
  for (; x != y; x = x->parent.get(), y = y->parent.get()) {  // equal sizes: both reach null together
    if (x->beta != y->beta) return false;
  }
  return true;
}

std::ostream& operator<<(std::ostream& out, const AssociationHistory& history) {
  out << '{';
  const std::vector<std::vector<int>> steps = history.steps();
  for (std::size_t k = 0; k < steps.size(); ++k) {
    out << (k > 0 ? ", {" : "{");
    for (std::size_t i = 0; i < steps[k].size(); ++i) out << (i > 0 ? ", " : "") << steps[k][i];
    out << '}';
  }
  return out << '}';
}

AssociationHistory HistoryInterner::extend(const AssociationHistory& parent, const std::vector<int>& beta) {
  auto [first, last] = made_.equal_range({parent.hash(), beta});
  for (auto it = first; it != last; ++it) {
    if (it->second.first == parent) return it->second.second;
  }
  AssociationHistory child = parent.extended(beta);
  made_.emplace(std::make_pair(parent.hash(), beta), std::make_pair(parent, child));
  return child;
}

}  // namespace semslam
