#!/usr/bin/python3
"""halfspace's plotting tool: figures from any halfspace HDF5 file.

Subcommands (PNG files are written next to the input unless --out is given):

  maps FILE.h5 [--step K]  height, pressure and contact maps of a result file
                           (docs/file-format.md); 1D results as line plots;
                           for a sweep file, load step K (default the last)
  profile FILE.h5 [--row J] [--step K]
                           a line through a 2D map (row J, default the middle
                           row; or the whole 1D profile): height and gap above,
                           pressure below
  sweep FILE.h5            contact fraction and mean gap (or approach) against
                           the mean pressure of a sweep file (1D datasets
                           /sweep/mean_pressure, /sweep/contact_fraction, ...)
  friction FILE.h5         a frictional result (solve --friction): the
                           tangential force Q_x against the approach
                           delta_x of a history (the fretting loop, from
                           /history) and the stick/slip map of the last step
  paper DIR                the Table 1 reproduction figures from DIR/testN.h5
                           (written by `halfspace paper`, docs/paper.md)
  film FILE.h5             a lubricated film (`halfspace lubricate`): pressure
                           and film thickness along the centre line (the
                           profile, or the middle row of a map; a mixed film's
                           fluid and contact pressures apart), and for a map
                           also the pressure, film and fluid fraction maps
  stribeck FILE.csv        a Stribeck curve (`lubricate --speeds --stribeck`):
                           the friction coefficient and the contact's share
                           of the load against the entrainment speed and the
                           Hersey number

--out names the output: a file ending in .png for a command that draws one
figure, else a directory. Also importable: plot_maps, plot_profile,
plot_sweep, plot_friction, plot_paper, plot_film and plot_stribeck take a path and return the PNG paths written.

Needs Debian's python3 with python3-matplotlib, python3-h5py and
python3-numpy (scripts/install-deps.sh); the shebang names /usr/bin/python3
so that another python3 earlier on PATH does not hide them.
"""

import argparse
import glob
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")  # files only, no display

import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

DPI = 110  # keeps line figures at tens of KB and maps well under 200 KB


class PlotError(Exception):
    """A file that is not what the subcommand needs; the message says why."""


# ---------------------------------------------------------------- units


def length_unit(extent):
    """(scale, label) so that lengths up to `extent` (m) read well."""
    if extent < 1e-6:
        return 1e9, "nm"
    if extent < 1e-3:
        return 1e6, "µm"
    if extent < 1.0:
        return 1e3, "mm"
    return 1.0, "m"


def pressure_unit(peak):
    """(scale, label) for pressures up to `peak` (Pa)."""
    for scale, label in ((1e-9, "GPa"), (1e-6, "MPa"), (1e-3, "kPa")):
        if peak >= 1.0 / scale:
            return scale, label
    return 1.0, "Pa"


def _attr(f, name, default=None):
    value = f.attrs.get(name, default)
    if isinstance(value, bytes):
        value = value.decode("utf-8", "replace")
    return value


def _output_path(source, suffix, out, single=True):
    """Where a figure goes: --out (a .png file or a directory) or next to `source`."""
    base = os.path.splitext(os.path.basename(source.rstrip("/")))[0]
    name = f"{base}{suffix}.png"
    if out is None:
        directory = source if os.path.isdir(source) else os.path.dirname(os.path.abspath(source))
        return os.path.join(directory, name)
    if single and out.endswith(".png"):
        return out
    os.makedirs(out, exist_ok=True)
    return os.path.join(out, name)


def _save(fig, path):
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
    return path


# ---------------------------------------------------------------- results


