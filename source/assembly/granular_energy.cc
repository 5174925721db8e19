#include <wetbed/assembly/granular_energy.h>
#include <wetbed/closures/kinetic_theory/collisional_terms.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace wetbed
{
using namespace dealii;

namespace
{
/** 2 mu D:D + (lambda - 2/3 mu)(tr D)^2: the viscous heating of the strain rate D. */
double viscous_heating (const closures::KineticTheory::Coefficients &c,
                        const double                                 trace_d,
                        const double                                 d_ddot_d)
{
  return 2 * c.shear_viscosity * d_ddot_d +
         (c.bulk_viscosity - 2.0 / 3 * c.shear_viscosity) * trace_d * trace_d;
}

/** The dissipation and drag exchange at the temperature `theta` of one Gauss point. */
void add_sinks_to_budget (GranularEnergyBudget                        &budget,
                          const closures::KineticTheory::Coefficients &c,
                          const double                                 theta,
                          const double                                 beta,
                          const double                                 JxW)
{
  budget.dissipation += c.dissipation_factor * std::pow (theta, 1.5) * JxW;
  budget.drag_exchange += 3 * beta * theta * JxW;
}

/**
 * Discrete upwinding of a cell's convection-diffusion matrix, weighted by `upwinding`
 * (min(1, Pe_h)): d_ij = upwinding max(0, a_ij, a_ji) off the diagonal moved onto it.
 */
void upwind_cell_matrix (FullMatrix<double> &cell_matrix, const double upwinding)
{
  const unsigned int n = cell_matrix.m ();
  for (unsigned int i = 0; i < n; ++i)
    for (unsigned int j = 0; j < n; ++j)
      if (i != j)
      {
        const double d =
            upwinding * std::max ({0.0, cell_matrix (i, j), cell_matrix (j, i)});
        if (d > 0 && j > i)
        {
          cell_matrix (i, j) -= d;
          cell_matrix (j, i) -= d;
          cell_matrix (i, i) += d;
          cell_matrix (j, j) += d;
        }
      }
}

} // namespace

/**
 * The FEValues of the Theta assembly on the alpha_s space and the flow space, the fields
 * at the Gauss points of the current cell, its local system, and what the assembly needs
 * of the case.
 */
template <int dim>
struct GranularEnergyAssembler<dim>::Scratch
{
  using CellIterator = typename DoFHandler<dim>::active_cell_iterator;

  explicit Scratch (const GranularEnergyInputs<dim> &inputs)
      : quadrature (2), face_quadrature (2),
        theta_values (inputs.mapping,
                      inputs.alpha_fe,
                      quadrature,
                      update_values | update_gradients | update_quadrature_points |
                          update_JxW_values),
        flow_values (
            inputs.mapping, inputs.flow_fe, quadrature, update_values | update_gradients),
        theta_face (inputs.mapping,
                    inputs.alpha_fe,
                    face_quadrature,
                    update_values | update_quadrature_points | update_JxW_values),
        flow_face (inputs.mapping,
                   inputs.flow_fe,
                   face_quadrature,
                   update_values | update_normal_vectors),
        n (inputs.alpha_fe.n_dofs_per_cell ()), n_q (quadrature.size ()),
        cell_matrix (n, n), cell_rhs (n), cell_mass (n),
        flow_local (inputs.flow_fe.n_dofs_per_cell ()), dofs (n), a (n_q), t_now (n_q),
        t_old (n_q), t_old2 (n_q), ug (n_q), us (n_q), grad_us (n_q),
        a_face (face_quadrature.size ()), t_face (face_quadrature.size ()),
        us_face (face_quadrature.size ()), gas (0), solids (dim),
        wall_velocity (inputs.moving_wall_velocity),
        imposed_sources (inputs.verification.exact_granular_temperature () != nullptr)
  {
  }

  /** The fields at the Gauss points of `cell` (and `flow_cell`, the same cell of the
   * flow space) at the linearisation point `theta`, its DoFs, and its local system
   * zeroed. */
  void reinit (const GranularEnergyInputs<dim> &inputs,
               const AlphaVector               &theta,
               const CellIterator              &cell,
               const CellIterator              &flow_cell)
  {
    theta_values.reinit (cell);
    flow_values.reinit (flow_cell);
    theta_values.get_function_values (inputs.alpha, a);
    theta_values.get_function_values (theta, t_now);
    theta_values.get_function_values (inputs.theta_old, t_old);
    theta_values.get_function_values (inputs.theta_old2, t_old2);
    // the cell's flow DoF values read once (a Trilinos vector looks every entry up by
    // its global index)
    flow_cell->get_dof_values (inputs.flow_solution, flow_local);
    const auto local = make_array_view (flow_local.begin (), flow_local.end ());
    flow_values[gas].get_function_values_from_local_dof_values (local, ug);
    flow_values[solids].get_function_values_from_local_dof_values (local, us);
    flow_values[solids].get_function_gradients_from_local_dof_values (local, grad_us);
    cell->get_dof_indices (dofs);
    cell_matrix = 0;
    cell_rhs    = 0;
    cell_mass   = 0;
  }

  const QGauss<dim>                    quadrature;
  const QGauss<dim - 1>                face_quadrature;
  FEValues<dim>                        theta_values, flow_values;
  FEFaceValues<dim>                    theta_face, flow_face;
  const unsigned int                   n, n_q;
  FullMatrix<double>                   cell_matrix;
  Vector<double>                       cell_rhs, cell_mass, flow_local;
  std::vector<types::global_dof_index> dofs;
  std::vector<double>                  a, t_now, t_old, t_old2;
  std::vector<Tensor<1, dim>>          ug, us;
  std::vector<Tensor<2, dim>>          grad_us;
  std::vector<double>                  a_face, t_face;
  std::vector<Tensor<1, dim>>          us_face;
  const FEValuesExtractors::Vector     gas, solids;
  const Tensor<1, dim>                 wall_velocity;
  // verification runs with an exact Theta: its volume and boundary sources
  const bool imposed_sources;
};

template <int dim>
GranularEnergyAssembler<dim>::GranularEnergyAssembler (const Parameters &parameters,
                                                       MPI_Comm          communicator)
    : parameters (parameters), communicator (communicator)
{
}

template <int dim>
void GranularEnergyAssembler<dim>::project_algebraic (
    const GranularEnergyInputs<dim> &inputs,
    const AlphaVector               &theta,
    TrilinosWrappers::MPI::Vector   &solution,
    GranularEnergyBudget            &budget) const
{
  const auto                   &kt = parameters.kinetic_theory;
  Scratch                       scratch (inputs);
  const FEValues<dim>          &theta_values = scratch.theta_values;
  Vector<double>               &cell_rhs     = scratch.cell_rhs;
  Vector<double>               &cell_mass    = scratch.cell_mass;
  TrilinosWrappers::MPI::Vector rhs (inputs.alpha_dof_handler.locally_owned_dofs (),
                                     communicator),
      lumped (rhs);

  auto flow_cell = inputs.flow_dof_handler.begin_active ();
  for (const auto &cell : inputs.alpha_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      scratch.reinit (inputs, theta, cell, flow_cell);
      for (unsigned int q = 0; q < scratch.n_q; ++q)
      {
        const double alpha_s = std::max (scratch.a[q], 0.0), JxW = theta_values.JxW (q);
        const SymmetricTensor<2, dim> D        = symmetrize (scratch.grad_us[q]);
        const double                  trace_d  = trace (D);
        const double                  d_ddot_d = D * D;
        const double                  beta =
            inputs.closures.drag (alpha_s, (scratch.ug[q] - scratch.us[q]).norm ());
        for (unsigned int i = 0; i < scratch.n; ++i)
          cell_mass (i) += theta_values.shape_value (i, q) * JxW;
        // as the PDE's production: scaled by min(1, alpha_s/alpha_dilute) (the local
        // equilibrium of a trace of particles, ~1/alpha_s, is meaningless), clamped
        const double value = std::clamp (kt.dilute_weight (alpha_s) *
                                             inputs.kinetic_theory.algebraic_temperature (
                                                 alpha_s, trace_d, d_ddot_d, beta),
                                         kt.minimum_temperature,
                                         kt.maximum_temperature);
        for (unsigned int i = 0; i < scratch.n; ++i)
          cell_rhs (i) += value * theta_values.shape_value (i, q) * JxW;
        const auto c = inputs.kinetic_theory.evaluate (alpha_s, value);
        budget.production += viscous_heating (c, trace_d, d_ddot_d) * JxW;
        add_sinks_to_budget (budget, c, value, beta, JxW);
      }
      inputs.alpha_constraints.distribute_local_to_global (cell_rhs, scratch.dofs, rhs);
      inputs.alpha_constraints.distribute_local_to_global (
          cell_mass, scratch.dofs, lumped);
    }
    ++flow_cell;
  }
  rhs.compress (VectorOperation::add);
  lumped.compress (VectorOperation::add);

  for (const auto i : solution.locally_owned_elements ())
    solution (i) =
        inputs.alpha_constraints.is_constrained (i) ? 0.0 : rhs (i) / lumped (i);
}

