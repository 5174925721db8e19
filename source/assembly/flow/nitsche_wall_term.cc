#include <wetbed/assembly/flow/nitsche_wall_term.h>
#include <wetbed/assembly/nitsche_wall.h>

#include <deal.II/grid/manifold.h>

namespace wetbed
{
template <int dim>
std::array<NitschePhase, 2>
NitscheWallTerm<dim>::phase_data (const typename FlowTerm<dim>::CellIterator &cell,
                                  const FlowCellScratch<dim>                 &s,
                                  const FlowAssemblyState<dim>               &state,
                                  const unsigned int                          q,
                                  dealii::Tensor<1, dim> &wall_normal) const
{
  const auto                &fv    = s.face_values;
  const auto                 face  = cell->face (s.face_number);
  const std::array<bool, 2> &slips = phases.at (face->boundary_id ());
  const double h = s.h, rho_g = material.gas_density, mu_g = material.gas_viscosity;
  // the phase coefficients as in the volume terms, at the face point
  const double                 a    = s.face_alpha_s[q];
  const double                 slip = (s.face_u[0][q] - s.face_u[1][q]).norm ();
  const double                 beta = evaluator.coupling_drag (a, slip);
  const closures::SolidsStress stress =
      evaluator.stress (a,
                        s.face_theta[q],
                        closures::ClosureEvaluator::shear_rate<dim> (s.face_grad_u_s[q]),
                        trace (s.face_grad_u_s[q]));
  double compaction = 0;
  for (unsigned int j = 0; j < s.closures.nodal_compaction_pressure.size (); ++j)
    compaction +=
        s.closures.nodal_compaction_pressure[j] * s.alpha_face_values.shape_value (j, q);
  auto scale = [&] (const double mu, const double inertia, const double u)
  {
    return mu + inertia * u * h + inertia * h * h * state.bdf.a0 / state.dt +
           beta * h * h;
  };
  // the wall's own normal where the wall is curved (a manifold other than flat),
  // oriented as the mapped one
  const dealii::Tensor<1, dim> n = fv.normal_vector (q);
  wall_normal                    = n;
  if (face->manifold_id () != dealii::numbers::flat_manifold_id)
  {
    wall_normal = face->get_manifold ().normal_vector (face, fv.quadrature_point (q));
    wall_normal /= wall_normal.norm ();
    if (wall_normal * n < 0)
      wall_normal *= -1.0;
  }
  return {
      {NitschePhase{slips[0],
                    0,
                    1 - a,
                    (1 - a) * mu_g,
                    -2.0 / 3.0 * (1 - a) * mu_g,
                    scale ((1 - a) * mu_g, (1 - a) * rho_g, s.face_u[0][q].norm ()),
                    0.0},
       NitschePhase{slips[1],
                    dim,
                    a,
                    stress.shear_viscosity,
                    stress.bulk_viscosity - 2.0 / 3.0 * stress.shear_viscosity,
                    scale (stress.shear_viscosity,
                           evaluator.inertial_fraction (a) * material.particle_density,
                           s.face_u[1][q].norm ()),
                    compaction + stress.kinetic_pressure}}};
}

template <int dim>
void NitscheWallTerm<dim>::face (const typename FlowTerm<dim>::CellIterator &cell,
                                 unsigned int,
                                 const FlowCellScratch<dim>   &s,
                                 const FlowAssemblyState<dim> &state,
                                 FlowCellCopy                 &copy) const
{
  for (unsigned int q = 0; q < s.face_values.n_quadrature_points; ++q)
  {
    dealii::Tensor<1, dim>            wall_normal;
    const std::array<NitschePhase, 2> nitsche =
        phase_data (cell, s, state, q, wall_normal);
    add_nitsche_no_penetration (s.face_values,
                                q,
                                wall_normal,
                                s.indices.component,
                                nitsche,
                                gamma,
                                s.h,
                                copy.with_matrix ? &copy.matrix : nullptr,
                                copy.rhs);
  }
}

template <int dim>
void NitscheWallTerm<dim>::face_coefficients (
    const typename FlowTerm<dim>::CellIterator &cell,
    unsigned int,
    const FlowCellScratch<dim>     &s,
    const FlowAssemblyState<dim>   &state,
    const unsigned int              q,
    FlowFacePointCoefficients<dim> &c) const
{
  const std::array<NitschePhase, 2> nitsche =
      phase_data (cell, s, state, q, c.wall_normal);
  for (unsigned int k = 0; k < 2; ++k)
  {
    c.slips[k]     = nitsche[k].slips;
    c.viscosity[k] = nitsche[k].viscosity;
    c.bulk[k]      = nitsche[k].bulk;
    c.penalty[k]   = gamma * nitsche[k].penalty_scale / s.h;
    c.fraction[k]  = nitsche[k].fraction;
  }
}

template class NitscheWallTerm<2>;
template class NitscheWallTerm<3>;
} // namespace wetbed