def read_result(path, step=None):
    """A halfspace result file as a dict of numpy arrays and attributes.

    For a sweep file (fields in /steps/NNN) the fields of load step `step`
    are read, the last one by default.
    """
    if not os.path.isfile(path):
        raise PlotError(f"{path}: no such file")
    with h5py.File(path, "r") as f:
        kind = _attr(f, "format", "")
        if kind == "halfspace-paper-test":
            raise PlotError(f"{path} is a paper reproduction file: use 'paper {os.path.dirname(path) or '.'}'")
        fields, attrs = f, {key: _attr(f, key) for key in f.attrs}
        if "steps" in f and "pressure" not in f:
            steps = sorted(f["steps"].keys())
            if not steps:
                raise PlotError(f"{path}: the sweep has no steps")
            index = len(steps) - 1 if step is None else step
            if not 0 <= index < len(steps):
                raise PlotError(f"--step {step} is out of range: the sweep has steps 0 to {len(steps) - 1}")
            fields = f["steps"][steps[index]]
            attrs.update({key: _attr(fields, key) for key in fields.attrs})
            attrs["step"] = index
        elif step is not None:
            raise PlotError(f"--step {step}: {path} is not a sweep file")
        missing = [name for name in ("pressure", "gap") if name not in fields] + (["height"] if "height" not in f else [])
        if missing:
            raise PlotError(f"{path}: not a halfspace result file (no dataset {', '.join('/' + m for m in missing)})")
        result = {name: fields[name][...] for name in ("pressure", "gap", "displacement", "contact") if name in fields}
        result["height"] = f["height"][...]
        result["attrs"] = attrs
    if "contact" not in result:
        result["contact"] = (result["pressure"] > 0).astype(np.uint8)
    attrs = result["attrs"]
    result["dimension"] = int(attrs.get("dimension", result["pressure"].ndim))
    result["dx"] = float(attrs.get("dx", 1.0))
    result["dy"] = float(attrs.get("dy", 0.0))
    return result


def _title(result, path):
    a = result["attrs"]
    parts = [os.path.basename(path)]
    if "step" in a:
        parts.append(f"step {a['step']}")
    if "solver" in a:
        parts.append(str(a["solver"]))
    if "mean_pressure" in a:
        parts.append(f"mean pressure {float(a['mean_pressure']):.3g} Pa")
    if "contact_fraction" in a:
        parts.append(f"contact {100 * float(a['contact_fraction']):.2f} %")
    return ", ".join(parts)


def _line_figure(result, path, x, height, gap, pressure, xlabel):
    """Two stacked panels: height and gap, then pressure, against x."""
    lscale, lunit = length_unit(max(np.ptp(height), np.ptp(gap), 1e-300) * 10)
    pscale, punit = pressure_unit(max(float(np.max(pressure)), 1e-300))
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5), constrained_layout=True)
    top.plot(x, height * lscale, color="0.3", label="height")
    top.plot(x, gap * lscale, color="tab:blue", label="gap after loading")
    top.set_ylabel(f"height, gap ({lunit})")
    top.legend(loc="best", fontsize="small")
    bottom.plot(x, pressure * pscale, color="tab:red")
    bottom.fill_between(x, 0, pressure * pscale, color="tab:red", alpha=0.15)
    bottom.set_ylabel(f"pressure ({punit})")
    bottom.set_xlabel(xlabel)
    top.set_title(_title(result, path), fontsize="small")
    return fig


def plot_maps(path, out=None, step=None):
    """Height, pressure and contact maps (2D) or line plots (1D) of a result file (or of a sweep's step)."""
    result = read_result(path, step)
    suffix = "_maps" if step is None else f"_maps_step{step}"
    if result["dimension"] == 1:
        n = result["pressure"].shape[-1]
        xscale, xunit = length_unit(n * result["dx"])
        x = np.arange(n) * result["dx"] * xscale
        fig = _line_figure(result, path, x, result["height"], result["gap"], result["pressure"], f"x ({xunit})")
        return [_save(fig, _output_path(path, suffix, out))]

    ny, nx = result["pressure"].shape
    dx, dy = result["dx"], result["dy"] or result["dx"]
    scale, unit = length_unit(max(nx * dx, ny * dy))
    extent = (0, nx * dx * scale, 0, ny * dy * scale)
    hscale, hunit = length_unit(max(np.ptp(result["height"]), 1e-300) * 10)
    pscale, punit = pressure_unit(max(float(np.max(result["pressure"])), 1e-300))
    panels = (
        (result["height"] * hscale, f"height ({hunit})", "viridis"),
        (result["pressure"] * pscale, f"pressure ({punit})", "magma"),
        (result["contact"], "contact (1 = in contact)", "Greys"),
    )
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2), constrained_layout=True)
    for axis, (field, label, cmap) in zip(axes, panels):
        image = axis.imshow(field, origin="lower", extent=extent, cmap=cmap, interpolation="nearest", aspect="equal")
        axis.set_xlabel(f"x ({unit})")
        axis.set_ylabel(f"y ({unit})")
        ticks = [0, 1] if field is result["contact"] else None
        fig.colorbar(image, ax=axis, shrink=0.85, label=label, ticks=ticks)
    fig.suptitle(_title(result, path), fontsize="small")
    return [_save(fig, _output_path(path, suffix, out))]


