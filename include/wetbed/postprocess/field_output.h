#pragma once

#include <wetbed/core/parameters.h>
#include <wetbed/solvers/solver_state.h>

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/timer.h>
#include <deal.II/numerics/data_out.h>

#include <vector>

namespace wetbed
{
/**
 * The field files as a component: u_g, u_s, p', alpha_s, alpha_g, P_s, Theta and the
 * cell means of the closures, as VTU pieces with a PVTU record and/or one parallel HDF5
 * file per output indexed by fields.xdmf (`output/field format`). It reads the state
 * through SolverState and writes only the files and its own counters (the next output
 * time, the output index and the XDMF index), which a checkpoint keeps
 * (source/postprocess/field_output.cc).
 */
template <int dim>
class FieldOutput
{
public:
  /** What a checkpoint saves of the outputs so far. */
  struct Counters
  {
    double                         next_output_time = 0;
    unsigned int                   output_index     = 0;
    std::vector<dealii::XDMFEntry> xdmf_entries; // the HDF5 outputs written so far
  };

  FieldOutput (const Parameters &parameters, dealii::TimerOutput &timer);

  /** Writes the fields of `state` and counts the output; collective. An output that
   * does not fit on the disk (estimated before writing), or a write that fails on any
   * rank, throws std::runtime_error naming output/folder on every rank, with the files
   * of this output removed and fields.xdmf as before. */
  void write (const SolverState<dim> &state);

  /** Whether an output is due at `time` (every `output/field interval` > 0 s). */
  bool due (double time) const;

  const Counters &counters () const { return count; }
  /** The counters of a resumed run, from its checkpoint. */
  void restore (const Counters &saved) { count = saved; }

private:
  /** The files of one output (VTU pieces and record, HDF5 and the XDMF index), each
   * checked complete. */
  void write_files (const dealii::DataOut<dim> &data_out, double time, MPI_Comm comm);
  /** Room for one output of `data_out` in the output folder, estimated from its patches
   * and what the last output took (an error naming output/folder where it lacks);
   * returns the estimate. */
  double check_room (const dealii::DataOut<dim> &data_out,
                     const std::string          &stem,
                     double                      time,
                     MPI_Comm                    comm) const;
  /** The XDMF index of the complete outputs and `entry`, rewritten beside the old one
   * and renamed over it once whole; false where that failed (collective). */
  bool write_xdmf_index (const dealii::DataOut<dim> &data_out,
                         const dealii::XDMFEntry    &entry,
                         MPI_Comm                    comm);

  const Parameters    &parameters;
  dealii::TimerOutput &timer;
  Counters             count;
  // the bytes of the files of the last output and what write_files estimated for them
  double last_output_bytes = 0, last_output_estimate = 1;
};
} // namespace wetbed
