#include <wetbed/postprocess/cross_section_sampler.h>
#include <wetbed/postprocess/csv_append.h>
#include <wetbed/postprocess/profiles.h>
#include <wetbed/postprocess/time_averages.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <limits>
#include <sstream>

namespace wetbed
{
using namespace dealii;

template <int dim>
struct Profiles<dim>::Profile
{
  Kind              kind;
  double            height = 0;
  SampleLine        line;
  std::string       file;        // relative to the output folder
  unsigned int      bins    = 0; // rows per time; each the mean of `per_bin` points
  unsigned int      per_bin = 1;
  FieldSampler<dim> sampler;
  std::ofstream     out;
};

namespace
{
const char *axis_name (const unsigned int axis)
{
  static const char *names[] = {"x", "y", "z"};
  return names[axis];
}

std::string height_label (const double height)
{
  std::ostringstream label;
  label << height << 'm';
  return label.str ();
}

/** The axis of the radial profiles: the centre of the horizontal bounding box. */
template <int dim>
Point<dim> column_axis (const HorizontalFrame<dim> &frame)
{
  Point<dim> centre;
  for (const unsigned int a : frame.across)
    centre[a] = (frame.lower[a] + frame.upper[a]) / 2;
  return centre;
}

/** The radius of the column: the largest horizontal distance of a vertex from the axis
 * (the wall's vertices lie on the cylinder, whatever their azimuths); collective. */
template <int dim>
double column_radius (const SolverState<dim> &s, const HorizontalFrame<dim> &frame)
{
  const Point<dim> centre = column_axis (frame);
  double           radius = 0;
  for (const auto &cell : s.triangulation.active_cell_iterators ())
    if (cell->is_locally_owned ())
      for (const unsigned int v : cell->vertex_indices ())
      {
        Tensor<1, dim> horizontal  = cell->vertex (v) - centre;
        horizontal[frame.vertical] = 0;
        radius                     = std::max (radius, horizontal.norm ());
      }
  return Utilities::MPI::max (radius, s.communicator);
}

/** The fractional position of bin or point `k` of `n` (their centres). */
double centre_of (const unsigned int k, const unsigned int n)
{
  return (k + 0.5) / n;
}
/** The rows' directions of the velocity components: radial, azimuthal and axial at
 * `point` for a radial profile (`radial`), else the Cartesian axes. */
template <int dim>
Tensor<2, dim> velocity_basis (const bool                  radial_profile,
                               const Point<dim>           &point,
                               const HorizontalFrame<dim> &frame)
{
  Tensor<2, dim> basis;
  if (radial_profile)
  {
    Tensor<1, dim> radial  = point - column_axis (frame);
    radial[frame.vertical] = 0;
    radial /= radial.norm ();
    basis[0] = radial;
    if (dim == 3)
    {
      basis[1][frame.across[0]]             = -radial[frame.across[1 % (dim - 1)]];
      basis[1][frame.across[1 % (dim - 1)]] = radial[frame.across[0]];
    }
    basis[dim - 1][frame.vertical] = frame.up;
  }
  else
    for (unsigned int d = 0; d < dim; ++d)
      basis[d][d] = 1;
  return basis;
}
} // namespace

/** The position columns of a bin whose first point is `first` (`start`: the profile's
 * first point): the radius, the lateral coordinate, or the distance along the line and
 * the coordinates. */
template <int dim>
void Profiles<dim>::write_position (std::ostream               &out,
                                    const Kind                  kind,
                                    const Point<dim>           &first,
                                    const Point<dim>           &start,
                                    const HorizontalFrame<dim> &frame)
{
  switch (kind)
  {
  case Kind::radial:
  {
    Tensor<1, dim> radial  = first - column_axis (frame);
    radial[frame.vertical] = 0;
    out << ',' << radial.norm ();
    break;
  }
  case Kind::lateral:
    out << ',' << first[frame.across[0]];
    break;
  case Kind::line:
    out << ',' << first.distance (start);
    [[fallthrough]];
  case Kind::plane:
    for (unsigned int d = 0; d < dim; ++d)
      out << ',' << first[d];
  }
}

template <int dim>
Profiles<dim>::Profiles (const StatisticsParameters &parameters)
    : parameters (parameters),
      root (Utilities::MPI::this_mpi_process (MPI_COMM_WORLD) == 0), last_time (-1)
{
  const unsigned int n = parameters.profile_points, m = parameters.averaging_points;
  const auto         add = [&] (const Kind                          kind,
                        const double                        height,
                        const SampleLine                   &line,
                        const std::string                  &file,
                        const unsigned int                  bins,
                        const unsigned int                  per_bin,
                        typename FieldSampler<dim>::Locator where)
  {
    profiles.push_back (std::unique_ptr<Profile> (new Profile{
        kind, height, line, file, bins, per_bin, FieldSampler<dim> (where), {}}));
  };
  for (const double h : parameters.radial_profile_heights)
    add (Kind::radial,
         h,
         {},
         "statistics/radial_at_" + height_label (h) + ".csv",
         n,
         m,
         [h, n, m] (const SolverState<dim> &s)
         {
           const HorizontalFrame<dim> frame  = horizontal_frame (s);
           const Point<dim>           centre = column_axis (frame);
           const double               radius = column_radius (s, frame);
           std::vector<Point<dim>>    where;
           for (unsigned int i = 0; i < n; ++i)
             for (unsigned int j = 0; j < m; ++j)
             {
               const double r   = centre_of (i, n) * radius,
                            phi = 2 * numbers::PI * centre_of (j, m);
               std::vector<double> horizontal (dim - 1);
               horizontal[0] = centre[frame.across[0]] + r * std::cos (phi);
               if (dim == 3)
                 horizontal[dim - 2] = centre[frame.across[dim - 2]] + r * std::sin (phi);
               where.push_back (frame.at (h, horizontal));
             }
           return where;
         });
  for (const double h : parameters.lateral_profile_heights)
    add (Kind::lateral,
         h,
         {},
         "statistics/lateral_at_" + height_label (h) + ".csv",
         n,
         dim == 3 ? m : 1,
         [h, n, m] (const SolverState<dim> &s)
         {
           const HorizontalFrame<dim> frame  = horizontal_frame (s);
           const unsigned int         depths = dim == 3 ? m : 1;
           std::vector<Point<dim>>    where;
           for (unsigned int i = 0; i < n; ++i)
             for (unsigned int k = 0; k < depths; ++k)
             {
               std::vector<double> horizontal (dim - 1);
               for (unsigned int a = 0; a < dim - 1; ++a)
               {
                 const unsigned int axis = frame.across[a];
                 horizontal[a]           = frame.lower[axis] +
                                 (frame.upper[axis] - frame.lower[axis]) *
                                     centre_of (a == 0 ? i : k, a == 0 ? n : depths);
               }
               where.push_back (frame.at (h, horizontal));
             }
           return where;
         });
  const unsigned int resolution = parameters.plane_resolution;
  for (const double h : parameters.plane_heights)
    add (Kind::plane,
         h,
         {},
         "statistics/plane_at_" + height_label (h) + ".csv",
         dim == 3 ? resolution * resolution : resolution,
         1,
         [h, resolution] (const SolverState<dim> &s)
         { return cross_section_points (horizontal_frame (s), {h}, resolution); });
  for (const SampleLine &line : parameters.lines)
    add (Kind::line,
         0,
         line,
         "statistics/line_" + line.name + ".csv",
         line.points,
         1,
         [line] (const SolverState<dim> &)
         {
           std::vector<Point<dim>> where;
           for (unsigned int k = 0; k < line.points; ++k)
           {
             Point<dim>   p;
             const double f = static_cast<double> (k) / (line.points - 1);
             for (unsigned int d = 0; d < dim; ++d)
               p[d] = (1 - f) * line.from[d] + f * line.to[d];
             where.push_back (p);
           }
           return where;
         });
}

template <int dim>
Profiles<dim>::~Profiles () = default;

template <int dim>
std::string Profiles<dim>::header (const Profile &profile) const
{
  const bool         averaged = parameters.time_averages;
  const std::string  mean     = averaged ? "_mean" : "";
  std::ostringstream h;
  h << "time";
  switch (profile.kind)
  {
  case Kind::radial:
    h << ",r";
    break;
  case Kind::lateral:
    h << ",position";
    break;
  case Kind::line:
    h << ",s";
    [[fallthrough]];
  case Kind::plane:
    for (unsigned int d = 0; d < dim; ++d)
      h << ',' << axis_name (d);
  }
  h << ",alpha_s" << mean << (averaged ? ",alpha_s_std" : "") << ",theta" << mean << ",p"
    << mean << (averaged ? ",p_std" : "");
  for (const char *phase : {"u_g", "u_s"})
    for (unsigned int d = 0; d < dim; ++d)
      h << ',' << phase << '_'
        << (profile.kind == Kind::radial
                ? std::vector<std::string>{"r", "theta", "axial"}[d]
                : std::string (axis_name (d)))
        << mean;
  if (averaged)
    for (const char *phase : {"u_g", "u_s"})
    {
      if (profile.kind == Kind::radial)
        h << ',' << phase << "_axial_std";
      else
        for (unsigned int d = 0; d < dim; ++d)
          h << ',' << phase << '_' << axis_name (d) << "_std";
    }
  h << '\n';
  return h.str ();
}

template <int dim>
std::string Profiles<dim>::rows (Profile &profile, const SolverState<dim> &s) const
{
  using FlowValue = typename FieldSampler<dim>::FlowValue;
  const TimeAverages<dim> *averages =
      parameters.time_averages ? s.time_averages : nullptr;
  const double                   weight  = averages ? averages->weight (s.time) : 0;
  FieldSampler<dim>             &sampler = profile.sampler;
  const std::vector<Point<dim>> &points  = sampler.points (s);
  const std::vector<double>      alpha =
      sampler.scalar (s, averages ? averages->alpha_average () : s.alpha);
  const std::vector<double> theta =
      sampler.scalar (s, averages ? averages->theta_average () : s.theta);
  const std::vector<FlowValue> flow =
      sampler.flow (s, averages ? averages->flow_average () : s.flow_solution);
  std::vector<double>    alpha_m2;
  std::vector<FlowValue> flow_m2;
  if (averages)
  {
    alpha_m2 = sampler.scalar (s, averages->alpha_squared_deviations ());
    flow_m2  = sampler.flow (s, averages->flow_squared_deviations ());
  }
  const HorizontalFrame<dim> frame = horizontal_frame (s);
  if (!root)
    return "";

  // each point's values in the columns' order, deviations as variances
  const auto at_point = [&] (const unsigned int i)
  {
    std::vector<double> v{alpha[i]};
    if (averages)
      v.push_back (alpha_m2[i] / weight);
    v.push_back (theta[i]);
    v.push_back (flow[i][2 * dim]);
    if (averages)
      v.push_back (flow_m2[i][2 * dim] / weight);
    const Tensor<2, dim> basis =
        velocity_basis (profile.kind == Kind::radial, points[i], frame);
    for (const unsigned int phase : {0u, 1u})
      for (unsigned int d = 0; d < dim; ++d)
      {
        double component = 0;
        for (unsigned int e = 0; e < dim; ++e)
          component += basis[d][e] * flow[i][phase * dim + e];
        v.push_back (component);
      }
    if (averages)
      for (const unsigned int phase : {0u, 1u})
        for (unsigned int d = 0; d < dim; ++d)
          if (profile.kind != Kind::radial || d == dim - 1)
            v.push_back (flow_m2[i][phase * dim +
                                    (profile.kind == Kind::radial ? frame.vertical : d)] /
                         weight);
    return v;
  };

  std::ostringstream out;
  out << std::setprecision (12);
  for (unsigned int b = 0; b < profile.bins; ++b)
  {
    // the mean over the bin's points inside the domain
    std::vector<double> sum;
    unsigned int        found = 0;
    for (unsigned int k = 0; k < profile.per_bin; ++k)
    {
      const unsigned int        i = b * profile.per_bin + k;
      const std::vector<double> v = at_point (i);
      if (sum.empty ())
        sum.assign (v.size (), 0.0);
      if (std::isnan (v[0]))
        continue;
      for (unsigned int c = 0; c < v.size (); ++c)
        sum[c] += v[c];
      ++found;
    }
    for (double &x : sum)
      x = found > 0 ? x / found : std::numeric_limits<double>::quiet_NaN ();
    // the deviations as standard deviations
    if (averages)
    {
      sum[1] = std::sqrt (std::max (sum[1], 0.0));
      sum[4] = std::sqrt (std::max (sum[4], 0.0));
      for (unsigned int c = 5 + 2 * dim; c < sum.size (); ++c)
        sum[c] = std::sqrt (std::max (sum[c], 0.0));
    }
    out << std::setprecision (12) << s.time;
    write_position (out, profile.kind, points[b * profile.per_bin], points[0], frame);
    for (const double x : sum)
      out << ',' << x;
    out << '\n';
  }
  return out.str ();
}

template <int dim>
void Profiles<dim>::open (const std::string &folder)
{
  if (!root)
    return;
  // a new run (the folder's earlier results are being replaced): no earlier profile
  // stays beside this run's
  std::error_code ignored;
  std::filesystem::remove_all (folder + "/statistics", ignored);
  std::filesystem::create_directories (folder + "/statistics");
  for (auto &profile : profiles)
  {
    profile->out.open (folder + "/" + profile->file, std::ios::trunc);
    profile->out << header (*profile) << std::flush;
  }
}

template <int dim>
void Profiles<dim>::reopen (
    const std::string                                             &folder,
    const std::vector<std::pair<std::string, unsigned long long>> &appended)
{
  if (!root)
    return;
  std::filesystem::create_directories (folder + "/statistics");
  for (auto &profile : profiles)
  {
    bool continued = false;
    for (const auto &[name, bytes] : appended)
      if (name == profile->file)
      {
        continue_csv (profile->out, folder + "/" + name, bytes);
        continued = true;
      }
    if (!continued)
    {
      profile->out.open (folder + "/" + profile->file, std::ios::trunc);
      profile->out << header (*profile) << std::flush;
    }
  }
}

template <int dim>
void Profiles<dim>::write (const SolverState<dim> &s)
{
  if (s.time == last_time ||
      (parameters.time_averages &&
       (!s.time_averages || s.time_averages->weight (s.time) <= 0)))
    return;
  last_time = s.time;
  for (auto &profile : profiles)
  {
    const std::string text = rows (*profile, s);
    if (root)
      profile->out << text << std::flush;
  }
}

template <int dim>
std::vector<std::pair<std::string, unsigned long long>> Profiles<dim>::file_lengths ()
{
  std::vector<std::pair<std::string, unsigned long long>> lengths;
  for (auto &profile : profiles)
    lengths.emplace_back (profile->file,
                          root && profile->out.is_open ()
                              ? static_cast<unsigned long long> (profile->out.tellp ())
                              : 0ull);
  return lengths;
}

template <int dim>
bool Profiles<dim>::writing_failed () const
{
  if (!root)
    return false;
  for (const auto &profile : profiles)
    if (profile->out.is_open () && !profile->out)
      return true;
  return false;
}

template class Profiles<2>;
template class Profiles<3>;
} // namespace wetbed
