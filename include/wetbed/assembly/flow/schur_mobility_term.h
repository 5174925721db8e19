#pragma once

#include <wetbed/assembly/flow/flow_term.h>

namespace wetbed
{
/**
 * The partial-elimination mobility Laplacian L_c of the Schur-complement preconditioner
 * (doc/theory.md, "Block preconditioner"): the mixture volume flux a unit pressure
 * gradient drives when the two momentum equations are reduced to their local (mass,
 * viscous h^-2, drag) parts and solved together,
 *   m = (alpha_g^2 A_s + alpha_s^2 A_g + beta) / (A_g A_s + beta (A_g + A_s)).
 */
template <int dim>
class SchurMobilityTerm : public FlowTerm<dim>
{
public:
  explicit SchurMobilityTerm (const FlowMaterial<dim> &material) : material (material) {}
  std::string name () const override { return "Schur mobility"; }
  void        cell (const FlowCellScratch<dim>   &scratch,
                    const FlowAssemblyState<dim> &state,
                    FlowCellCopy                 &copy) const override;

  // L_c, the Schur preconditioner's matrix, not the system's
  bool has_matrix () const override { return false; }

private:
  FlowMaterial<dim> material;
};
} // namespace wetbed
