// Welch spectra (FFTW): a sinusoid sampled at a varying time step gives its frequency,
// the integral of the density gives the variance (Parseval), and the spectrum of a
// synthetic monitors.csv names its dominant frequencies.
#include "test_utilities.h"

#include <wetbed/postprocess/spectrum.h>

#include <fstream>
#include <random>
#include <sstream>

using namespace wetbed;
using wetbed::testing::check;
using wetbed::testing::check_close;

int main ()
{
  // samples at a step varying between 0.8 and 1.2 ms over 6 s; 2 + 0.3 sin(2 pi 7.3 t)
  // + 0.1 sin(2 pi 21 t + 1) + noise
  std::mt19937                           random (7);
  std::uniform_real_distribution<double> step (0.8e-3, 1.2e-3), noise (-0.02, 0.02);
  std::vector<double>                    t, y, z;
  for (double time = 0; time < 6; time += step (random))
  {
    t.push_back (time);
    y.push_back (2 + 0.3 * std::sin (2 * M_PI * 7.3 * time) +
                 0.1 * std::sin (2 * M_PI * 21 * time + 1) + noise (random));
    z.push_back (std::cos (2 * M_PI * 1.7 * time));
  }
  const Spectrum s          = welch_spectrum (t, y, 1.0, 4);
  const double   resolution = 1 / (s.segment_length * s.sampling_interval);
  std::cout << "dominant " << s.dominant_frequency << " Hz (exact 7.3), resolution "
            << resolution << " Hz, " << s.segments << " segments of " << s.segment_length
            << " samples at " << s.sampling_interval << " s" << std::endl;
  check (std::abs (s.dominant_frequency - 7.3) < 0.1 * resolution,
         "sinusoid: dominant frequency within a tenth of the resolution");
  // Parseval: the density integrates to the variance 0.3^2/2 + 0.1^2/2 + 0.02^2/3
  double integral = 0;
  for (std::size_t j = 0; j < s.power.size (); ++j)
    integral += s.power[j] * resolution;
  check_close (
      integral, 0.045 + 0.005 + 0.0004 / 3, 0.05, "Parseval: integral of the PSD");
  // the second peak is 9x weaker in power
  double p21 = 0;
  for (std::size_t j = 0; j < s.power.size (); ++j)
    if (std::abs (s.frequency[j] - 21) < 1.5 * resolution)
      p21 = std::max (p21, s.power[j]);
  double p7 = *std::max_element (s.power.begin (), s.power.end ());
  check (p7 / p21 > 5 && p7 / p21 < 15, "power ratio of the two tones ~9");

  // the same through a monitors.csv with a pressure_drop and a plane column
  const std::string file = "spectrum_monitors.csv";
  {
    std::ofstream out (file);
    // a support share that is exactly balanced prints as a subnormal number
    out << "step,time,pressure_drop,alpha_s_plane_0.076,wall_support_gas\n";
    for (std::size_t i = 0; i < t.size (); ++i)
      out << i << ',' << std::setprecision (12) << t[i] << ',' << y[i] << ',' << z[i]
          << ',' << (i == 3 ? "-4.39372578846621e-320" : "0") << '\n';
  }
  const CsvTable read = read_csv (file);
  check (read.columns.size () == 5 && read.columns[4].size () == t.size () &&
             read.columns[4][3] < 0 && read.columns[4][3] > -1e-300,
         "a subnormal value is read as the number it is");
  std::ostringstream table;
  const auto         dominant = write_monitor_spectra (file, {}, 1.0, 4, table);
  check (dominant.size () == 2, "two monitor columns analysed");
  if (dominant.size () == 2)
  {
    std::cout << "monitors: pressure_drop " << dominant[0] << " Hz, plane " << dominant[1]
              << " Hz" << std::endl;
    check (std::abs (dominant[0] - 7.3) < 0.1 * resolution,
           "monitors: pressure drop 7.3 Hz");
    check (std::abs (dominant[1] - 1.7) < 0.1 * resolution, "monitors: plane 1.7 Hz");
  }
  check (table.str ().find ("# alpha_s_plane_0.076: dominant frequency") !=
             std::string::npos,
         "monitors: comment line names the column");
  bool threw = false;
  try
  {
    welch_spectrum (t, y, 5.999, 4);
  }
  catch (const std::invalid_argument &)
  {
    threw = true;
  }
  check (threw, "too few samples: an error, not a spectrum");
  return wetbed::testing::finish ("spectrum");
}
