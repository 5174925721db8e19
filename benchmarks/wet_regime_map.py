#!/usr/bin/env python3
"""The wet-closure regime map of a case (seed 000 Fig. 2, for any parameters): runs
`wetbed closures CASE.prm` over alpha_s at several granular temperatures and draws
  (a) the Woodcock gap h(alpha_s), the rupture distance h_c and the asperity height h_a,
  (b) P_wet(alpha_s) for each Theta,  (c) mu_wet(alpha_s) (capped) for each Theta,
  (d) e_wet(alpha_s) with St and St* for each Theta,
as a PNG (default doc/wet_regime_map.png) and prints the wet window in alpha_s.

usage: python3 benchmarks/wet_regime_map.py [--case prm/wet_column_2d.prm]
           [--theta 1e-4 1e-3 1e-2] [--shear-rate 1] [--output doc/wet_regime_map.png]
(build first: bash scripts/build.sh)
"""
import argparse
import csv
import io
import os
import subprocess

from benchmark_setup import repository_root

root = repository_root()
parser = argparse.ArgumentParser()
parser.add_argument("--case", default=os.path.join(root, "prm", "wet_column_2d.prm"))
parser.add_argument("--theta", nargs="+", type=float, default=[1e-4, 1e-3, 1e-2])
parser.add_argument("--shear-rate", type=float, default=1.0)
parser.add_argument("--output", default=os.path.join(root, "doc", "wet_regime_map.png"))
parser.add_argument("--wetbed", default=os.path.join(root, "build", "wetbed"))
args = parser.parse_args()

alphas = [round(0.005 * k, 4) for k in range(2, 121)]  # 0.01 ... 0.6
text = subprocess.run(
    [args.wetbed, "closures", args.case, "--alpha-s", ",".join(map(str, alphas)),
     "--theta", ",".join(map(str, args.theta)), "--shear-rate", str(args.shear_rate)],
    check=True, capture_output=True, text=True).stdout
rows = list(csv.DictReader(io.StringIO(text)))
if "gap" not in rows[0]:
    raise SystemExit(f"{args.case}: a dry case (liquid loading 0): no wet closures to map")


def series(theta, key):
    pts = [(float(r["alpha_s"]), float(r[key])) for r in rows if float(r["theta"]) == theta]
    return [p[0] for p in pts], [p[1] for p in pts]


bridged = sorted({float(r["alpha_s"]) for r in rows if r["regime"] == "bridged"})
print(f"wet window (bridged contacts): alpha_s in [{bridged[0]:.3f}, {bridged[-1]:.3f}]"
      if bridged else "no bridged contacts at these points")

import matplotlib  # noqa: E402
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(2, 2, figsize=(10, 7.5))
theta0 = args.theta[0]
a, h = series(theta0, "gap")
_, hc = series(theta0, "rupture_distance")
ax[0, 0].semilogy(a, [max(v, 1e-8) for v in h], label="gap h (Woodcock)")
for theta in args.theta:
    _, hc = series(theta, "rupture_distance")
    ax[0, 0].semilogy(a, hc, "--", label=f"rupture h_c, Θ = {theta:g}")
contact = [float(r["alpha_s"]) for r in rows if r["regime"] == "contact"]
if contact:
    ax[0, 0].axvline(min(contact), color="grey", lw=0.8)
ax[0, 0].set(xlabel="α_s", ylabel="m", title="(a) gap and rupture distance")
ax[0, 0].legend(fontsize=8)
for theta in args.theta:
    a, p = series(theta, "wet_pressure")
    ax[0, 1].semilogy(a, [max(v, 1e-3) for v in p], label=f"Θ = {theta:g} m²/s²")
    a, mu = series(theta, "wet_viscosity")
    ax[1, 0].semilogy(a, [max(v, 1e-6) for v in mu], label=f"Θ = {theta:g}")
    a, e = series(theta, "wet_restitution")
    ax[1, 1].plot(a, e, label=f"e_wet, Θ = {theta:g}")
ax[0, 1].set(xlabel="α_s", ylabel="Pa", title="(b) liquid-bridge pressure P_wet")
ax[1, 0].set(xlabel="α_s", ylabel="Pa·s",
             title=f"(c) wet viscosity μ_wet (|γ̇| = {args.shear_rate:g} 1/s)")
ax[1, 1].set(xlabel="α_s", ylabel="e", title="(d) wet restitution (dissipation only)")
for axis in (ax[0, 1], ax[1, 0], ax[1, 1]):
    axis.legend(fontsize=8)
fig.suptitle(os.path.basename(args.case))
fig.tight_layout()
fig.savefig(args.output, dpi=110)
print("wrote", args.output)
