#!/usr/bin/env python3
"""Reference values of the wet closures (seed 000 s3 as read in doc/theory.md, "Wet
closures"), written from the paper's equations independently of the C++
(tests/closures_wet.cc embeds them).
Seed-000 liquid: silicone oil mu_L = 0.4945 Pa s, rho_L = 969, gamma_c = 0.175 rad,
h_a = 2.8 um; 350 um glass, rho_s = 2500, e_dry = 0.9; c_u = 3/2, phi' = 30 deg;
delta = 0.1e-2; sigma = 0.021 N/m; film delta_f/d = 0.1; sharp switches (width 0)."""
import math

d, rho_s, e = 350e-6, 2500.0, 0.9
mu_l, rho_l, gamma_c, h_a = 0.4945, 969.0, 0.175, 2.8e-6
c_u, phi, delta, sigma, film = 1.5, math.radians(30.0), 0.1e-2, 0.021, 0.1
eps, mu_max = 1e-3, 1000.0


def gap(a):  # Woodcock, Eq. 7
    return d * (math.sqrt(1.0 / (3.0 * math.pi * a) + 5.0 / 6.0) - 1.0)


def approach(theta):  # u_dot = c_u sqrt(pi Theta)
    return c_u * math.sqrt(math.pi * theta)


def volume():  # V* = delta rho_s / rho_L (Eq. 8)
    return delta * rho_s / rho_l


def rupture_lian():
    return 0.5 * (1 + 0.5 * gamma_c) * d * volume() ** (1.0 / 3.0)


def rupture_pitois(u):
    return (1 + math.sqrt(mu_l * u / sigma)) * rupture_lian()


def rupture_mikami():
    return 0.5 * d * (0.62 * gamma_c + 0.99) * volume() ** 0.34


def stokes(u):  # Eq. 12
    m = rho_s * math.pi * d ** 3 / 6
    return 8 * m * u / (3 * math.pi * mu_l * d * d)


def critical_stokes(h):  # Eq. 13
    return (1 + 1 / e) * math.log(h / h_a)


def pressure(a, theta):  # Eq. 5 with c_u = 3/2 (equal to Eqs. 2-4)
    h, hc = gap(a), rupture_lian()
    if not (h_a < h <= hc):
        return 0.0
    eq5 = 9.0 / (16.0 * h) * math.pi * mu_l * math.sqrt(math.pi * theta) * (
        6 * a / math.pi) ** (2.0 / 3.0)
    eq2 = 3.0 / 8.0 * math.pi * mu_l * d * d * approach(theta) / h * (
        6 * a / (math.pi * d ** 3)) ** (2.0 / 3.0)
    assert abs(eq5 - eq2) < 1e-12 * eq5
    return eq5


def viscosity(p, i2d):  # Eq. 6, |gamma_dot| = 2 sqrt(I_2D + eps^2)
    return min(math.sqrt(2) * p * math.sin(phi) / (2 * math.sqrt(i2d + eps * eps)), mu_max)


def bridged(st, sts):
    return e * min(1.0, max(0.0, 1 - sts / st))


def e_gated(a, theta):
    h = gap(a)
    if h_a < h <= rupture_lian():
        return bridged(stokes(approach(theta)), critical_stokes(h))
    return e


def e_literal(a, theta):
    h, st = gap(a), stokes(approach(theta))
    if h <= h_a:
        return e
    sts = critical_stokes(h)
    if h <= rupture_lian():
        return bridged(st, sts)
    return e if st >= sts else 0.0


def e_gollwitzer(theta):
    v = (e - 1.5 * rho_l / rho_s * film / e) * (1 - 14 / stokes(approach(theta)))
    return min(max(v, 0.0), e)


if __name__ == "__main__":
    print("h_c Lian %.16e  Mikami %.16e" % (rupture_lian(), rupture_mikami()))
    for a, theta, i2d in [(0.2, 1e-3, 1.0), (0.45, 1e-3, 1.0), (0.45, 1e-2, 25.0),
                          (0.59, 1e-3, 1.0), (0.45, 50.0, 1.0), (0.45, 1e-3, 1e8)]:
        u = approach(theta)
        h = gap(a)
        p = pressure(a, theta)
        print("alpha %.2f Theta %g I2D %g: h %.16e u %.16e St %.16e St* %.16e "
              "P %.16e mu %.16e e_gated %.16e e_literal %.16e e_Gollwitzer %.16e "
              "h_c Pitois %.16e" % (a, theta, i2d, h, u, stokes(u),
                                   critical_stokes(max(h, 0.01 * h_a)), p,
                                   viscosity(p, i2d), e_gated(a, theta),
                                   e_literal(a, theta), e_gollwitzer(theta),
                                   rupture_pitois(u)))
