#include <wetbed/closures/wet/rupture_distance.h>
#include <wetbed/closures/wet/wet_restitution.h>
#include <wetbed/core/input_error.h>
#include <wetbed/core/wet_particle_parameters.h>

#include <cmath>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void WetParticleParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("wet particles");
  prm.declare_entry ("liquid loading",
                     "0",
                     Double (0),
                     "delta = M_L/M_s (liquid mass per solids mass). 0: a dry bed, no "
                     "wet closure is evaluated.");
  prm.declare_entry (
      "liquid viscosity", "0.4945", Double (), "mu_L (Pa s); default silicone oil.");
  prm.declare_entry ("liquid density", "969", Double (), "rho_L (kg/m^3).");
  prm.declare_entry (
      "contact angle", "0.175", Double (), "gamma_c (rad) in the rupture distance.");
  prm.declare_entry (
      "surface tension",
      "0.021",
      Double (),
      "sigma (N/m), in the capillary number of the Pitois rupture distance.");
  prm.declare_entry ("asperity height", "2.8e-6", Double (), "h_a (m).");
  prm.declare_entry ("approach velocity factor",
                     "1.5",
                     Double (),
                     "c_u in u_dot = c_u sqrt(pi Theta). 3/2 makes seed 000 Eq. 5 follow "
                     "from its Eqs. 2-4 (its Eq. 3 prints 2/3).");
  prm.declare_entry ("angle of stability",
                     "30",
                     Double (),
                     "phi' (degrees) in mu_wet = sqrt(2) P_wet sin(phi')/|gamma_dot|.");
  prm.declare_entry (
      "rupture distance",
      "Lian",
      Selection (closures::rupture_distance_names ()),
      "Liquid-bridge rupture distance h_c: " + closures::rupture_distance_names () + ".");
  prm.declare_entry ("restitution",
                     "bridge-gated",
                     Selection (closures::wet_restitution_names ()),
                     "Wet restitution e_wet (collisional dissipation only): "
                     "bridge-gated (seed 000 Eq. 11, liquid only where h_a < h <= h_c), "
                     "literal (Eq. 11 as printed: e = 0 for St <= St* at any h > h_a), "
                     "Gollwitzer (seed 003 Eq. 26, a film of the film thickness).");
  prm.declare_entry ("film thickness",
                     "0.1",
                     Double (),
                     "delta_f/d, the liquid film of the Gollwitzer restitution.");
  prm.declare_entry ("switch width",
                     "0.05",
                     Double (0),
                     "Relative width of the smoothed switches (gap window h_a < h <= "
                     "h_c, St > St* of the literal law); 0: sharp.");
  prm.declare_entry ("strain rate regularisation",
                     "1e-3",
                     Double (),
                     "eps (1/s) in |gamma_dot| = 2 sqrt(I_2D + eps^2) of mu_wet.");
  prm.declare_entry ("maximum wet viscosity", "1000", Double (), "Cap of mu_wet (Pa s).");
  prm.declare_entry (
      "lubrication stress",
      "approach and separation",
      Selection ("approach and separation|approach only"),
      "Where the liquid-bridge stress (P_wet and mu_wet) acts. approach and "
      "separation: everywhere, as seed 000 writes it; a lubrication film resists "
      "separation as much as approach, so the wet bed gets a tensile strength. "
      "approach only: where the solids converge (div u_s < 0), weighted by "
      "eps^2/(eps^2 + div u_s^2) where they separate, eps the strain rate "
      "regularisation (doc/theory.md, \"Wet closures\").");
  prm.declare_entry ("wet pressure in solids pressure",
                     "false",
                     Bool (),
                     "Add P_wet to the solids pressure (seed 000 Eq. 17 has only the dry "
                     "P_s; P_wet enters through mu_wet).");
  prm.leave_subsection ();
}

void WetParticleParameters::parse_parameters (ParameterHandler &prm,
                                              const bool        kinetic_theory,
                                              const bool        algebraic_temperature)
{
  prm.enter_subsection ("wet particles");
  liquid.liquid_loading             = prm.get_double ("liquid loading");
  liquid.liquid_viscosity           = prm.get_double ("liquid viscosity");
  liquid.liquid_density             = prm.get_double ("liquid density");
  liquid.contact_angle              = prm.get_double ("contact angle");
  liquid.surface_tension            = prm.get_double ("surface tension");
  liquid.asperity                   = prm.get_double ("asperity height");
  liquid.approach_factor            = prm.get_double ("approach velocity factor");
  const double phi_degrees          = prm.get_double ("angle of stability");
  liquid.film_thickness             = prm.get_double ("film thickness");
  liquid.switch_width               = prm.get_double ("switch width");
  liquid.strain_rate_regularisation = prm.get_double ("strain rate regularisation");
  liquid.maximum_viscosity          = prm.get_double ("maximum wet viscosity");
  rupture_distance                  = prm.get ("rupture distance");
  restitution                       = prm.get ("restitution");
  pressure_in_solids_pressure       = prm.get_bool ("wet pressure in solids pressure");
  liquid.approach_only              = prm.get ("lubrication stress") == "approach only";
  prm.leave_subsection ();
  liquid.stability_angle = phi_degrees * M_PI / 180.0;
  const std::string s    = "wet particles/";
  require (liquid.liquid_loading < 1.0, s + "liquid loading", "must lie in [0, 1)");
  require_positive (liquid.liquid_viscosity, s + "liquid viscosity");
  require_positive (liquid.liquid_density, s + "liquid density");
  require (liquid.contact_angle >= 0.0 && liquid.contact_angle < M_PI / 2,
           s + "contact angle",
           "must lie in [0, pi/2) rad");
  require_positive (liquid.surface_tension, s + "surface tension");
  require_positive (liquid.asperity, s + "asperity height");
  require_positive (liquid.approach_factor, s + "approach velocity factor");
  require (phi_degrees > 0.0 && phi_degrees < 90.0,
           s + "angle of stability",
           "must lie in (0, 90) degrees");
  require (liquid.film_thickness >= 0.0, s + "film thickness", "must be >= 0");
  require (liquid.switch_width < 0.5, s + "switch width", "must lie in [0, 0.5)");
  require_positive (liquid.strain_rate_regularisation, s + "strain rate regularisation");
  require_positive (liquid.maximum_viscosity, s + "maximum wet viscosity");
  if (enabled ())
  {
    require (kinetic_theory,
             s + "liquid loading",
             "wet particles need solids stress/model = kinetic theory (the wet closures "
             "depend on the granular temperature)");
    require (!algebraic_temperature,
             s + "liquid loading",
             "wet particles need kinetic theory/granular temperature = PDE (e_wet "
             "depends on Theta: the local equilibrium would be implicit in it)");
  }
}
} // namespace wetbed
