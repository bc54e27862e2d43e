#include "semslam/solve/SparseCholesky.h"

#include <dlfcn.h>

#include <stdexcept>

namespace semslam {
namespace {

// The calling thread's OpenMP max-active-levels in the runtime CHOLMOD was linked with (SparseCholesky.h,
// "Threads"). The runtime is found among the process's symbols (RTLD_DEFAULT) rather than linked by semslam: then it
// is CHOLMOD's own (libgomp on Debian) and never a second runtime, and a CHOLMOD without OpenMP leaves both null.
struct OpenMPActiveLevels {
  using Get = int (*)();
  using Set = void (*)(int);
  Get get = nullptr;
  Set set = nullptr;
};

const OpenMPActiveLevels& openMPActiveLevels() {
  static const OpenMPActiveLevels levels = [] {
    OpenMPActiveLevels found;
    found.get = reinterpret_cast<OpenMPActiveLevels::Get>(dlsym(RTLD_DEFAULT, "omp_get_max_active_levels"));
    found.set = reinterpret_cast<OpenMPActiveLevels::Set>(dlsym(RTLD_DEFAULT, "omp_set_max_active_levels"));
    if (!found.get || !found.set) found = OpenMPActiveLevels{};
    return found;
  }();
  return levels;
}

// While it lives, OpenMP parallel regions started on this thread run serially (max-active-levels 0); the level the
// thread had is restored when it goes, exceptions included.
class SerialOpenMPRegions {
 public:
  SerialOpenMPRegions() : levels_(openMPActiveLevels()) {
    if (!levels_.set) return;
    saved_ = levels_.get();
    levels_.set(0);
  }
  ~SerialOpenMPRegions() {
    if (levels_.set) levels_.set(saved_);
  }
  SerialOpenMPRegions(const SerialOpenMPRegions&) = delete;
  SerialOpenMPRegions& operator=(const SerialOpenMPRegions&) = delete;

 private:
  const OpenMPActiveLevels& levels_;
  int saved_ = 0;
};

}  // namespace

SparseCholesky::SparseCholesky() {
  // A matrix that is not positive definite is reported through factorize()'s result, never printed: CHOLMOD's
  // print level 0 silences its own messages ("CHOLMOD error: not positive definite ..."), which would reach the
  // user before the explanation the solvers give (solve/UnconstrainedSystem.h).
  llt_.cholmod().print = 0;
  llt_.setMode(Eigen::CholmodAuto);
  // LLᵀ also in the simplicial case: an LDLᵀ factorization would accept a negative pivot, and a matrix that is
  // not positive definite must be reported (an unconstrained variable), never solved.
  llt_.cholmod().final_ll = 1;
}

void SparseCholesky::analyze(const SparseMatrix& upper) {
  const SerialOpenMPRegions serial;
  llt_.analyzePattern(upper);
  analyzed_ = true;
}

bool SparseCholesky::factorize(const SparseMatrix& upper) {
  if (!analyzed_) analyze(upper);
  const SerialOpenMPRegions serial;
  llt_.factorize(upper);
  return llt_.info() == Eigen::Success;
}

Vector SparseCholesky::solve(const Vector& b) const {
  const SerialOpenMPRegions serial;
  Vector x = llt_.solve(b);
  if (llt_.info() != Eigen::Success) throw std::runtime_error("sparse Cholesky solve failed");
  return x;
}

Matrix SparseCholesky::solve(const Matrix& b) const {
  const SerialOpenMPRegions serial;
  Matrix x = llt_.solve(b);
  if (llt_.info() != Eigen::Success) throw std::runtime_error("sparse Cholesky solve failed");
  return x;
}

double SparseCholesky::logDeterminant() const { return llt_.logDeterminant(); }

std::size_t SparseCholesky::memoryBytes() const { return llt_.cholmod().memory_inuse; }

}  // namespace semslam
