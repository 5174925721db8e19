#pragma once

#include <wetbed/assembly/flow/flow_term.h>

namespace wetbed
{
/**
 * The well-balanced compaction force and buoyant weight on the solids (doc/theory.md,
 * "Well-balanced compaction force"): (P_s + P_kin, div v_s) with P_s the Q1
 * interpolant of P_s(alpha_j) at the nodes, and alpha_mean (rho_s - rho_g) g with the
 * cell mean of alpha_s. Then a bed whose nodal alpha_s satisfies P_s(alpha_k) -
 * P_s(alpha_k+1) = h (rho_s - rho_g)|g| (alpha_k + alpha_k+1)/2 cell by cell is an exact
 * discrete rest state, free surface included.
 */
template <int dim>
class BodyForceTerm : public FlowTerm<dim>
{
public:
  explicit BodyForceTerm (const FlowMaterial<dim> &material) : material (material) {}
  std::string name () const override { return "body force"; }
  void        cell (const FlowCellScratch<dim>   &scratch,
                    const FlowAssemblyState<dim> &state,
                    FlowCellCopy                 &copy) const override;

  bool has_matrix () const override { return false; }

private:
  FlowMaterial<dim> material;
};
} // namespace wetbed
