#include <wetbed/assembly/flow/wall_friction_term.h>

namespace wetbed
{
template <int dim>
WallFrictionTerm<dim>::WallFrictionTerm (
    WallConditions                       conditions_,
    std::set<dealii::types::boundary_id> moving_walls,
    const dealii::Tensor<1, dim>        &wall_velocity)
    : conditions (std::move (conditions_)), moving_walls (std::move (moving_walls)),
      wall_velocity (wall_velocity)
{
  for (const Phase phase : {Phase::gas, Phase::solids})
    for (const auto id : conditions.walls (
             phase, [] (const WallCondition &c) { return c.has_friction (); }))
      friction_walls.insert (id);
}

template <int dim>
void WallFrictionTerm<dim>::face (const typename FlowTerm<dim>::CellIterator &cell,
                                  const unsigned int                          face_number,
                                  const FlowCellScratch<dim>                 &s,
                                  const FlowAssemblyState<dim> &,
                                  FlowCellCopy &copy) const
{
  const auto        &fv     = s.face_values;
  const unsigned int n_u    = s.indices.n_velocity_basis;
  const auto         id     = cell->face (face_number)->boundary_id ();
  const bool         moving = moving_walls.count (id) > 0;
  const auto        &first  = s.indices.velocity[0];
  for (const Phase phase : {Phase::gas, Phase::solids})
  {
    const WallCondition &condition = conditions.at (id, phase);
    if (!condition.has_friction ())
      continue;
    const unsigned int offset = phase == Phase::gas ? 0 : dim;
    for (unsigned int q = 0; q < fv.n_quadrature_points; ++q)
    {
      const dealii::Tensor<1, dim> n = fv.normal_vector (q);
      const double c = condition.friction ({s.face_alpha_s[q], s.face_theta[q]});
      // the slip is relative to a moving wall: C P_t (u - u_w), P_t u_w on the rhs
      dealii::Tensor<1, dim> wall_motion;
      if (moving)
        wall_motion = wall_velocity - (wall_velocity * n) * n;
      const double w = c * fv.JxW (q);
      for (unsigned int d = 0; d < dim; ++d)
      {
        const auto &rows = s.indices.velocity[offset + d];
        for (unsigned int a = 0; a < n_u; ++a)
        {
          const double phi_a = fv.shape_value (first[a], q) * w;
          copy.rhs (rows[a]) += wall_motion[d] * phi_a;
          for (unsigned int e = 0; e < dim && copy.with_matrix; ++e)
          {
            // C (P_t u).(P_t v) with P_t = I - n n
            const double projector = (d == e ? 1.0 : 0.0) - n[d] * n[e];
            const auto  &cols      = s.indices.velocity[offset + e];
            for (unsigned int b = 0; b < n_u; ++b)
              copy.matrix (rows[a], cols[b]) +=
                  projector * phi_a * fv.shape_value (first[b], q);
          }
        }
      }
    }
  }
}

template <int dim>
void WallFrictionTerm<dim>::face_coefficients (
    const typename FlowTerm<dim>::CellIterator &cell,
    const unsigned int                          face_number,
    const FlowCellScratch<dim>                 &s,
    const FlowAssemblyState<dim> &,
    const unsigned int              q,
    FlowFacePointCoefficients<dim> &c) const
{
  const auto id = cell->face (face_number)->boundary_id ();
  for (const Phase phase : {Phase::gas, Phase::solids})
  {
    const WallCondition &condition = conditions.at (id, phase);
    if (condition.has_friction ())
      c.friction[phase == Phase::gas ? 0 : 1] +=
          condition.friction ({s.face_alpha_s[q], s.face_theta[q]});
  }
}

template class WallFrictionTerm<2>;
template class WallFrictionTerm<3>;
} // namespace wetbed
