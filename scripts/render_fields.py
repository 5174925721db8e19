#!/usr/bin/env python3
"""Pictures of a wetbed run's field output: alpha_s snapshots and an animation.

usage: scripts/render_fields.py RUN_FOLDER [--field NAME] [--times T,T,...] [--count N]
                                [--size WxH] [--out FOLDER] [--frames N] [--fps F]
                                [--no-animation] [--iso A] [--no-iso] [--height LOW,HIGH]

Reads the run's own field output: fields.xdmf with its fields_NNN.h5 files
(`output/field format = hdf5` or `vtu and hdf5`) or, without them, the fields_NNN.pvtu
records and their .vtu pieces (the default `vtu`; their times from fields.pvd, 6
digits; read by scripts/wetbed_results.py), and writes into OUT (default
RUN_FOLDER/pictures):
  <field>_t<time>.png   one snapshot per chosen time (--times, else --count times spread
                        evenly over the run, first and last output included; default 4)
  <field>_snapshots.png the same times side by side
  <field>.gif           the animation over the run (at most --frames outputs, evenly
                        picked; default 120; --fps frames per second, default 10)
  alpha_g_iso.png       3D only: the iso-surface alpha_g = --iso (default 0.8, the
                        bubble threshold of `bubble analysis`) at the last time of
                        --times, else at the last output time
--height LOW,HIGH draws only that vertical range (m; slices and the iso-surface), e.g.
the bed of a tall column.
2D: the field over the whole domain. 3D: the vertical slice through the axis of the
domain (the plane of the first horizontal coordinate through the centre of the bounding
box). Vertical is the direction of gravity in RUN_FOLDER/parameters.prm (else the last
coordinate). --size sets the pixel size of the snapshots (default 360x900 for a 2D or
3D slice). The colour scale of alpha_s runs from 0 to `maximum packing` of the run
(viridis: dark is gas, yellow is packed). Prints the files it wrote.
Uses Debian's python3-matplotlib and python3-h5py (re-executes under /usr/bin/python3
if needed); VTU reading needs neither h5py nor VTK."""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
# the field readers live in wetbed_results.py; their names here as before (tests and
# benchmarks call render_fields.hdf5_frames, pvd_times, ...)
from wetbed_results import (Frame, ensure_modules, frames, hdf5_frames, parameter,  # noqa: E402,F401
                            pvd_times, run_parameters, vtu_array, vtu_frames)


def read_run_parameters(folder):
    """The run's gravity vector and maximum packing from parameters.prm (None where absent)."""
    values = run_parameters(folder)
    gravity, packing = parameter(values, "gravity"), parameter(values, "maximum packing")
    return ([float(v) for v in gravity.split(",")] if gravity is not None else None,
            float(packing) if packing is not None else None)


def find_frames(folder):
    """The run's field outputs (wetbed_results.frames); exits without any."""
    found = frames(folder)
    if not found:
        sys.exit(f"render_fields: no field output in {folder} (fields.xdmf or fields_*.pvtu): "
                 "the case needs `output/field interval` > 0")
    return found


class View:
    """Where the pictures look: the vertical axis, the horizontal axis drawn, and for 3D
    the slice plane (coordinate index and value)."""

    def __init__(self, frame, gravity):
        import numpy as np

        self.dim = 3 if frame.cells.shape[1] == 8 else 2
        if gravity is not None and any(abs(g) > 0 for g in gravity[: self.dim]):
            self.vertical = int(np.argmax(np.abs(gravity[: self.dim])))
        else:
            self.vertical = self.dim - 1
        horizontal = [d for d in range(self.dim) if d != self.vertical]
        self.horizontal = horizontal[-1] if self.dim == 3 else horizontal[0]
        lo, hi = frame.points.min(axis=0), frame.points.max(axis=0)
        self.slice_axis = horizontal[0] if self.dim == 3 else None
        self.slice_at = 0.5 * (lo[horizontal[0]] + hi[horizontal[0]]) if self.dim == 3 else None
        self.extent = (lo[self.horizontal], hi[self.horizontal], lo[self.vertical], hi[self.vertical])
        self.names = "xyz"


