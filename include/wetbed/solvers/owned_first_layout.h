#pragma once

#include <deal.II/base/exceptions.h>
#include <deal.II/base/index_set.h>
#include <deal.II/lac/trilinos_index_access.h>
#include <deal.II/lac/trilinos_parallel_block_vector.h>

#include <Epetra_Map.h>

#include <vector>

namespace wetbed
{
/**
 * Lists each block's locally owned entries first in the map of a ghosted Trilinos block
 * vector that is still zero (the values need no permutation), the ghost entries after
 * them. Epetra finds the local index of a global one by an offset within the map's
 * first contiguous run and by a hash table elsewhere; deal.II lists a ghosted map's
 * entries in ascending order, so on every rank but the first the ghosts with smaller
 * indices come first and each owned entry went through the hash table: on the 2-rank
 * seed column that was 9% of the second rank's time against 2% of the first's, which
 * waited for it. Copies of the vector (reinit from it, assignment) share the map.
 */
inline void list_owned_entries_first (dealii::TrilinosWrappers::MPI::BlockVector &vector,
                                      const std::vector<dealii::IndexSet>        &owned)
{
  using Index = dealii::TrilinosWrappers::types::int_type;
  AssertThrow (owned.size () == vector.n_blocks (),
               dealii::ExcDimensionMismatch (owned.size (), vector.n_blocks ()));
  // Epetra's ReplaceMap leaves the vector's communicator pointing into the map it
  // replaced: `keep` holds those maps while `reordered` lives, and `vector` takes fresh
  // Epetra vectors on the new maps from it
  std::vector<Epetra_BlockMap>               keep;
  dealii::TrilinosWrappers::MPI::BlockVector reordered (vector);
  for (unsigned int b = 0; b < vector.n_blocks (); ++b)
  {
    Epetra_FEVector       &values = reordered.block (b).trilinos_vector ();
    const Epetra_BlockMap &map    = values.Map ();
    double                 largest[1];
    values.NormInf (largest);
    AssertThrow (largest[0] == 0, dealii::ExcMessage ("the vector is not zero"));
    std::vector<Index> entries;
    entries.reserve (map.NumMyElements ());
    for (const auto i : owned[b])
      entries.push_back (static_cast<Index> (i));
    for (int local = 0; local < map.NumMyElements (); ++local)
    {
      const Index global = dealii::TrilinosWrappers::global_index (map, local);
      if (!owned[b].is_element (global))
        entries.push_back (global);
    }
    AssertThrow (entries.size () == static_cast<std::size_t> (map.NumMyElements ()),
                 dealii::ExcMessage ("a ghosted map without all its owned entries"));
    keep.push_back (map);
    const Epetra_Map new_map (
        Index (-1), static_cast<int> (entries.size ()), entries.data (), 0, map.Comm ());
    const int error = values.ReplaceMap (new_map);
    AssertThrow (error == 0, dealii::ExcTrilinosError (error));
  }
  vector.reinit (reordered);
}
} // namespace wetbed
