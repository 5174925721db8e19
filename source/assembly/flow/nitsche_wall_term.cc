#include <wetbed/assembly/flow/nitsche_wall_term.h>
#include <wetbed/assembly/nitsche_wall.h>

#include <deal.II/grid/manifold.h>

namespace wetbed
{
template <int dim>
void NitscheWallTerm<dim>::face (const typename FlowTerm<dim>::CellIterator &cell,
                                 const unsigned int                          face_number,
                                 const FlowCellScratch<dim>                 &s,
                                 const FlowAssemblyState<dim>               &state,
                                 FlowCellCopy                               &copy) const
{
  const auto                &fv    = s.face_values;
  const auto                 face  = cell->face (face_number);
  const std::array<bool, 2> &slips = phases.at (face->boundary_id ());
  const double h = s.h, rho_g = material.gas_density, mu_g = material.gas_viscosity;
  for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
  {
    // the phase coefficients as in the volume terms, at the face point
    const double                 a      = s.face_alpha_s[q];
    const double                 slip   = (s.face_u[0][q] - s.face_u[1][q]).norm ();
    const double                 beta   = evaluator.coupling_drag (a, slip);
    const closures::SolidsStress stress = evaluator.stress (
        a,
        s.face_theta[q],
        closures::ClosureEvaluator::shear_rate<dim> (s.face_grad_u_s[q]));
    double compaction = 0;
    for (unsigned int j = 0; j < s.closures.nodal_compaction_pressure.size (); ++j)
      compaction += s.closures.nodal_compaction_pressure[j] *
                    s.alpha_face_values.shape_value (j, q);
    auto scale = [&] (const double mu, const double inertia, const double u)
    {
      return mu + inertia * u * h + inertia * h * h * state.bdf.a0 / state.dt +
             beta * h * h;
    };
    const std::array<NitschePhase, 2> nitsche = {
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
    // the wall's own normal where the wall is curved (a manifold other than flat),
    // oriented as the mapped one
    const dealii::Tensor<1, dim> n           = fv.normal_vector (q);
    dealii::Tensor<1, dim>       wall_normal = n;
    if (face->manifold_id () != dealii::numbers::flat_manifold_id)
    {
      wall_normal = face->get_manifold ().normal_vector (face, fv.quadrature_point (q));
      wall_normal /= wall_normal.norm ();
      if (wall_normal * n < 0)
        wall_normal *= -1.0;
    }
    add_nitsche_no_penetration (fv,
                                q,
                                wall_normal,
                                s.indices.component,
                                nitsche,
                                gamma,
                                h,
                                copy.matrix,
                                copy.rhs);
  }
}

template class NitscheWallTerm<2>;
template class NitscheWallTerm<3>;
} // namespace wetbed
