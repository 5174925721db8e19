#include <wetbed/assembly/flow/flow_assembly_data.h>

namespace wetbed
{
template <int dim>
FlowElementIndices::FlowElementIndices (const dealii::FESystem<dim> &fe)
    : n_dofs (fe.n_dofs_per_cell ()),
      n_velocity_basis (fe.base_element (0).n_dofs_per_cell ()),
      n_pressure_basis (fe.base_element (1).n_dofs_per_cell ()),
      velocity (2 * dim, std::vector<unsigned int> (n_velocity_basis)),
      pressure (n_pressure_basis), component (n_dofs)
{
  for (unsigned int c = 0; c < 2 * dim; ++c)
    for (unsigned int a = 0; a < n_velocity_basis; ++a)
      velocity[c][a] = fe.component_to_system_index (c, a);
  for (unsigned int b = 0; b < n_pressure_basis; ++b)
    pressure[b] = fe.component_to_system_index (2 * dim, b);
  for (unsigned int i = 0; i < n_dofs; ++i)
    component[i] = fe.system_to_component_index (i).first;
}

template <int dim>
FlowCellScratch<dim>::FlowCellScratch (const dealii::Mapping<dim>        &mapping,
                                       const dealii::FESystem<dim>       &flow_fe,
                                       const dealii::FiniteElement<dim>  &alpha_fe,
                                       const dealii::Quadrature<dim>     &quadrature,
                                       const dealii::Quadrature<dim - 1> &face_quadrature)
    : velocity_values (mapping,
                       flow_fe.base_element (0),
                       quadrature,
                       dealii::update_values | dealii::update_gradients |
                           dealii::update_quadrature_points | dealii::update_JxW_values),
      pressure_values (mapping,
                       flow_fe.base_element (1),
                       quadrature,
                       dealii::update_values | dealii::update_gradients),
      alpha_values (mapping,
                    alpha_fe,
                    quadrature,
                    dealii::update_values | dealii::update_gradients),
      face_values (mapping,
                   flow_fe,
                   face_quadrature,
                   dealii::update_values | dealii::update_gradients |
                       dealii::update_normal_vectors | dealii::update_quadrature_points |
                       dealii::update_JxW_values),
      alpha_face_values (mapping, alpha_fe, face_quadrature, dealii::update_values),
      indices (flow_fe)
{
  const unsigned int n_q = quadrature.size (), n_fq = face_quadrature.size ();
  JxW.resize (n_q);
  phi.assign (n_q, std::vector<double> (indices.n_velocity_basis));
  grad_phi.assign (n_q, std::vector<dealii::Tensor<1, dim>> (indices.n_velocity_basis));
  phi_p.assign (n_q, std::vector<double> (indices.n_pressure_basis));
  grad_phi_p.assign (n_q, std::vector<dealii::Tensor<1, dim>> (indices.n_pressure_basis));
  for (auto *v :
       {&alpha_s, &alpha_s_old, &alpha_s_old2, &theta, &slip, &compaction_pressure})
    v->resize (n_q);
  grad_alpha_s.resize (n_q);
  for (unsigned int k = 0; k < 2; ++k)
  {
    u[k].resize (n_q);
    u_old[k].resize (n_q);
    u_old2[k].resize (n_q);
    grad_u[k].resize (n_q);
    for (auto *v : {&fraction[k], &inertia[k], &viscosity[k], &bulk[k], &bdf_mass[k]})
      v->resize (n_q);
    face_u[k].resize (n_fq);
  }
  alpha_nodal.reinit (alpha_fe.n_dofs_per_cell ());
  for (auto *v : {&flow_local, &flow_old_local, &flow_old2_local})
    v->reinit (flow_fe.n_dofs_per_cell ());
  closures.resize (n_q, alpha_fe.n_dofs_per_cell ());
  face_alpha_s.resize (n_fq);
  face_theta.resize (n_fq);
  face_grad_u_s.resize (n_fq);
}

template <int dim>
FlowCellScratch<dim>::FlowCellScratch (const FlowCellScratch &other)
    : FlowCellScratch (
          other.velocity_values.get_mapping (),
          dynamic_cast<const dealii::FESystem<dim> &> (other.face_values.get_fe ()),
          other.alpha_values.get_fe (),
          other.velocity_values.get_quadrature (),
          other.face_values.get_quadrature ())
{
}

FlowCellCopy::FlowCellCopy (const unsigned int n_dofs, const unsigned int n_pressure_dofs)
    : matrix (n_dofs, n_dofs), schur (n_pressure_dofs, n_pressure_dofs), rhs (n_dofs),
      dofs (n_dofs), pressure_dofs (n_pressure_dofs)
{
}

template FlowElementIndices::FlowElementIndices (const dealii::FESystem<2> &);
template FlowElementIndices::FlowElementIndices (const dealii::FESystem<3> &);
template struct FlowCellScratch<2>;
template struct FlowCellScratch<3>;
} // namespace wetbed