template <int dim>
void GranularEnergyAssembler<dim>::assemble (const GranularEnergyInputs<dim> &inputs,
                                             const AlphaVector               &theta,
                                             TrilinosWrappers::SparseMatrix  &matrix,
                                             TrilinosWrappers::MPI::Vector   &rhs,
                                             GranularEnergyBudget &budget) const
{
  Scratch scratch (inputs);
  matrix = 0;

  auto flow_cell = inputs.flow_dof_handler.begin_active ();
  for (const auto &cell : inputs.alpha_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      scratch.reinit (inputs, theta, cell, flow_cell);
      const double peclet = volume_terms (inputs, cell, scratch, budget);
      // discrete upwinding: d_ij = max(0, a_ij, a_ji) of the convection-diffusion
      // matrix, weighted by min(1, Pe_h). On Q1 hexahedra the Laplacian's entries
      // between edge neighbours are zero (positive on distorted cells), so the full
      // d_ij is O(rho |u| h^2) however fine the mesh: a first-order error (measured:
      // Theta converged at rate 1.0 in the 3D verification run, doc/verification.md).
      // Weighted by Pe_h it is O(h^2) where the conduction resolves the convection and
      // the full upwinding (an M-matrix) where it does not (the dilute freeboard, coarse
      // beds).
      const double upwinding = std::min (1.0, peclet);
      upwind_cell_matrix (scratch.cell_matrix, upwinding);
      boundary_terms (inputs, theta, cell, flow_cell, scratch, budget);
      inputs.alpha_constraints.distribute_local_to_global (
          scratch.cell_matrix, scratch.dofs, matrix);
      inputs.alpha_constraints.distribute_local_to_global (
          scratch.cell_rhs, scratch.dofs, rhs);
    }
    ++flow_cell;
  }
  rhs.compress (VectorOperation::add);
  matrix.compress (VectorOperation::add);
}

