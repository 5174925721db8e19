#pragma once

#include <wetbed/solvers/solver_state.h>

namespace wetbed
{
/** The gas mass flows through the inlets and the outlets (kg/s; kg/s per metre depth in
 * 2D): rho_g times the integral of alpha_g u_g . n, into the domain on the inlets, out
 * of it on the outlets (source/postprocess/gas_flows.cc); collective. */
struct GasFlows
{
  double inflow  = 0;
  double outflow = 0;
};

template <int dim>
GasFlows evaluate_gas_flows (const SolverState<dim> &state);
} // namespace wetbed
