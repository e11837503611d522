"""The first-impact figures of one load probe of one run, in SI units and scaled: pressure by
rho g H, force by rho g H^2/2 (`impact.Scales.force`), time by sqrt(H/g), impulse by the
load's scale times sqrt(H/g). A force probe enters by one component (default: the force into
the tank face it sits on)."""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .impact import (CONTACT_FRACTION, DEFAULT_FILTER_S, DEFAULT_SMOOTH_S,
                     DEFAULT_WINDOW_STAR, first_impact_window, window_peaks)
from .runs import FORCE_COMPONENTS, BadInput, Probe, Run, read_probe
from .signals import dry_as_zero, moving_average

# The figures each row carries, in the load's unit (times in s); *_scaled beside each.
LOAD_KEYS = ["peak_raw", "peak_filt", "peak_smooth"]
TIME_KEYS = ["t_contact", "t_peak_raw", "t_peak_filt", "t_peak_smooth", "t_window_end"]


@dataclass
class Options:
    filter_s: float = DEFAULT_FILTER_S
    smooth_s: float = DEFAULT_SMOOTH_S
    window_star: float = DEFAULT_WINDOW_STAR  # 0: the window runs to t_to (or the record's end)
    t_from: float = -math.inf
    t_to: float = math.inf
    contact: float = CONTACT_FRACTION         # of the load's scale
    component: str | None = None              # force probes: Fx, -Fx, Fy, ...; None: default


def probe_signal(probe: Probe, component: str | None) -> tuple[np.ndarray, np.ndarray, str]:
    """(t, values, what) of a load probe: a pressure probe's pressure, a force probe's chosen
    component (a leading '-' reverses it)."""
    header, data = read_probe(probe.path)
    if probe.kind != "force":
        return data[:, 0], data[:, 1], "pressure"
    comp = component or probe.default_component()
    name = comp.lstrip("-")
    if name not in FORCE_COMPONENTS or f"{name}_N" not in header:
        have = ", ".join(h[:-2] for h in header if h.endswith("_N"))
        raise BadInput(f"{probe.path}: force probe '{probe.name}' has no component '{comp}' "
                       f"(it has {have}; a leading '-' reverses one)")
    v = data[:, header.index(f"{name}_N")]
    return data[:, 0], (-v if comp.startswith("-") else v), comp


def units(run: Run, probe: Probe) -> tuple[str, str, float | None, str]:
    """(load unit, impulse unit, scale value or None, scale's name) of a probe."""
    if probe.kind == "force":
        si = "N/m" if run.dimension == 2 else "N"
        scale = run.scales.force(run.dimension) if run.scales else None
        return si, si.replace("N", "N s"), scale, "rho g H^2/2"
    return "Pa", "Pa s", run.scales.p if run.scales else None, "rho g H"


def probe_figures(run: Run, probe: Probe, opt: Options) -> dict:
    """One row: the probe's first-impact figures over [t_from, t_to] (NaN where it never
    reaches contact); BadInput when the run has no scale for the contact threshold."""
    if run.scales is None:
        src = run.summary.get("source_file", "not recorded")
        raise BadInput(f"{run.folder}: no scale for the contact threshold: the case file "
                       f"(summary.json source_file: {src}) was not found; give --case CASE.toml "
                       "or --scale rho,g,H")
    t, v, what = probe_signal(probe, opt.component)
    unit, imp_unit, scale, scale_name = units(run, probe)
    sc = run.scales
    row = {"run": run.label, "probe": probe.name, "kind": probe.kind, "signal": what,
           "unit": unit, "impulse_unit": imp_unit, "dx": run.dx, "samples": int(len(t)),
           "scale": scale, "scale_unit": scale_name, "t_scale_s": sc.t}
    nan = math.nan
    row.update({k: nan for k in LOAD_KEYS + TIME_KEYS + ["impulse"]})
    row["window_complete"] = ""
    q = dry_as_zero(v)
    window_s = opt.window_star * sc.t if opt.window_star > 0 else math.inf
    window = first_impact_window(t, q, opt.contact * scale, window_s, opt.t_from, opt.t_to)
    if window is not None:
        tc, te = window
        if not math.isfinite(te):
            te = float(t[-1])
        pf = moving_average(t, q, opt.filter_s)
        ps = moving_average(t, q, opt.smooth_s)
        row.update(window_peaks(t, q, pf, ps, tc, te))
    for k in LOAD_KEYS:
        row[k + "_scaled"] = row[k] / scale
    for k in TIME_KEYS:
        row[k + "_star"] = row[k] / sc.t
    row["impulse_scaled"] = row["impulse"] / (scale * sc.t)
    return row


def run_figures(run: Run, names: list[str], opt: Options) -> list[dict]:
    """Rows for the named probes of a run (every load probe when names is empty)."""
    probes = [run.probe(n) for n in names] if names else list(run.probes.values())
    if not probes:
        raise BadInput(f"{run.folder}/probes: no load probe (pressure, area sensor or force)")
    return [probe_figures(run, p, opt) for p in probes]
