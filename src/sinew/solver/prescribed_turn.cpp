#include "sinew/solver/prescribed_turn.hpp"

namespace sinew::solver {

double step_within_turn_bound(const fem::DofMap& dofs, double from, double size, double smallest) {
  while (size >= smallest && dofs.largest_prescribed_turn(from, from + size) > kMaxPrescribedTurnPerStep) size /= 2;
  return size;
}

}  // namespace sinew::solver
