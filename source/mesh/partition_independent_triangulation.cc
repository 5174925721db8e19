#include <wetbed/mesh/partition_independent_triangulation.h>

namespace wetbed
{
using namespace dealii;

namespace
{
/** Counts a deal.II rebuilding operation for its duration (exceptions included). */
struct RebuildingScope
{
  explicit RebuildingScope (unsigned int &depth) : depth (depth) { ++depth; }
  ~RebuildingScope () { --depth; }
  unsigned int &depth;
};
} // namespace

template <int dim>
PartitionIndependentTriangulation<dim>::PartitionIndependentTriangulation (
    MPI_Comm communicator)
    : parallel::distributed::Triangulation<dim> (communicator,
                                                 dealii::Triangulation<dim>::none)
{
  // p4est has refined, coarsened and balanced: deal.II now rebuilds its cells
  this->signals.pre_distributed_refinement.connect ([this] () { ++rebuilding; });
  this->signals.post_distributed_refinement.connect ([this] () { --rebuilding; });
  this->signals.pre_distributed_repartition.connect ([this] () { ++rebuilding; });
  this->signals.post_distributed_repartition.connect ([this] () { --rebuilding; });
}

template <int dim>
bool PartitionIndependentTriangulation<dim>::prepare_coarsening_and_refinement ()
{
  if (rebuilding > 0)
    return parallel::distributed::Triangulation<
        dim>::prepare_coarsening_and_refinement ();
  return make_flags_well_formed ();
}

template <int dim>
void PartitionIndependentTriangulation<dim>::execute_coarsening_and_refinement ()
{
  const unsigned int depth = rebuilding;
  make_flags_well_formed ();
  try
  {
    parallel::distributed::Triangulation<dim>::execute_coarsening_and_refinement ();
  }
  catch (...)
  {
    rebuilding = depth;
    throw;
  }
  rebuilding = depth;
}

template <int dim>
void PartitionIndependentTriangulation<dim>::create_triangulation (
    const std::vector<Point<dim>>    &vertices,
    const std::vector<CellData<dim>> &cells,
    const SubCellData                &subcell_data)
{
  RebuildingScope scope (rebuilding);
  parallel::distributed::Triangulation<dim>::create_triangulation (
      vertices, cells, subcell_data);
}

template <int dim>
void PartitionIndependentTriangulation<dim>::load (const std::string &filename)
{
  RebuildingScope scope (rebuilding);
  parallel::distributed::Triangulation<dim>::load (filename);
}

template <int dim>
void PartitionIndependentTriangulation<dim>::load (const std::string &filename,
                                                   const bool         autopartition)
{
  RebuildingScope scope (rebuilding);
  parallel::distributed::Triangulation<dim>::load (filename, autopartition);
}

template <int dim>
bool PartitionIndependentTriangulation<dim>::make_flags_well_formed ()
{
  bool changed = false;
  for (const auto &cell : this->active_cell_iterators ())
    if (!cell->is_locally_owned ())
    {
      cell->clear_refine_flag ();
      cell->clear_coarsen_flag ();
    }
    else if (cell->coarsen_flag_set () &&
             (cell->refine_flag_set () || cell->level () == 0))
    {
      cell->clear_coarsen_flag ();
      changed = true;
    }

  for (const auto &cell : this->active_cell_iterators ())
    if (cell->is_locally_owned () && cell->coarsen_flag_set ())
    {
      const auto parent   = cell->parent ();
      bool       complete = true;
      for (unsigned int c = 0; c < parent->n_children (); ++c)
      {
        const auto child = parent->child (c);
        complete = complete && child->is_active () && child->is_locally_owned () &&
                   child->coarsen_flag_set ();
      }
      if (!complete)
        for (unsigned int c = 0; c < parent->n_children (); ++c)
          if (parent->child (c)->is_active () && parent->child (c)->coarsen_flag_set ())
          {
            parent->child (c)->clear_coarsen_flag ();
            changed = true;
          }
    }
  return changed;
}

template class PartitionIndependentTriangulation<2>;
template class PartitionIndependentTriangulation<3>;
} // namespace wetbed
