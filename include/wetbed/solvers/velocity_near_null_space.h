#pragma once

#include <deal.II/base/index_set.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>

#include <vector>

namespace wetbed
{
/** The near-null space of the two-phase velocity block, for the velocity AMG. */
struct VelocityNearNullSpace
{
  // one vector per mode, each with the locally owned velocity rows in order
  std::vector<std::vector<double>> modes;
  // the velocity DoFs of one support point when they are consecutive rows, else 1
  unsigned int dofs_per_node;
};

/**
 * Per phase, the translation of each velocity component and, with `rotations`, the
 * rigid rotations about the mesh centre (the modes a slip wall leaves almost free: a
 * rotation in a cylinder costs only its axial shear); collective.
 */
template <int dim>
VelocityNearNullSpace velocity_near_null_space (const dealii::Mapping<dim>    &mapping,
                                                const dealii::DoFHandler<dim> &flow_dofs,
                                                const dealii::IndexSet &owned_velocity,
                                                bool                    rotations,
                                                MPI_Comm                communicator);
} // namespace wetbed
