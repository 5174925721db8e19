#pragma once

#include <deal.II/distributed/tria.h>

#include <string>
#include <vector>

namespace wetbed
{
/**
 * A parallel::distributed::Triangulation whose adapted mesh does not depend on the
 * number of MPI ranks.
 *
 * deal.II prepares refinement and coarsening flags with the sequential mesh-smoothing
 * rules applied to each rank's own cells and ghost layer; where those rules cascade
 * (a removed coarsen flag blocking a neighbour's, a refinement forcing a coarser
 * neighbour's), a rank decides on partial information and the mesh after a heavy
 * coarsening differed between 1 and 2 ranks (doc/verification.md, T13).
 *
 * Here the preparation of the flags a user sets only makes the flags of the locally
 * owned cells well formed (refinement wins over coarsening; a family is coarsened only
 * if all its children are active, owned here and flagged: p4est partitions so that
 * families stay together) and leaves the 2:1 balance (faces and vertices) to p4est,
 * whose refine, coarsen and balance act on the global forest: a coarsening that would
 * break the balance is undone by balancing, a refinement refines its coarser
 * neighbours. The same flags on the owned cells give the same mesh on any number of
 * ranks.
 *
 * deal.II itself also calls prepare_coarsening_and_refinement() while it rebuilds its
 * cells from p4est's forest (after refinement, repartitioning, loading, creation); those
 * calls keep deal.II's own preparation, which the rebuilding relies on.
 */
template <int dim>
class PartitionIndependentTriangulation
    : public dealii::parallel::distributed::Triangulation<dim>
{
public:
  explicit PartitionIndependentTriangulation (MPI_Comm communicator);

  /** The user's flags made well formed (see the class documentation), or deal.II's own
   * preparation inside deal.II's rebuilding of the mesh; true if a flag changed here. */
  bool prepare_coarsening_and_refinement () override;

  void execute_coarsening_and_refinement () override;
  void create_triangulation (const std::vector<dealii::Point<dim>>    &vertices,
                             const std::vector<dealii::CellData<dim>> &cells,
                             const dealii::SubCellData &subcell_data) override;
  void load (const std::string &filename) override;
  void load (const std::string &filename, const bool autopartition) override;

private:
  bool make_flags_well_formed ();

  /** Depth of deal.II operations that rebuild the mesh from p4est's forest. */
  unsigned int rebuilding = 0;
};
} // namespace wetbed
