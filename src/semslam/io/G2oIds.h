#pragma once
// The g2o id of each key when a graph is written as g2o, whose vertices share one numeric id space:
//   a plain key k keeps id k; a pose key x<i> gets id i; every other typed key (l<i>, o<i>, ...) is numbered
//   consecutively after the largest id so far (of plain and pose keys), in increasing key order, i.e. by tag
//   and then by index. So a graph read from g2o or TORO is written with its own ids, and an iSAM graph keeps its
//   pose numbers, its landmarks following the last pose.

#include <map>
#include <vector>

#include "semslam/graph/Key.h"

namespace semslam {

/// The g2o id of every key in `keys` (see above). Throws std::invalid_argument if a plain key and a pose key
/// would share an id.
std::map<Key, std::uint64_t> g2oIds(const std::vector<Key>& keys);

}  // namespace semslam
