#include <wetbed/postprocess/spectrum.h>

#include <fftw3.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace wetbed
{
Spectrum welch_spectrum (const std::vector<double> &t,
                         const std::vector<double> &y,
                         const double               start_time,
                         const unsigned int         segments)
{
  if (t.size () != y.size ())
    throw std::invalid_argument ("spectrum: times and values differ in length");
  if (segments < 1)
    throw std::invalid_argument ("spectrum: segments must be >= 1");
  std::vector<double> ts, ys;
  for (std::size_t i = 0; i < t.size (); ++i)
    if (t[i] >= start_time && (ts.empty () || t[i] > ts.back ()))
    {
      ts.push_back (t[i]);
      ys.push_back (y[i]);
    }
  if (ts.size () < 16)
    throw std::invalid_argument ("spectrum: fewer than 16 samples after t = " +
                                 std::to_string (start_time) + " s");

  Spectrum            s;
  std::vector<double> intervals (ts.size () - 1);
  for (std::size_t i = 0; i + 1 < ts.size (); ++i)
    intervals[i] = ts[i + 1] - ts[i];
  std::nth_element (
      intervals.begin (), intervals.begin () + intervals.size () / 2, intervals.end ());
  s.sampling_interval = intervals[intervals.size () / 2];

  // uniform resampling by linear interpolation, mean removed
  const std::size_t n =
      static_cast<std::size_t> ((ts.back () - ts.front ()) / s.sampling_interval) + 1;
  std::vector<double> uniform (n);
  std::size_t         k = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const double ti = ts.front () + i * s.sampling_interval;
    while (k + 2 < ts.size () && ts[k + 1] < ti)
      ++k;
    const double w = std::clamp ((ti - ts[k]) / (ts[k + 1] - ts[k]), 0.0, 1.0);
    uniform[i]     = (1 - w) * ys[k] + w * ys[k + 1];
  }
  double mean = 0;
  for (const double v : uniform)
    mean += v / n;
  for (double &v : uniform)
    v -= mean;

  // Welch: K segments of length L overlapping by L/2 cover (K + 1) L / 2 samples
  s.segments            = std::min<unsigned int> (segments, n / 8);
  s.segments            = std::max (s.segments, 1u);
  s.segment_length      = static_cast<unsigned int> (2 * n / (s.segments + 1));
  const unsigned int  L = s.segment_length, half = L / 2;
  std::vector<double> window (L);
  double              window_power = 0;
  for (unsigned int i = 0; i < L; ++i)
  {
    window[i] = 0.5 * (1 - std::cos (2 * M_PI * i / L));
    window_power += window[i] * window[i];
  }
  double       *in   = fftw_alloc_real (L);
  fftw_complex *out  = fftw_alloc_complex (L / 2 + 1);
  fftw_plan     plan = fftw_plan_dft_r2c_1d (L, in, out, FFTW_ESTIMATE);
  s.power.assign (L / 2 + 1, 0.0);
  for (unsigned int seg = 0; seg < s.segments; ++seg)
  {
    for (unsigned int i = 0; i < L; ++i)
      in[i] = window[i] * uniform[seg * half + i];
    fftw_execute (plan);
    for (unsigned int j = 0; j <= L / 2; ++j)
    {
      // one-sided density: doubled except at 0 and the Nyquist frequency
      const double scale = (j == 0 || 2 * j == L) ? 1.0 : 2.0;
      s.power[j] += scale * (out[j][0] * out[j][0] + out[j][1] * out[j][1]) *
                    s.sampling_interval / window_power / s.segments;
    }
  }
  fftw_destroy_plan (plan);
  fftw_free (in);
  fftw_free (out);

  s.frequency.resize (L / 2 + 1);
  for (unsigned int j = 0; j <= L / 2; ++j)
    s.frequency[j] = j / (L * s.sampling_interval);
  const auto peak = static_cast<unsigned int> (
      std::max_element (s.power.begin () + 1, s.power.end ()) - s.power.begin ());
  double shift = 0;
  if (peak + 1 < s.power.size () && s.power[peak - 1] > 0 && s.power[peak + 1] > 0)
  {
    const double a = std::log (s.power[peak - 1]), b = std::log (s.power[peak]),
                 c = std::log (s.power[peak + 1]);
    if (a - 2 * b + c < 0)
      shift = 0.5 * (a - c) / (a - 2 * b + c);
  }
  s.dominant_frequency = (peak + shift) / (L * s.sampling_interval);
  return s;
}