def plane_triangles(frame, view, values):
    """(x, y, triangles, values) of the picture plane: the 2D mesh itself, or in 3D the
    faces of the output's sub-cells lying in the slice plane (deal.II's patches of the
    shipped O-grid column put faces on the axis planes), else the points within half a
    sub-cell of it triangulated."""
    import numpy as np

    if view.dim == 2:
        quads = frame.cells
        triangles = np.vstack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
        return frame.points[:, view.horizontal], frame.points[:, view.vertical], triangles, values
    p = frame.points
    size = np.median(np.linalg.norm(p[frame.cells[:, 1]] - p[frame.cells[:, 0]], axis=1))
    distance = np.abs(p[:, view.slice_axis] - view.slice_at)
    tolerance = 1e-6 * size
    faces = np.array([[0, 1, 2, 3], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]])
    quads = frame.cells[:, faces].reshape(-1, 4)
    on_plane = quads[(distance[quads] < tolerance).all(axis=1)]
    if len(on_plane) > 0:
        triangles = np.vstack([on_plane[:, [0, 1, 2]], on_plane[:, [0, 2, 3]]])
        return p[:, view.horizontal], p[:, view.vertical], triangles, values
    import matplotlib.tri as mtri

    near = np.nonzero(distance < 0.5 * size)[0]
    x, y = p[near, view.horizontal], p[near, view.vertical]
    return x, y, mtri.Triangulation(x, y).triangles, values[near]


def draw_field(ax, frame, view, field, vmax, cmap):
    import matplotlib.tri as mtri

    x, y, triangles, values = plane_triangles(frame, view, frame.fields[field])
    mesh = ax.tripcolor(mtri.Triangulation(x, y, triangles), values, shading="gouraud",
                        cmap=cmap, vmin=0.0, vmax=vmax)
    ax.set_xlim(view.extent[0], view.extent[1])
    ax.set_ylim(view.extent[2], view.extent[3])
    ax.set_aspect("equal")
    return mesh


def snapshot_figure(frame, view, field, vmax, size, title=True):
    """A figure of size (w, h) pixels: the field in the left part, its colour bar at the
    right."""
    import matplotlib.pyplot as plt

    dpi = 100
    fig = plt.figure(figsize=(size[0] / dpi, size[1] / dpi), dpi=dpi)
    ax = fig.add_axes([0.2, 0.06, 0.46, 0.88 if title else 0.92])
    bar = fig.add_axes([0.7, 0.06, 0.05, 0.88 if title else 0.92])
    mesh = draw_field(ax, frame, view, field, vmax, "viridis")
    fig.colorbar(mesh, cax=bar, label=field)
    ax.set_xlabel(f"{view.names[view.horizontal]} (m)", fontsize=8)
    ax.set_ylabel(f"{view.names[view.vertical]} (m)", fontsize=8)
    ax.tick_params(labelsize=7)
    if title:
        where = "" if view.dim == 2 else f", {view.names[view.slice_axis]} = {view.slice_at:.3g} m"
        ax.set_title(f"t = {frame.time:.3f} s{where}", fontsize=9)
    return fig


def iso_triangles(frame, field, level):
    """Marching tetrahedra: the triangles (k x 3 x 3 points) of the iso-surface field =
    level over the hexahedral sub-cells (6 tetrahedra each)."""
    import numpy as np

    tets = np.array([[0, 1, 2, 6], [0, 2, 3, 6], [0, 3, 7, 6], [0, 7, 4, 6], [0, 4, 5, 6], [0, 5, 1, 6]])
    t = frame.cells[:, tets].reshape(-1, 4)
    v = frame.fields[field][t]
    above = v > level
    crossing = above.any(axis=1) & ~above.all(axis=1)
    t, v, above = t[crossing], v[crossing], above[crossing]
    p = frame.points

    def cut(rows, a, b):
        """The point on each tetrahedron's edge (a, b) where the field is at the level."""
        va, vb = v[rows, a], v[rows, b]
        s = ((level - va) / (vb - va))[:, None]
        return p[t[rows, a]] + s * (p[t[rows, b]] - p[t[rows, a]])

    out = []
    n_above = above.sum(axis=1)
    order = np.argsort(~above, axis=1, kind="stable")  # vertices above first
    rows = np.arange(len(t))
    for lone in (1, 3):
        r = rows[n_above == lone]
        if len(r) == 0:
            continue
        o = order[r] if lone == 1 else order[r][:, ::-1]  # the vertex alone on its side first
        i = o[:, 0]
        tri = [cut(r, i, o[:, k]) for k in (1, 2, 3)]
        out.append(np.stack(tri, axis=1))
    r = rows[n_above == 2]
    if len(r):
        o = order[r]
        a, b, c, d = o[:, 0], o[:, 1], o[:, 2], o[:, 3]
        q = [cut(r, a, c), cut(r, a, d), cut(r, b, d), cut(r, b, c)]
        out.append(np.stack([q[0], q[1], q[2]], axis=1))
        out.append(np.stack([q[0], q[2], q[3]], axis=1))
    return np.concatenate(out) if out else np.zeros((0, 3, 3))


