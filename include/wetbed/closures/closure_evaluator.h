#pragma once

#include <wetbed/closures/drag/drag_model.h>
#include <wetbed/closures/solids_stress/solids_stress_model.h>

#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace wetbed::closures
{
class KineticTheory;

/**
 * The closures of one point, every quantity a consumer reads (assembly, Theta,
 * postprocessing, the closure table), evaluated once from the local state.
 */
struct PointClosures
{
  double       alpha_s;           // the fraction the laws saw: max(alpha_s, 0)
  double       inertial_fraction; // max(alpha_s, residual): solids inertia and coupling
  double       coupling_drag;     // beta at the inertial fraction (momentum coupling)
  double       shear_rate;        // sqrt(2 D_dev : D_dev) of u_s (1/s)
  SolidsStress stress;            // at (max(alpha_s, 0), max(Theta, 0), shear rate)
};

/**
 * Evaluates every closure of the two-fluid model at a point, with one convention for
 * the inputs (doc/theory.md, "Closure inputs"):
 *   - the laws see alpha_s* = max(alpha_s, 0) and Theta* = max(Theta, 0);
 *   - the momentum coupling (drag, solids inertia) uses the inertial fraction
 *     max(alpha_s, alpha_res), so that the solids block stays regular where there are
 *     no solids; every other use of beta (the granular energy exchange, reports) sees
 *     beta(alpha_s*), which vanishes with alpha_s for every registered law;
 *   - the compaction pressure P_s and its slope dP_s/dalpha are functions of alpha_s
 *     alone, evaluated at nodes (the well-balanced compaction force).
 * The laws behind it are the registered drag and solids-stress models; the evaluator
 * owns none of them.
 */
class ClosureEvaluator
{
public:
  ClosureEvaluator (const DragModel             &drag,
                    const SolidsStressModel     &solids_stress,
                    const GasParticleProperties &gas_particle,
                    double                       residual_solids_fraction);

  /** All closures at a point with the slip |u_g - u_s|, the shear rate and the
   * divergence of u_s. */
  PointClosures evaluate (double alpha_s,
                          double theta,
                          double slip,
                          double shear_rate,
                          double velocity_divergence) const;

  /** beta(max(alpha_s, 0), slip): the drag as the physics has it. */
  double drag (double alpha_s, double slip) const;
  /** beta(max(alpha_s, alpha_res), slip): the drag of the momentum coupling. */
  double coupling_drag (double alpha_s, double slip) const;
  /** max(alpha_s, alpha_res). */
  double inertial_fraction (double alpha_s) const;
  /** The solids stress at (max(alpha_s, 0), max(Theta, 0), shear rate, div u_s). */
  SolidsStress stress (double alpha_s,
                       double theta,
                       double shear_rate,
                       double velocity_divergence = 0) const;
  /** The compaction pressure P_s(alpha_s) (Pa). */
  double compaction_pressure (double alpha_s) const;
  /** dP_s/dalpha_s (Pa). */
  double compaction_slope (double alpha_s) const;

  /** sqrt(2 D_dev : D_dev), D = sym(grad u). */
  template <int dim>
  static double shear_rate (const dealii::Tensor<2, dim> &grad_u)
  {
    const dealii::SymmetricTensor<2, dim> deviator =
        dealii::deviator_tensor<dim> () * dealii::symmetrize (grad_u);
    return std::sqrt (2.0 * deviator * deviator);
  }

  const DragModel             &drag_model () const { return *drag_law; }
  const SolidsStressModel     &solids_stress_model () const { return *stress_model; }
  const GasParticleProperties &gas_particle_properties () const { return properties; }
  /** The kinetic theory behind the solids stress; null without it. */
  const KineticTheory *kinetic_theory () const;
  double               residual_solids_fraction () const { return residual; }

private:
  const DragModel         *drag_law;
  const SolidsStressModel *stress_model;
  GasParticleProperties    properties;
  double                   residual;
};

/**
 * The closures of one cell at its quadrature points (structure of arrays) and at its
 * alpha_s nodes: what the flow terms read, filled once per cell.
 */
struct CellClosures
{
  // at quadrature points
  std::vector<double> alpha_s, inertial_fraction, coupling_drag, shear_rate,
      shear_viscosity, bulk_viscosity, kinetic_pressure;
  // at the alpha_s nodes: P_s(alpha_j)
  std::vector<double> nodal_compaction_pressure;

  void resize (unsigned int n_points, unsigned int n_nodes);
  /** From alpha_s, Theta, the slip and the grad u_s at the points, and alpha_s at the
   * nodes. */
  template <int dim>
  void evaluate (const ClosureEvaluator                    &evaluator,
                 const std::vector<double>                 &alpha_s_q,
                 const std::vector<double>                 &theta_q,
                 const std::vector<double>                 &slip_q,
                 const std::vector<dealii::Tensor<2, dim>> &grad_u_s_q,
                 const dealii::Vector<double>              &alpha_nodal);
};
} // namespace wetbed::closures
