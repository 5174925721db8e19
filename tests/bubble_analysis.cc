// Bubble detection and tracking on synthetic fields (run on 1, 2 and 3 MPI ranks):
// circles/spheres of gas in an emulsion, one across two refinement levels, one across the
// partition, one at a wall, and a freeboard that must not count; then a scripted bubble
// that splits in two and coalesces again, with a mesh change between the analyses.
#include "test_utilities.h"

#include <wetbed/postprocess/bubble_analysis.h>

#include <deal.II/base/function.h>
#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/numerics/vector_tools.h>

#include <filesystem>
#include <fstream>

using namespace dealii;
using namespace wetbed;
using wetbed::testing::check;

namespace
{
struct Sphere
{
  double x, y, z, r;
};

/** alpha_s = 0.6 in the emulsion, 0 inside the spheres and above `freeboard`. */
template <int dim>
class GasRegions : public Function<dim>
{
public:
  GasRegions (std::vector<Sphere> spheres, double freeboard)
      : spheres (std::move (spheres)), freeboard (freeboard)
  {
  }
  double value (const Point<dim> &p, unsigned int = 0) const override
  {
    if (p[dim - 1] > freeboard)
      return 0;
    for (const auto &s : spheres)
    {
      const double c[3] = {s.x, s.y, s.z};
      double       r2   = 0;
      for (unsigned int d = 0; d < dim; ++d)
        r2 += std::pow (p[d] - c[d], 2);
      if (r2 < s.r * s.r)
        return 0;
    }
    return 0.6;
  }
  std::vector<Sphere> spheres;
  double              freeboard;
};

template <int dim>
struct Setup
{
  explicit Setup (MPI_Comm communicator)
      : triangulation (communicator), fe (1), dof_handler (triangulation), mapping (1)
  {
  }
  void distribute ()
  {
    dof_handler.distribute_dofs (fe);
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs (dof_handler, relevant);
    alpha.reinit (
        dof_handler.locally_owned_dofs (), relevant, triangulation.get_communicator ());
  }
  void impose (const Function<dim> &f)
  {
    alpha.zero_out_ghost_values ();
    VectorTools::interpolate (mapping, dof_handler, f, alpha);
    alpha.update_ghost_values ();
  }
  parallel::distributed::Triangulation<dim>  triangulation;
  FE_Q<dim>                                  fe;
  DoFHandler<dim>                            dof_handler;
  MappingQ<dim>                              mapping;
  LinearAlgebra::distributed::Vector<double> alpha;
};

BubbleCriteria criteria_of_box (const unsigned int dim)
{
  // colorized box: 0/1 x-faces, 2/3 y-faces, 4/5 z-faces; the inlet is the bottom, the
  // outlet the top
  BubbleCriteria c;
  c.freeboard_boundaries = {types::boundary_id (2 * dim - 1)};
  c.open_boundaries      = {types::boundary_id (2 * dim - 2),
                            types::boundary_id (2 * dim - 1)};
  return c;
}

/** Refines the cells left of x = 0.5 once more: a second level across the domain. */
template <int dim>
void refine_left_half (parallel::distributed::Triangulation<dim> &triangulation)
{
  for (const auto &cell : triangulation.active_cell_iterators ())
    if (cell->is_locally_owned () && cell->center ()[0] < 0.5)
      cell->set_refine_flag ();
  triangulation.execute_coarsening_and_refinement ();
}

/** Ranks owning cells of `bubble`, and the refinement levels of its cells. */
template <int dim>
std::pair<unsigned int, unsigned int>
spread (const Setup<dim> &s, const BubbleField &field, int bubble)
{
  std::set<unsigned int> levels;
  bool                   here = false;
  for (const auto &cell : s.triangulation.active_cell_iterators ())
    if (cell->is_locally_owned () &&
        field.cell_bubble[cell->active_cell_index ()] == bubble)
    {
      here = true;
      levels.insert (cell->level ());
    }
  const auto    comm = s.triangulation.get_communicator ();
  std::set<int> all_levels;
  for (const auto &part : Utilities::MPI::all_gather (
           comm, std::vector<int> (levels.begin (), levels.end ())))
    all_levels.insert (part.begin (), part.end ());
  return {Utilities::MPI::sum (here ? 1u : 0u, comm),
          static_cast<unsigned int> (all_levels.size ())};
}

void detection_2d (MPI_Comm comm)
{
  Setup<2> s (comm);
  GridGenerator::hyper_rectangle (
      s.triangulation, Point<2> (0, 0), Point<2> (1, 2), true);
  s.triangulation.refine_global (6);  // h = 1/64
  refine_left_half (s.triangulation); // h = 1/128 for x < 0.5
  s.distribute ();
  const double h = 1.0 / 64;
  // (0.5, 0.4): across the two levels; (0.5, 1.0): large, across the partition of 2 or 3
  // ranks; (0.95, 1.4): cut by the right wall; the freeboard above y = 1.7
  s.impose (GasRegions<2> ({{0.5, 0.4, 0, 0.15}, {0.5, 1.0, 0, 0.2}, {0.95, 1.4, 0, 0.1}},
                           1.7));
  const BubbleField field =
      detect_bubbles (s.mapping, s.dof_handler, s.alpha, criteria_of_box (2), comm);
  check (field.bubbles.size () == 3,
         "2D: 3 bubbles (freeboard excluded), found " +
             std::to_string (field.bubbles.size ()));
  if (field.bubbles.size () != 3)
    return;
  // sorted by height: the areas of the two circles and the wall-cut one
  const double cut     = 0.01 * std::acos (0.5) - 0.05 * std::sqrt (0.0075);
  const double area[3] = {
      numbers::PI * 0.0225, numbers::PI * 0.04, numbers::PI * 0.01 - cut};
  const double centre_y[3] = {0.4, 1.0, 1.4};
  for (unsigned int i = 0; i < 3; ++i)
  {
    const Bubble &b        = field.bubbles[i];
    const double  diameter = std::sqrt (4 * area[i] / numbers::PI);
    std::cout << "2D bubble " << i << ": d_eq " << b.equivalent_diameter << " (exact "
              << diameter << ", h " << h << "), centroid (" << b.centroid[0] << ", "
              << b.centroid[1] << "), cells " << b.cells << ", wall " << b.touches_wall
              << std::endl;
    check (std::abs (b.equivalent_diameter - diameter) < 1.5 * h,
           "2D bubble " + std::to_string (i) + ": equivalent diameter within 1.5 h");
    check (std::abs (b.centroid[1] - centre_y[i]) < h,
           "2D bubble " + std::to_string (i) + ": centroid height within h");
    check (b.touches_wall == (i == 2), "2D bubble " + std::to_string (i) + ": wall flag");
  }
  const auto [ranks0, levels0] = spread (s, field, 0);
  check (levels0 == 2, "2D bubble 0 lies on two refinement levels");
  const unsigned int n_ranks   = Utilities::MPI::n_mpi_processes (comm);
  const auto [ranks1, levels1] = spread (s, field, 1);
  std::cout << "2D bubble 1 is owned by " << ranks1 << " of " << n_ranks << " ranks"
            << std::endl;
  check (n_ranks == 1 || ranks1 > 1, "2D bubble 1 spans more than one rank");
}

void detection_3d (MPI_Comm comm)
{
  Setup<3> s (comm);
  GridGenerator::hyper_rectangle (
      s.triangulation, Point<3> (0, 0, 0), Point<3> (1, 1, 2), true);
  s.triangulation.refine_global (4); // h = 1/16
  refine_left_half (s.triangulation);
  s.distribute ();
  const double h = 1.0 / 16;
  s.impose (GasRegions<3> ({{0.5, 0.5, 1.0, 0.4}}, 1.7));
  const BubbleField field =
      detect_bubbles (s.mapping, s.dof_handler, s.alpha, criteria_of_box (3), comm);
  check (field.bubbles.size () == 1,
         "3D: 1 bubble, found " + std::to_string (field.bubbles.size ()));
  if (field.bubbles.size () != 1)
    return;
  const Bubble &b = field.bubbles[0];
  std::cout << "3D bubble: d_eq " << b.equivalent_diameter << " (exact 0.8, h " << h
            << "), centroid z " << b.centroid[2] << ", cells " << b.cells << std::endl;
  check (std::abs (b.equivalent_diameter - 0.8) < 1.5 * h,
         "3D: equivalent diameter within 1.5 h");
  check (std::abs (b.centroid[2] - 1.0) < h, "3D: centroid height within h");
  check (!b.touches_wall, "3D: no wall contact");
  const auto [ranks, levels] = spread (s, field, 0);
  check (levels == 2, "3D bubble lies on two refinement levels");
  check (Utilities::MPI::n_mpi_processes (comm) == 1 || ranks > 1,
         "3D bubble spans more than one rank");
}

/** Counts the data rows of a CSV file. */
unsigned int rows (const std::string &file)
{
  std::ifstream in (file);
  std::string   line;
  unsigned int  n = 0;
  while (std::getline (in, line))
    ++n;
  return n - 1;
}

void tracking_2d (MPI_Comm comm, const std::string &folder)
{
  Setup<2> s (comm);
  GridGenerator::hyper_rectangle (
      s.triangulation, Point<2> (0, 0), Point<2> (1, 2), true);
  s.triangulation.refine_global (6);
  s.distribute ();
  BubbleAnalysisParameters p;
  p.enabled                = true;
  p.interval               = 1;
  p.gas_fraction_threshold = 0.8;
  p.minimum_diameter       = 0;
  BubbleAnalysis<2> analysis (p, criteria_of_box (2), s.triangulation, 1, comm);
  analysis.open (folder, "0123456789abcdef");
  // a peanut (two overlapping circles), then the two apart (split), rising; a mesh
  // change; then merged again (coalescence)
  const std::vector<std::vector<Sphere>> frames = {
      {{0.4, 0.8, 0, 0.12}, {0.6, 0.8, 0, 0.12}},
      {{0.33, 0.82, 0, 0.1}, {0.67, 0.82, 0, 0.1}},
      {{0.33, 0.945, 0, 0.1}, {0.67, 0.945, 0, 0.1}},
      {{0.42, 0.96, 0, 0.12}, {0.58, 0.96, 0, 0.12}}};
  std::vector<unsigned int> counts;
  for (unsigned int k = 0; k < frames.size (); ++k)
  {
    if (k == 3) // refine the lower half, coarsen nothing: the labels follow the cells
    {
      for (const auto &cell : s.triangulation.active_cell_iterators ())
        if (cell->is_locally_owned () && cell->center ()[1] < 0.85)
          cell->set_refine_flag ();
      analysis.prepare_for_mesh_change ();
      s.triangulation.execute_coarsening_and_refinement ();
      analysis.after_mesh_change ();
      s.distribute ();
    }
    s.impose (GasRegions<2> (frames[k], 1.7));
    counts.push_back (analysis.analyse (k, 0.01 * k, s.mapping, s.dof_handler, s.alpha));
  }
  check (counts == std::vector<unsigned int> ({1, 2, 2, 1}),
         "tracking: bubble counts 1, 2, 2, 1");
  check (analysis.tracker ().splittings () == 1,
         "tracking: one splitting event, counted " +
             std::to_string (analysis.tracker ().splittings ()));
  check (analysis.tracker ().coalescences () == 1,
         "tracking: one coalescence event, counted " +
             std::to_string (analysis.tracker ().coalescences ()));
  if (Utilities::MPI::this_mpi_process (comm) == 0)
  {
    check (rows (folder + "/bubble_events.csv") == 2,
           "tracking: two rows in bubble_events.csv");
    check (rows (folder + "/bubbles.csv") == 6, "tracking: six rows in bubbles.csv");
    check (rows (folder + "/bubble_summary.csv") == 4,
           "tracking: four rows in bubble_summary.csv");
    // the rise velocity of the continued tracks between frames 1 and 2: 0.125 / 0.01 s
    // (eight cells: the same cell pattern, shifted)
    std::ifstream in (folder + "/bubbles.csv");
    std::string   line;
    unsigned int  n = 0, measured = 0, with_run = 0;
    std::getline (in, line);
    check (line.substr (line.rfind (',') + 1) == "run",
           "bubbles.csv: the last column is run");
    while (std::getline (in, line))
    {
      const std::size_t last = line.rfind (',');
      with_run += line.substr (last + 1) == "0123456789abcdef";
      if (++n == 4 || n == 5)
      {
        const std::size_t before = line.rfind (',', last - 1);
        const std::string rise   = line.substr (before + 1, last - before - 1);
        std::cout << "frame 2 rise velocity: " << rise << std::endl;
        if (!rise.empty () && std::abs (std::stod (rise) - 12.5) < 1e-8)
          ++measured;
      }
    }
    check (with_run == 6, "bubbles.csv: every row carries the run's id");
    check (measured == 2,
           "tracking: rise velocity 12.5 m/s of both halves after the split");
  }
}
} // namespace

int main (int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi (argc, argv, 1);
  const std::string                folder = argc > 1 ? argv[1] : "bubble_analysis_output";
  const MPI_Comm                   comm   = MPI_COMM_WORLD;
  if (Utilities::MPI::this_mpi_process (comm) == 0)
    std::filesystem::create_directories (folder);
  MPI_Barrier (comm);
  detection_2d (comm);
  detection_3d (comm);
  tracking_2d (comm, folder);
  const unsigned int failures =
      Utilities::MPI::sum (wetbed::testing::failure_count (), comm);
  wetbed::testing::failure_count () = failures;
  return wetbed::testing::finish ("bubble_analysis");
}
