#include <wetbed/core/output_folder.h>
#include <wetbed/postprocess/field_output.h>
#include <wetbed/postprocess/time_averages.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <hdf5.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <stdexcept>

#include <sstream>
namespace wetbed
{
using namespace dealii;

namespace
{
/** Whether `file` exists and ends with `tail` (the closing tag of a complete file). */
bool ends_with (const std::string &file, const std::string &tail)
{
  std::ifstream in (file, std::ios::binary | std::ios::ate);
  if (!in)
    return false;
  const std::streamoff size = in.tellg ();
  if (size < static_cast<std::streamoff> (tail.size ()))
    return false;
  in.seekg (size - static_cast<std::streamoff> (tail.size ()));
  std::string end (tail.size (), '\0');
  in.read (end.data (), end.size ());
  return in && end == tail;
}

/** Whether the PVTU record `pvtu` and every piece it lists are complete. */
bool complete_vtu (const std::string &folder, const std::string &pvtu)
{
  const std::string closing = "</VTKFile>\n";
  if (!ends_with (folder + pvtu, closing))
    return false;
  std::ifstream     in (folder + pvtu);
  const std::string record ((std::istreambuf_iterator<char> (in)),
                            std::istreambuf_iterator<char> ());
  const std::regex  source ("Source=\"([^\"]+)\"");
  unsigned int      pieces = 0;
  for (auto m = std::sregex_iterator (record.begin (), record.end (), source);
       m != std::sregex_iterator ();
       ++m, ++pieces)
    if (!ends_with (folder + (*m)[1].str (), closing))
      return false;
  return pieces > 0;
}
/**
 * fields.pvd, ParaView's time record of the VTU outputs: the entries of the existing
 * record for the outputs before `index` (a resumed run's, cut back to its checkpoint; a
 * new run starts at index 0 and drops them all), then (time, pvtu). Written beside the
 * old one and renamed over it once whole; false if that failed.
 */
bool update_pvd_record (const std::string &folder,
                        const unsigned int index,
                        const double       time,
                        const std::string &pvtu)
{
  const std::string                           path = folder + "fields.pvd";
  std::vector<std::pair<double, std::string>> entries;
  {
    std::ifstream      in (path);
    std::ostringstream text;
    text << in.rdbuf ();
    const std::regex dataset (
        "timestep=\"([^\"]+)\"[^>]*file=\"fields_([0-9]+)\\.pvtu\"");
    const std::string content = text.str ();
    for (std::sregex_iterator it (content.begin (), content.end (), dataset), end;
         it != end;
         ++it)
    {
      const unsigned int earlier = std::stoul ((*it)[2].str ());
      if (earlier < index)
        entries.emplace_back (std::stod ((*it)[1].str ()),
                              "fields_" + Utilities::int_to_string (earlier, 5) +
                                  ".pvtu");
    }
  }
  entries.emplace_back (time, pvtu);
  {
    std::ofstream out (path + ".partial");
    DataOutBase::write_pvd_record (out, entries);
    out.flush ();
    if (!out)
      return false;
  }
  std::error_code error;
  std::filesystem::rename (path + ".partial", path, error);
  return !error;
}
/** The cell fields of an output: the mean drag coefficient and solids shear viscosity
 * of each cell, its refinement level and, with the kinetic theory, the shear rate, the
 * stress split (kinetic, collisional, frictional, wet) and the collisional dissipation.
 */
struct CellFields
{
  static const std::vector<std::string> split_names;
  dealii::Vector<float>                 drag_coefficient, shear_viscosity, level;
  std::vector<dealii::Vector<float>>    split;
  bool                                  wet_scene = false;
};
const std::vector<std::string> CellFields::split_names = {"solids_shear_rate",
                                                          "kinetic_shear_stress",
                                                          "collisional_shear_stress",
                                                          "frictional_shear_stress",
                                                          "wet_shear_stress",
                                                          "collisional_dissipation"};

template <int dim>
CellFields cell_fields (const SolverState<dim> &s)
{
  using AlphaVector                      = typename SolverState<dim>::AlphaVector;
  const Mapping<dim>            &mapping = s.mapping;
  const DoFHandler<dim>         &flow_dof_handler  = s.flow_dof_handler;
  const AlphaVector             &alpha             = s.alpha;
  const AlphaVector             &theta             = s.theta;
  const auto                    &flow_solution     = s.flow_solution;
  const auto                    &closure_evaluator = s.closures;
  const closures::KineticTheory *kinetic_theory    = s.kinetic_theory;
  const unsigned int             n_cells           = s.triangulation.n_active_cells ();
  CellFields                     fields;
  fields.drag_coefficient.reinit (n_cells);
  fields.shear_viscosity.reinit (n_cells);
  fields.level.reinit (n_cells);
  fields.wet_scene = kinetic_theory && kinetic_theory->wet () != nullptr;
  fields.split.assign (kinetic_theory ? CellFields::split_names.size () : 0,
                       Vector<float> (n_cells));
  auto &drag_coefficient = fields.drag_coefficient,
       &shear_viscosity = fields.shear_viscosity, &level = fields.level;
  auto               &split = fields.split;
  std::vector<double> split_integral (split.size ());
  const QGauss<dim>   quadrature (2);
  FEValues<dim>       flow_values (mapping,
                             s.flow_fe,
                             quadrature,
                             update_values | update_gradients | update_JxW_values);
  FEValues<dim>       alpha_values (mapping, s.alpha_fe, quadrature, update_values);
  const FEValuesExtractors::Vector gas (0), solids (dim);
  std::vector<Tensor<1, dim>>      u_g (quadrature.size ()), u_s (quadrature.size ());
  std::vector<Tensor<2, dim>>      grad_u_s (quadrature.size ());
  std::vector<double> alpha_q (quadrature.size ()), theta_q (quadrature.size ());
  auto                alpha_cell = s.alpha_dof_handler.begin_active ();
  for (const auto &cell : flow_dof_handler.active_cell_iterators ())
  {
    if (cell->is_locally_owned ())
    {
      flow_values.reinit (cell);
      alpha_values.reinit (alpha_cell);
      flow_values[gas].get_function_values (flow_solution, u_g);
      flow_values[solids].get_function_values (flow_solution, u_s);
      flow_values[solids].get_function_gradients (flow_solution, grad_u_s);
      alpha_values.get_function_values (alpha, alpha_q);
      alpha_values.get_function_values (theta, theta_q);
      double integral = 0, viscosity = 0, volume = 0;
      std::fill (split_integral.begin (), split_integral.end (), 0.0);
      for (unsigned int q = 0; q < quadrature.size (); ++q)
      {
        const double shear_rate =
            closures::ClosureEvaluator::shear_rate<dim> (grad_u_s[q]);
        const double a = std::max (alpha_q[q], 0.0);
        const auto   stress =
            closure_evaluator.stress (a, theta_q[q], shear_rate, trace (grad_u_s[q]));
        const double JxW = flow_values.JxW (q);
        integral += closure_evaluator.drag (a, (u_g[q] - u_s[q]).norm ()) * JxW;
        viscosity += stress.shear_viscosity * JxW;
        volume += JxW;
        if (kinetic_theory)
        {
          const auto   c       = kinetic_theory->evaluate (a, theta_q[q]);
          const double parts[] = {
              shear_rate,
              (c.shear_viscosity - c.collisional_viscosity) * shear_rate,
              c.collisional_viscosity * shear_rate,
              stress.frictional_viscosity * shear_rate,
              stress.wet_viscosity * shear_rate,
              c.dissipation_factor * std::pow (std::max (theta_q[q], 0.0), 1.5)};
          for (unsigned int k = 0; k < split.size (); ++k)
            split_integral[k] += parts[k] * JxW;
        }
      }
      drag_coefficient (cell->active_cell_index ()) = integral / volume;
      shear_viscosity (cell->active_cell_index ())  = viscosity / volume;
      for (unsigned int k = 0; k < split.size (); ++k)
        split[k](cell->active_cell_index ()) = split_integral[k] / volume;
      level (cell->active_cell_index ()) = cell->level ();
    }
    ++alpha_cell;
  }
  return fields;
}
} // namespace

/**
 * Writes u_g, u_s, p', alpha_s, alpha_g, the solids pressure P_s(alpha_s) (nodal, on the
 * alpha_s space, as the compaction force uses it), Theta (kinetic theory), the drag
 * coefficient beta and the solids shear viscosity mu_s (cell means over the Gauss points,
 * with the local slip, Theta and strain rate), the refinement level and the MPI rank;
 * with the kinetic theory also the solids shear rate |gamma| = sqrt(2 D_dev:D_dev), the
 * parts of the solids shear stress mu_i |gamma| (kinetic, collisional, frictional and,
 * in a wet scene, liquid-bridge) and the collisional dissipation gamma (cell means; the
 * stress split and dissipation of seed 000's Figs. 9-10);
 * as VTU pieces with a PVTU record and/or as one parallel HDF5 file per output indexed
 * by fields.xdmf (`output/field format`).
 */
template <int dim>
FieldOutput<dim>::FieldOutput (const Parameters &parameters, TimerOutput &timer)
    : parameters (parameters), timer (timer)
{
}

template <int dim>
void FieldOutput<dim>::write (const SolverState<dim> &s)
{
  using AlphaVector                        = typename SolverState<dim>::AlphaVector;
  const auto            &triangulation     = s.triangulation;
  const DoFHandler<dim> &flow_dof_handler  = s.flow_dof_handler;
  const DoFHandler<dim> &alpha_dof_handler = s.alpha_dof_handler;
  const AlphaVector     &alpha             = s.alpha;
  TimerOutput::Scope     scope (timer, "output");
  DataOut<dim>           data_out;
  data_out.attach_triangulation (triangulation);
  std::vector<std::string> names;
  for (unsigned int d = 0; d < dim; ++d)
    names.push_back ("gas_velocity");
  for (unsigned int d = 0; d < dim; ++d)
    names.push_back ("solids_velocity");
  names.push_back ("pressure");
  std::vector<DataComponentInterpretation::DataComponentInterpretation> kinds (
      2 * dim, DataComponentInterpretation::component_is_part_of_vector);
  kinds.push_back (DataComponentInterpretation::component_is_scalar);
  data_out.add_data_vector (flow_dof_handler, s.flow_solution, names, kinds);
  data_out.add_data_vector (alpha_dof_handler, alpha, "alpha_s");
  AlphaVector alpha_g (alpha);
  for (unsigned int i = 0; i < alpha_g.locally_owned_size (); ++i)
    alpha_g.local_element (i) = 1.0 - alpha.local_element (i);
  alpha_g.update_ghost_values ();
  data_out.add_data_vector (alpha_dof_handler, alpha_g, "alpha_g");
  AlphaVector solids_pressure (alpha);
  for (unsigned int i = 0; i < solids_pressure.locally_owned_size (); ++i)
    solids_pressure.local_element (i) =
        s.closures.compaction_pressure (alpha.local_element (i));
  solids_pressure.update_ghost_values ();
  data_out.add_data_vector (alpha_dof_handler, solids_pressure, "solids_pressure");
  if (s.kinetic_theory)
    data_out.add_data_vector (alpha_dof_handler, s.theta, "granular_temperature");
  if (s.time_averages)
    s.time_averages->add_fields (
        data_out, flow_dof_handler, alpha_dof_handler, names, s.time);

  // the cell fields (DataOut keeps pointers to them until build_patches)
  const CellFields fields = cell_fields (s);
  data_out.add_data_vector (fields.drag_coefficient, "drag_coefficient");
  data_out.add_data_vector (fields.shear_viscosity, "solids_shear_viscosity");
  for (unsigned int k = 0; k < fields.split.size (); ++k)
    if (CellFields::split_names[k] != "wet_shear_stress" || fields.wet_scene)
      data_out.add_data_vector (fields.split[k], CellFields::split_names[k]);
  data_out.add_data_vector (fields.level, "refinement_level");
  Vector<float> subdomain (triangulation.n_active_cells ());
  subdomain = triangulation.locally_owned_subdomain ();
  data_out.add_data_vector (subdomain, "rank");
  data_out.build_patches (s.mapping, 2, DataOut<dim>::curved_inner_cells);
  write_files (data_out, s.time, s.communicator);
  ++count.output_index;
  count.next_output_time += parameters.output.field_interval;
}

template <int dim>
double FieldOutput<dim>::check_room (const DataOut<dim> &data_out,
                                     const std::string  &stem,
                                     const double        time,
                                     const MPI_Comm      communicator) const
{
  // room first: a full disk in the middle of the collective HDF5 write leaves the ranks
  // waiting for each other. Estimated: the patch points' coordinates and values, in
  // double for HDF5 and in float for VTU (before its compression), scaled by what the
  // last output took of its estimate, 1.2x, and 64 kB; refused on every rank together
  double values = 0;
  for (const auto &patch : data_out.get_patches ())
    values += (patch.data.n_rows () + dim + 1.0) * patch.data.n_cols ();
  const double bytes_per_value =
      (parameters.output.vtu ? 4.0 : 0.0) + (parameters.output.hdf5 ? 8.0 : 0.0);
  const double estimate = bytes_per_value * Utilities::MPI::sum (values, communicator);
  const double needed =
      1.2 * estimate *
          (last_output_bytes > 0 ? last_output_bytes / last_output_estimate : 1.0) +
      65536.0;
  const double available = free_space (parameters.output.folder, communicator);
  if (available < needed)
    throw std::runtime_error (
        "output/folder: no room for the field output " + stem +
        " at t = " + std::to_string (time) + " in '" + parameters.output.folder +
        "' (needs ~" + std::to_string (needed / 1048576.0) + " MB, " +
        std::to_string (available / 1048576.0) +
        " MB free); the outputs before and the last checkpoint are kept");
  return estimate;
}

template <int dim>
bool FieldOutput<dim>::write_xdmf_index (const DataOut<dim> &data_out,
                                         const XDMFEntry    &entry,
                                         const MPI_Comm      communicator)
{
  const bool        root    = Utilities::MPI::this_mpi_process (communicator) == 0;
  const std::string folder  = parameters.output.folder + "/";
  bool              written = true;
  // the XDMF index of the complete outputs, rewritten (rank 0) beside the old one and
  // renamed over it once whole
  std::vector<XDMFEntry> entries = count.xdmf_entries;
  entries.push_back (entry);
  const std::string index = folder + "fields.xdmf";
  try
  {
    data_out.write_xdmf_file (entries, index + ".partial", communicator);
  }
  catch (const std::exception &)
  {
    written = false;
  }
  if (root && written)
  {
    std::error_code error;
    written = ends_with (index + ".partial", "</Xdmf>\n");
    if (written)
      std::filesystem::rename (index + ".partial", index, error);
    written = written && !error;
  }
  return Utilities::MPI::min (written ? 1 : 0, communicator) == 1;
}

template <int dim>
void FieldOutput<dim>::write_files (const DataOut<dim> &data_out,
                                    const double        time,
                                    const MPI_Comm      communicator)
{
  const bool        root   = Utilities::MPI::this_mpi_process (communicator) == 0;
  const std::string folder = parameters.output.folder + "/";
  const std::string stem   = "fields_" + Utilities::int_to_string (count.output_index, 5);
  // HDF5 prints its error stack itself before deal.II throws: the failure is reported
  // below, in one line
  H5Eset_auto2 (H5E_DEFAULT, nullptr, nullptr);
  const double estimate = check_room (data_out, stem, time, communicator);
  bool         written  = true;
  XDMFEntry    entry;
  std::string  pvtu; // the VTU record
  try
  {
    if (parameters.output.vtu)
    {
      pvtu = data_out.write_vtu_with_pvtu_record (
          folder, "fields", count.output_index, communicator, 5);
    }
    if (parameters.output.hdf5)
    {
      // one file per output, written collectively. Vertices are not merged between
      // patches: the cell fields (beta, mu_s, level, rank) stay piecewise constant
      // instead of being averaged at shared vertices.
      DataOutBase::DataOutFilter filter (DataOutBase::DataOutFilterFlags (false, true));
      data_out.write_filtered_data (filter);
      data_out.write_hdf5_parallel (filter, folder + stem + ".h5", communicator);
      entry = data_out.create_xdmf_entry (filter, stem + ".h5", time, communicator);
    }
  }
  catch (const std::exception &)
  {
    written = false;
  }
  written = Utilities::MPI::min (written ? 1 : 0, communicator) == 1;
  // every piece closed by now: rank 0 reads them
  if (written && parameters.output.vtu)
    written = Utilities::MPI::broadcast (
        communicator,
        root ? complete_vtu (folder, pvtu) &&
                   update_pvd_record (folder, count.output_index, time, pvtu)
             : true,
        0);
  if (written && root)
  {
    // the size of this output, for the room the next one needs
    std::error_code error;
    last_output_bytes = 0;
    for (const auto &file : std::filesystem::directory_iterator (folder, error))
      if (file.path ().filename ().string ().rfind (stem + ".", 0) == 0)
        last_output_bytes += file.file_size (error);
  }
  last_output_bytes    = Utilities::MPI::broadcast (communicator, last_output_bytes, 0);
  last_output_estimate = estimate;
  if (written && parameters.output.hdf5)
  {
    written = write_xdmf_index (data_out, entry, communicator);
    if (written)
      count.xdmf_entries.push_back (entry);
  }
  if (!written)
  {
    // the files of this output go (the outputs before and the checkpoint stay)
    if (root)
    {
      std::error_code error;
      for (const auto &file : std::filesystem::directory_iterator (folder, error))
      {
        const std::string name = file.path ().filename ().string ();
        if (name.rfind (stem + ".", 0) == 0 || name == "fields.xdmf.partial" ||
            name == "fields.pvd.partial")
          std::filesystem::remove (file.path (), error);
      }
    }
    throw std::runtime_error ("output/folder: cannot write the field output " + stem +
                              " at t = " + std::to_string (time) + " into '" +
                              parameters.output.folder +
                              "' (disk full or not writable); the outputs before and "
                              "the last checkpoint are kept");
  }
}

template <int dim>
bool FieldOutput<dim>::due (const double time) const
{
  return parameters.output.field_interval > 0 && time >= count.next_output_time - 1e-12;
}

template class FieldOutput<2>;
template class FieldOutput<3>;
} // namespace wetbed
