#include <wetbed/assembly/nitsche_wall.h>

namespace wetbed
{
using namespace dealii;

template <int dim>
void add_nitsche_no_penetration (const FEFaceValues<dim>           &face_values,
                                 const unsigned int                 q,
                                 const Tensor<1, dim>              &n,
                                 const std::vector<unsigned int>   &component,
                                 const std::array<NitschePhase, 2> &phases,
                                 const double                       gamma,
                                 const double                       h,
                                 FullMatrix<double>                *cell_matrix,
                                 Vector<double>                    &cell_rhs)
{
  const double       JxW      = face_values.JxW (q);
  const unsigned int n_dofs   = component.size ();
  const unsigned int pressure = 2 * dim;
  // per dof: its phase (0, 1; 2 for the pressure), phi n_c (the normal part of a vector
  // shape function), and n.tau(phi) n / mu-free parts
  std::vector<unsigned int> phase_of (n_dofs);
  std::vector<double>       value (n_dofs), normal_part (n_dofs), normal_stress (n_dofs);
  for (unsigned int i = 0; i < n_dofs; ++i)
  {
    const unsigned int c = component[i];
    phase_of[i]          = c == pressure ? 2 : c / dim;
    value[i]             = face_values.shape_value (i, q);
    if (c == pressure)
      continue;
    const unsigned int    k = phase_of[i], e = c % dim;
    const Tensor<1, dim> &grad = face_values.shape_grad (i, q);
    normal_part[i]             = value[i] * n[e];
    // n.tau(phi e_e) n = 2 mu n_e (grad phi . n) + b d_e phi
    normal_stress[i] =
        2 * phases[k].viscosity * n[e] * (grad * n) + phases[k].bulk * grad[e];
  }
  for (unsigned int i = 0; i < n_dofs; ++i)
  {
    const unsigned int k = phase_of[i];
    if (k < 2)
    {
      const NitschePhase &phase = phases[k];
      if (!phase.slips)
        continue;
      cell_rhs (i) -= phase.normal_pressure * normal_part[i] * JxW;
      if (cell_matrix == nullptr)
        continue;
      const double penalty = gamma * phase.penalty_scale / h;
      for (unsigned int j = 0; j < n_dofs; ++j)
      {
        double entry = 0;
        if (phase_of[j] == k)
          entry = -normal_stress[j] * normal_part[i] - normal_stress[i] * normal_part[j] +
                  penalty * normal_part[i] * normal_part[j];
        else if (phase_of[j] == 2) // + alpha_k p (v.n)
          entry = phase.fraction * value[j] * normal_part[i];
        (*cell_matrix) (i, j) += entry * JxW;
      }
    }
    else if (cell_matrix != nullptr) // continuity: + alpha_k q (u_k.n)
      for (unsigned int j = 0; j < n_dofs; ++j)
      {
        const unsigned int l = phase_of[j];
        if (l < 2 && phases[l].slips)
          (*cell_matrix) (i, j) += phases[l].fraction * value[i] * normal_part[j] * JxW;
      }
  }
}

template void add_nitsche_no_penetration<2> (const FEFaceValues<2> &,
                                             unsigned int,
                                             const Tensor<1, 2> &,
                                             const std::vector<unsigned int> &,
                                             const std::array<NitschePhase, 2> &,
                                             double,
                                             double,
                                             FullMatrix<double> *,
                                             Vector<double> &);
template void add_nitsche_no_penetration<3> (const FEFaceValues<3> &,
                                             unsigned int,
                                             const Tensor<1, 3> &,
                                             const std::vector<unsigned int> &,
                                             const std::array<NitschePhase, 2> &,
                                             double,
                                             double,
                                             FullMatrix<double> *,
                                             Vector<double> &);
} // namespace wetbed