def plot_profile(path, row=None, out=None, step=None):
    """Height, gap and pressure along row `row` of a 2D map (middle row by default), or a 1D profile."""
    result = read_result(path, step)
    if result["dimension"] == 1:
        height, gap, pressure = result["height"], result["gap"], result["pressure"]
        label, suffix = "x", "_profile"
    else:
        ny = result["pressure"].shape[0]
        row = ny // 2 if row is None else row
        if not 0 <= row < ny:
            raise PlotError(f"--row {row} is out of range: the map has rows 0 to {ny - 1}")
        height, gap, pressure = (result[name][row] for name in ("height", "gap", "pressure"))
        label, suffix = f"x along row {row} (y = {row * result['dy']:.3g} m)", f"_profile_row{row}"
    n = pressure.shape[0]
    xscale, xunit = length_unit(n * result["dx"])
    x = np.arange(n) * result["dx"] * xscale
    fig = _line_figure(result, path, x, height, gap, pressure, f"{label} ({xunit})")
    if step is not None:
        suffix += f"_step{step}"
    return [_save(fig, _output_path(path, suffix, out))]


# ---------------------------------------------------------------- friction


def plot_friction(path, out=None):
    """The loop Q_x against delta_x of a friction history (if the file is one) and the stick/slip map."""
    if not os.path.isfile(path):
        raise PlotError(f"{path}: no such file")
    with h5py.File(path, "r") as f:
        if "stick" not in f or "contact" not in f:
            raise PlotError(f"{path}: not a frictional result (no /stick; solve with --friction)")
        history = {name: np.asarray(f["history"][name][...]) for name in f["history"]} if "history" in f else None
        stick = np.asarray(f["stick"][...])
        contact = np.asarray(f["contact"][...])
        dx = float(_attr(f, "dx", 1.0))
        dy = float(_attr(f, "dy", 0.0)) or dx
        one_d = int(_attr(f, "dimension", stick.ndim)) == 1
    # 0 out of contact, 1 slip, 2 stick.
    state = np.where(contact > 0, np.where(stick > 0, 2, 1), 0)
    fig, axes = plt.subplots(1, 2 if history is not None else 1, figsize=(11 if history is not None else 6, 4.2),
                             constrained_layout=True)
    axes = np.atleast_1d(axes)
    if history is not None:
        delta = history["delta_x"]
        lscale, lunit = length_unit(max(float(np.max(np.abs(delta))), 1e-300) * 10)
        force_unit = "N/m" if one_d else "N"
        axes[0].plot(np.concatenate([[0.0], delta * lscale]), np.concatenate([[0.0], history["Q_x"]]), "o-",
                     color="tab:purple", ms=3)
        axes[0].set_xlabel(f"tangential approach delta_x ({lunit})")
        axes[0].set_ylabel(f"tangential force Q_x ({force_unit})")
        axes[0].set_title(f"{len(delta)} steps, dissipated {np.sum(history['dissipated_energy']):.3g} "
                          f"{'J/m' if one_d else 'J'}", fontsize="small")
        axes[0].grid(True, alpha=0.3)
    axis = axes[-1]
    cmap = matplotlib.colors.ListedColormap(["white", "tab:orange", "tab:blue"])
    if one_d:
        scale, unit = length_unit(state.size * dx)
        axis.step(np.arange(state.size) * dx * scale, state, where="mid", color="black")
        axis.set_yticks([0, 1, 2], ["out", "slip", "stick"])
        axis.set_xlabel(f"x ({unit})")
    else:
        ny, nx = state.shape
        scale, unit = length_unit(max(nx * dx, ny * dy))
        image = axis.imshow(state, origin="lower", extent=(0, nx * dx * scale, 0, ny * dy * scale), cmap=cmap,
                            vmin=0, vmax=2, interpolation="nearest", aspect="equal")
        colorbar = fig.colorbar(image, ax=axis, shrink=0.85, ticks=[0, 1, 2])
        colorbar.ax.set_yticklabels(["out", "slip", "stick"])
        axis.set_xlabel(f"x ({unit})")
        axis.set_ylabel(f"y ({unit})")
    axis.set_title("stick and slip" + (" (last step)" if history is not None else ""), fontsize="small")
    fig.suptitle(os.path.basename(path), fontsize="small")
    return [_save(fig, _output_path(path, "_friction", out))]


