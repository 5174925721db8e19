#include <wetbed/assembly/scalar_sparsity.h>
#include <wetbed/assembly/solids_pressure_correction.h>
#include <wetbed/core/interruptible_solver_control.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_precondition.h>

#include <algorithm>

namespace wetbed
{
using namespace dealii;

/**
 * Implicit solids-pressure correction (doc/theory.md, "One time step", step 3; the
 * OpenFOAM implicitPhasePressure / MFIX solids-correction idea in increment form). The
 * momentum solve that produced the
 * transporting u_s saw -grad P_h(alpha_m), P_h = sum_j P_s(alpha_m,j) phi_j the Q1
 * interpolant of the nodal solids pressure (the well-balanced compaction force). The
 * correction makes the response of exactly that force implicit in the change since then:
 *   M_L (alpha - alpha*)/dt + K w = 0,  w_j = P'_j (alpha_j - alpha_m,j),
 *   K_ij = int D grad phi_i . grad phi_j,  D = alpha_s / R (compaction_mobility),
 * with P'_j the nodal stiffness. For z = S^-1 w, S = diag(sqrt(P'_j)), it is symmetric
 * positive definite:
 *   (M_L + dt S K S) z = S M_L (alpha* - alpha_m),   w = S z,
 * (w = 0 where P' = 0: those nodes only receive mass; no division by P'). K has zero
 * row sums, so the edge fluxes dt K_ij (w_j - w_i) conserve the solids mass; a bed at
 * rest (alpha* = alpha_m) is left exactly at rest. Skipped where P'_j = 0 at every node,
 * i.e. in every scene without compacted regions.
 *
 * Why nodal: a node packed to P_s ~ 1e5 Pa between loose neighbours pushes through the
 * nodal interpolant with its full P_s, while P_s' at the quadrature points (alpha_s
 * interpolated towards the loose neighbours) is small or zero; a correction with
 * quadrature-point stiffness then under-estimates the force the momentum solve will
 * see and the compaction mode grows (measured: a 1D bed at U = 1.8 U_mf flung its
 * bottom layer at 4 m/s within two steps of dt = 2 ms).
 */

/**
 * The stiffness dP_s/dalpha the correction uses: P_s is convex, so the slope at the
 * larger of alpha_s (now) and alpha_m (what the momentum solve saw) bounds the secant
 * the momentum equation will see from above. An estimate below it (r = s_c/s_m < 1/2
 * in a Fourier analysis of the scheme) lets compaction modes grow; above it (up to
 * r ~ 5) they are damped by ~1/2 per step.
 */
template <int dim>
SolidsPressureCorrection<dim>::SolidsPressureCorrection (const Parameters &parameters,
                                                         MPI_Comm          communicator,
                                                         TimerOutput      &timer)
    : parameters (parameters), communicator (communicator), timer (timer)
{
}

template <int dim>
void SolidsPressureCorrection<dim>::reinit (
    const DoFHandler<dim>           &alpha_dof_handler,
    const AffineConstraints<double> &alpha_constraints,
    const AlphaVector               &layout)
{
  alpha_momentum.reinit (layout);
  const IndexSet              &alpha_owned = alpha_dof_handler.locally_owned_dofs ();
  const DynamicSparsityPattern dsp =
      distributed_scalar_sparsity (alpha_dof_handler, alpha_constraints);
  correction_matrix.reinit (alpha_owned, alpha_owned, dsp, communicator);
  compaction_flux_matrix.reinit (alpha_owned, alpha_owned, dsp, communicator);
}

template <int dim>
void SolidsPressureCorrection<dim>::begin (const AlphaVector &alpha)
{
  last_correction_momentum = 0;
  alpha_momentum           = alpha;
  alpha_momentum.update_ghost_values ();
}

template <int dim>
double SolidsPressureCorrection<dim>::compaction_stiffness (
    const closures::ClosureEvaluator &closures,
    const double                      alpha_s,
    const double                      alpha_m) const
{
  return closures.compaction_slope (std::max (alpha_s, alpha_m));
}

template <int dim>
void SolidsPressureCorrection<dim>::nodal_compaction_stiffness (
    const closures::ClosureEvaluator           &closures,
    const std::vector<types::global_dof_index> &dofs,
    const AlphaVector                          &alpha,
    std::vector<double>                        &slopes) const
{
  slopes.resize (dofs.size ());
  for (unsigned int j = 0; j < dofs.size (); ++j)
    slopes[j] =
        compaction_stiffness (closures, alpha (dofs[j]), alpha_momentum (dofs[j]));
}

/**
 * Volumetric mobility D = alpha_s / R of the solids under a compaction force when the
 * gas gives way (mixture volume flux unchanged, u_g = -alpha_s/alpha_g u_s):
 * eliminating the gas momentum and the pressure gives
 *   R = a0/dt alpha_s rho_s + a0/dt alpha_s^2 rho_g / alpha_g + beta / alpha_g^2,
 * i.e. the drag counts 1/alpha_g^2 times (6 times in a packed bed), not once. Written as
 * 1 / (a0/dt (rho_s + alpha_s rho_g/alpha_g) + beta/(alpha_s alpha_g^2)), finite as
 * alpha_s -> 0 (beta ~ alpha_s); 0 where there are no solids.
 */
template <int dim>
double SolidsPressureCorrection<dim>::compaction_mobility (
    const closures::ClosureEvaluator &closures,
    const double                      alpha_s,
    const Tensor<1, dim>             &slip,
    const double                      rate) const
{
  if (!(alpha_s > 0))
    return 0.0;
  const double alpha_g = std::max (1.0 - alpha_s, 1e-6);
  const auto  &pp      = parameters.physical;
  const double beta    = closures.drag (alpha_s, slip.norm ());
  return 1.0 / (rate * (pp.particle_density + alpha_s * pp.gas_density / alpha_g) +
                beta / (alpha_s * alpha_g * alpha_g));
}

/**
 * z from (M_L + dt S K S) z = rhs by CG. The matrix is the lumped mass plus a
 * compaction Laplacian that outweighs it only where P' is very stiff, so point Jacobi
 * converges in a few iterations in most steps, for a fraction of an AMG set-up (the
 * AMG set-up took 0.45-0.6 s on the 7,105 DoFs of the 6,336-cell 3D column, its CG 3
 * iterations); where Jacobi has not converged within 50 iterations, the solve restarts
 * from zero with AMG, which is robust in the stiffness.
 */
namespace
{
/** CG on `matrix` with `preconditioner` within `steps` iterations, recorded in
 * `record` as `name`; true when it converged. A stop signal (StepInterrupted) passes
 * through; a missed tolerance is rethrown where `rethrow`. */
template <typename Preconditioner>
bool cg_solve (MPI_Comm                              communicator,
               const TrilinosWrappers::SparseMatrix &matrix,
               const Preconditioner                 &preconditioner,
               const TrilinosWrappers::MPI::Vector  &rhs,
               TrilinosWrappers::MPI::Vector        &solution,
               const std::pair<unsigned int, double> steps_and_tolerance,
               const std::string                    &name,
               const bool                            rethrow,
               const SolveRecord                    &record)
{
  InterruptibleSolverControl control (
      communicator, steps_and_tolerance.first, steps_and_tolerance.second);
  control.enable_history_data ();
  SolverCG<TrilinosWrappers::MPI::Vector> cg (control);
  try
  {
    cg.solve (matrix, solution, rhs, preconditioner);
  }
  catch (const SolverControl::NoConvergence &)
  {
    record (name, control, false);
    if (rethrow)
      throw;
    return false;
  }
  record (name, control, true);
  return true;
}
} // namespace

template <int dim>
void SolidsPressureCorrection<dim>::solve_correction (
    const TrilinosWrappers::MPI::Vector &rhs,
    TrilinosWrappers::MPI::Vector       &increment,
    const SolveRecord                   &record) const
{
  const double tolerance =
      parameters.linear_solver.scalar_tolerance * rhs.l2_norm () + 1e-300;
  TrilinosWrappers::PreconditionJacobi jacobi;
  jacobi.initialize (correction_matrix);
  if (cg_solve (communicator,
                correction_matrix,
                jacobi,
                rhs,
                increment,
                {50, tolerance},
                "solids-pressure correction CG (Jacobi; AMG on a miss)",
                false,
                record))
    return;
  increment = 0;
  TrilinosWrappers::PreconditionAMG amg;
  amg.initialize (correction_matrix);
  cg_solve (communicator,
            correction_matrix,
            amg,
            rhs,
            increment,
            {1000, tolerance},
            "solids-pressure correction CG (AMG)",
            true,
            record);
}

template <int dim>
bool SolidsPressureCorrection<dim>::correct_solids_fraction (
    const SolidsTransportInputs<dim> &inputs,
    const BlockVector                &flow_solution,
    AlphaVector                      &alpha,
    VolumeFractionTransport<dim>     &transport,
    const SolveRecord                &record)
{
  TimerOutput::Scope                scope (timer, "solids pressure correction");
  const Mapping<dim>               &mapping           = inputs.mapping;
  const FiniteElement<dim>         &alpha_fe          = inputs.alpha_fe;
  const FiniteElement<dim>         &flow_fe           = inputs.flow_fe;
  const DoFHandler<dim>            &alpha_dof_handler = inputs.alpha_dof_handler;
  const DoFHandler<dim>            &flow_dof_handler  = inputs.flow_dof_handler;
  const AffineConstraints<double>  &alpha_constraints = inputs.alpha_constraints;
  const closures::ClosureEvaluator &closures          = inputs.closures;
  const BDFCoefficients            &bdf               = inputs.bdf;
  const double                      dt                = inputs.dt;

  const QGauss<dim>  quadrature (2);
  FEValues<dim>      alpha_values (mapping,
                              alpha_fe,
                              quadrature,
                              update_values | update_gradients | update_JxW_values);
  FEValues<dim>      flow_values (mapping, flow_fe, quadrature, update_values);
  const unsigned int n = alpha_fe.n_dofs_per_cell ();
  FullMatrix<double> cell_flux (n, n), cell_system (n, n);
  Vector<double>     cell_rhs (n), cell_mass (n);
  std::vector<types::global_dof_index> dofs (n);
  std::vector<double>                  a (quadrature.size ()), slopes (n);
  std::vector<Tensor<1, dim>>          ug (quadrature.size ()), us (quadrature.size ());
  const FEValuesExtractors::Vector     gas (0), solids (dim);

  correction_matrix      = 0;
  compaction_flux_matrix = 0;
  TrilinosWrappers::MPI::Vector rhs (alpha_dof_handler.locally_owned_dofs (),
                                     communicator);
  bool                          active    = false;
  auto                          flow_cell = flow_dof_handler.begin_active ();
  for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      cell->get_dof_indices (dofs);
      nodal_compaction_stiffness (closures, dofs, alpha, slopes);
      alpha_values.reinit (cell);
      flow_values.reinit (flow_cell);
      alpha_values.get_function_values (alpha, a);
      flow_values[gas].get_function_values (flow_solution, ug);
      flow_values[solids].get_function_values (flow_solution, us);
      cell_flux   = 0;
      cell_system = 0;
      cell_rhs    = 0;
      cell_mass   = 0;
      // no compacted node: w = 0 on the whole cell, no flux to compute
      const bool compacted =
          std::any_of (slopes.begin (), slopes.end (), [] (double s) { return s > 0; });
      for (unsigned int q = 0; q < quadrature.size (); ++q)
      {
        for (unsigned int i = 0; i < n; ++i)
          cell_mass (i) += alpha_values.shape_value (i, q) * alpha_values.JxW (q);
        if (!compacted)
          continue;
        const double diffusivity =
            compaction_mobility (closures, a[q], ug[q] - us[q], bdf.a0 / dt);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            cell_flux (i, j) +=
                diffusivity * dt *
                (alpha_values.shape_grad (i, q) * alpha_values.shape_grad (j, q)) *
                alpha_values.JxW (q);
      }
      for (unsigned int i = 0; i < n; ++i)
      {
        active = active || slopes[i] > 0;
        for (unsigned int j = 0; j < n; ++j)
          cell_system (i, j) = std::sqrt (slopes[i] * slopes[j]) * cell_flux (i, j);
        cell_system (i, i) += cell_mass (i);
        cell_rhs (i) = std::sqrt (slopes[i]) * cell_mass (i) *
                       (alpha (dofs[i]) - alpha_momentum (dofs[i]));
      }
      alpha_constraints.distribute_local_to_global (
          cell_system, cell_rhs, dofs, correction_matrix, rhs);
      alpha_constraints.distribute_local_to_global (
          cell_flux, dofs, compaction_flux_matrix);
    }
    ++flow_cell;
  }
  correction_matrix.compress (VectorOperation::add);
  compaction_flux_matrix.compress (VectorOperation::add);
  rhs.compress (VectorOperation::add);
  if (!Utilities::MPI::logical_or (active, communicator))
    return false;

  TrilinosWrappers::MPI::Vector increment (rhs); // z
  increment = 0;
  solve_correction (rhs, increment, record);
  apply_pressure_increment (closures, increment, alpha, transport);
  return true;
}

