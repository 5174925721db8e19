#pragma once

#include <Sacado.hpp>

#include <memory>
#include <string>

namespace wetbed::closures
{
/** Number type the closures are differentiated with. */
using ADNumber = Sacado::Fad::DFad<double>;

/** Material data a drag law needs. */
struct GasParticleProperties
{
  double gas_density;
  double gas_viscosity;
  double particle_diameter;
};

/**
 * Interphase momentum exchange coefficient beta (kg m^-3 s^-1) in the force
 * beta (u_g - u_s) on the solids. Laws are pure functions of (alpha_s, |u_g - u_s|),
 * templated on the number type; this interface exposes them for double and ADNumber.
 */
class DragModel
{
public:
  virtual ~DragModel ()             = default;
  virtual std::string name () const = 0;
  virtual double
  coefficient (double alpha_s, double slip, const GasParticleProperties &p) const = 0;
  virtual ADNumber coefficient (const ADNumber              &alpha_s,
                                const ADNumber              &slip,
                                const GasParticleProperties &p) const             = 0;
};

/** Wraps a law `Law::beta<Number>(alpha_s, slip, properties)` as a DragModel. */
template <class Law>
class DragModelFromLaw : public DragModel
{
public:
  std::string name () const override { return Law::name; }
  double
  coefficient (double alpha_s, double slip, const GasParticleProperties &p) const override
  {
    return Law::template beta<double> (alpha_s, slip, p);
  }
  ADNumber coefficient (const ADNumber              &alpha_s,
                        const ADNumber              &slip,
                        const GasParticleProperties &p) const override
  {
    return Law::template beta<ADNumber> (alpha_s, slip, p);
  }
};

/** The drag model registered under `name`; throws if there is none. */
std::unique_ptr<DragModel> create_drag_model (const std::string &name);

/** Registered names joined by '|', for Patterns::Selection. */
std::string drag_model_names ();
} // namespace wetbed::closures
