#include <wetbed/closures/kinetic_theory/granular_material.h>
#include <wetbed/core/input_error.h>
#include <wetbed/core/kinetic_theory_parameters.h>

#include <cmath>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void KineticTheoryParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("kinetic theory");
  prm.declare_entry ("radial distribution",
                     "Ogawa",
                     Selection (closures::radial_distribution_names ()),
                     "g0(alpha_s): " + closures::radial_distribution_names () + ".");
  prm.declare_entry ("kinetic viscosity",
                     "Syamlal",
                     Selection (closures::kinetic_viscosity_names ()),
                     "Kinetic part of mu_s: " + closures::kinetic_viscosity_names () +
                         ".");
  prm.declare_entry (
      "conductivity",
      "Gidaspow",
      Selection (closures::granular_conductivity_names ()),
      "Granular conductivity kappa: " + closures::granular_conductivity_names () + ".");
  prm.declare_entry (
      "restitution coefficient", "0.9", Double (), "e, particle-particle.");
  prm.declare_entry ("radial distribution cap",
                     "0.58",
                     Double (),
                     "g0 is evaluated at min(alpha_s, cap): finite and frozen in the "
                     "frictional regime (OpenFOAM caps at alphaMinFriction).");
  prm.declare_entry ("granular temperature",
                     "PDE",
                     Selection ("PDE|algebraic"),
                     "PDE: the granular energy equation; algebraic: local equilibrium "
                     "(production = dissipation + drag exchange), no matrix.");
  prm.declare_entry (
      "internal friction angle", "30", Double (), "phi (degrees), Schaeffer viscosity.");
  prm.declare_entry ("maximum frictional viscosity",
                     "100",
                     Double (),
                     "Cap of the Schaeffer viscosity (Pa s; MFIX: 100).");
  prm.declare_entry ("strain rate regularisation",
                     "1e-3",
                     Double (),
                     "eps (1/s) in P_fr sin(phi)/(2 sqrt(I_2D + eps^2)).");
  prm.declare_entry (
      "minimum shear viscosity",
      "1e-3",
      Double (),
      "Floor of mu_s (Pa s) where alpha_s or Theta vanish (about the dilute "
      "kinetic-theory viscosity 0.1 rho_s d sqrt(Theta) at Theta ~ 1e-4). A much "
      "lower floor lets the solids velocity of the dilute splash zone next to the "
      "walls lose its viscous coupling, oscillate node to node and break FGMRES "
      "down (doc/theory.md \"Dilute regions\").");
  prm.declare_entry (
      "minimum granular temperature", "1e-10", Double (), "Floor of Theta (m^2/s^2).");
  prm.declare_entry (
      "maximum granular temperature",
      "1",
      Double (),
      "Cap of Theta (m^2/s^2). Where alpha_s -> 0 the kinetic viscosity "
      "heats ~ alpha_s while collisions dissipate ~ alpha_s^2, so Theta of "
      "the last particles in the freeboard grows without bound (OpenFOAM "
      "clamps Theta too).");
  prm.declare_entry (
      "dilute solids fraction",
      "1e-4",
      Double (),
      "Granular energy production is scaled by min(1, alpha_s/this): in the "
      "empty freeboard u_s is the velocity of no particles, and its shear "
      "must not heat them (MFIX's DIL_EP_S plays the same role).");
  prm.declare_entry ("initial granular temperature",
                     "1e-4",
                     Double (),
                     "Theta at t = 0 where there are solids (m^2/s^2).");
  prm.declare_entry (
      "specularity coefficient", "0.5", Double (), "phi' of the Johnson-Jackson wall.");
  prm.declare_entry ("wall restitution coefficient",
                     "0.8",
                     Double (),
                     "e_w of the Johnson-Jackson wall.");
  prm.leave_subsection ();
}

void KineticTheoryParameters::parse_parameters (ParameterHandler &prm,
                                                const double      maximum_packing)
{
  prm.enter_subsection ("kinetic theory");
  radial_distribution          = prm.get ("radial distribution");
  kinetic_viscosity            = prm.get ("kinetic viscosity");
  conductivity                 = prm.get ("conductivity");
  restitution                  = prm.get_double ("restitution coefficient");
  radial_distribution_cap      = prm.get_double ("radial distribution cap");
  algebraic                    = prm.get ("granular temperature") == "algebraic";
  const double phi_degrees     = prm.get_double ("internal friction angle");
  maximum_frictional_viscosity = prm.get_double ("maximum frictional viscosity");
  strain_rate_regularisation   = prm.get_double ("strain rate regularisation");
  minimum_shear_viscosity      = prm.get_double ("minimum shear viscosity");
  minimum_temperature          = prm.get_double ("minimum granular temperature");
  maximum_temperature          = prm.get_double ("maximum granular temperature");
  dilute_fraction              = prm.get_double ("dilute solids fraction");
  initial_temperature          = prm.get_double ("initial granular temperature");
  specularity                  = prm.get_double ("specularity coefficient");
  wall_restitution             = prm.get_double ("wall restitution coefficient");
  prm.leave_subsection ();
  internal_friction_angle = phi_degrees * M_PI / 180.0;
  require (restitution > 0.0 && restitution <= 1.0,
           "kinetic theory/restitution coefficient",
           "must lie in (0, 1]");
  require (radial_distribution_cap > 0.0 && radial_distribution_cap < maximum_packing,
           "kinetic theory/radial distribution cap",
           "must lie in (0, physical properties/maximum packing)");
  require (phi_degrees > 0.0 && phi_degrees < 90.0,
           "kinetic theory/internal friction angle",
           "must lie in (0, 90) degrees");
  require (maximum_frictional_viscosity > 0.0,
           "kinetic theory/maximum frictional viscosity",
           "must be > 0");
  require (strain_rate_regularisation > 0.0,
           "kinetic theory/strain rate regularisation",
           "must be > 0");
  require (minimum_shear_viscosity > 0.0,
           "kinetic theory/minimum shear viscosity",
           "must be > 0");
  require (minimum_temperature > 0.0,
           "kinetic theory/minimum granular temperature",
           "must be > 0");
  require (dilute_fraction > 0.0 && dilute_fraction < maximum_packing,
           "kinetic theory/dilute solids fraction",
           "must lie in (0, physical properties/maximum packing)");
  require (maximum_temperature > minimum_temperature,
           "kinetic theory/maximum granular temperature",
           "must exceed the minimum granular temperature");
  require (initial_temperature >= minimum_temperature &&
               initial_temperature <= maximum_temperature,
           "kinetic theory/initial granular temperature",
           "must lie between the minimum and maximum granular temperature");
  require (specularity >= 0.0 && specularity <= 1.0,
           "kinetic theory/specularity coefficient",
           "must lie in [0, 1]");
  require (wall_restitution >= 0.0 && wall_restitution <= 1.0,
           "kinetic theory/wall restitution coefficient",
           "must lie in [0, 1]");
}
} // namespace wetbed