template <int dim>
void SolidsPressureCorrection<dim>::apply_pressure_increment (
    const closures::ClosureEvaluator    &closures,
    const TrilinosWrappers::MPI::Vector &increment,
    AlphaVector                         &alpha,
    VolumeFractionTransport<dim>        &transport) const
{
  // the nodal pressure increment w = S z becomes the limited edge fluxes
  // -dt K_ij (w_j - w_i)
  AlphaVector pressure_increment (alpha);
  for (unsigned int i = 0; i < pressure_increment.locally_owned_size (); ++i)
    pressure_increment.local_element (i) =
        std::sqrt (compaction_stiffness (
            closures, alpha.local_element (i), alpha_momentum.local_element (i))) *
        increment[alpha.get_partitioner ()->local_to_global (i)];
  pressure_increment.update_ghost_values ();
  transport.apply_diffusive_fluxes (alpha,
                                    compaction_flux_matrix,
                                    pressure_increment,
                                    parameters.physical.maximum_packing);
}

/**
 * The velocity half of the correction (the SIMPLE/MFIX solids-fraction correction): the
 * compaction force the alpha correction made implicit, -grad w_h with w_h = sum_j P'_j
 * (alpha_j - alpha_m,j) phi_j the nodal pressure increment, is the impulse the momentum
 * solve would have seen with P_h at the corrected alpha_s, so u_s receives it with the
 * same local mobility 1/R, as a lumped L2 projection onto the Q2 nodes; the gas gives
 * way (mixture flux unchanged). Without it u_s keeps the explicit P_s impulse, which in a
 * packed bed is dt P' k |d alpha| / rho_s: a velocity that does not move alpha but grows
 * with the stiffness P' (measured at ~1 m/s in a bed at rest). With it the stiff modes
 * are damped by ~1/2 per step.
 */