# ---------------------------------------------------------------- sweeps


def plot_sweep(path, out=None):
    """Contact fraction and mean gap (else approach) against the mean pressure of a sweep file."""
    if not os.path.isfile(path):
        raise PlotError(f"{path}: no such file")
    with h5py.File(path, "r") as f:
        if "sweep" not in f:
            raise PlotError(f"{path}: not a sweep file (no group /sweep)")
        sweep = {name: np.asarray(f["sweep"][name][...]) for name in f["sweep"] if f["sweep"][name].ndim == 1}
    for name in ("mean_pressure", "contact_fraction"):
        if name not in sweep:
            raise PlotError(f"{path}: the sweep has no dataset /sweep/{name}")
    load = sweep["mean_pressure"]
    order = np.argsort(load)
    second = "mean_gap" if "mean_gap" in sweep else ("approach" if "approach" in sweep else None)
    pscale, punit = pressure_unit(float(np.max(load)))
    positive = load[load > 0]
    logarithmic = positive.size == load.size and positive.size > 1 and np.max(positive) / np.min(positive) > 100

    fig, axes = plt.subplots(1, 2 if second else 1, figsize=(11 if second else 6, 4.2), constrained_layout=True)
    axes = np.atleast_1d(axes)
    axes[0].plot(load[order] * pscale, sweep["contact_fraction"][order], "o-", color="tab:red", ms=3)
    axes[0].set_ylabel("contact fraction A/A0")
    if second:
        values = sweep[second][order]
        lscale, lunit = length_unit(max(float(np.max(np.abs(values))), 1e-300) * 10)
        axes[1].plot(load[order] * pscale, values * lscale, "o-", color="tab:blue", ms=3)
        axes[1].set_ylabel(f"{second.replace('_', ' ')} ({lunit})")
    for axis in axes:
        axis.set_xlabel(f"mean pressure ({punit})")
        if logarithmic:
            axis.set_xscale("log")
        axis.grid(True, alpha=0.3)
    fig.suptitle(os.path.basename(path), fontsize="small")
    return [_save(fig, _output_path(path, "_sweep", out))]


# ---------------------------------------------------------------- lubricated films


def read_film(path):
    """A `halfspace lubricate` file as a dict of numpy arrays and attributes."""
    if not os.path.isfile(path):
        raise PlotError(f"{path}: no such file")
    with h5py.File(path, "r") as f:
        missing = [name for name in ("pressure", "film", "fluid_fraction") if name not in f]
        if missing:
            raise PlotError(f"{path}: not a lubricated film file (no dataset {', '.join('/' + m for m in missing)})")
        film = {name: f[name][...] for name in ("pressure", "film", "fluid_fraction", "fluid_pressure",
                                                "contact_pressure", "deformation") if name in f}
        film["attrs"] = {key: _attr(f, key) for key in f.attrs}
    attrs = film["attrs"]
    film["dimension"] = int(attrs.get("dimension", film["pressure"].ndim))
    film["dx"] = float(attrs.get("dx", 1.0))
    film["dy"] = float(attrs.get("dy", 0.0))
    return film


def _film_title(film, path):
    a = film["attrs"]
    parts = [os.path.basename(path), f"{a.get('model', 'film')} film"]
    if "entrainment_speed" in a:
        parts.append(f"U {float(a['entrainment_speed']):.3g} m/s")
    if "central_film_thickness" in a:
        parts.append(f"h_c {float(a['central_film_thickness']):.3g} m")
    if "contact_load_fraction" in a:
        parts.append(f"contact {100 * float(a['contact_load_fraction']):.1f} % of the load")
    if "friction_coefficient" in a:
        parts.append(f"mu {float(a['friction_coefficient']):.3g}")
    return ", ".join(parts)


