#include <wetbed/postprocess/bubble_detection.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>

#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

/*
 * Bubble detection in parallel. Each rank labels its gas cells (mean alpha_g above the
 * threshold) by union-find over shared faces (a face with children links to the active
 * cells behind its subfaces, so hanging nodes join regions across refinement levels),
 * numbers its components globally, hands the labels of cells at the partition boundary
 * to the ranks that see them as ghosts, and the component statistics and the
 * cross-rank links are merged by a second union-find over the global labels (the data
 * are per component, not per cell: small).
 */
namespace wetbed
{
using namespace dealii;

namespace
{
/** Union-find with path halving and union by index (the smaller index is the root). */
class DisjointSets
{
public:
  explicit DisjointSets (std::size_t n) : parent (n)
  {
    std::iota (parent.begin (), parent.end (), 0);
  }
  std::size_t find (std::size_t i)
  {
    while (parent[i] != i)
      i = parent[i] = parent[parent[i]];
    return i;
  }
  void join (std::size_t a, std::size_t b)
  {
    a = find (a);
    b = find (b);
    if (a != b)
      parent[std::max (a, b)] = std::min (a, b);
  }

private:
  std::vector<std::size_t> parent;
};

// layout of one component's partial statistics in the gathered arrays
enum Field : unsigned int
{
  label,
  volume,
  moment,                 // 3 entries
  lower     = moment + 3, // 3 entries
  upper     = lower + 3,  // 3 entries
  wall      = upper + 3,
  freeboard = wall + 1,
  cells     = freeboard + 1,
  stride    = cells + 1
};

/** The gas cells among the owned and ghost cells, by active cell index. */
template <int dim>
struct GasCells
{
  std::vector<char>       gas;         // mean alpha_g above the threshold
  std::vector<double>     cell_volume; // of every owned and ghost cell
  std::vector<Point<dim>> cell_moment; // first moment of every owned and ghost cell
};

/** The global labels of the components. */
struct ComponentLabels
{
  // by active cell index: of the owned and ghost gas cells, else invalid
  std::vector<unsigned long long> cell_label;
  // this rank's components are labels offset, ..., offset + n_local - 1
  unsigned long long n_local, offset;
};

/** The gas cells among the owned and ghost cells, their volume and first moment. */
template <int dim>
GasCells<dim> find_gas_cells (const Mapping<dim>    &mapping,
                              const DoFHandler<dim> &dof_handler,
                              const LinearAlgebra::distributed::Vector<double> &alpha_s,
                              const BubbleCriteria                             &criteria)
{
  const unsigned int       n_cells = dof_handler.get_triangulation ().n_active_cells ();
  const QGauss<dim>        quadrature (2);
  FEValues<dim>            values (mapping,
                        dof_handler.get_fe (),
                        quadrature,
                        update_values | update_JxW_values | update_quadrature_points);
  std::vector<double>      a_q (quadrature.size ());
  GasCells<dim>            cells_of_gas;
  std::vector<char>       &gas         = cells_of_gas.gas;
  std::vector<double>     &cell_volume = cells_of_gas.cell_volume;
  std::vector<Point<dim>> &cell_moment = cells_of_gas.cell_moment;
  gas.assign (n_cells, 0);
  cell_volume.assign (n_cells, 0.0);
  cell_moment.resize (n_cells);
  for (const auto &cell : dof_handler.active_cell_iterators ())
    if (!cell->is_artificial ())
    {
      values.reinit (cell);
      values.get_function_values (alpha_s, a_q);
      double gas_volume = 0, v = 0;
      for (unsigned int q = 0; q < quadrature.size (); ++q)
      {
        gas_volume += (1.0 - a_q[q]) * values.JxW (q);
        v += values.JxW (q);
        cell_moment[cell->active_cell_index ()] +=
            values.JxW (q) * values.quadrature_point (q);
      }
      cell_volume[cell->active_cell_index ()] = v;
      gas[cell->active_cell_index ()] = gas_volume > criteria.gas_fraction_threshold * v;
    }
  return cells_of_gas;
}

/** Joins the owned gas cells in `local` into components; returns the links to ghost
 * gas cells. */
template <int dim>
std::vector<std::pair<unsigned int, unsigned int>> join_local_components (
    const DoFHandler<dim> &dof_handler, const std::vector<char> &gas, DisjointSets &local)
{
  std::vector<std::pair<unsigned int, unsigned int>> ghost_links; // (owned, ghost) cells
  const auto visit_neighbor = [&] (const auto &cell, const auto &neighbor)
  {
    if (!gas[neighbor->active_cell_index ()])
      return;
    if (neighbor->is_locally_owned ())
      local.join (cell->active_cell_index (), neighbor->active_cell_index ());
    else if (neighbor->is_ghost ())
      ghost_links.emplace_back (cell->active_cell_index (),
                                neighbor->active_cell_index ());
  };
  for (const auto &cell : dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned () && gas[cell->active_cell_index ()])
      for (const unsigned int f : cell->face_indices ())
      {
        if (cell->at_boundary (f))
          continue;
        if (cell->face (f)->has_children ())
          for (unsigned int s = 0; s < cell->face (f)->n_children (); ++s)
            visit_neighbor (cell, cell->neighbor_child_on_subface (f, s));
        else
          visit_neighbor (cell, cell->neighbor (f));
      }
  return ghost_links;
}

/** Global labels: the local roots numbered after those of the lower ranks, handed to
 * the ranks that see their cells as ghosts. */
template <int dim>
ComponentLabels label_components (const DoFHandler<dim>   &dof_handler,
                                  const std::vector<char> &gas,
                                  DisjointSets            &local,
                                  MPI_Comm                 communicator)
{
  std::map<std::size_t, unsigned long long> root_index;
  for (const auto &cell : dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned () && gas[cell->active_cell_index ()])
      root_index.emplace (local.find (cell->active_cell_index ()), root_index.size ());
  ComponentLabels labels;
  labels.n_local = root_index.size ();
  labels.offset  = 0;
  MPI_Exscan (
      &labels.n_local, &labels.offset, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, communicator);
  if (Utilities::MPI::this_mpi_process (communicator) == 0)
    labels.offset = 0;
  std::vector<unsigned long long> &cell_label = labels.cell_label;
  cell_label.assign (gas.size (), numbers::invalid_dof_index);
  for (const auto &cell : dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned () && gas[cell->active_cell_index ()])
      cell_label[cell->active_cell_index ()] =
          labels.offset + root_index[local.find (cell->active_cell_index ())];
  using CellIterator = typename DoFHandler<dim>::active_cell_iterator;
  GridTools::exchange_cell_data_to_ghosts<unsigned long long, DoFHandler<dim>> (
      dof_handler,
      [&] (const CellIterator &cell) -> std_cxx17::optional<unsigned long long>
      {
        if (gas[cell->active_cell_index ()])
          return cell_label[cell->active_cell_index ()];
        return {};
      },
      [&] (const CellIterator &cell, const unsigned long long &value)
      { cell_label[cell->active_cell_index ()] = value; });
  return labels;
}

/** The partial statistics of the local components, `stride` entries each, in label
 * order. */
template <int dim>
std::vector<double> partial_statistics (const DoFHandler<dim> &dof_handler,
                                        const GasCells<dim>   &cells_of_gas,
                                        const ComponentLabels &labels,
                                        const BubbleCriteria  &criteria)
{
  const unsigned long long n_local = labels.n_local, offset = labels.offset;
  std::vector<double>      partial (n_local * stride, 0.0);
  for (unsigned long long c = 0; c < n_local; ++c)
  {
    partial[c * stride + label] = offset + c;
    for (unsigned int d = 0; d < 3; ++d)
    {
      partial[c * stride + lower + d] = std::numeric_limits<double>::max ();
      partial[c * stride + upper + d] = -std::numeric_limits<double>::max ();
    }
  }
  for (const auto &cell : dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned () && cells_of_gas.gas[cell->active_cell_index ()])
    {
      const unsigned int i = cell->active_cell_index ();
      double            *s = &partial[(labels.cell_label[i] - offset) * stride];
      s[volume] += cells_of_gas.cell_volume[i];
      s[cells] += 1;
      for (unsigned int d = 0; d < dim; ++d)
        s[moment + d] += cells_of_gas.cell_moment[i][d];
      for (const unsigned int v : cell->vertex_indices ())
        for (unsigned int d = 0; d < dim; ++d)
        {
          s[lower + d] = std::min (s[lower + d], cell->vertex (v)[d]);
          s[upper + d] = std::max (s[upper + d], cell->vertex (v)[d]);
        }
      for (const unsigned int f : cell->face_indices ())
        if (cell->at_boundary (f))
        {
          const auto id = cell->face (f)->boundary_id ();
          if (criteria.freeboard_boundaries.count (id))
            s[freeboard] = 1;
          if (!criteria.open_boundaries.count (id))
            s[wall] = 1;
        }
    }
  return partial;
}

/** The cross-rank links: the label pairs of the links to labelled ghost cells. */
std::vector<unsigned long long>
cross_rank_links (const std::vector<std::pair<unsigned int, unsigned int>> &ghost_links,
                  const std::vector<unsigned long long>                    &cell_label)
{
  std::vector<unsigned long long> links;
  for (const auto &link : ghost_links)
    if (cell_label[link.second] != numbers::invalid_dof_index)
    {
      links.push_back (cell_label[link.first]);
      links.push_back (cell_label[link.second]);
    }
  return links;
}

/** Every rank's `local`, concatenated in rank order, on every rank. */
template <typename T>
std::vector<T> gather_on_all_ranks (const std::vector<T> &local, MPI_Comm communicator)
{
  std::vector<T> all;
  for (const auto &part : Utilities::MPI::all_gather (communicator, local))
    all.insert (all.end (), part.begin (), part.end ());
  return all;
}

/** The statistics of the merged components, each at the entry of its root in `global`
 * (the gathered components are in label order: label c is entry c). */
std::vector<double> merge_statistics (const std::vector<double> &all_partial,
                                      DisjointSets              &global)
{
  const std::size_t   n_global = all_partial.size () / stride;
  std::vector<double> merged (n_global * stride, 0.0);
  for (std::size_t c = 0; c < n_global; ++c)
    for (unsigned int d = 0; d < 3; ++d)
    {
      merged[c * stride + lower + d] = std::numeric_limits<double>::max ();
      merged[c * stride + upper + d] = -std::numeric_limits<double>::max ();
    }
  for (std::size_t c = 0; c < n_global; ++c)
  {
    const std::size_t r = global.find (c);
    double           *m = &merged[r * stride];
    const double     *p = &all_partial[c * stride];
    m[volume] += p[volume];
    m[cells] += p[cells];
    for (unsigned int d = 0; d < 3; ++d)
    {
      m[moment + d] += p[moment + d];
      m[lower + d] = std::min (m[lower + d], p[lower + d]);
      m[upper + d] = std::max (m[upper + d], p[upper + d]);
    }
    m[wall]      = std::max (m[wall], p[wall]);
    m[freeboard] = std::max (m[freeboard], p[freeboard]);
  }
  return merged;
}

/** The bubbles, each with its root: roots that are not the freeboard and not too
 * small, sorted by height then x. */
template <int dim>
std::vector<std::pair<Bubble, std::size_t>>
find_bubbles (const std::vector<double> &merged,
              DisjointSets              &global,
              const BubbleCriteria      &criteria)
{
  const std::size_t                           n_global = merged.size () / stride;
  std::vector<std::pair<Bubble, std::size_t>> found;
  for (std::size_t r = 0; r < n_global; ++r)
  {
    const double *m = &merged[r * stride];
    if (global.find (r) != r || m[freeboard] > 0)
      continue;
    Bubble b;
    b.volume              = m[volume];
    b.equivalent_diameter = dim == 2 ? std::sqrt (4.0 * b.volume / numbers::PI)
                                     : std::cbrt (6.0 * b.volume / numbers::PI);
    if (b.equivalent_diameter < criteria.minimum_diameter)
      continue;
    for (unsigned int d = 0; d < dim; ++d)
    {
      b.centroid[d] = m[moment + d] / b.volume;
      b.lower[d]    = m[lower + d];
      b.upper[d]    = m[upper + d];
    }
    b.touches_wall = m[wall] > 0;
    b.cells        = static_cast<unsigned long long> (m[cells]);
    found.emplace_back (b, r);
  }
  std::sort (found.begin (),
             found.end (),
             [] (const auto &a, const auto &b)
             {
               return std::make_pair (a.first.centroid[dim - 1], a.first.centroid[0]) <
                      std::make_pair (b.first.centroid[dim - 1], b.first.centroid[0]);
             });
  return found;
}
} // namespace

template <int dim>
BubbleField detect_bubbles (const Mapping<dim>                               &mapping,
                            const DoFHandler<dim>                            &dof_handler,
                            const LinearAlgebra::distributed::Vector<double> &alpha_s,
                            const BubbleCriteria                             &criteria,
                            MPI_Comm communicator)
{
  const unsigned int n_cells = dof_handler.get_triangulation ().n_active_cells ();

  // 1. gas cells among the owned and ghost cells: volume, first moment
  const GasCells<dim> cells_of_gas =
      find_gas_cells (mapping, dof_handler, alpha_s, criteria);
  const std::vector<char> &gas = cells_of_gas.gas;

  // 2. local components of the owned gas cells; links to ghost gas cells
  DisjointSets local (n_cells);
  const auto   ghost_links = join_local_components (dof_handler, gas, local);

  // 3. global labels: the local roots numbered after those of the lower ranks
  const ComponentLabels labels = label_components (dof_handler, gas, local, communicator);
  const std::vector<unsigned long long> &cell_label = labels.cell_label;

  // 4. partial statistics of the local components, and the cross-rank links
  const std::vector<double> partial =
      partial_statistics (dof_handler, cells_of_gas, labels, criteria);
  const std::vector<unsigned long long> links =
      cross_rank_links (ghost_links, cell_label);

  // 5. merge on every rank (component data, not cell data)
  const std::vector<double> all_partial = gather_on_all_ranks (partial, communicator);
  const std::vector<unsigned long long> all_links =
      gather_on_all_ranks (links, communicator);
  const std::size_t n_global = all_partial.size () / stride;
  DisjointSets      global (n_global);
  for (std::size_t k = 0; k + 1 < all_links.size (); k += 2)
    global.join (all_links[k], all_links[k + 1]);
  const std::vector<double> merged = merge_statistics (all_partial, global);

  // 6. the bubbles: roots that are not the freeboard and not too small
  const std::vector<std::pair<Bubble, std::size_t>> found =
      find_bubbles<dim> (merged, global, criteria);
  std::vector<int> index_of_root (n_global, -1);
  BubbleField      field;
  for (const auto &f : found)
  {
    index_of_root[f.second] = field.bubbles.size ();
    field.bubbles.push_back (f.first);
  }
  field.cell_bubble.assign (n_cells, -1);
  for (const auto &cell : dof_handler.active_cell_iterators ())
    if (cell->is_locally_owned () && gas[cell->active_cell_index ()])
      field.cell_bubble[cell->active_cell_index ()] =
          index_of_root[global.find (cell_label[cell->active_cell_index ()])];
  return field;
}

template BubbleField detect_bubbles (const Mapping<2> &,
                                     const DoFHandler<2> &,
                                     const LinearAlgebra::distributed::Vector<double> &,
                                     const BubbleCriteria &,
                                     MPI_Comm);
template BubbleField detect_bubbles (const Mapping<3> &,
                                     const DoFHandler<3> &,
                                     const LinearAlgebra::distributed::Vector<double> &,
                                     const BubbleCriteria &,
                                     MPI_Comm);
} // namespace wetbed
