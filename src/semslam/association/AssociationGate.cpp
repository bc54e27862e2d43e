#include "semslam/association/AssociationGate.h"

#include <stdexcept>
#include <string>

#include "semslam/core/ChiSquare.h"

namespace semslam {

AssociationGate::AssociationGate(double confidence) : confidence_(confidence) {
  if (!(confidence > 0.0 && confidence < 1.0)) {
    throw std::invalid_argument("gate confidence must be in (0, 1), not " + std::to_string(confidence));
  }
  for (int dof = 1; dof < static_cast<int>(thresholds_.size()); ++dof) thresholds_[dof] = chiSquareQuantile(confidence, dof);
}

double AssociationGate::threshold(int dof) const {
  if (dof < 1) throw std::invalid_argument("gate needs at least one degree of freedom");
  if (dof < static_cast<int>(thresholds_.size())) return thresholds_[dof];
  return chiSquareQuantile(confidence_, dof);
}

}  // namespace semslam
