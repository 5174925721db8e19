#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace wetbed
{
/** The one-sided power spectral density of a signal (Welch's method). */
struct Spectrum
{
  std::vector<double> frequency;              // Hz
  std::vector<double> power;                  // signal units^2 / Hz
  double              dominant_frequency = 0; // of the largest peak (f > 0), interpolated
  double              sampling_interval  = 0; // of the uniform resampling (s)
  unsigned int        segment_length     = 0; // samples per Welch segment
  unsigned int        segments           = 0;
};

/**
 * Welch spectrum of the samples y(t) from `start_time` on: linear resampling onto a
 * uniform grid (spacing: the median interval of the samples, since the time step
 * varies), mean removed, `segments` Hann-windowed segments with 50% overlap transformed
 * by FFTW, periodograms averaged. The dominant frequency is refined by a parabola
 * through the logarithm of the peak and its neighbours. Throws std::invalid_argument if
 * fewer than 16 samples lie after start_time.
 */
Spectrum welch_spectrum (const std::vector<double> &t,
                         const std::vector<double> &y,
                         double                     start_time,
                         unsigned int               segments);

/** A CSV file with a header line, as named columns of numbers (the text column run,
 * the run's id, reads as NaN). */
struct CsvTable
{
  std::vector<std::string>         names;
  std::vector<std::vector<double>> columns;
  /** The column called `name`; throws std::invalid_argument if there is none. */
  const std::vector<double> &column (const std::string &name) const;
};
CsvTable read_csv (const std::string &filename);

/**
 * The spectra of the columns of a monitors.csv (pressure_drop, probe_pressure_drop
 * and every alpha_s_plane_* column unless `columns` names others), written as CSV:
 * comment lines
 * `# <column>: dominant frequency <f> Hz`, then frequency and one PSD column each.
 * Returns the dominant frequencies.
 */
std::vector<double> write_monitor_spectra (const std::string       &monitors_file,
                                           std::vector<std::string> columns,
                                           double                   start_time,
                                           unsigned int             segments,
                                           std::ostream            &out);
} // namespace wetbed
