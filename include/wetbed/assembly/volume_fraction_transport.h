#pragma once

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/la_parallel_vector.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <deal.II/fe/fe_values.h>

#include <functional>
#include <vector>

namespace wetbed
{
/**
 * Explicit, sub-cycled, bounded and conservative transport of the solids fraction,
 *   d alpha/dt + div(alpha u_s) = 0,
 * on a continuous Q1 space: lumped mass, the Galerkin operator in the conservative
 * form k_ij = int phi_j u_s . grad phi_i (columns sum to zero, so the solids mass is
 * conserved exactly whatever u_s does at the boundary), discrete upwinding
 * d_ij = max(-k_ij, 0, -k_ji) for the low-order update, and Zalesak's limiter of the
 * antidiffusive fluxes with local bounds and the global bounds [0, alpha_max]
 * (Kuzmin-Turek algebraic FCT). Works on distributed vectors with ghosts.
 *
 * On adaptively refined meshes every operator is condensed with the hanging-node
 * constraints (C^T K C, C^T m): the columns of the condensed K still sum to zero and
 * sum_i m_i alpha_i is still the integral of alpha_h, so the transport stays exactly
 * conservative; hanging nodes take their constrained (convex) values after each update,
 * so the bounds hold there too.
 */
template <int dim>
class VolumeFractionTransport
{
public:
  using Vector = dealii::LinearAlgebra::distributed::Vector<double>;

  /**
   * Builds the graph, the lumped mass and the derivative matrices (once per mesh).
   * `layout` gives the parallel layout of the alpha_s vectors (owned and ghost dofs);
   * its values are not used.
   */
  void setup (const dealii::DoFHandler<dim>           &dof_handler,
              const dealii::Mapping<dim>              &mapping,
              const dealii::AffineConstraints<double> &hanging_node_constraints,
              const Vector                            &layout);

  /** Fills `u` with the solids velocity at the quadrature points of `fe_values`' cell. */
  using VelocityAtQuadrature =
      std::function<void (const typename dealii::DoFHandler<dim>::active_cell_iterator &,
                          const dealii::FEValues<dim> &,
                          std::vector<dealii::Tensor<1, dim>> &)>;
  /**
   * Assembles the Galerkin operator k_ij = int phi_j u_s . grad phi_i with u_s at the
   * quadrature points (the full velocity field, not its nodal values: a Q2 u_s moves
   * alpha through its edge and face nodes too, so the transport is the adjoint of the
   * discrete gradient that P_s acts through, and no velocity mode is left that P_s
   * drives but alpha does not feel).
   */
  void set_velocity (const VelocityAtQuadrature &velocity);
  /**
   * Advances `alpha` (ghosted, in/out) by `dt` with the operator of the last
   * set_velocity(); returns the number of sub-steps taken. A step that would need more
   * than `max_sub_steps` (or whose stable sub-step is not a positive finite number)
   * leaves `alpha` as it was and returns dealii::numbers::invalid_unsigned_int:
   * the solids would cross that many cells in one flow step, a flow far outside the
   * step's own speed estimate, which the caller rejects (doc/theory.md, "One time
   * step"). required_sub_steps() gives the count it would have needed.
   */
  unsigned int advance (Vector &alpha, double dt, double cfl, double alpha_max);

  /** The most explicit sub-steps of one advance() (the shipped cases take 1 to 4). */
  static constexpr unsigned int max_sub_steps = 1000;

  /**
   * The solids a feed brings in (InletConditions::solids_inflow_rates: m^3/s per node,
   * the alpha_s layout; size 0: none): every sub-step adds tau rates_i / m_i to the
   * node after the limited fluxes, cut where it would exceed alpha_max, and the volume
   * added is kept in inflow_volume.
   */
  void set_inflow (const Vector &rates) { inflow_rates = rates; }

  /** dt / (cfl * stable sub-step) of the last advance(), infinite when nothing
   * bounds it from below (no stable sub-step could be found). */
  double required_sub_steps () const { return last_required_sub_steps; }

  const Vector &lumped_mass () const { return mass; }

