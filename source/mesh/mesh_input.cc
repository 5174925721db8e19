#include <wetbed/core/input_error.h>
#include <wetbed/mesh/geo_constants.h>
#include <wetbed/mesh/mesh_input.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/manifold_lib.h>

#include <deal.II/base/function_parser.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <limits>
#include <map>
#include <memory>
#include <set>
#include <spawn.h>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace wetbed
{
namespace
{
/** Physical names of dimension `group_dim` in a MSH file: name -> tag; the highest
 * dimension of any physical group into `highest` (0 if none). */
std::map<std::string, int>
read_physical_names (const std::string &msh_file, const int group_dim, int &highest)
{
  highest = 0;
  std::ifstream              in (msh_file);
  std::map<std::string, int> names;
  std::string                line;
  while (std::getline (in, line))
    if (line.rfind ("$PhysicalNames", 0) == 0)
    {
      int count = 0;
      in >> count;
      for (int i = 0; i < count; ++i)
      {
        int         d, tag;
        std::string quoted;
        in >> d >> tag;
        highest = std::max (highest, d);
        std::getline (in, quoted);
        const auto first = quoted.find ('"'), last = quoted.rfind ('"');
        if (d == group_dim && first != std::string::npos && last > first)
          names[quoted.substr (first + 1, last - first - 1)] = tag;
      }
      break;
    }
  return names;
}

/** The exit status and the merged stdout/stderr of a program run without a shell. */
struct ProgramRun
{
  int         spawn_error = 0; // errno of posix_spawnp (0: it started)
  int         status      = 0; // waitpid status
  std::string output;
};

/**
 * Runs `arguments[0]` (looked up on PATH) with the argument vector `arguments`, no
 * shell in between: a path holding `$(...)`, quotes or `;` is one argument and
 * nothing else. stdin is /dev/null; stdout and stderr are captured through a pipe.
 */
ProgramRun run_program (const std::vector<std::string> &arguments)
{
  ProgramRun run;
  int        pipe_ends[2];
  if (pipe2 (pipe_ends, O_CLOEXEC) != 0)
  {
    run.spawn_error = errno;
    return run;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init (&actions);
  posix_spawn_file_actions_addopen (&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2 (&actions, pipe_ends[1], 1);
  posix_spawn_file_actions_adddup2 (&actions, pipe_ends[1], 2);
  std::vector<char *> argv;
  for (const auto &argument : arguments)
    argv.push_back (const_cast<char *> (argument.c_str ()));
  argv.push_back (nullptr);
  pid_t pid = 0;
  run.spawn_error =
      posix_spawnp (&pid, argv[0], &actions, nullptr, argv.data (), environ);
  posix_spawn_file_actions_destroy (&actions);
  close (pipe_ends[1]);
  if (run.spawn_error == 0)
  {
    char buffer[4096];
    for (;;)
    {
      const ssize_t n = read (pipe_ends[0], buffer, sizeof (buffer));
      if (n > 0)
        run.output.append (buffer, n);
      else if (n == 0 || errno != EINTR)
        break;
    }
    while (waitpid (pid, &run.status, 0) < 0 && errno == EINTR)
      ;
  }
  close (pipe_ends[0]);
  return run;
}

/** The last line of gmsh's output that reports an error (else its last line). */
std::string last_error_line (const std::string &output)
{
  std::istringstream lines (output);
  std::string        line, last, last_error;
  while (std::getline (lines, line))
  {
    while (!line.empty () && std::isspace (static_cast<unsigned char> (line.back ())))
      line.pop_back ();
    if (line.empty ())
      continue;
    last = line;
    if (line.find ("Error") != std::string::npos)
      last_error = line;
  }
  return last_error.empty () ? last : last_error;
}

/** Whether gmsh reported an error (a line `Error   : ...`; it may still exit 0). */
bool reports_error (const std::string &output)
{
  std::istringstream lines (output);
  for (std::string line; std::getline (lines, line);)
    if (line.rfind ("Error", 0) == 0)
      return true;
  return false;
}

/** Writes `text` to `path` through a temporary file and a rename. */
void write_atomically (const std::string &path, const std::string &text)
{
  const std::string temporary = path + ".tmp-" + std::to_string (getpid ());
  {
    std::ofstream out (temporary, std::ios::binary);
    out << text;
    if (!out)
    {
      std::error_code ignored;
      std::filesystem::remove (temporary, ignored);
      return; // the log is a courtesy; the run does not depend on it
    }
  }
  std::error_code ignored;
  std::filesystem::rename (temporary, path, ignored);
}

/** Whether two files hold the same bytes (false if either cannot be read). */
bool same_bytes (const std::string &a, const std::string &b)
{
  std::ifstream first (a, std::ios::binary), second (b, std::ios::binary);
  if (!first || !second)
    return false;
  return std::equal (std::istreambuf_iterator<char> (first),
                     std::istreambuf_iterator<char> (),
                     std::istreambuf_iterator<char> (second),
                     std::istreambuf_iterator<char> ());
}

/**
 * The mesh that gmsh generates from a .geo: into a temporary file of the output
 * folder, moved to mesh.msh (and its log to gmsh.log) by commit() only once the mesh
 * has been read and accepted; a mesh that is not accepted is removed, and a previous
 * run's mesh.msh stays as it was (as it does when the new mesh is the same bytes, a
 * resumed run's).
 */
class GeneratedMesh
{
public:
  GeneratedMesh (const std::string                                 &geo,
                 const int                                          dim,
                 const std::string                                 &folder,
                 const std::vector<std::pair<std::string, double>> &numbers)
      : root (dealii::Utilities::MPI::this_mpi_process (MPI_COMM_WORLD) == 0),
        final_path (folder + "/mesh.msh"), log_path (folder + "/gmsh.log")
  {
    // one name on every rank: the root's process id
    const unsigned int id = dealii::Utilities::MPI::broadcast (
        MPI_COMM_WORLD, static_cast<unsigned int> (getpid ()), 0);
    temporary = folder + "/mesh.tmp-" + std::to_string (id) + ".msh";
    std::string error;
    if (root)
    {
      std::vector<std::string> arguments{"gmsh", "-" + std::to_string (dim)};
      for (const auto &[name, value] : numbers)
      {
        std::ostringstream text;
        text << std::setprecision (17) << value;
        arguments.insert (arguments.end (), {"-setnumber", name, text.str ()});
      }
      arguments.insert (arguments.end (), {"-format", "msh41", geo, "-o", temporary});
      const ProgramRun run = run_program (arguments);
      log                  = run.output;
      if (run.spawn_error != 0)
        error = "cannot start gmsh to mesh '" + geo +
                "' (is it installed and on PATH?): " + std::strerror (run.spawn_error);
      else if (!WIFEXITED (run.status) || WEXITSTATUS (run.status) != 0 ||
               !std::filesystem::is_regular_file (temporary) ||
               std::filesystem::file_size (temporary) == 0 || reports_error (run.output))
      {
        const std::string line = last_error_line (run.output);
        error                  = "gmsh failed to mesh '" + geo + "'" +
                (WIFEXITED (run.status)
                     ? " (exit " + std::to_string (WEXITSTATUS (run.status)) + ")"
                     : std::string (" (killed by a signal)")) +
                (line.empty () ? std::string () : ": " + line);
      }
    }
    error = dealii::Utilities::MPI::broadcast (MPI_COMM_WORLD, error, 0);
    if (!error.empty ())
    {
      discard ();
      throw InputError ("mesh/file", error);
    }
  }

  ~GeneratedMesh ()
  {
    if (!committed)
      discard ();
  }

  const std::string &path () const { return temporary; }

  /** Every rank has read the mesh and accepted it: it becomes mesh.msh. */
  void commit ()
  {
    MPI_Barrier (MPI_COMM_WORLD);
    if (root)
    {
      std::error_code error;
      if (same_bytes (temporary, final_path))
        std::filesystem::remove (temporary,
                                 error); // mesh.msh and gmsh.log stay as they are
      else
      {
        std::filesystem::rename (temporary, final_path, error);
        if (error)
          std::filesystem::remove (temporary, error);
        write_atomically (log_path, log);
      }
    }
    committed = true;
  }

private:
  void discard ()
  {
    if (root)
    {
      std::error_code ignored;
      std::filesystem::remove (temporary, ignored);
    }
  }

  bool        root, committed = false;
  std::string final_path, log_path, temporary, log;
};

// a DeferredMeshCommit is alive: read_mesh() leaves the generated mesh here
bool                           defer_commit = false;
std::unique_ptr<GeneratedMesh> pending_mesh;

/** The element types (gmsh numbering) of an ASCII .msh file (2.x or 4.x): type -> count.
 */
std::map<int, std::size_t> read_element_types (const std::string &msh_file, bool &binary)
{
  std::ifstream              in (msh_file);
  std::map<int, std::size_t> types;
  std::string                line;
  double                     version   = 0;
  int                        file_type = 0;
  binary                               = false;
  while (std::getline (in, line))
  {
    if (line.rfind ("$MeshFormat", 0) == 0)
    {
      in >> version >> file_type;
      binary = file_type != 0;
      if (binary)
        return types;
    }
    else if (line.rfind ("$Elements", 0) == 0)
    {
      if (version >= 4)
      {
        std::size_t blocks = 0, elements = 0, min_tag = 0, max_tag = 0;
        in >> blocks >> elements >> min_tag >> max_tag;
        std::getline (in, line);
        for (std::size_t b = 0; b < blocks && in; ++b)
        {
          int         entity_dim = 0, entity_tag = 0, type = 0;
          std::size_t count = 0;
          in >> entity_dim >> entity_tag >> type >> count;
          std::getline (in, line);
          types[type] += count;
          for (std::size_t e = 0; e < count && std::getline (in, line); ++e)
            ;
        }
      }
      else
      {
        std::size_t count = 0;
        in >> count;
        std::getline (in, line);
        for (std::size_t e = 0; e < count && std::getline (in, line); ++e)
        {
          std::istringstream fields (line);
          long               tag  = 0;
          int                type = 0;
          if (fields >> tag >> type)
            ++types[type];
        }
      }
      break;
    }
  }
  return types;
}

/**
 * An all-quadrilateral (2D) or all-hexahedral (3D) first-order mesh, as deal.II's
 * p4est triangulation needs (a triangle or tetrahedron crashes inside its copy):
 * checked before the file is handed to GridIn.
 */
void check_element_types (const std::string &msh, const std::string &shown, const int dim)
{
  bool       binary = false;
  const auto types  = read_element_types (msh, binary);
  if (binary)
    return; // GridIn reads ASCII files only; it reports the file
  // gmsh numbering: 1 line, 2 triangle, 3 quadrangle, 4 tetrahedron, 5 hexahedron,
  // 6 prism, 7 pyramid, 15 point; second-order and other types beyond
  const std::map<int, std::string> simplex = {{2, "triangles"},
                                              {4, "tetrahedra"},
                                              {6, "prisms"},
                                              {7, "pyramids"},
                                              {9, "second-order triangles"},
                                              {11, "second-order tetrahedra"}};
  const std::string                fix =
      dim == 2 ? "add `Recombine Surface{...};` (and a Transfinite or quad-meshing "
                                "algorithm) to the .geo"
                              : "add `Recombine` to the .geo (e.g. `Recombine Surface{...};` with "
                                "`Transfinite Volume{...};`, or `Extrude {...} { Layers{n}; "
                                "Recombine; }`)";
  std::size_t cells = 0;
  for (const auto &[type, count] : types)
  {
    const auto s = simplex.find (type);
    if (s != simplex.end ())
      throw InputError ("mesh/file",
                        "'" + shown + "' holds " + std::to_string (count) + " " +
                            s->second + ": wetbed needs an all-" +
                            (dim == 2 ? "quadrilateral" : "hexahedral") + " mesh; " +
                            fix);
    const bool allowed = type == 15 || type == 1 || type == 3 || (dim == 3 && type == 5);
    require (allowed,
             "mesh/file",
             "'" + shown + "' holds " + std::to_string (count) +
                 " elements of gmsh type " + std::to_string (type) +
                 (type == 5 ? " (hexahedra in a 2D case: set dimension = 3?)"
                            : " (second order or not a quadrilateral/hexahedron)") +
                 "; wetbed reads first-order all-" +
                 (dim == 2 ? "quadrilateral" : "hexahedral") + " meshes");
    if (type == (dim == 2 ? 3 : 5))
      cells += count;
  }
  require (cells > 0 || types.empty (),
           "mesh/file",
           "'" + shown + "' has no " + (dim == 2 ? "quadrilateral" : "hexahedral") +
               " cells (a mesh of dimension " + std::to_string (dim) + " is needed; " +
               fix + ")");
}

/**
 * Bytes of memory per cell of the whole run (the Q2^2dim x Q1 flow system and its
 * preconditioner, the Q1 alpha_s and Theta with their histories, closures, monitors,
 * output): the growth of the peak resident memory between two short serial runs (2
 * steps, default solver settings) divided by the growth of the cell count.
 * 3D: prm/column_3d.prm with 24 and 96 layers (792 and 3,168 hexahedra): matrix-free
 * (the default) 241 and 408 MB, 70 kB per hexahedron; `operator = assembled` 529 and
 * 1,515 MB, 415 kB. 2D: prm/bubbling_bed_2d.prm at initial refinement 1 and 3 (600 and
 * 9,600 quadrilaterals): matrix-free 195 and 365 MB, 19 kB; assembled 206 and 518 MB,
 * 35 kB (doc/user_guide.md, "What is checked before the run starts").
 */
double bytes_per_cell (const int dim, const bool assembled_operator)
{
  if (dim == 2)
    return assembled_operator ? 35.0e3 : 19.0e3;
  return assembled_operator ? 415.0e3 : 70.0e3;
}

/** Physical memory of the machines the run is on (the sum over the nodes). */
double physical_memory ()
{
  MPI_Comm node;
  MPI_Comm_split_type (MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int node_ranks = 1;
  MPI_Comm_size (node, &node_ranks);
  MPI_Comm_free (&node);
  const double pages = static_cast<double> (sysconf (_SC_PHYS_PAGES)),
               page  = static_cast<double> (sysconf (_SC_PAGE_SIZE));
  const double share = pages > 0 && page > 0 ? pages * page / node_ranks : 0.0;
  return dealii::Utilities::MPI::sum (share, MPI_COMM_WORLD);
}

std::string format_number (const double value, const int precision = 3)
{
  std::ostringstream out;
  out << std::setprecision (precision) << value;
  return out.str ();
}

/** Cells and memory of the requested refinement against the machines' memory. */
template <int dim>
void check_refinement (const DomainChecks &checks, const std::size_t coarse_cells)
{
  const double memory = physical_memory ();
  if (memory <= 0)
    return;
  for (const auto &[parameter, levels] : checks.refinement_levels)
  {
    const double cells =
        static_cast<double> (coarse_cells) * std::pow (2.0, dim * levels);
    const double bytes = cells * bytes_per_cell (dim, checks.assembled_operator);
    require (bytes <= memory,
             parameter,
             std::to_string (levels) + " levels of " + std::to_string (coarse_cells) +
                 " coarse cells make about " + format_number (cells) +
                 " cells, an estimated " + format_number (bytes / 1e9) +
                 " GB, more than the " + format_number (memory / 1e9) +
                 " GB of physical memory");
  }
}

/** The centroid of the coarse faces on the given boundary groups; false if none. */
template <int dim>
bool boundary_centroid (const dealii::Triangulation<dim>           &triangulation,
                        const std::set<dealii::types::boundary_id> &ids,
                        dealii::Point<dim>                         &centroid)
{
  double area = 0;
  centroid    = dealii::Point<dim> ();
  for (const auto &cell : triangulation.cell_iterators_on_level (0))
    for (const auto &face : cell->face_iterators ())
      if (face->at_boundary () && ids.count (face->boundary_id ()) > 0)
      {
        const double a = std::max (face->measure (), 1e-300);
        centroid += a * face->center ();
        area += a;
      }
  if (area > 0)
    centroid /= area;
  return area > 0;
}

/** Whether gravity has a component in the plane (the space) of the mesh. */
template <int dim>
bool vertical_gravity (const dealii::Tensor<1, dim> &g,
                       const dealii::Tensor<1, 3>   &gravity)
{
  return g.norm () > 1e-12 * gravity.norm ();
}

/** The point probes within the domain's bounding box [low, high] (to `tolerance`). */
template <int dim>
void check_point_probes (const DomainChecks       &checks,
                         const dealii::Point<dim> &low,
                         const dealii::Point<dim> &high,
                         const double              tolerance)
{
  for (const auto &p : checks.point_probes)
  {
    bool        inside = true;
    std::string text, box_low, box_high;
    for (int d = 0; d < dim; ++d)
    {
      inside = inside && p[d] >= low[d] - tolerance && p[d] <= high[d] + tolerance;
      text += (d ? ", " : "") + format_number (p[d], 6);
      box_low += (d ? ", " : "") + format_number (low[d], 6);
      box_high += (d ? ", " : "") + format_number (high[d], 6);
    }
    require (inside,
             "bed monitors/point probes",
             "(" + text + ") lies outside the domain's bounding box (" + box_low +
                 ") - (" + box_high + ")");
  }
}

/** The held solids velocity finite at the corners and the centre of the bounding box
 * [low, high] at 201 times up to the end time. */
template <int dim>
void check_held_solids_velocity (const DomainChecks       &checks,
                                 const dealii::Point<dim> &low,
                                 const dealii::Point<dim> &high)
{
  dealii::FunctionParser<3> f (3);
  f.initialize ("x,y,z,t", checks.held_solids_velocity, {}, true);
  const unsigned int              n_times = 200;
  std::vector<dealii::Point<dim>> points;
  for (unsigned int corner = 0; corner < (1u << dim); ++corner)
  {
    dealii::Point<dim> x;
    for (int d = 0; d < dim; ++d)
      x[d] = (corner >> d) & 1 ? high[d] : low[d];
    points.push_back (x);
  }
  points.push_back (0.5 * (low + high));
  for (unsigned int i = 0; i <= n_times; ++i)
    for (const auto &x : points)
    {
      const double     t = checks.end_time * i / n_times;
      dealii::Point<3> x3;
      for (int d = 0; d < dim; ++d)
        x3[d] = x[d];
      f.set_time (t);
      for (unsigned int c = 0; c < static_cast<unsigned int> (dim); ++c)
      {
        const double value = f.value (x3, c);
        require (std::isfinite (value),
                 "boundary conditions/held solids velocity",
                 "component " + std::to_string (c + 1) + " of '" +
                     checks.held_solids_velocity + "' is " + format_number (value) +
                     " at t = " + format_number (t) + " s, x = (" +
                     format_number (x3[0]) + ", " + format_number (x3[1]) + ", " +
                     format_number (x3[2]) + ")");
      }
    }
}

/**
 * The case's placements against the mesh: gravity from the outlet toward the inlet,
 * the heights (bed, probes, planes) within the domain's extent along -gravity, the
 * point probes in its bounding box, the held solids velocity finite in it.
 */
template <int dim>
void check_domain (const DomainChecks               &checks,
                   const Boundaries                 &ids,
                   const dealii::Tensor<1, 3>       &gravity,
                   const dealii::Triangulation<dim> &triangulation)
{
  const auto        &vertices = triangulation.get_vertices ();
  const auto        &used     = triangulation.get_used_vertices ();
  const auto         up       = upward_direction<dim> (gravity);
  dealii::Point<dim> low, high;
  double             bottom = std::numeric_limits<double>::max (),
         top                = std::numeric_limits<double>::lowest ();
  bool first                = true;
  for (std::size_t v = 0; v < vertices.size (); ++v)
    if (used[v])
    {
      const auto &x = vertices[v];
      for (int d = 0; d < dim; ++d)
      {
        low[d]  = first ? x[d] : std::min (low[d], x[d]);
        high[d] = first ? x[d] : std::max (high[d], x[d]);
      }
      first  = false;
      bottom = std::min (bottom, x * up);
      top    = std::max (top, x * up);
    }
  if (first)
    return;
  const double size      = std::max ((high - low).norm (), 1e-300);
  const double tolerance = 1e-9 * size;

  dealii::Tensor<1, dim> g;
  for (int d = 0; d < dim; ++d)
    g[d] = gravity[d];
  dealii::Point<dim> inlet, outlet;
  if (checks.gravity_from_outlet_to_inlet && vertical_gravity (g, gravity) &&
      boundary_centroid (triangulation, ids.ids (BoundaryType::inlet), inlet) &&
      boundary_centroid (triangulation, ids.ids (BoundaryType::outlet), outlet))
  {
    const auto rise = outlet - inlet;
    require (g * rise < -1e-6 * g.norm () * rise.norm (),
             "physical properties/gravity",
             "must point from the outlet toward the inlet (the gas rises against "
             "gravity), but gravity . (outlet centroid - inlet centroid) = " +
                 format_number (g * rise) + " m^2/s^2 is not negative");
  }

  // a mesh lying flat (no gravity in its plane) has no top for the bed to be above
  const bool vertical = vertical_gravity (g, gravity);
  for (const auto &[parameter, value, top_only] : checks.heights)
    require ((top_only && !vertical) ||
                 ((top_only || value >= bottom - tolerance) && value <= top + tolerance),
             parameter,
             format_number (value, 6) + " m lies outside the domain, which spans [" +
                 format_number (bottom, 6) + ", " + format_number (top, 6) +
                 "] m along -gravity from the origin");

  check_point_probes<dim> (checks, low, high, tolerance);
  if (!checks.held_solids_velocity.empty ())
    check_held_solids_velocity<dim> (checks, low, high);
}
} // namespace

std::string resolve_path (const std::string &file, const std::string &directory)
{
  const std::filesystem::path path (file);
  if (path.is_absolute () || directory.empty ())
    return file;
  return (std::filesystem::path (directory) / path).lexically_normal ().string ();
}

DeferredMeshCommit::DeferredMeshCommit ()
{
  defer_commit = true;
}

DeferredMeshCommit::~DeferredMeshCommit ()
{
  pending_mesh.reset (); // not committed: the generated mesh is removed
  defer_commit = false;
}

void DeferredMeshCommit::discard ()
{
  pending_mesh.reset ();
}

void DeferredMeshCommit::commit ()
{
  if (pending_mesh)
    pending_mesh->commit ();
  pending_mesh.reset ();
}

std::string check_mesh_file (const MeshParameters &parameters,
                             const std::string    &parameter_directory)
{
  const std::string file = resolve_path (parameters.file, parameter_directory);
  require (std::filesystem::is_regular_file (file),
           "mesh/file",
           "file '" + file + "' not found");
  const std::string extension = std::filesystem::path (file).extension ().string ();
  require (extension == ".geo" || extension == ".msh",
           "mesh/file",
           "'" + file + "' is neither a .geo nor a .msh file");
  if (!parameters.geometry_parameters.empty ())
  {
    require (extension == ".geo",
             "mesh/geometry parameters",
             "are given, but '" + file + "' is a .msh (only a .geo takes them)");
    std::ifstream      in (file);
    std::ostringstream text;
    text << in.rdbuf ();
    const auto  defined = geo_defined_constants (text.str ());
    std::string list;
    for (const auto &name : defined)
      list += (list.empty () ? "" : ", ") + name;
    for (const auto &entry : parameters.geometry_parameters)
      require (defined.count (entry.first) > 0,
               "mesh/geometry parameters",
               "'" + entry.first + "' is not a DefineConstant of '" + file +
                   "' (it defines: " + (list.empty () ? "none" : list) + ")");
  }
  return file;
}

namespace
{
/** The case's inlet, outlet, wall, periodic and moving-wall groups, each looked up by
 * name among the mesh's physical groups `names` (of the mesh named `shown`). */
Boundaries named_boundaries (const MeshParameters             &parameters,
                             const std::string                &moving_wall_name,
                             const std::map<std::string, int> &names,
                             const std::string                &shown)
{
  auto id_of = [&] (const std::string &name, const std::string &parameter)
  {
    const auto it = names.find (name);
    require (it != names.end (),
             parameter,
             "physical group '" + name + "' is not in the mesh '" + shown + "'");
    return static_cast<dealii::types::boundary_id> (it->second);
  };
  Boundaries ids;
  auto       add = [&] (const std::string &name,
                  const BoundaryType type,
                  const std::string &parameter,
                  const std::string &taken)
  {
    const auto id = id_of (name, parameter);
    require (ids.find (id) == nullptr, parameter, "'" + name + "' " + taken);
    ids.add (name, type, id);
    return id;
  };
  const std::string twice = "is named twice (each group is one inlet, outlet or wall)";
  for (const auto &name : parameters.inlet_names)
    add (name, BoundaryType::inlet, "mesh/inlet", twice);
  for (const auto &name : parameters.outlet_names)
    add (name, BoundaryType::outlet, "mesh/outlet", twice);
  for (const auto &name : parameters.wall_names)
    add (name, BoundaryType::wall, "mesh/wall", twice);
  if (!parameters.periodic_low_name.empty ())
  {
    const std::string taken = "is already the inlet, outlet or wall";
    add (parameters.periodic_low_name,
         BoundaryType::periodic_low,
         "mesh/periodic boundaries",
         taken);
    add (parameters.periodic_high_name,
         BoundaryType::periodic_high,
         "mesh/periodic boundaries",
         taken);
  }
  if (!moving_wall_name.empty ())
    add (moving_wall_name,
         BoundaryType::moving_wall,
         "boundary conditions/moving wall",
         "is already another boundary of the case");
  return ids;
}

/** `mesh/cylindrical wall`: the walls on a cylinder about the axis along gravity
 * through the mesh's centre, the interior transfinite. */
template <int dim>
void attach_cylindrical_manifolds (
    dealii::parallel::distributed::Triangulation<dim> &triangulation,
    const Boundaries                                  &ids,
    const dealii::Tensor<1, 3>                        &gravity)
{
  require (dim == 3, "mesh/cylindrical wall", "needs a 3D mesh");
  if constexpr (dim == 3)
  {
    dealii::Tensor<1, 3>   axis = gravity / gravity.norm ();
    const auto             box  = dealii::GridTools::compute_bounding_box (triangulation);
    const dealii::Point<3> centre = box.center ();
    triangulation.set_all_manifold_ids (2);
    for (const auto wall : ids.ids (BoundaryType::wall))
      triangulation.set_all_manifold_ids_on_boundary (wall, 1);
    triangulation.set_manifold (1, dealii::CylindricalManifold<3> (axis, centre));
    dealii::TransfiniteInterpolationManifold<3> transfinite;
    transfinite.initialize (triangulation);
    triangulation.set_manifold (2, transfinite);
  }
}

/** The periodic pair of boundaries matched face by face and added to `triangulation`;
 * an InputError naming `mesh/periodic boundaries` where they do not match. */
template <int dim>
void make_periodic (dealii::parallel::distributed::Triangulation<dim> &triangulation,
                    const Boundaries                                  &ids,
                    const MeshParameters                              &parameters)
{
  const auto periodic_low  = ids.id_of (BoundaryType::periodic_low),
             periodic_high = ids.id_of (BoundaryType::periodic_high);
  std::vector<dealii::GridTools::PeriodicFacePair<
      typename dealii::parallel::distributed::Triangulation<dim>::cell_iterator>>
                    pairs;
  const std::string mismatch = "the faces of '" + parameters.periodic_high_name +
                               "' are not those of '" + parameters.periodic_low_name +
                               "' translated along the periodic direction";
  try
  {
    dealii::GridTools::collect_periodic_faces (
        triangulation, periodic_low, periodic_high, parameters.periodic_direction, pairs);
  }
  catch (const std::exception &)
  {
    throw InputError ("mesh/periodic boundaries", mismatch);
  }
  std::size_t low_faces = 0;
  for (const auto &cell : triangulation.active_cell_iterators ())
    for (const auto &face : cell->face_iterators ())
      low_faces += face->at_boundary () && face->boundary_id () == periodic_low;
  require (parameters.periodic_direction < dim && !pairs.empty () &&
               pairs.size () == low_faces,
           "mesh/periodic boundaries",
           mismatch);
  triangulation.add_periodicity (pairs);
}
} // namespace

template <int dim>
Boundaries read_mesh (const MeshParameters       &parameters,
                      const std::string          &moving_wall_name,
                      const std::string          &parameter_directory,
                      const std::string          &output_folder,
                      const dealii::Tensor<1, 3> &gravity,
                      dealii::parallel::distributed::Triangulation<dim> &triangulation)
{
  const std::string file      = check_mesh_file (parameters, parameter_directory);
  const std::string extension = std::filesystem::path (file).extension ().string ();
  std::unique_ptr<GeneratedMesh> generated;
  if (extension == ".geo")
    generated = std::make_unique<GeneratedMesh> (
        file, dim, output_folder, parameters.geometry_parameters);
  const std::string msh = generated ? generated->path () : file;
  // named as the user knows it: the .geo, or the .msh given
  const std::string shown = generated ? file : msh;

  int        mesh_dim = 0;
  const auto names    = read_physical_names (msh, dim - 1, mesh_dim);
  require (mesh_dim < 2 || mesh_dim == dim, // a damaged mesh is mesh/file's
           "dimension",
           "the mesh '" + shown + "' is " + std::to_string (mesh_dim) +
               "D (its highest physical group), the case says `set dimension = " +
               std::to_string (dim) + "`");
  const Boundaries ids = named_boundaries (parameters, moving_wall_name, names, shown);

  check_element_types (msh, shown, dim);
  dealii::GridIn<dim> grid_in (triangulation);
  std::ifstream       in (msh);
  try
  {
    grid_in.read_msh (in);
  }
  catch (const dealii::ExceptionBase &e)
  {
    throw InputError ("mesh/file",
                      "cannot read '" + shown + "' as a gmsh quad/hex mesh" +
                          (generated ? " (as meshed by gmsh)" : ""));
  }
  check_refinement<dim> (parameters.checks, triangulation.n_cells (0));
  if (parameters.cylindrical_wall)
    attach_cylindrical_manifolds (triangulation, ids, gravity);
  if (ids.has (BoundaryType::periodic_low))
    make_periodic (triangulation, ids, parameters);
  check_domain<dim> (parameters.checks, ids, gravity, triangulation);
  if (generated && defer_commit)
    pending_mesh = std::move (generated); // DeferredMeshCommit::commit() moves it
  else if (generated)
    generated->commit ();
  triangulation.refine_global (parameters.initial_refinement);
  return ids;
}

template Boundaries read_mesh<2> (const MeshParameters &,
                                  const std::string &,
                                  const std::string &,
                                  const std::string &,
                                  const dealii::Tensor<1, 3> &,
                                  dealii::parallel::distributed::Triangulation<2> &);
template Boundaries read_mesh<3> (const MeshParameters &,
                                  const std::string &,
                                  const std::string &,
                                  const std::string &,
                                  const dealii::Tensor<1, 3> &,
                                  dealii::parallel::distributed::Triangulation<3> &);
} // namespace wetbed
