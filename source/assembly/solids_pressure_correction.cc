#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/trilinos_precondition.h>

namespace wetbed
{
using namespace dealii;

/**
 * Implicit solids-pressure correction (DESIGN s4.2, the OpenFOAM implicitPhasePressure /
 * MFIX solids-correction idea in increment form). The momentum solve that produced the
 * transporting u_s saw -grad P_s(alpha_m); the correction makes the compaction response
 * implicit in the change since then:
 *   M_L (alpha - alpha*)/dt + K[D_p] (alpha - alpha_m) = 0,
 *   D_p = alpha_s P_s'(alpha*) / (a0 alpha_s rho_s / dt + beta).
 * K[D_p] is symmetric with zero row sums, so the solids mass is kept to solver
 * tolerance; a bed at rest (alpha* = alpha_m) is left exactly at rest. Skipped where
 * P_s' = 0, i.e. in every scene without compacted regions.
 */
/**
 * The stiffness dP_s/dalpha the correction uses: P_s is convex, so the slope at the
 * larger of alpha_s (now) and alpha_m (what the momentum solve saw) bounds the secant
 * the momentum equation will see from above. An estimate below it (r = s_c/s_m < 1/2
 * in a Fourier analysis of the scheme) lets compaction modes grow; above it (up to
 * r ~ 5) they are damped by ~1/2 per step.
 */
template <int dim>
double TwoFluidSolver<dim>::compaction_stiffness (const double alpha_s,
                                                  const double alpha_m) const
{
  return solids_stress->evaluate ({std::max (alpha_s, alpha_m), 0.0, 0.0})
      .pressure_derivative;
}

/**
 * Resistance of the solids to a compaction velocity when the gas gives way (mixture
 * volume flux unchanged, u_g = -alpha_s/alpha_g u_s): eliminating the gas momentum
 * and the pressure gives
 *   a0/dt alpha_s rho_s + a0/dt alpha_s^2 rho_g / alpha_g + beta / alpha_g^2,
 * i.e. the drag counts 1/alpha_g^2 times (6 times in a packed bed), not once.
 */
template <int dim>
double TwoFluidSolver<dim>::compaction_resistance (const double alpha_s,
                                                   const double beta,
                                                   const double rate) const
{
  const double alpha_g = std::max (1.0 - alpha_s, 1e-6);
  const auto  &pp      = parameters.physical;
  return rate * alpha_s * (pp.particle_density + alpha_s * pp.gas_density / alpha_g) +
         beta / (alpha_g * alpha_g);
}

template <int dim>
bool TwoFluidSolver<dim>::correct_solids_pressure (const AlphaVector     &alpha_momentum,
                                                   const BDFCoefficients &bdf,
                                                   const double           dt)
{
  TimerOutput::Scope scope (timer, "solids pressure correction");

  const QGauss<dim>  quadrature (2);
  FEValues<dim>      alpha_values (mapping,
                              alpha_fe,
                              quadrature,
                              update_values | update_gradients | update_JxW_values);
  FEValues<dim>      flow_values (mapping, flow_fe, quadrature, update_values);
  const unsigned int n = alpha_fe.n_dofs_per_cell ();
  FullMatrix<double> cell_matrix (n, n);
  Vector<double>     cell_rhs (n);
  std::vector<types::global_dof_index> dofs (n);
  std::vector<double>                  a (quadrature.size ()), a_m (quadrature.size ());
  std::vector<Tensor<1, dim>>          ug (quadrature.size ()), us (quadrature.size ());
  const FEValuesExtractors::Vector     gas (0), solids (dim);

  correction_matrix = 0;
  TrilinosWrappers::MPI::Vector rhs (alpha_dof_handler.locally_owned_dofs (),
                                     communicator);
  bool                          active    = false;
  auto                          flow_cell = flow_dof_handler.begin_active ();
  for (const auto &cell : alpha_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      alpha_values.reinit (cell);
      flow_values.reinit (flow_cell);
      alpha_values.get_function_values (alpha, a);
      alpha_values.get_function_values (alpha_momentum, a_m);
      flow_values[gas].get_function_values (flow_solution, ug);
      flow_values[solids].get_function_values (flow_solution, us);
      cell->get_dof_indices (dofs);
      cell_matrix = 0;
      cell_rhs    = 0;
      for (unsigned int q = 0; q < quadrature.size (); ++q)
      {
        const double alpha_s = a[q];
        const double slope   = compaction_stiffness (alpha_s, a_m[q]);
        const double beta =
            alpha_s > 0
                ? drag->coefficient (alpha_s, (ug[q] - us[q]).norm (), gas_particle)
                : 0;
        const double diffusivity =
            slope > 0
                ? alpha_s * slope / compaction_resistance (alpha_s, beta, bdf.a0 / dt)
                : 0.0;
        active = active || diffusivity > 0;
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            cell_matrix (i, j) +=
                diffusivity * dt *
                (alpha_values.shape_grad (i, q) * alpha_values.shape_grad (j, q)) *
                alpha_values.JxW (q);
      }
      // rhs: K (alpha_m - alpha*) so that the unknown is the increment alpha - alpha*
      for (unsigned int i = 0; i < n; ++i)
        for (unsigned int j = 0; j < n; ++j)
          cell_rhs (i) +=
              cell_matrix (i, j) * (alpha_momentum (dofs[j]) - alpha (dofs[j]));
      // lumped mass on the diagonal
      for (unsigned int q = 0; q < quadrature.size (); ++q)
        for (unsigned int i = 0; i < n; ++i)
          cell_matrix (i, i) += alpha_values.shape_value (i, q) * alpha_values.JxW (q);
      correction_matrix.add (dofs, cell_matrix);
      rhs.add (dofs, cell_rhs);
    }
    ++flow_cell;
  }
  correction_matrix.compress (VectorOperation::add);
  rhs.compress (VectorOperation::add);
  if (!Utilities::MPI::logical_or (active, communicator))
    return false;

