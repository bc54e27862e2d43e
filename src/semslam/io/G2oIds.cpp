#include "semslam/io/G2oIds.h"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace semslam {

std::map<Key, std::uint64_t> g2oIds(const std::vector<Key>& keys) {
  std::vector<Key> sorted = keys;
  std::sort(sorted.begin(), sorted.end());
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());

  std::map<Key, std::uint64_t> ids;
  std::map<std::uint64_t, Key> owner;
  bool any = false;
  std::uint64_t largest = 0;
  for (Key key : sorted) {
    const Symbol symbol(key);
    if (symbol.tag() != 0 && symbol.tag() != 'x') continue;
    const std::uint64_t id = symbol.index();
    const auto [it, inserted] = owner.emplace(id, key);
    if (!inserted) {
      throw std::invalid_argument("writeG2o: keys " + keyToString(it->second) + " and " + keyToString(key) +
                                  " would both be g2o id " + std::to_string(id));
    }
    ids[key] = id;
    largest = any ? std::max(largest, id) : id;
    any = true;
  }
  std::uint64_t next = any ? largest + 1 : 0;
  for (Key key : sorted) {
    if (ids.count(key)) continue;
    if (next > Symbol::kIndexMask) throw std::invalid_argument("writeG2o: g2o ids run past 2^56");
    ids[key] = next++;
  }
  return ids;
}

}  // namespace semslam
