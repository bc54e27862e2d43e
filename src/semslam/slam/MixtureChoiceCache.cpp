#include "semslam/slam/MixtureChoiceCache.h"

#include "semslam/factors/SeenPointMove.h"

namespace semslam {

int MixtureChoiceCache::activeComponent(std::size_t detection, const FactorPtr& mixture, const Values& estimate,
                                        const KnownValue* landmark) {
  if (entries_.size() <= detection) entries_.resize(detection + 1);
  std::optional<Entry>& entry = entries_[detection];
  if (entry && entry->mixture == mixture && entry->reach > 0.0) {
    const Value& landmarkNow =
        landmark && landmark->first == entry->landmarkKey ? *landmark->second : estimate.value(entry->landmarkKey);
    const std::optional<double> moved =
        seenPointMove(entry->pose, entry->landmark, estimate.value(entry->poseKey), landmarkNow);
    if (moved && *moved < entry->reach) return entry->component;
  }
  ++choicesMade_;
  const MaxMixtureFactor::Choice choice = static_cast<const MaxMixtureFactor&>(*mixture).chooseAt(estimate);
  entry = Entry{mixture, choice.component, choice.reach};
  if (choice.reach > 0.0) {  // a mixture of one pose and one landmark, in that order (MaxMixtureFactor::chooseAt)
    entry->poseKey = mixture->keys()[0];
    entry->landmarkKey = mixture->keys()[1];
    entry->pose = estimate.value(entry->poseKey);
    entry->landmark = estimate.value(entry->landmarkKey);
  }
  return choice.component;
}

}  // namespace semslam
