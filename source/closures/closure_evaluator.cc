#include <wetbed/closures/closure_evaluator.h>

#include <algorithm>

namespace wetbed::closures
{
ClosureEvaluator::ClosureEvaluator (const DragModel             &drag,
                                    const SolidsStressModel     &solids_stress,
                                    const GasParticleProperties &gas_particle,
                                    const double                 residual_solids_fraction)
    : drag_law (&drag), stress_model (&solids_stress), properties (gas_particle),
      residual (residual_solids_fraction)
{
}

PointClosures ClosureEvaluator::evaluate (const double alpha_s,
                                          const double theta,
                                          const double slip,
                                          const double shear_rate,
                                          const double velocity_divergence) const
{
  PointClosures c;
  c.alpha_s           = std::max (alpha_s, 0.0);
  c.inertial_fraction = inertial_fraction (alpha_s);
  c.coupling_drag     = drag_law->coefficient (c.inertial_fraction, slip, properties);
  c.shear_rate        = shear_rate;
  c.stress            = stress (alpha_s, theta, shear_rate, velocity_divergence);
  return c;
}

double ClosureEvaluator::drag (const double alpha_s, const double slip) const
{
  return drag_law->coefficient (std::max (alpha_s, 0.0), slip, properties);
}

double ClosureEvaluator::coupling_drag (const double alpha_s, const double slip) const
{
  return drag_law->coefficient (inertial_fraction (alpha_s), slip, properties);
}

double ClosureEvaluator::inertial_fraction (const double alpha_s) const
{
  return std::max (alpha_s, residual);
}

SolidsStress ClosureEvaluator::stress (const double alpha_s,
                                       const double theta,
                                       const double shear_rate,
                                       const double velocity_divergence) const
{
  return stress_model->evaluate (
      {std::max (alpha_s, 0.0), std::max (theta, 0.0), shear_rate, velocity_divergence});
}

double ClosureEvaluator::compaction_pressure (const double alpha_s) const
{
  return stress_model->evaluate ({alpha_s, 0.0, 0.0}).pressure;
}

double ClosureEvaluator::compaction_slope (const double alpha_s) const
{
  return stress_model->evaluate ({alpha_s, 0.0, 0.0}).pressure_derivative;
}

const KineticTheory *ClosureEvaluator::kinetic_theory () const
{
  return stress_model->kinetic_theory ();
}

void CellClosures::resize (const unsigned int n_points, const unsigned int n_nodes)
{
  for (auto *v : {&alpha_s,
                  &inertial_fraction,
                  &coupling_drag,
                  &shear_rate,
                  &shear_viscosity,
                  &bulk_viscosity,
                  &kinetic_pressure})
    v->resize (n_points);
  nodal_compaction_pressure.resize (n_nodes);
}

template <int dim>
void CellClosures::evaluate (const ClosureEvaluator                    &evaluator,
                             const std::vector<double>                 &alpha_s_q,
                             const std::vector<double>                 &theta_q,
                             const std::vector<double>                 &slip_q,
                             const std::vector<dealii::Tensor<2, dim>> &grad_u_s_q,
                             const dealii::Vector<double>              &alpha_nodal)
{
  resize (alpha_s_q.size (), alpha_nodal.size ());
  for (unsigned int q = 0; q < alpha_s_q.size (); ++q)
  {
    const PointClosures c =
        evaluator.evaluate (alpha_s_q[q],
                            theta_q[q],
                            slip_q[q],
                            ClosureEvaluator::shear_rate<dim> (grad_u_s_q[q]),
                            dealii::trace (grad_u_s_q[q]));
    alpha_s[q]           = c.alpha_s;
    inertial_fraction[q] = c.inertial_fraction;
    coupling_drag[q]     = c.coupling_drag;
    shear_rate[q]        = c.shear_rate;
    shear_viscosity[q]   = c.stress.shear_viscosity;
    bulk_viscosity[q]    = c.stress.bulk_viscosity;
    kinetic_pressure[q]  = c.stress.kinetic_pressure;
  }
  for (unsigned int j = 0; j < alpha_nodal.size (); ++j)
    nodal_compaction_pressure[j] = evaluator.compaction_pressure (alpha_nodal[j]);
}

template void CellClosures::evaluate<2> (const ClosureEvaluator &,
                                         const std::vector<double> &,
                                         const std::vector<double> &,
                                         const std::vector<double> &,
                                         const std::vector<dealii::Tensor<2, 2>> &,
                                         const dealii::Vector<double> &);
template void CellClosures::evaluate<3> (const ClosureEvaluator &,
                                         const std::vector<double> &,
                                         const std::vector<double> &,
                                         const std::vector<double> &,
                                         const std::vector<dealii::Tensor<2, 3>> &,
                                         const dealii::Vector<double> &);
} // namespace wetbed::closures
