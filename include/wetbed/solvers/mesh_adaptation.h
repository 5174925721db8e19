#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/solvers/solver_state.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <array>
#include <set>
#include <string>
#include <vector>

namespace wetbed
{
/**
 * Bubble-following adaptive refinement as a component (doc/theory.md, "Adaptive
 * meshes"): before a mesh change it flags the cells from the state's alpha_s and u_s
 * and records the parents of the cells to be coarsened and the solids mass of alpha_s
 * at the three levels; after the change (and the field transfer, FieldTransfer) it
 * gives the coarsening deficit back on the nodes of the coarsened cells, so that the
 * solids mass is conserved to round-off within [0, alpha_max]
 * (source/solvers/mesh_adaptation.cc). It reads the state through SolverState and
 * writes only the refinement flags of the triangulation it is handed and the alpha_s
 * levels it is handed.
 */
template <int dim>
class MeshAdaptation
{
public:
  using AlphaVector = dealii::LinearAlgebra::distributed::Vector<double>;

  explicit MeshAdaptation (const Parameters &parameters);

  /** Flags the cells of `triangulation` (the state's mesh) for refinement and
   * coarsening from `state` and prepares the change (2:1 balance); remembers the
   * parents of the cells to be coarsened and the solids mass of each of
   * `alpha_levels` (alpha_s^{n+1}, ^n, ^{n-1}, and its time average when there is
   * one); collective. */
  void prepare (const SolverState<dim>                            &state,
                dealii::parallel::distributed::Triangulation<dim> &triangulation,
                const std::vector<const AlphaVector *>            &alpha_levels);

  /** After the mesh change, the new DoFs and the transfer (`state` on the new mesh,
   * `alpha_constraints` its hanging nodes): each of `alpha_levels` gets its solids mass
   * back from before the change; collective. */
  void restore_solids_mass (const SolverState<dim>                  &state,
                            const dealii::AffineConstraints<double> &alpha_constraints,
                            const std::vector<AlphaVector *>        &alpha_levels) const;

private:
  void
  flag_cells (const SolverState<dim>                            &state,
              dealii::parallel::distributed::Triangulation<dim> &triangulation) const;
  /** Gives `target - sum m a` back to `a` where `candidate` (else anywhere), in
   * proportion to the room within [0, alpha_max]. */
  void restore (const SolverState<dim>                  &state,
                const dealii::AffineConstraints<double> &alpha_constraints,
                AlphaVector                             &a,
                double                                   target,
                const std::vector<bool>                 &candidate) const;

  const Parameters &parameters;
  // the CellIds of the parents of the cells flagged for coarsening (all ranks')
  std::set<std::string> coarsened;
  // the solids mass of alpha_s^{n+1}, ^n, ^{n-1} before the change
  std::vector<double> masses;
};
} // namespace wetbed