template <int dim>
double
GranularEnergyAssembler<dim>::volume_terms (const GranularEnergyInputs<dim> &inputs,
                                            const CellIterator              &cell,
                                            Scratch                         &scratch,
                                            GranularEnergyBudget            &budget) const
{
  const auto          &kt             = parameters.kinetic_theory;
  const double         rho_s          = parameters.physical.particle_density;
  const double         residual_alpha = 1e-6;
  const unsigned int   n              = scratch.n;
  const FEValues<dim> &theta_values   = scratch.theta_values;
  FullMatrix<double>  &cell_matrix    = scratch.cell_matrix;
  Vector<double>      &cell_rhs       = scratch.cell_rhs;
  const auto          &us             = scratch.us;
  // cell Peclet number of the Theta convection (the largest over the Gauss points)
  const double h_cell = cell->diameter () / std::sqrt (double (dim));
  double       peclet = 0;
  for (unsigned int q = 0; q < scratch.n_q; ++q)
  {
    const double alpha_s = std::max (scratch.a[q], 0.0), JxW = theta_values.JxW (q);
    const SymmetricTensor<2, dim> D        = symmetrize (scratch.grad_us[q]);
    const double                  trace_d  = trace (D);
    const double                  d_ddot_d = D * D;
    const double beta = inputs.closures.drag (alpha_s, (scratch.ug[q] - us[q]).norm ());
    const double theta_star   = std::max (scratch.t_now[q], kt.minimum_temperature);
    const auto   c            = inputs.kinetic_theory.evaluate (alpha_s, theta_star);
    const double capacity     = 1.5 * rho_s * std::max (alpha_s, residual_alpha);
    const double dilute       = kt.dilute_weight (alpha_s);
    const double conductivity = dilute * c.conductivity;
    peclet                    = std::max (peclet,
                       capacity * us[q].norm () * h_cell /
                           (2 * conductivity + std::numeric_limits<double>::min ()));
    const double heating =
        dilute * (viscous_heating (c, trace_d, d_ddot_d) +
                  c.pressure_factor * theta_star * std::max (-trace_d, 0.0));
    const double sink = c.dissipation_factor * std::sqrt (theta_star) + 3 * beta +
                        c.pressure_factor * std::max (trace_d, 0.0);
    const double history =
        -(inputs.bdf.a1 * scratch.t_old[q] + inputs.bdf.a2 * scratch.t_old2[q]) /
        inputs.dt;
    const double source = scratch.imposed_sources
                              ? inputs.verification.granular_energy_source (
                                    theta_values.quadrature_point (q))
                              : 0.0;
    budget.production += heating * JxW;
    add_sinks_to_budget (budget, c, theta_star, beta, JxW);
    for (unsigned int i = 0; i < n; ++i)
    {
      const double phi_i = theta_values.shape_value (i, q);
      // lumped: mass, history, sinks on the diagonal
      cell_matrix (i, i) += (capacity * inputs.bdf.a0 / inputs.dt + sink) * phi_i * JxW;
      cell_rhs (i) += (heating + source + capacity * history) * phi_i * JxW;
      for (unsigned int j = 0; j < n; ++j)
        cell_matrix (i, j) +=
            (capacity * phi_i * (us[q] * theta_values.shape_grad (j, q)) +
             conductivity *
                 (theta_values.shape_grad (i, q) * theta_values.shape_grad (j, q))) *
            JxW;
    }
  }
  return peclet;
}

