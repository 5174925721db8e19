#include <wetbed/solvers/two_fluid_solver.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/numerics/vector_tools.h>

/*
 * The errors of a verification run against the exact fields of its hook (the MMS tests).
 */
namespace wetbed
{
using namespace dealii;

template <int dim>
typename TwoFluidSolver<dim>::Errors TwoFluidSolver<dim>::compute_errors () const
{
  AssertThrow (verification->exact_flow () != nullptr,
               ExcMessage ("the verification hook has no exact flow fields"));
  const Function<dim> &exact = *verification->exact_flow ();
  const QGauss<dim>    quadrature (5);
  Vector<float>        cellwise (triangulation.n_active_cells ());
  auto                 norm = [&] (const unsigned int          first,
                   const unsigned int          count,
                   const VectorTools::NormType type)
  {
    ComponentSelectFunction<dim> mask (std::make_pair (first, first + count),
                                       2 * dim + 1);
    VectorTools::integrate_difference (
        mapping, flow_dof_handler, fields.flow, exact, cellwise, quadrature, type, &mask);
    return VectorTools::compute_global_error (triangulation, cellwise, type);
  };
  Errors errors{norm (0, dim, VectorTools::L2_norm),
                norm (0, dim, VectorTools::H1_seminorm),
                norm (dim, dim, VectorTools::L2_norm),
                norm (dim, dim, VectorTools::H1_seminorm),
                norm (2 * dim, 1, VectorTools::L2_norm)};
  if (const Function<dim> *exact_theta = verification->exact_granular_temperature ())
  {
    for (const auto type : {VectorTools::L2_norm, VectorTools::H1_seminorm})
    {
      VectorTools::integrate_difference (mapping,
                                         alpha_dof_handler,
                                         fields.theta,
                                         *exact_theta,
                                         cellwise,
                                         quadrature,
                                         type);
      (type == VectorTools::L2_norm ? errors.granular_temperature_l2
                                    : errors.granular_temperature_h1) =
          VectorTools::compute_global_error (triangulation, cellwise, type);
    }
  }
  return errors;
}

template TwoFluidSolver<2>::Errors TwoFluidSolver<2>::compute_errors () const;
template TwoFluidSolver<3>::Errors TwoFluidSolver<3>::compute_errors () const;
} // namespace wetbed