def iso_figure(frame, view, field, level, size):
    import matplotlib.pyplot as plt
    import numpy as np
    from mpl_toolkits.mplot3d.art3d import Poly3DCollection

    dpi = 100
    fig = plt.figure(figsize=(size[0] / dpi, size[1] / dpi), dpi=dpi)
    ax = fig.add_subplot(projection="3d")
    triangles = iso_triangles(frame, field, level)
    low, high = view.extent[2], view.extent[3]
    heights = triangles[:, :, view.vertical]
    triangles = triangles[(heights >= low - 1e-12).all(axis=1) & (heights <= high + 1e-12).all(axis=1)]
    if len(triangles):
        height = triangles[:, :, view.vertical].mean(axis=1)
        lo, hi = view.extent[2], view.extent[3]
        colours = plt.get_cmap("cividis")((height - lo) / max(hi - lo, 1e-30))
        ax.add_collection3d(Poly3DCollection(triangles, facecolors=colours, edgecolors="none", alpha=0.8))
    lo, hi = frame.points.min(axis=0), frame.points.max(axis=0)
    lo[view.vertical], hi[view.vertical] = low, high
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.set_zlim(lo[2], hi[2])
    # a tall column drawn at most 3 times as tall as wide (the vertical axis compressed)
    extent = np.maximum(hi - lo, 1e-12)
    extent[view.vertical] = min(extent[view.vertical], 3 * max(np.delete(extent, view.vertical)))
    ax.set_box_aspect(extent)
    fig.subplots_adjust(left=0, right=1, bottom=0, top=0.95)
    for d, axis in enumerate((ax.xaxis, ax.yaxis, ax.zaxis)):
        axis.set_label_text(f"{view.names[d]} (m)", fontsize=7)
        if d != view.vertical:
            axis.set_ticklabels([])
    ax.tick_params(labelsize=6)
    ax.set_title(f"{field} = {level} at t = {frame.time:.3f} s ({len(triangles)} triangles)", fontsize=8)
    return fig


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_folder")
    parser.add_argument("--field", default="alpha_s")
    parser.add_argument("--times", default=None, help="comma-separated simulated times (nearest outputs)")
    parser.add_argument("--count", type=int, default=4)
    parser.add_argument("--size", default="360x900", help="snapshot size in pixels, WxH")
    parser.add_argument("--out", default=None)
    parser.add_argument("--frames", type=int, default=120)
    parser.add_argument("--fps", type=float, default=10)
    parser.add_argument("--no-animation", action="store_true")
    parser.add_argument("--iso", type=float, default=0.8)
    parser.add_argument("--no-iso", action="store_true")
    parser.add_argument("--height", default=None,
                        help="LOW,HIGH: the vertical range drawn (m), e.g. 0,0.3 for the bed of a tall column")
    args = parser.parse_args()
    ensure_modules("matplotlib", "numpy")
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    m = re.fullmatch(r"(\d+)x(\d+)", args.size)
    if not m or int(m.group(1)) < 50 or int(m.group(2)) < 50:
        sys.exit(f"render_fields: --size '{args.size}' is not WxH pixels (each at least 50)")
    size = (int(m.group(1)), int(m.group(2)))
    folder = args.run_folder
    out = args.out or os.path.join(folder, "pictures")
    os.makedirs(out, exist_ok=True)
    gravity, packing = read_run_parameters(folder)
    frames = find_frames(folder)
    times = np.array([t for t, _ in frames])
    first = frames[0][1]([args.field])
    if args.field not in first.fields:
        sys.exit(f"render_fields: no field '{args.field}' in the output of {folder}")
    view = View(first, gravity)
    if args.height:
        try:
            low, high = (float(v) for v in args.height.split(","))
        except ValueError:
            sys.exit(f"render_fields: --height '{args.height}' is not LOW,HIGH in metres")
        if not low < high:
            sys.exit(f"render_fields: --height '{args.height}': LOW must be below HIGH")
        view.extent = (view.extent[0], view.extent[1], low, high)
    vmax = (packing or 0.63) if args.field == "alpha_s" else max(float(first.fields[args.field].max()), 1e-30)
    if args.times:
        chosen = sorted({int(np.argmin(np.abs(times - float(t)))) for t in args.times.split(",")})
    else:
        count = max(1, min(args.count, len(frames)))
        chosen = sorted({int(round(i)) for i in np.linspace(0, len(frames) - 1, count)})
    written = []
    loaded = {}
    for i in chosen:
        loaded[i] = frames[i][1]([args.field])
        fig = snapshot_figure(loaded[i], view, args.field, vmax, size)
        path = os.path.join(out, f"{args.field}_t{frames[i][0]:.3f}.png")
        fig.savefig(path, dpi=100)
        plt.close(fig)
        written.append(path)
    if len(chosen) > 1:
        # side by side for a tall domain, one above the other for a wide one
        dpi = 100
        aspect = (view.extent[1] - view.extent[0]) / max(view.extent[3] - view.extent[2], 1e-30)
        tall = aspect <= 1.5
        if tall:
            panel = (max(60.0, 0.8 * size[1] * aspect) + 30, size[1])
            shape = (1, len(chosen))
        else:
            panel = (size[0], max(60.0, 0.8 * size[0] / aspect) + 30)
            shape = (len(chosen), 1)
        fig, axes = plt.subplots(*shape, figsize=(panel[0] * shape[1] / dpi + 1.2, panel[1] * shape[0] / dpi),
                                 dpi=dpi, squeeze=False)
        fig.subplots_adjust(left=0.04, right=0.82, bottom=0.03, top=0.95, wspace=0.1, hspace=0.4)
        for ax, i in zip(axes.ravel(), chosen):
            mesh = draw_field(ax, loaded[i], view, args.field, vmax, "viridis")
            ax.set_title(f"t = {frames[i][0]:.2f} s", fontsize=9)
            ax.set_xticks([])
            ax.set_yticks([])
        fig.colorbar(mesh, cax=fig.add_axes([0.86, 0.1, 0.03, 0.8]), label=args.field)
        path = os.path.join(out, f"{args.field}_snapshots.png")
        fig.savefig(path, dpi=dpi)
        plt.close(fig)
        written.append(path)
    if not args.no_animation and len(frames) > 1:
        from matplotlib.animation import PillowWriter

        picked = sorted({int(round(i)) for i in np.linspace(0, len(frames) - 1, min(args.frames, len(frames)))})
        fig = snapshot_figure(first, view, args.field, vmax, size)
        ax = fig.axes[0]
        path = os.path.join(out, f"{args.field}.gif")
        writer = PillowWriter(fps=args.fps)
        with writer.saving(fig, path, dpi=100):
            for i in picked:
                frame = loaded.get(i) or frames[i][1]([args.field])
                for artist in list(ax.collections):
                    artist.remove()
                draw_field(ax, frame, view, args.field, vmax, "viridis")
                where = "" if view.dim == 2 else f", {view.names[view.slice_axis]} = {view.slice_at:.3g} m"
                ax.set_title(f"t = {frame.time:.3f} s{where}", fontsize=9)
                writer.grab_frame()
        plt.close(fig)
        written.append(path)
    if view.dim == 3 and not args.no_iso:
        # at the last chosen time (--times), else at the last output
        last = frames[chosen[-1] if args.times else -1][1](["alpha_g"])
        if "alpha_g" in last.fields:
            fig = iso_figure(last, view, "alpha_g", args.iso, (max(size[0], 500), size[1]))
            path = os.path.join(out, "alpha_g_iso.png")
            fig.savefig(path, dpi=100)
            plt.close(fig)
            written.append(path)
    for path in written:
        print(path)


if __name__ == "__main__":
    main()
