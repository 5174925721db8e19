#include <wetbed/solvers/solve_history.h>

#include <algorithm>
#include <sstream>

namespace wetbed
{
void SolveHistory::clear ()
{
  attempts.clear ();
  outer_iteration = 0;
}

void SolveHistory::begin_attempt (const double dt, const unsigned int bdf_order)
{
  attempts.push_back ({dt, bdf_order, {}, ""});
  outer_iteration = 0;
}

void SolveHistory::set_outer_iteration (const unsigned int k)
{
  outer_iteration = k;
}

void SolveHistory::record (const std::string           &solver,
                           const dealii::SolverControl &control,
                           const bool                   converged)
{
  if (attempts.empty ())
    begin_attempt (0.0, 0);
  std::vector<double> residuals = control.get_history_data ();
  if (residuals.empty ())
    residuals.push_back (control.last_value ());
  attempts.back ().solves.push_back ({solver,
                                      outer_iteration,
                                      control.last_step (),
                                      control.tolerance (),
                                      converged,
                                      std::move (residuals)});
}

void SolveHistory::reject (const std::string &reason)
{
  if (!attempts.empty ())
    attempts.back ().rejection = reason;
}

std::string SolveHistory::describe () const
{
  std::ostringstream out;
  out.precision (3);
  out << "residual history of the attempts at this step (" << attempts.size () << "):\n";
  for (unsigned int a = 0; a < attempts.size (); ++a)
  {
    const Attempt &attempt = attempts[a];
    out << "  attempt " << a + 1 << ": dt " << attempt.dt << " s, BDF"
        << attempt.bdf_order << "\n";
    for (const Solve &solve : attempt.solves)
    {
      out << "    outer " << solve.outer_iteration + 1 << ", " << solve.solver << ": "
          << solve.iterations << " iterations, residual " << solve.residuals.front ()
          << " -> " << solve.residuals.back () << " (target " << solve.target << ")"
          << (solve.converged ? "" : " FAILED") << "\n";
      if (!solve.converged && solve.residuals.size () > 2)
      {
        // about a dozen samples, the last one included
        const std::size_t n      = solve.residuals.size ();
        const std::size_t stride = std::max<std::size_t> (1, (n + 11) / 12);
        out << "      residual every " << stride << " iterations:";
        for (std::size_t i = 0; i < n; i += stride)
          out << " " << solve.residuals[i];
        if ((n - 1) % stride != 0)
          out << " " << solve.residuals.back ();
        out << "\n";
      }
    }
    if (!attempt.rejection.empty ())
      out << "    rejected: " << attempt.rejection << "\n";
  }
  return out.str ();
}
} // namespace wetbed
