#pragma once

#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/base/types.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/lac/la_parallel_vector.h>

#include <array>
#include <set>
#include <vector>

namespace wetbed
{
/** One bubble (a connected gas region) found in one analysis. */
struct Bubble
{
  double volume              = 0; // m^3 in 3D; area (m^2, i.e. m^3 per metre depth) in 2D
  double equivalent_diameter = 0; // of the sphere (3D) or circle (2D) of that volume
  std::array<double, 3> centroid{{0, 0, 0}};
  std::array<double, 3> lower{{0, 0, 0}}, upper{{0, 0, 0}}; // bounding box
  bool                  touches_wall = false;
  unsigned long long    cells        = 0;
};

/** What makes a cell part of a bubble, and which boundaries are what. */
struct BubbleCriteria
{
  double gas_fraction_threshold = 0.8; // a cell is gas where its mean alpha_g exceeds it
  double minimum_diameter       = 0;   // smaller gas regions are not reported (m)
  // a gas region touching the outlet is the freeboard (or a bubble erupting into it)
  std::set<dealii::types::boundary_id> freeboard_boundaries;
  // boundaries that are not walls (inlet, outlet): a bubble touching any other touches a
  // wall
  std::set<dealii::types::boundary_id> open_boundaries;
};

/** The bubbles of one analysis and which locally owned cell belongs to which. */
struct BubbleField
{
  std::vector<Bubble> bubbles; // the same on every rank, sorted by height then x
  // by active cell index: the bubble index, or -1 (not a bubble, or not owned)
  std::vector<int> cell_bubble;
};

/**
 * Bubbles of the solids fraction field alpha_s (ghosted, on `dof_handler`): cells whose
 * mean gas fraction 1 - alpha_s exceeds the threshold, joined through shared faces
 * (across hanging nodes and MPI ranks) into connected components; the freeboard and
 * regions below the minimum diameter are left out. Collective.
 */
template <int dim>
BubbleField
detect_bubbles (const dealii::Mapping<dim>                               &mapping,
                const dealii::DoFHandler<dim>                            &dof_handler,
                const dealii::LinearAlgebra::distributed::Vector<double> &alpha_s,
                const BubbleCriteria                                     &criteria,
                MPI_Comm                                                  communicator);
} // namespace wetbed