  TrilinosWrappers::MPI::Vector increment (rhs);
  increment = 0;
  SolverControl control (
      1000, parameters.linear_solver.scalar_tolerance * rhs.l2_norm () + 1e-300);
  SolverCG<TrilinosWrappers::MPI::Vector> cg (control);
  TrilinosWrappers::PreconditionAMG       amg;
  amg.initialize (correction_matrix);
  cg.solve (correction_matrix, increment, rhs, amg);
  // x = alpha* + increment - alpha_m; the increment becomes the limited edge fluxes
  // -A_ij (x_j - x_i) of the scaled operator A = dt K (its off-diagonal part)
  AlphaVector x (alpha);
  for (unsigned int i = 0; i < x.locally_owned_size (); ++i)
    x.local_element (i) = alpha.local_element (i) +
                          increment[alpha.get_partitioner ()->local_to_global (i)] -
                          alpha_momentum.local_element (i);
  x.update_ghost_values ();
  transport.apply_diffusive_fluxes (
      alpha, correction_matrix, x, parameters.physical.maximum_packing);
  return true;
}

/**
 * The velocity half of the correction (the SIMPLE/MFIX solids-fraction correction): the
 * compaction that the alpha correction made implicit, -P_s' grad(alpha - alpha_m), is
 * the impulse the momentum solve would have seen with P_s at the corrected alpha_s, so
 * u_s receives it with the same local mobility 1/(a0 alpha_s rho_s/dt + beta), as a
 * lumped L2 projection onto the Q2 nodes. Without it u_s keeps the explicit P_s
 * impulse, which in a packed bed is dt P' k |d alpha| / rho_s: a velocity that does
 * not move alpha but grows with the stiffness P' (an undamped oscillation, measured
 * at ~1 m/s in a bed at rest). With it the stiff modes are damped by ~1/2 per step.
 */
template <int dim>
void TwoFluidSolver<dim>::correct_solids_velocity (const AlphaVector     &alpha_momentum,
                                                   const BDFCoefficients &bdf,
                                                   const double           dt)
{
  TimerOutput::Scope scope (timer, "solids pressure correction");
  const QGauss<dim>  quadrature (3);
  FEValues<dim>      flow_values (
      mapping, flow_fe, quadrature, update_values | update_JxW_values);
  FEValues<dim> alpha_values (
      mapping, alpha_fe, quadrature, update_values | update_gradients);
  const unsigned int                   n = flow_fe.n_dofs_per_cell ();
  std::vector<types::global_dof_index> dofs (n);
  std::vector<double>                  a (quadrature.size ()), a_m (quadrature.size ());
  std::vector<Tensor<1, dim>> grad_a (quadrature.size ()), grad_a_m (quadrature.size ()),
      ug (quadrature.size ()), us (quadrature.size ());
  const FEValuesExtractors::Vector gas (0), solids (dim);
  BlockVector impulse (flow_owned, communicator), lumped_mass (flow_owned, communicator);
  Vector<double> cell_impulse (n), cell_mass (n);
  auto           alpha_cell = alpha_dof_handler.begin_active ();
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      flow_values.reinit (cell);
      alpha_values.reinit (alpha_cell);
      alpha_values.get_function_values (alpha, a);
      alpha_values.get_function_gradients (alpha, grad_a);
      alpha_values.get_function_gradients (alpha_momentum, grad_a_m);
      alpha_values.get_function_values (alpha_momentum, a_m);
      flow_values[gas].get_function_values (flow_solution, ug);
      flow_values[solids].get_function_values (flow_solution, us);
      cell->get_dof_indices (dofs);
      cell_impulse = 0;
      cell_mass    = 0;
      for (unsigned int q = 0; q < quadrature.size (); ++q)
      {
        const double slope = compaction_stiffness (a[q], a_m[q]);
        if (!(slope > 0))
          continue;
        const double beta =
            a[q] > 0 ? drag->coefficient (a[q], (ug[q] - us[q]).norm (), gas_particle)
                     : 0;
        const Tensor<1, dim> velocity_change =
            -slope / compaction_resistance (a[q], beta, bdf.a0 / dt) *
            (grad_a[q] - grad_a_m[q]);
        // the gas gives way so that the mixture volume flux is unchanged
        const double gas_share = -a[q] / (1.0 - a[q]);
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
  flow_constraints.distribute (corrected);
  flow_solution = corrected;
}

template void   TwoFluidSolver<2>::correct_solids_velocity (const AlphaVector &,
                                                          const BDFCoefficients &,
                                                          double);
template void   TwoFluidSolver<3>::correct_solids_velocity (const AlphaVector &,
                                                          const BDFCoefficients &,
                                                          double);
template double TwoFluidSolver<2>::compaction_resistance (double, double, double) const;
template double TwoFluidSolver<3>::compaction_resistance (double, double, double) const;
template double TwoFluidSolver<2>::compaction_stiffness (double, double) const;
template double TwoFluidSolver<3>::compaction_stiffness (double, double) const;
template bool   TwoFluidSolver<2>::correct_solids_pressure (const AlphaVector &,
                                                          const BDFCoefficients &,
                                                          double);
template bool   TwoFluidSolver<3>::correct_solids_pressure (const AlphaVector &,
                                                          const BDFCoefficients &,
                                                          double);
} // namespace wetbed
