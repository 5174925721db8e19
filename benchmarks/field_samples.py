"""Cell samples of a run's HDF5 field outputs (fields.xdmf + fields_NNNNN.h5), for the
scatter plots of the solids stress split and the dissipation against alpha_s (seed 000,
Figs. 9-10). Each output sub-cell gives one sample: alpha_s and Theta averaged over its
vertices, the cell fields (shear rate, stress parts, dissipation) as written."""
import os
import re

CELL_FIELDS = ["solids_shear_rate", "kinetic_shear_stress", "collisional_shear_stress",
               "frictional_shear_stress", "wet_shear_stress", "collisional_dissipation"]


def output_times(folder):
    """[(time, h5 file name)] of the outputs listed in FOLDER/fields.xdmf."""
    path = os.path.join(folder, "fields.xdmf")
    if not os.path.exists(path):
        return []
    text = open(path).read()
    grids = re.findall(r'<Time Value="([^"]+)"/>.*?(fields_\d+\.h5):/nodes', text, flags=re.S)
    return [(float(t), name) for t, name in grids]


def cell_samples(folder, start_up):
    """{field: numpy array} over every sub-cell of every output after START_UP: alpha_s,
    granular_temperature (vertex means) and the CELL_FIELDS present (zeros for
    wet_shear_stress in a dry scene). Empty dict if no output qualifies."""
    import h5py
    import numpy
    columns = {}
    for time, name in output_times(folder):
        if time <= start_up or not os.path.exists(os.path.join(folder, name)):
            continue
        with h5py.File(os.path.join(folder, name), "r") as f:
            cells = f["cells"][()].astype(int)
            if "collisional_dissipation" not in f:
                continue
            sample = {key: f[key][()][:, 0][cells].mean(axis=1)
                      for key in ("alpha_s", "granular_temperature")}
            for key in CELL_FIELDS:
                sample[key] = (f[key][()][:, 0][cells[:, 0]] if key in f
                               else numpy.zeros(len(cells)))
        for key, values in sample.items():
            columns.setdefault(key, []).append(values)
    return {key: numpy.concatenate(parts) for key, parts in columns.items()}


def stress_split(samples, dense=0.3):
    """Shares (%) of the kinetic, collisional, frictional and wet parts in the summed
    solids shear stress over the samples with alpha_s > DENSE, and their mean
    collisional dissipation (W/m^3); None without samples."""
    if not samples:
        return None
    keep = samples["alpha_s"] > dense
    if not keep.any():
        return None
    parts = [samples[k][keep].sum() for k in CELL_FIELDS[1:5]]
    total = sum(parts)
    return {"shares": [100 * p / total if total > 0 else float("nan") for p in parts],
            "dissipation": float(samples["collisional_dissipation"][keep].mean()),
            "theta": float(samples["granular_temperature"][keep].mean())}
