#include <wetbed/core/adaptive_refinement_parameters.h>
#include <wetbed/core/input_error.h>

namespace wetbed
{
using dealii::ParameterHandler;
using namespace dealii::Patterns;

void AdaptiveRefinementParameters::declare_parameters (ParameterHandler &prm)
{
  prm.enter_subsection ("adaptive refinement");
  prm.declare_entry ("enabled",
                     "false",
                     Bool (),
                     "Refine where bubbles are (the gas-emulsion interfaces) and coarsen "
                     "the freeboard and the uniform emulsion, every `interval` steps.");
  prm.declare_entry ("interval", "5", Integer (1), "Accepted steps between adaptations.");
  prm.declare_entry ("minimum level",
                     "0",
                     Integer (0),
                     "No cell is coarsened below this level, and cells below it are "
                     "refined (0: the gmsh mesh).");
  prm.declare_entry ("maximum level",
                     "2",
                     Integer (0, 12),
                     "No cell is refined beyond this level (0: the gmsh mesh; the mesh "
                     "starts at mesh/initial refinement).");
  prm.declare_entry ("velocity weight",
                     "0.1",
                     Double (0),
                     "Indicator = h_K max|grad alpha_s| / alpha_max + weight x Kelly "
                     "estimate of u_s (normalised by its largest value). 0: the "
                     "interfaces of alpha_s alone.");
  prm.declare_entry ("refine threshold",
                     "0.1",
                     Double (0),
                     "Cells whose indicator exceeds this are refined (a gas-emulsion "
                     "interface across a cell has h|grad alpha_s|/alpha_max ~ 0.3-0.7). "
                     "Thresholds, not fractions of the cell count: symmetric cells with "
                     "equal indicators are flagged alike, so the mesh does not depend "
                     "on round-off or on the number of MPI ranks.");
  prm.declare_entry ("coarsen threshold",
                     "0.03",
                     Double (0),
                     "Cells whose indicator is below this are coarsened (the freeboard, "
                     "a uniform emulsion).");
  prm.declare_entry ("initial cycles",
                     "2",
                     Integer (0, 12),
                     "Adaptations to the initial state (re-imposed on each new mesh) "
                     "before the first step: the bed surface starts resolved.");
  prm.declare_entry ("distributor band height",
                     "0",
                     Double (0),
                     "Cells with a vertex below this height (m, along -g from the "
                     "coordinate origin: the inlet plane of the shipped meshes) are "
                     "refined to maximum level and never coarsened. Bubbles are born at "
                     "the distributor, before their interfaces are sharp enough to "
                     "trigger refinement; a bubble born in coarse cells starts too "
                     "large. 0: no band.");
  prm.leave_subsection ();
}

void AdaptiveRefinementParameters::parse_parameters (
    ParameterHandler &prm, const unsigned int initial_refinement)
{
  prm.enter_subsection ("adaptive refinement");
  enabled                 = prm.get_bool ("enabled");
  interval                = prm.get_integer ("interval");
  minimum_level           = prm.get_integer ("minimum level");
  maximum_level           = prm.get_integer ("maximum level");
  velocity_weight         = prm.get_double ("velocity weight");
  refine_threshold        = prm.get_double ("refine threshold");
  coarsen_threshold       = prm.get_double ("coarsen threshold");
  initial_cycles          = prm.get_integer ("initial cycles");
  distributor_band_height = prm.get_double ("distributor band height");
  prm.leave_subsection ();
  const std::string s = "adaptive refinement/";
  require (maximum_level >= minimum_level,
           s + "maximum level",
           "must be >= minimum level (" + std::to_string (minimum_level) + ")");
  require (!enabled || maximum_level >= initial_refinement,
           s + "maximum level",
           "must be >= mesh/initial refinement (" + std::to_string (initial_refinement) +
               ")");
  require (coarsen_threshold < refine_threshold,
           s + "coarsen threshold",
           "must be below refine threshold (" + std::to_string (refine_threshold) + ")");
}
} // namespace wetbed