def plot_film(path, out=None):
    """Pressure and film along the centre line (fluid and contact pressure apart for a mixed film); maps for 2D."""
    film = read_film(path)
    line = {name: (values if film["dimension"] == 1 else values[values.shape[0] // 2])
            for name, values in film.items() if isinstance(values, np.ndarray)}
    n = line["pressure"].shape[0]
    xscale, xunit = length_unit(n * film["dx"])
    x = np.arange(n) * film["dx"] * xscale
    pscale, punit = pressure_unit(max(float(np.max(film["pressure"])), 1e-300))
    lscale, lunit = length_unit(max(float(np.max(line["film"])), 1e-300) * 10)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5.5), constrained_layout=True)
    if "contact_pressure" in line:
        top.plot(x, line["fluid_pressure"] * pscale, color="tab:blue", label="fluid pressure")
        top.plot(x, line["contact_pressure"] * pscale, color="tab:red", label="contact pressure")
        top.plot(x, line["pressure"] * pscale, color="0.3", linewidth=0.8, linestyle="--", label="total")
        top.legend(loc="best", fontsize="small")
    else:
        top.plot(x, line["pressure"] * pscale, color="tab:red")
    top.set_ylabel(f"pressure ({punit})")
    top.grid(True, alpha=0.3)
    bottom.plot(x, line["film"] * lscale, color="tab:blue")
    bottom.set_ylabel(f"film thickness h ({lunit})")
    where = "x" if film["dimension"] == 1 else f"x along the middle row (row {film['pressure'].shape[0] // 2})"
    bottom.set_xlabel(f"{where} ({xunit})")
    bottom.grid(True, alpha=0.3)
    fig.suptitle(_film_title(film, path), fontsize="small")
    written = [_save(fig, _output_path(path, "_film", out, single=film["dimension"] == 1))]
    if film["dimension"] == 1:
        return written

    ny, nx = film["pressure"].shape
    dx, dy = film["dx"], film["dy"] or film["dx"]
    scale, unit = length_unit(max(nx * dx, ny * dy))
    extent = (0, nx * dx * scale, 0, ny * dy * scale)
    hscale, hunit = length_unit(max(float(np.max(film["film"])), 1e-300) * 10)
    if "contact_pressure" in film:
        panels = ((film["fluid_pressure"] * pscale, f"fluid pressure ({punit})", "magma"),
                  (film["contact_pressure"] * pscale, f"contact pressure ({punit})", "magma"),
                  (film["film"] * hscale, f"film thickness ({hunit})", "viridis"))
    else:
        panels = ((film["pressure"] * pscale, f"pressure ({punit})", "magma"),
                  (film["film"] * hscale, f"film thickness ({hunit})", "viridis"),
                  (film["fluid_fraction"], "fluid fraction theta", "Blues"))
    fig, axes = plt.subplots(1, 3, figsize=(13, 4.2), constrained_layout=True)
    for axis, (field, label, cmap) in zip(axes, panels):
        image = axis.imshow(field, origin="lower", extent=extent, cmap=cmap, interpolation="nearest", aspect="equal")
        axis.set_xlabel(f"x ({unit})")
        axis.set_ylabel(f"y ({unit})")
        fig.colorbar(image, ax=axis, shrink=0.85, label=label)
    fig.suptitle(_film_title(film, path), fontsize="small")
    written.append(_save(fig, _output_path(path, "_film_maps", out, single=False)))
    return written


def read_stribeck(path):
    """A Stribeck curve CSV (`halfspace lubricate --stribeck`) as a dict of columns."""
    if not os.path.isfile(path):
        raise PlotError(f"{path}: no such file")
    with open(path, newline="") as file:
        header = file.readline().strip().split(",")
        rows = [line.strip().split(",") for line in file if line.strip()]
    needed = ("entrainment_speed", "hersey_number", "friction_coefficient", "contact_load_fraction")
    missing = [name for name in needed if name not in header]
    if missing:
        raise PlotError(f"{path}: not a Stribeck curve (no column {', '.join(missing)})")
    if not rows:
        raise PlotError(f"{path}: the Stribeck curve has no points")
    columns = {name: [row[k] for row in rows] for k, name in enumerate(header)}
    curve = {name: np.array(columns[name], dtype=float) for name in needed}
    curve["status"] = columns.get("status", ["converged"] * len(rows))
    return curve