  /**
   * Applies the implicit correction increment of a symmetric, zero-row-sum diffusion
   * operator A (off-diagonal entries A_ij, same graph) as edge fluxes
   * G_ij = -A_ij (x_j - x_i), limited so that alpha stays in [0, alpha_max]:
   * alpha_i += sum_j l_ij G_ij / m_i. `x` is ghosted. Returns the volume held back.
   */
  double apply_diffusive_fluxes (Vector                                       &alpha,
                                 const dealii::TrilinosWrappers::SparseMatrix &A,
                                 const Vector                                 &x,
                                 double                                        alpha_max);

  /** Statistics of the last call. */
  double limiter_activity = 0; // fraction of antidiffusive flux removed
  double bound_activity   = 0; // solids volume held back by the packing limit
  double inflow_volume    = 0; // solids volume the feed added (m^3; m^2 in 2D)

private:
  double last_required_sub_steps = 0;
  using EdgeValues = std::vector<std::vector<double>>; // [owned row][column of the row]

  /** The low-order artificial diffusion d_ij = max(-k_ij, 0, -k_ji) of each row into
   * `diffusion`; returns this rank's largest stable explicit step. */
  double artificial_diffusion (EdgeValues &diffusion) const;
  /** One low-order sub-step of length tau from `alpha` (ghosted) as antisymmetric edge
   * fluxes into `low_flux`, and its result into `low`. */
  void low_order_step (const Vector     &alpha,
                       const EdgeValues &diffusion,
                       double            tau,
                       EdgeValues       &low_flux,
                       Vector           &low) const;
  /** The prelimited antidiffusive fluxes into `flux` and Zalesak's ratios R+ and R- into
   * `r_plus`, `r_minus`, keeping each node within its neighbours' range and [0,
   * alpha_max]. */
  void antidiffusive_fluxes (const Vector     &alpha,
                             const Vector     &low,
                             const EdgeValues &diffusion,
                             double            tau,
                             double            alpha_max,
                             EdgeValues       &flux,
                             Vector           &r_plus,
                             Vector           &r_minus) const;
  /** flux_ij = low_flux_ij + l_ij flux_ij with Zalesak's limiter from ghosted `r_plus`,
   * `r_minus`; the removed and the total antidiffusive flux added up. */
  void limit_antidiffusive_fluxes (const EdgeValues &low_flux,
                                   const Vector     &r_plus,
                                   const Vector     &r_minus,
                                   EdgeValues       &flux,
                                   double           &removed,
                                   double           &total) const;

  /** alpha_i += tau rates_i / m_i, cut at alpha_max; returns the volume added. */
  double add_inflow (Vector &alpha, double tau, double alpha_max) const;

  /** alpha_i += sum_j l_ij G_ij / m_i with l_ij keeping [0, alpha_max]; returns held-back
   * volume. */
  double limit_to_bounds (Vector                                 &alpha,
                          const std::vector<std::vector<double>> &flux,
                          double                                  alpha_max);

  struct Row
  {
    std::vector<unsigned int> columns; // local indices (owned + ghost)
    std::vector<double>       k;       // int phi_j u . grad phi_i
    std::vector<double>       kt;      // int phi_i u . grad phi_j
  };
  const dealii::DoFHandler<dim>           *dof_handler = nullptr;
  const dealii::Mapping<dim>              *mapping     = nullptr;
  const dealii::AffineConstraints<double> *constraints = nullptr;
  std::vector<bool> constrained; // per locally owned dof: a hanging node
  dealii::TrilinosWrappers::SparseMatrix convection, convection_transpose;
  std::vector<Row> rows; // one per locally owned dof, in local order
  Vector           mass;
  Vector           inflow_rates; // the feed's source per node; size 0: none
  /** Copies alpha_out's owned values into `work` (ghosted with every column). */
  void load (const Vector &alpha_out);
  /** Copies `work` back into alpha_out; hanging nodes follow their parents. */
  void store (Vector &alpha_out) const;
  // work vectors (owned + every column of the owned rows as ghosts: condensed rows of
  // adapted meshes reach beyond the locally relevant dofs)
  Vector work, work_x, scratch_low, scratch_plus, scratch_minus;
};
} // namespace wetbed