template <int dim>
void SolidsPressureCorrection<dim>::correct_solids_velocity (
    const SolidsTransportInputs<dim> &inputs,
    const AlphaVector                &alpha,
    BlockVector                      &flow_solution)
{
  TimerOutput::Scope                scope (timer, "solids pressure correction");
  const Mapping<dim>               &mapping           = inputs.mapping;
  const FiniteElement<dim>         &alpha_fe          = inputs.alpha_fe;
  const FiniteElement<dim>         &flow_fe           = inputs.flow_fe;
  const DoFHandler<dim>            &alpha_dof_handler = inputs.alpha_dof_handler;
  const DoFHandler<dim>            &flow_dof_handler  = inputs.flow_dof_handler;
  const std::vector<IndexSet>      &flow_owned        = inputs.flow_owned;
  const closures::ClosureEvaluator &closures          = inputs.closures;
  const BDFCoefficients            &bdf               = inputs.bdf;
  const double                      dt                = inputs.dt;
  const QGauss<dim>                 quadrature (3);
  FEValues<dim>                     flow_values (
      mapping, flow_fe, quadrature, update_values | update_JxW_values);
  FEValues<dim> alpha_values (
      mapping, alpha_fe, quadrature, update_values | update_gradients);
  const unsigned int                   n       = flow_fe.n_dofs_per_cell ();
  const unsigned int                   n_alpha = alpha_fe.n_dofs_per_cell ();
  std::vector<types::global_dof_index> dofs (n), alpha_dofs (n_alpha);
  std::vector<double>                  a (quadrature.size ()), slopes (n_alpha);
  std::vector<Tensor<1, dim>>          ug (quadrature.size ()), us (quadrature.size ());
  const FEValuesExtractors::Vector     gas (0), solids (dim);
  BlockVector impulse (flow_owned, communicator), lumped_mass (flow_owned, communicator);
  Vector<double>       cell_impulse (n), cell_mass (n);
  const Tensor<1, dim> up = upward_direction<dim> (parameters.physical.gravity);
  const double         density_difference =
      parameters.physical.particle_density - parameters.physical.gas_density;
  double momentum   = 0;
  auto   alpha_cell = alpha_dof_handler.begin_active ();
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      alpha_cell->get_dof_indices (alpha_dofs);
      nodal_compaction_stiffness (closures, alpha_dofs, alpha, slopes);
      flow_values.reinit (cell);
      alpha_values.reinit (alpha_cell);
      cell->get_dof_indices (dofs);
      cell_impulse   = 0;
      cell_mass      = 0;
      bool compacted = false;
      for (unsigned int j = 0; j < n_alpha; ++j)
        compacted = compacted || (slopes[j] > 0 && alpha (alpha_dofs[j]) !=
                                                       alpha_momentum (alpha_dofs[j]));
      if (compacted)
      {
        alpha_values.get_function_values (alpha, a);
        flow_values[gas].get_function_values (flow_solution, ug);
        flow_values[solids].get_function_values (flow_solution, us);
      }
      for (unsigned int q = 0; q < quadrature.size () && compacted; ++q)
      {
        Tensor<1, dim> grad_w;
        for (unsigned int j = 0; j < n_alpha; ++j)
          grad_w += slopes[j] * (alpha (alpha_dofs[j]) - alpha_momentum (alpha_dofs[j])) *
                    alpha_values.shape_grad (j, q);
        if (!(a[q] > 1e-12))
          continue;
        const Tensor<1, dim> velocity_change =
            -compaction_mobility (closures, a[q], ug[q] - us[q], bdf.a0 / dt) / a[q] *
            grad_w;
        // the gas gives way so that the mixture volume flux is unchanged
        const double gas_share = -a[q] / (1.0 - a[q]);
        // the mixture momentum it adds: alpha_s rho_s du_s + alpha_g rho_g du_g
        momentum +=
            a[q] * density_difference * (velocity_change * up) * flow_values.JxW (q);
        for (unsigned int i = 0; i < n; ++i)
        {
          const unsigned int c = flow_fe.system_to_component_index (i).first;
          if (c >= 2 * dim)
            continue;
          const double phi = flow_values.shape_value (i, q) * flow_values.JxW (q);
          cell_impulse (i) +=
              (c < dim ? gas_share * velocity_change[c] : velocity_change[c - dim]) * phi;
        }
      }
      for (unsigned int q = 0; q < quadrature.size (); ++q)
        for (unsigned int i = 0; i < n; ++i)
          cell_mass (i) +=
              flow_values.shape_value (i, q) * flow_values.JxW (q); // lumped Q2 mass
      impulse.add (dofs, cell_impulse);
      lumped_mass.add (dofs, cell_mass);
    }
    ++alpha_cell;
  }
  impulse.compress (VectorOperation::add);
  lumped_mass.compress (VectorOperation::add);
  last_correction_momentum = Utilities::MPI::sum (momentum, communicator);
  // impulse / lumped mass, entry by entry (the mass is positive at every Q2 node)
  for (unsigned int b = 0; b < impulse.n_blocks (); ++b)
    for (const auto i : impulse.block (b).locally_owned_elements ())
      if (impulse.block (b) (i) != 0)
        impulse.block (b) (i) = impulse.block (b) (i) / lumped_mass.block (b) (i);
  impulse.compress (VectorOperation::insert);
  BlockVector corrected (flow_owned, communicator);
  corrected = flow_solution;
  corrected.add (1.0, impulse);
  // constrained u_s (inlet, wall normal) follow from the corrected unconstrained ones
  inputs.flow_constraints.distribute (corrected);
  flow_solution = corrected;
}

template class SolidsPressureCorrection<2>;
template class SolidsPressureCorrection<3>;
} // namespace wetbed