def plot_stribeck(path, out=None):
    """The friction coefficient and the contact's load share against the speed and the Hersey number."""
    curve = read_stribeck(path)
    order = np.argsort(curve["entrainment_speed"])
    failed = np.array([status != "converged" for status in curve["status"]])[order]
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    for axis, name, label in ((axes[0], "entrainment_speed", "entrainment speed U (m/s)"),
                              (axes[1], "hersey_number", "Hersey number eta0 U / w'")):
        x = curve[name][order]
        axis.plot(x, curve["friction_coefficient"][order], "o-", color="tab:red", ms=3, label="friction coefficient")
        if failed.any():
            axis.plot(x[failed], curve["friction_coefficient"][order][failed], "x", color="k", ms=7,
                      label="not converged")
        axis.set_xscale("log")
        mu = curve["friction_coefficient"]
        if np.all(mu > 0) and np.max(mu) > 50 * np.min(mu):
            axis.set_yscale("log")
        axis.set_xlabel(label)
        axis.set_ylabel("friction coefficient mu", color="tab:red")
        axis.grid(True, alpha=0.3, which="both")
        twin = axis.twinx()
        twin.plot(x, curve["contact_load_fraction"][order], "s--", color="tab:blue", ms=3)
        twin.set_ylabel("contact share of the load", color="tab:blue")
        twin.set_ylim(-0.02, 1.02)
        if failed.any():
            axis.legend(loc="best", fontsize="small")
    fig.suptitle(f"{os.path.basename(path)}: Stribeck curve", fontsize="small")
    return [_save(fig, _output_path(path, "_stribeck", out))]


# ---------------------------------------------------------------- paper

_METHODS = (
    ("p_lemke", "Lemke (LCPSolve)", "tab:blue", "-", None),
    ("p_lcpquad", "LCPquad (QP)", "tab:orange", "--", None),
    ("p_pk", "Polonsky–Keer (FFT)", "tab:green", ":", None),
    ("p_hertz", "Hertz", "0.2", "none", "o"),
)
_VARIANTS = {
    "p_lcpquad_si": ("LCPquad in SI units, load as equality", "tab:purple", "-"),
    "p_lcpquad_si_approach": ("LCPquad in SI units, approach of Lemke", "tab:brown", "--"),
    "p_lemke_eq4": ("Lemke, paper's eq. (4) kernel", "tab:pink", "-"),
}


def read_paper_test(path):
    """One testN.h5 of `halfspace paper` as a dict of arrays and attributes."""
    with h5py.File(path, "r") as f:
        if _attr(f, "format", "") != "halfspace-paper-test":
            raise PlotError(f"{path}: not a paper reproduction file (format attribute is not halfspace-paper-test)")
        data = {name: f[name][...] for name in f}
        data["attrs"] = {key: _attr(f, key) for key in f.attrs}
    return data


def _pressure_axes(axis, data, names, title):
    a = data["attrs"]
    peak, x = float(a["hertz_peak"]), data["x"] * 1e3
    few = x.size <= 30  # then mark the nodes of every method
    for name, label, color, style, marker in _METHODS:
        if name in names:
            axis.plot(x, data[name] / peak, color=color, linestyle=style, marker=marker or ("." if few else None),
                      ms=3 if marker else 5, label=label)
    axis.set_xlabel("x (mm)")
    axis.set_ylabel("p / p_H")
    axis.set_title(title, fontsize="small")
    axis.grid(True, alpha=0.3)


def _with_gap(axis, data):
    """The initial gap x^2/(2R) on a second axis, drawn smooth between the nodes."""
    twin = axis.twinx()
    x = np.linspace(data["x"].min(), data["x"].max(), 400)
    gap = x**2 / (2.0 * float(data["attrs"]["radius"]))
    twin.plot(x * 1e3, gap * 1e6, color="0.6", linewidth=1, label="initial gap")
    twin.set_ylabel("initial gap x²/(2R) (µm)", color="0.4")
    twin.tick_params(axis="y", colors="0.4")
    return twin