template <int dim>
void GranularEnergyAssembler<dim>::boundary_terms (
    const GranularEnergyInputs<dim> &inputs,
    const AlphaVector               &theta,
    const CellIterator              &cell,
    const CellIterator              &flow_cell,
    Scratch                         &scratch,
    GranularEnergyBudget            &budget) const
{
  const auto            &kt              = parameters.kinetic_theory;
  const unsigned int     n               = scratch.n;
  const QGauss<dim - 1> &face_quadrature = scratch.face_quadrature;
  FEFaceValues<dim>     &theta_face      = scratch.theta_face;
  FEFaceValues<dim>     &flow_face       = scratch.flow_face;
  FullMatrix<double>    &cell_matrix     = scratch.cell_matrix;
  Vector<double>        &cell_rhs        = scratch.cell_rhs;
  for (const auto &face : cell->face_iterators ())
  {
    if (!face->at_boundary ())
      continue;
    const bool wall_face = inputs.boundaries.is_wall (face->boundary_id ()) &&
                           inputs.wall_conditions.at (face->boundary_id (), Phase::solids)
                               .has_granular_energy_flux ();
    // the slip is relative to a moving wall
    const Tensor<1, dim> wall_motion =
        inputs.boundaries.is (face->boundary_id (), BoundaryType::moving_wall)
            ? scratch.wall_velocity
            : Tensor<1, dim> ();
    if (scratch.imposed_sources)
    {
      theta_face.reinit (cell, face);
      flow_face.reinit (flow_cell, face);
      for (unsigned int q = 0; q < face_quadrature.size (); ++q)
      {
        const double flux = inputs.verification.granular_energy_boundary_source (
            theta_face.quadrature_point (q), flow_face.normal_vector (q), wall_face);
        for (unsigned int i = 0; i < n; ++i)
          cell_rhs (i) += flux * theta_face.shape_value (i, q) * theta_face.JxW (q);
      }
    }
    if (wall_face)
    {
      theta_face.reinit (cell, face);
      flow_face.reinit (flow_cell, face);
      theta_face.get_function_values (inputs.alpha, scratch.a_face);
      theta_face.get_function_values (theta, scratch.t_face);
      flow_face[scratch.solids].get_function_values (inputs.flow_solution,
                                                     scratch.us_face);
      for (unsigned int q = 0; q < face_quadrature.size (); ++q)
      {
        const double alpha_s     = std::max (scratch.a_face[q], 0.0);
        const double theta_star  = std::max (scratch.t_face[q], kt.minimum_temperature);
        const double g0          = inputs.kinetic_theory.radial_distribution (alpha_s);
        const Tensor<1, dim> n_w = flow_face.normal_vector (q);
        const Tensor<1, dim> relative = scratch.us_face[q] - wall_motion;
        const double         slip     = (relative - (relative * n_w) * n_w).norm ();
        const double         generation =
            kt.dilute_weight (alpha_s) * inputs.kinetic_theory.wall ().energy_generation (
                                             alpha_s, g0, theta_star, slip);
        const double sink =
            inputs.kinetic_theory.wall ().energy_dissipation (alpha_s, g0, theta_star) /
            theta_star;
        budget.wall_flux += (generation - sink * theta_star) * theta_face.JxW (q);
        for (unsigned int i = 0; i < n; ++i)
        {
          const double phi_i = theta_face.shape_value (i, q) * theta_face.JxW (q);
          cell_rhs (i) += generation * phi_i;
          cell_matrix (i, i) += sink * phi_i;
        }
      }
    }
  }
}

template class GranularEnergyAssembler<2>;
template class GranularEnergyAssembler<3>;
} // namespace wetbed
