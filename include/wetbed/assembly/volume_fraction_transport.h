#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <vector>

namespace wetbed
{
  /**
   * Explicit, sub-cycled, bounded and conservative transport of the solids fraction,
   *   d alpha/dt + div(alpha u_s) = 0,
   * on a continuous Q1 space: lumped mass, the Galerkin operator in the conservative
   * form k_ij = u_j . int phi_j grad phi_i (columns sum to zero, so the solids mass is
   * conserved exactly whatever u_s does at the boundary), discrete upwinding
   * d_ij = max(-k_ij, 0, -k_ji) for the low-order update, and Zalesak's limiter of the
   * antidiffusive fluxes with local bounds and the global bounds [0, alpha_max]
   * (Kuzmin-Turek algebraic FCT). Works on distributed vectors with ghosts.
   */
  template <int dim>
  class VolumeFractionTransport
  {
  public:
    using Vector = dealii::LinearAlgebra::distributed::Vector<double>;

    /** Builds the graph, the lumped mass and the derivative matrices (once per mesh). */
    void setup (const dealii::DoFHandler<dim> &dof_handler,
                const dealii::Mapping<dim>     &mapping,
                const Vector                   &layout);

    /**
     * Advances `alpha` (ghosted, in/out) by `dt` with the nodal solids velocity `u`
     * (dim ghosted vectors); returns the number of sub-steps taken.
     */
    unsigned int advance (Vector                    &alpha,
                          const std::vector<Vector> &u,
                          double                     dt,
                          double                     cfl,
                          double                     alpha_max);

    const Vector &lumped_mass () const { return mass; }

    /** Statistics of the last call. */
    double limiter_activity = 0; // fraction of antidiffusive flux removed

  private:
    struct Row
    {
      std::vector<unsigned int> columns; // local indices (owned + ghost)
      std::vector<double>       c[dim];  // int phi_j d_d phi_i
      std::vector<double>       ct[dim]; // int phi_i d_d phi_j
    };
    std::vector<Row> rows; // one per locally owned dof, in local order
    Vector           mass;
  };
} // namespace wetbed
