#include <wetbed/boundary_conditions/inlet_conditions.h>
#include <wetbed/core/expression_constants.h>
#include <wetbed/core/input_error.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <sstream>

namespace wetbed
{
using namespace dealii;

template <int dim>
InletConditions<dim>::InletConditions (const BoundaryConditionParameters &parameters,
                                       const double                       gas_density,
                                       const Tensor<1, dim>              &upward,
                                       const double                       end_time)
    : parameters (parameters), gas_density (gas_density), end_time (end_time),
      upward (upward)
{
}

template <int dim>
void InletConditions<dim>::reinit (const Triangulation<dim> &triangulation,
                                   const Mapping<dim>       &mapping,
                                   const Boundaries         &boundaries,
                                   const MPI_Comm            communicator)
{
  groups.clear ();
  for (const Boundary &b : boundaries.all ())
  {
    if (b.type != BoundaryType::inlet)
      continue;
    groups.push_back (make_group (b));
  }

  // the quadrature points, weights and projections of the locally owned inlet faces,
  // then those of all ranks
  const FE_Q<dim> linear (1);
  // Gauss-Lobatto points: the Q2 nodes of the faces are among them
  const QGaussLobatto<dim - 1>     quadrature (3);
  FEFaceValues<dim>                face (mapping,
                          linear,
                          quadrature,
                          update_quadrature_points | update_JxW_values |
                              update_normal_vectors);
  std::vector<std::vector<double>> local (groups.size ());
  for (const auto &cell : triangulation.active_cell_iterators ())
    if (cell->is_locally_owned () && cell->at_boundary ())
      for (const unsigned int f : cell->face_indices ())
        if (cell->face (f)->at_boundary ())
          for (unsigned int k = 0; k < groups.size (); ++k)
            if (cell->face (f)->boundary_id () == groups[k].id)
            {
              face.reinit (cell, f);
              for (unsigned int q = 0; q < quadrature.size (); ++q)
              {
                for (unsigned int d = 0; d < dim; ++d)
                  local[k].push_back (face.quadrature_point (q)[d]);
                local[k].push_back (face.JxW (q));
                // the inflow's share: -d.n (n the outward normal)
                local[k].push_back (-(groups[k].direction * face.normal_vector (q)));
              }
            }
  for (unsigned int k = 0; k < groups.size (); ++k)
  {
    Group &g = groups[k];
    g.area = g.projected_area = 0;
    double inward             = 0;
    for (const auto &part : Utilities::MPI::all_gather (communicator, local[k]))
      for (std::size_t i = 0; i + dim + 2 <= part.size (); i += dim + 2)
      {
        Point<dim> x;
        for (unsigned int d = 0; d < dim; ++d)
          x[d] = part[i + d];
        const double w = part[i + dim], share = part[i + dim + 1];
        g.points.push_back (x);
        g.weights.push_back (w * std::abs (share));
        g.area += w;
        g.projected_area += w * std::abs (share);
        inward += w * share;
      }
    // a group without faces (none in this mesh) lets nothing in and is left alone
    require (g.area == 0 || g.projected_area > 1e-12 * g.area,
             g.mass_flow ? "boundary conditions/inlet mass flow rates"
                         : "boundary conditions/inlet directions",
             "the group '" + g.name +
                 "' has no area across its direction (the gas would flow along it)");
    require (g.area == 0 || inward > 0,
             "boundary conditions/inlet directions",
             "the gas of the group '" + g.name +
                 "' would leave the domain (its direction points out of it)");
    check_speeds (g);
  }
}

template <int dim>
typename InletConditions<dim>::Group
InletConditions<dim>::make_group (const Boundary &b) const
{
  Group g;
  g.name               = b.name;
  g.id                 = b.id;
  g.direction          = upward;
  std::string velocity = parameters.inlet_superficial_velocity, mass_flow;
  for (const InletGroup &entry : parameters.inlet_groups)
    if (entry.name == b.name)
    {
      if (!entry.direction.empty ())
        for (unsigned int d = 0; d < dim; ++d)
          g.direction[d] = entry.direction[d];
      if (!entry.velocity.empty ())
      {
        velocity  = entry.velocity;
        g.uniform = false;
      }
      mass_flow         = entry.mass_flow;
      g.solids_fraction = entry.solids_fraction;
      g.solids_speed    = entry.solids_speed;
    }
  if (!mass_flow.empty ())
  {
    g.mass_flow = std::make_unique<FunctionParser<1>> (1);
    g.mass_flow->initialize ("t", mass_flow, expression_constants ());
  }
  else
  {
    // the common U(t) is read as a function of x, y, (z,) t that ignores the position
    g.velocity = std::make_unique<FunctionParser<dim>> (1);
    g.velocity->initialize (
        dim == 3 ? "x,y,z,t" : "x,y,t", velocity, expression_constants (), true);
  }
  return g;
}

template <int dim>
void InletConditions<dim>::check_speeds (const Group &g) const
{
  for (unsigned int k = 0; k <= 50; ++k)
  {
    const double t = end_time * k / 50;
    for (std::size_t q = 0;
         q < (g.uniform ? 1 : g.points.size ()) && q < g.points.size ();
         ++q)
      if (const Point<dim> &x = g.points[q]; !std::isfinite (speed (g, x, t)))
      {
        std::ostringstream at;
        at << "the velocity of the group '" << g.name << "' is " << speed (g, x, t)
           << " at (" << x << "), t = " << t << " s";
        throw InputError (g.mass_flow ? "boundary conditions/inlet mass flow rates"
                                      : "boundary conditions/inlet velocities",
                          at.str ());
      }
  }
}

template <int dim>
double
InletConditions<dim>::speed (const Group &g, const Point<dim> &x, const double t) const
{
  if (g.mass_flow)
    return g.mass_flow->value (Point<1> (t)) / (gas_density * g.projected_area);
  g.velocity->set_time (t);
  return g.velocity->value (x);
}

template <int dim>
const typename InletConditions<dim>::Group &
InletConditions<dim>::group (const types::boundary_id id) const
{
  for (const Group &g : groups)
    if (g.id == id)
      return g;
  AssertThrow (false, ExcMessage ("boundary id " + std::to_string (id) + " is no inlet"));
  return groups.front ();
}

template <int dim>
Tensor<1, dim> InletConditions<dim>::superficial_velocity (const types::boundary_id id,
                                                           const Point<dim>        &x,
                                                           const double t) const
{
  const Group &g = group (id);
  return speed (g, x, t) * g.direction;
}

template <int dim>
double InletConditions<dim>::mean_superficial_velocity (const double t) const
{
  double flow = 0, area = 0;
  for (const Group &g : groups)
  {
    if (g.uniform && !g.points.empty ())
      flow += speed (g, g.points[0], t) * g.projected_area;
    else
      for (std::size_t q = 0; q < g.points.size (); ++q)
        flow += speed (g, g.points[q], t) * g.weights[q];
    area += g.area;
  }
  return area > 0 ? flow / area : 0;
}

template <int dim>
double InletConditions<dim>::peak_superficial_velocity (const double t) const
{
  double peak = 0;
  for (const Group &g : groups)
    for (const Point<dim> &x : g.points)
    {
      peak = std::max (peak, std::abs (speed (g, x, t)));
      if (g.uniform)
        break;
    }
  return peak;
}

template <int dim>
std::map<std::string, double> InletConditions<dim>::areas () const
{
  std::map<std::string, double> result;
  for (const Group &g : groups)
    result[g.name] = g.area;
  return result;
}

template <int dim>
Tensor<1, dim> InletConditions<dim>::solids_velocity (const types::boundary_id id) const
{
  const Group &g = group (id);
  return g.solids_speed * g.direction;
}

template <int dim>
bool InletConditions<dim>::feeds_solids (const types::boundary_id id) const
{
  return group (id).solids_fraction > 0;
}

template <int dim>
double InletConditions<dim>::solids_volume_flow () const
{
  double flow = 0;
  for (const Group &g : groups)
    flow += g.solids_fraction * g.solids_speed * g.projected_area;
  return flow;
}

template <int dim>
void InletConditions<dim>::solids_inflow_rates (
    const DoFHandler<dim>                            &alpha_dofs,
    const Mapping<dim>                               &mapping,
    const AffineConstraints<double>                  &constraints,
    const LinearAlgebra::distributed::Vector<double> &layout,
    LinearAlgebra::distributed::Vector<double>       &rates) const
{
  rates.reinit (0);
  if (solids_volume_flow () == 0)
    return;
  rates.reinit (layout);
  const QGauss<dim - 1>                quadrature (3);
  FEFaceValues<dim>                    face (mapping,
                          alpha_dofs.get_fe (),
                          quadrature,
                          update_values | update_JxW_values | update_normal_vectors);
  Vector<double>                       local (alpha_dofs.get_fe ().n_dofs_per_cell ());
  std::vector<types::global_dof_index> dofs (local.size ());
  for (const auto &cell : alpha_dofs.active_cell_iterators ())
    if (cell->is_locally_owned () && cell->at_boundary ())
      for (const unsigned int f : cell->face_indices ())
        if (cell->face (f)->at_boundary ())
          for (const Group &g : groups)
            if (g.id == cell->face (f)->boundary_id () && g.solids_fraction > 0)
            {
              face.reinit (cell, f);
              local = 0;
              for (unsigned int q = 0; q < quadrature.size (); ++q)
              {
                // alpha_in u_in.(-n): the feed's volume flux into the domain
                const double flux =
                    g.solids_fraction * g.solids_speed *
                    std::max (-(g.direction * face.normal_vector (q)), 0.0);
                for (unsigned int i = 0; i < local.size (); ++i)
                  local[i] += face.shape_value (i, q) * flux * face.JxW (q);
              }
              cell->get_dof_indices (dofs);
              constraints.distribute_local_to_global (local, dofs, rates);
            }
  rates.compress (VectorOperation::add);
}

template class InletConditions<2>;
template class InletConditions<3>;
} // namespace wetbed