const std::vector<double> &CsvTable::column (const std::string &name) const
{
  const auto it = std::find (names.begin (), names.end (), name);
  if (it == names.end ())
    throw std::invalid_argument ("no column '" + name + "'");
  return columns[it - names.begin ()];
}

namespace
{
/// A number of a CSV cell. Unlike std::stod this accepts subnormal values (a monitor
/// that balances to zero can print as 1e-320): strtod then reports an underflow but
/// returns the value itself.
double parse_number (const std::string &item)
{
  const char *begin      = item.c_str ();
  char       *end        = nullptr;
  errno                  = 0;
  const double value     = std::strtod (begin, &end);
  const bool   underflow = errno == ERANGE && std::abs (value) <= 1.0;
  if (end == begin || *end != '\0' || (errno == ERANGE && !underflow))
    throw std::invalid_argument (item);
  return value;
}
} // namespace

CsvTable read_csv (const std::string &filename)
{
  std::ifstream in (filename);
  if (!in)
    throw std::invalid_argument ("cannot read '" + filename + "'");
  CsvTable    table;
  std::string line, item;
  if (!std::getline (in, line))
    throw std::invalid_argument ("'" + filename + "' is empty");
  std::istringstream header (line);
  while (std::getline (header, item, ','))
    table.names.push_back (item);
  table.columns.resize (table.names.size ());
  unsigned int row = 1;
  while (std::getline (in, line))
  {
    ++row;
    if (line.empty ())
      continue;
    std::istringstream values (line);
    for (unsigned int c = 0; c < table.names.size (); ++c)
    {
      if (!std::getline (values, item, ','))
        throw std::invalid_argument ("'" + filename + "' line " + std::to_string (row) +
                                     " has fewer columns than its header");
      if (table.names[c] == "run") // the run's id: text
      {
        table.columns[c].push_back (std::nan (""));
        continue;
      }
      try
      {
        table.columns[c].push_back (item.empty () ? std::nan ("") : parse_number (item));
      }
      catch (const std::invalid_argument &)
      {
        throw std::invalid_argument ("'" + filename + "' line " + std::to_string (row) +
                                     ": '" + item + "' is not a number");
      }
    }
  }
  return table;
}

std::vector<double> write_monitor_spectra (const std::string       &monitors_file,
                                           std::vector<std::string> columns,
                                           const double             start_time,
                                           const unsigned int       segments,
                                           std::ostream            &out)
{
  const CsvTable table = read_csv (monitors_file);
  if (columns.empty ())
    for (const auto &name : table.names)
      if (name == "pressure_drop" || name == "probe_pressure_drop" ||
          name.rfind ("alpha_s_plane_", 0) == 0)
        columns.push_back (name);
  // the used samples finite: a NaN or inf would make every frequency NaN
  const auto &time = table.column ("time");
  for (const auto &name : columns)
  {
    const auto &values = table.column (name);
    for (std::size_t i = 0; i < time.size (); ++i)
      if (!std::isfinite (time[i]) ||
          (time[i] >= start_time && !std::isfinite (values[i])))
      {
        const bool         bad_time = !std::isfinite (time[i]);
        std::ostringstream value;
        value << (bad_time ? time[i] : values[i]);
        throw std::invalid_argument (
            "'" + monitors_file + "' data row " + std::to_string (i + 1) + ": column '" +
            (bad_time ? std::string ("time") : name) + "' is " + value.str () +
            " (not finite; the spectrum needs finite samples)");
      }
  }
  std::vector<Spectrum> spectra;
  std::vector<double>   dominant;
  for (const auto &name : columns)
  {
    spectra.push_back (welch_spectrum (
        table.column ("time"), table.column (name), start_time, segments));
    dominant.push_back (spectra.back ().dominant_frequency);
    out << "# " << name << ": dominant frequency " << std::setprecision (6)
        << dominant.back () << " Hz (Welch: " << spectra.back ().segments
        << " segments of " << spectra.back ().segment_length << " samples at "
        << spectra.back ().sampling_interval << " s, from t = " << start_time << " s)\n";
  }
  out << "frequency";
  for (const auto &name : columns)
    out << ",psd_" << name;
  out << '\n';
  for (std::size_t j = 0; !spectra.empty () && j < spectra[0].frequency.size (); ++j)
  {
    out << std::setprecision (10) << spectra[0].frequency[j];
    for (const auto &s : spectra)
      out << ',' << s.power[j];
    out << '\n';
  }
  return dominant;
}
} // namespace wetbed
