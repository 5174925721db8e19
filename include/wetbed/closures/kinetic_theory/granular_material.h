#pragma once

#include <wetbed/closures/drag/drag_model.h>

#include <memory>
#include <string>

namespace wetbed::closures
{
/** Particle data the kinetic-theory closures need. */
struct GranularMaterial
{
  double particle_density;  // rho_s (kg/m^3)
  double particle_diameter; // d (m)
  double restitution;       // e, particle-particle (dry)
  double maximum_packing;   // alpha_max
};

/**
 * A kinetic-theory transport coefficient f(alpha_s, Theta, g0) (a kinetic viscosity or a
 * conductivity), for double and for ADNumber. Laws are structs with
 * `template <class Number> static Number value(alpha, theta, g0, material)`.
 */
class KineticTheoryCoefficient
{
public:
  virtual ~KineticTheoryCoefficient ()                               = default;
  virtual std::string name () const                                  = 0;
  virtual double      value (double                  alpha_s,
                             double                  theta,
                             double                  g0,
                             const GranularMaterial &material) const = 0;
  virtual ADNumber    value (const ADNumber         &alpha_s,
                             const ADNumber         &theta,
                             const ADNumber         &g0,
                             const GranularMaterial &material) const = 0;
};

template <class Law>
class KineticTheoryCoefficientFromLaw : public KineticTheoryCoefficient
{
public:
  std::string name () const override { return Law::name; }
  double      value (double                  alpha_s,
                     double                  theta,
                     double                  g0,
                     const GranularMaterial &material) const override
  {
    return Law::template value<double> (alpha_s, theta, g0, material);
  }
  ADNumber value (const ADNumber         &alpha_s,
                  const ADNumber         &theta,
                  const ADNumber         &g0,
                  const GranularMaterial &material) const override
  {
    return Law::template value<ADNumber> (alpha_s, theta, g0, material);
  }
};

/** Radial distribution function at contact g0(alpha_s), for double and ADNumber. */
class RadialDistribution
{
public:
  virtual ~RadialDistribution ()                                           = default;
  virtual std::string name () const                                        = 0;
  virtual double      value (double alpha_s, double maximum_packing) const = 0;
  virtual ADNumber    value (const ADNumber &alpha_s, double maximum_packing) const = 0;
};

template <class Law>
class RadialDistributionFromLaw : public RadialDistribution
{
public:
  std::string name () const override { return Law::name; }
  double      value (double alpha_s, double maximum_packing) const override
  {
    return Law::template value<double> (alpha_s, maximum_packing);
  }
  ADNumber value (const ADNumber &alpha_s, double maximum_packing) const override
  {
    return Law::template value<ADNumber> (alpha_s, maximum_packing);
  }
};

/** Registries (source/closures/kinetic_theory/kinetic_theory_registry.cc). */
std::unique_ptr<RadialDistribution> create_radial_distribution (const std::string &name);
std::unique_ptr<KineticTheoryCoefficient>
create_kinetic_viscosity (const std::string &name);
std::unique_ptr<KineticTheoryCoefficient>
            create_granular_conductivity (const std::string &name);
std::string radial_distribution_names ();
std::string kinetic_viscosity_names ();
std::string granular_conductivity_names ();
} // namespace wetbed::closures
