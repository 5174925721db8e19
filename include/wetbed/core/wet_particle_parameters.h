#pragma once

#include <wetbed/closures/wet/liquid_bridge.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace wetbed
{
/** `subsection wet particles`: the liquid and the wet-collision laws (seed 000 s3). The
 * wet closures are on only with a positive liquid loading. */
struct WetParticleParameters
{
  closures::LiquidBridgeProperties liquid;
  std::string                      rupture_distance;            // h_c law
  std::string                      restitution;                 // e_wet law
  bool                             pressure_in_solids_pressure; // P_wet added to P_s

  bool enabled () const { return liquid.liquid_loading > 0; }

  static void declare_parameters (dealii::ParameterHandler &prm);
  /** The wet closures need the kinetic theory (Theta) and, for now, its PDE model. */
  void parse_parameters (dealii::ParameterHandler &prm,
                         bool                      kinetic_theory,
                         bool                      algebraic_temperature);
};
} // namespace wetbed