def plot_paper_test(path, out=None):
    """Figures of one test: pressures with the initial gap, a zoom with the differences, and variants if any."""
    data = read_paper_test(path)
    a = data["attrs"]
    test = int(a["test"])
    title = (f"Test {test}: N = {int(a['nodes'])}, R = {float(a['radius']) * 1e3:.4g} mm, "
             f"E* = {float(a['E_star']) / 1e9:.4g} GPa, W = {float(a['load']):.3g} N/m")
    written = []

    fig, axis = plt.subplots(figsize=(7.5, 4.5), constrained_layout=True)
    _pressure_axes(axis, data, [m[0] for m in _METHODS], title)
    twin = _with_gap(axis, data)
    lines = axis.get_legend_handles_labels()
    gap_lines = twin.get_legend_handles_labels()
    axis.legend(lines[0] + gap_lines[0], lines[1] + gap_lines[1], loc="upper right", fontsize="small")
    axis.set_ylim(bottom=0)
    written.append(_save(fig, _output_path(path, "", out, single=False)))

    # Zoom on the contact, and the differences from Lemke over p_H.
    peak, b = float(a["hertz_peak"]), float(a["hertz_half_width"])
    x = data["x"]
    window = np.abs(x) <= 1.3 * b if np.count_nonzero(np.abs(x) <= 1.3 * b) >= 3 else np.ones_like(x, bool)
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True)
    _pressure_axes(left, {**data, "x": x}, [m[0] for m in _METHODS], f"Test {test}: contact zone")
    left.set_xlim(x[window].min() * 1e3, x[window].max() * 1e3)
    left.legend(loc="lower center", fontsize="small")
    for name, label, color, style, _ in _METHODS[1:]:
        difference = (data[name] - data["p_lemke"]) / peak
        right.plot(x[window] * 1e3, difference[window], color=color, linestyle="-" if style == "none" else style,
                   marker="o" if name == "p_hertz" else None, ms=2, label=f"{label} − Lemke")
    right.set_yscale("symlog", linthresh=1e-12)
    right.set_xlabel("x (mm)")
    right.set_ylabel("(p − p_Lemke) / p_H")
    right.set_title("differences from Lemke (symmetric log scale, linear below 1e-12)", fontsize="small")
    right.grid(True, alpha=0.3)
    right.legend(loc="best", fontsize="small")
    written.append(_save(fig, _output_path(path, "_zoom", out, single=False)))

    variants = [name for name in _VARIANTS if name in data]
    if variants:
        fig, axis = plt.subplots(figsize=(7.5, 4.5), constrained_layout=True)
        _pressure_axes(axis, data, ["p_lemke", "p_hertz"], f"Test {test}: variants (docs/paper.md)")
        for name in variants:
            label, color, style = _VARIANTS[name]
            axis.plot(x * 1e3, data[name] / peak, color=color, linestyle=style, label=label)
        axis.legend(loc="upper right", fontsize="small")
        written.append(_save(fig, _output_path(path, "_variants", out, single=False)))
    return written


def plot_paper(directory, out=None):
    """All figures of a `halfspace paper` output directory."""
    if not os.path.isdir(directory):
        raise PlotError(f"{directory}: not a directory")
    files = sorted(glob.glob(os.path.join(directory, "test*.h5")),
                   key=lambda p: int(re.sub(r"\D", "", os.path.basename(p)) or 0))
    if not files:
        raise PlotError(f"{directory}: no testN.h5 files (run `halfspace paper --output-dir {directory}` first)")
    written = []
    for path in files:
        written += plot_paper_test(path, out)
    return written


# ---------------------------------------------------------------- command line


def main(argv=None):
    parser = argparse.ArgumentParser(prog="halfspace_plot.py", description=__doc__.split("\n\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)
    for name, help_text in (("maps", "height, pressure and contact maps of a result file"),
                            ("profile", "a line profile through a result file"),
                            ("sweep", "contact fraction and mean gap against load"),
                            ("friction", "the fretting loop and the stick/slip map of a frictional result"),
                            ("paper", "the Table 1 figures from a `halfspace paper` directory"),
                            ("film", "pressure and film of a lubricated film (`halfspace lubricate`)"),
                            ("stribeck", "a Stribeck curve (`halfspace lubricate --stribeck`)")):
        sub = commands.add_parser(name, help=help_text)
        sub.add_argument("path", metavar={"paper": "DIR", "stribeck": "FILE.csv"}.get(name, "FILE.h5"))
        sub.add_argument("--out", help="output .png file or directory [next to the input]")
        if name == "profile":
            sub.add_argument("--row", type=int, help="row index j of a 2D map [middle row]")
        if name in ("maps", "profile"):
            sub.add_argument("--step", type=int, help="load step of a sweep file, from 0 [the last]")
    args = parser.parse_args(argv)
    try:
        if args.command == "maps":
            written = plot_maps(args.path, args.out, args.step)
        elif args.command == "profile":
            written = plot_profile(args.path, args.row, args.out, args.step)
        elif args.command == "sweep":
            written = plot_sweep(args.path, args.out)
        elif args.command == "friction":
            written = plot_friction(args.path, args.out)
        elif args.command == "film":
            written = plot_film(args.path, args.out)
        elif args.command == "stribeck":
            written = plot_stribeck(args.path, args.out)
        else:
            written = plot_paper(args.path, args.out)
    except (PlotError, OSError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    for path in written:
        print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
