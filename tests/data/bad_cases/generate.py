#!/usr/bin/env python3
"""Generates the malformed/hostile case corpus in tests/data/bad_cases/generated/ from valid
cases: every file must be refused by `sluice check` with exit code 2 and a message naming the
key in expected.tsv (or, for broken syntax, the TOML parse position).

Run from anywhere: /usr/bin/python3 tests/data/bad_cases/generate.py [--sluice EXE] [OUT_DIR]
(deterministic; the output is committed: rerun after changing this script or the case schema
and commit the result; a ctest regenerates into a temporary folder and compares).

The keys come from the case schema, `EXE schema` (default: build/release/sluice): for every
key a wrong-type case, for a number, an integer or a vector with an interval (the schema's
min and max) a value just below and just above it (for a vector in its first component), for
a string or an array of strings with choices an unknown one, and for a key of one scheme
(numerics.scheme) a case of the other scheme carrying it. The hand-written mutations below add hostile values
(overflow, non-finite numbers, names that escape the results folder) and structural damage.

expected.tsv: <file>\t<what the message must name>, where the second column is a dotted key
('fluid.rho0', 'blocks[0].lo'), '@syntax' (a TOML parse error with line and column) or
'@any' (either: a truncated file may still parse and then lack a key).
"""
import argparse
import copy
import json
import math
import random
import re
import shutil
import subprocess
import tomllib
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[2]
BASES = {
    "db2": ROOT / "cases" / "dam_break_2d.toml",      # 2-D, dummy walls, probes
    "deb3": ROOT / "cases" / "debris_box_3d.toml",    # 3-D
    "per2": ROOT / "tests" / "data" / "uniform_flow_periodic.toml",  # periodic, no walls
}
# The base of each scheme for the schema-driven mutations.
SCHEME_BASES = {"wcsph": ("db2", ROOT / "cases" / "dam_break_2d.toml"),
                "projection": ("pdb2", ROOT / "cases" / "projection_dam_break_2d.toml")}
# Valid entries added where a base lacks one, so that a mutation of one key meets no other
# problem first: a wall plane, an obstacle clear of the fluid, a force probe.
SAMPLE_ENTRIES = {
    "walls.planes": {"point": [0.0, 0.0], "normal": [1.0, 0.0]},
    "walls.boxes": {"lo": [1.0, 0.0], "hi": [1.2, 0.2]},
    # The obstacle column's STL cut by z = 0.2: a square in the tank, clear of the fluid (the
    # path is relative to generated/).
    "walls.meshes": {"file": "../../../../cases/meshes/obstacle_box_3d.stl", "role": "solid",
                     "section_z": 0.2},
    "force": {"name": "F", "type": "force", "face": "x+"},
    # An area sensor on the x- face of the 2-D bases' tank (tank_lo = [0, 0]), 0.1 m up.
    "area": {"name": "A", "type": "pressure", "position": [0.0, 0.1], "diameter": 0.02},
    "damping_zones": {"start": [1.2, 0.0], "end": [1.6, 0.0]},
}
# A complete [[motions]] entry of each kind, so that a mutation of one of its keys is what the
# reader meets first (a motion file's keys are mutated on a "file" entry without a file: the
# mutated key is read before the file is).
SAMPLE_MOTIONS = {
    "sway": {"amplitude": [0.01, 0.0], "period": 1.0},
    "roll": {"angle": 2.0, "period": 1.0, "centre": [0.8, 0.0]},
    "constant_velocity": {"velocity": [0.1, 0.0]},
    "constant_acceleration": {"acceleration": [0.1, 0.0]},
    "file": {},
    "piston": {"wave_height": 0.01, "wave_period": 1.0, "depth": 0.4},
    "flap": {"wave_height": 0.01, "wave_period": 1.0, "depth": 0.4, "centre": [0.0, 0.0]},
    "piston_irregular": {"hs": 0.01, "tp": 1.0, "depth": 0.4},
    "free_body": {"density": 500.0},
}

# ------------------------------------------------------------------------------------------
# A small TOML writer (tomllib only reads): enough for case files, and able to write values
# TOML allows but a case must refuse (nan, inf, inline tables, mixed arrays).


def value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # JSON escapes are valid TOML basic-string escapes
    if isinstance(v, list):
        return "[" + ", ".join(value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{k} = {value(x)}" for k, x in v.items()) + " }"
    raise TypeError(v)


def is_table_array(v):
    return isinstance(v, list) and v and all(isinstance(x, dict) for x in v)


def dump(doc, prefix=""):
    lines = []
    for k, v in doc.items():
        if not isinstance(v, dict) and not is_table_array(v):
            lines.append(f"{k} = {value(v)}")
    for k, v in doc.items():
        name = f"{prefix}{k}"
        if isinstance(v, dict):
            lines += ["", f"[{name}]", dump(v, name + ".")]
        elif is_table_array(v):
            for entry in v:
                lines += ["", f"[[{name}]]", dump(entry, name + ".")]
    return "\n".join(lines).strip("\n") + "\n"


# ------------------------------------------------------------------------------------------
# Structured mutations: (name, function(doc) -> doc, expected key). Keys are the display
# paths of the case reader (docs/CASE_REFERENCE.md).


def set_at(path, v):
    def f(doc):
        d = doc
        parts = path.replace("]", "").replace("[", ".").split(".")
        for p in parts[:-1]:
            d = d[int(p)] if p.isdigit() else d.setdefault(p, {})
        d[parts[-1]] = v
        return doc
    return f


def delete_at(path):
    def f(doc):
        d = doc
        parts = path.replace("]", "").replace("[", ".").split(".")
        for p in parts[:-1]:
            d = d[int(p)] if p.isdigit() else d[p]
        del d[parts[-1]]
        return doc
    return f


def has(doc, path):
    d = doc
    for p in path.replace("]", "").replace("[", ".").split("."):
        if p.isdigit():
            if not isinstance(d, list) or int(p) >= len(d):
                return False
            d = d[int(p)]
        elif isinstance(d, dict) and p in d:
            d = d[p]
        else:
            return False
    return True


WRONG_TYPES = [("str", "heavy"), ("bool", True), ("arr", [1, 2]), ("tbl", {"x": 1})]
NON_FINITE = [("nan", float("nan")), ("inf", float("inf")), ("ninf", float("-inf"))]

# Numeric keys and values each must refuse (beyond wrong types and non-finite numbers).
NUMBERS = {
    "fluid.rho0": [-1000.0, 0, 1e308, 1e7],
    "fluid.viscosity": [-1e-3, 1e308],
    "fluid.sound_speed": [0, -28.0, 1e308],
    "fluid.gamma": [0, -7.0, 1e300],
    "fluid.background_pressure": [-1.0, 1e300],
    "particles.dx": [0, -0.01, 1e-300, 5e-324, 1e-7],
    "numerics.h_over_dx": [0, -1.0, 1e300, 0.1],
    "numerics.cfl": [0, -0.1, 2.0, 1e308],
    "numerics.viscous_cfl": [0, 1.5],
    "numerics.force_cfl": [-1.0, 7],
    "numerics.delta_sph": [-0.1, 1e300],
    "numerics.artificial_viscosity": [-1.0, 1e300],
    "numerics.shifting": [-1.0, 100],
    "numerics.dt": [0, -1e-4, 1e300, 1.0],
    "time.end_time": [0, -1.0],
    "time.output_interval": [-0.1, 1e-300],
    "walls.restitution": [-0.5, 1.5],
    "runtime.particles_per_group": [0, -5, 2**62, 1.5],
    "runtime.rebalance_threshold": [0, 100.0],
    "runtime.rebalance_window": [0, 10**12],
    "runtime.rebalance_every": [-1, 10**15],
    "case.dimension": [1, 4, 0, -2, 2.0, 2**63 - 1],
    "blocks[0].amplitude": [1e300],
}
CHOICES = {
    "numerics.kernel": ["quintc", "", 3],
    "numerics.density": ["sum"],
    "fluid.eos": ["tate"],
    "walls.model": ["rigid"],
    "runtime.balance_cost": ["memory"],
    "runtime.initial_decomposition": ["random"],
    "walls.tank_faces": [["w+"], "x-", ["x-", "x-"]],
    "output.fields": [["pressur"], "pressure", ["id", "id"]],
    "output.snapshots": ["yes", 1],
    "numerics.wall_artificial_viscosity": ["no", 0],
    "numerics.dissipation": ["godunov", "", 1],
    "blocks[0].hydrostatic": ["no"],
    "blocks[0].profile": ["swirl"],
    # Names become folder/file names: nothing may escape results/<case>/.
    "case.name": ["../../etc/evil", "/tmp/abs", "..", ".", "", "a\u0000b", "x" * 300,
                  "a\\b", 42, "line\nbreak"],
    "case.description": [7],
}


def triples(dim):
    bad = [("len1", [0.5]), ("empty", []), ("str", ["a"] * dim), ("nan", [float("nan")] * dim),
           ("long", [0.1] * (dim + 1)), ("nested", [[0.1]] * dim), ("scalar", 0.5)]
    if dim == 3:
        bad.append(("len2", [0.1, 0.2]))
    return bad


def structured(base, doc):
    dim = doc["case"]["dimension"]
    muts = []

    def add(name, fn, key):
        muts.append((name, fn, key))

    keys = list(NUMBERS) + list(CHOICES)
    for key in NUMBERS:
        parent = key.rsplit(".", 1)[0]
        tag = key.replace("[", "").replace("]", "").replace(".", "_")
        for i, v in enumerate(NUMBERS[key]):
            add(f"{tag}_bad{i}", set_at(key, v), key)
        # Wrong types and non-finite values: once per key over the corpus (first base).
        if base == "db2":
            for t, v in WRONG_TYPES:
                add(f"{tag}_{t}", set_at(key, v), key)
            if key not in ("case.dimension",) and not key.startswith("runtime.") or \
                    key == "runtime.rebalance_threshold":
                for t, v in NON_FINITE:
                    add(f"{tag}_{t}", set_at(key, v), key)
    for key, vals in CHOICES.items():
        tag = key.replace("[", "").replace("]", "").replace(".", "_")
        for i, v in enumerate(vals):
            add(f"{tag}_bad{i}", set_at(key, v), key)
    # A wrong element type is blamed on the element.
    add("walls_tank_faces_int", set_at("walls.tank_faces", ["x-", 1]), "walls.tank_faces[1]")
    add("output_fields_nested", set_at("output.fields", [["id"]]), "output.fields[0]")

    # Vectors of the wrong length or type.
    for key in ["domain.lo", "domain.hi", "fluid.gravity", "blocks[0].lo", "blocks[0].hi",
                "blocks[0].velocity"]:
        tag = key.replace("[", "").replace("]", "").replace(".", "_")
        for t, v in triples(dim):
            shown = key + "[0]" if t in ("str", "nan", "nested") else key
            add(f"{tag}_{t}", set_at(key, v), shown)
    if "walls" in doc and doc["walls"].get("model", "none") != "none":
        for key in ["walls.tank_lo", "walls.tank_hi"]:
            tag = key.replace(".", "_")
            for t, v in triples(dim)[:3]:
                shown = key + "[0]" if t == "str" else key
                add(f"{tag}_{t}", set_at(key, v), shown)
        add("tank_outside", set_at("walls.tank_hi", [9e5] * dim), "walls.tank_hi")
        add("tank_inverted", set_at("walls.tank_lo", [5.0] * dim), "walls.tank_hi")
    # Huge coordinates and speeds.
    add("domain_huge", set_at("domain.hi", [1e300] * dim), "domain.hi")
    add("gravity_huge", set_at("fluid.gravity", [0.0] * (dim - 1) + [-1e300]), "fluid.gravity")
    add("velocity_huge", set_at("blocks[0].velocity", [1e300] + [0.0] * (dim - 1)),
        "blocks[0].velocity")
    add("domain_inverted", set_at("domain.lo", [5.0] * dim), "domain.hi")
    add("block_outside", set_at("blocks[0].hi", [1e5] * dim), "blocks[0].hi")
    add("block_inverted", set_at("blocks[0].lo", doc["blocks"][0]["hi"]), "blocks[0].hi")
    # Absurd sizes: memory would run out long before the first step.
    big = [1e5] * dim
    add("count_fluid_huge", lambda d: (set_at("domain.hi", big)(d), set_at("blocks[0].hi", big)(d),
                                       d.pop("walls", None), d.pop("probes", None), d)[-1],
        "particles.dx")
    # Below the hostile bound but beyond any machine's memory on one rank: 1e10 particles (the
    # memory estimate per rank, sluice/io/memory_estimate.hpp).
    side = doc["particles"]["dx"] * 1e10 ** (1 / dim)
    add("count_memory_huge", lambda d: (set_at("domain.hi", [side] * dim)(d),
                                        set_at("blocks[0].hi", [side] * dim)(d),
                                        d.pop("walls", None), d.pop("probes", None), d)[-1],
        "particles.dx")
    add("count_cells_huge", lambda d: (set_at("domain.hi", [1e6] * dim)(d), d.pop("walls", None),
                                       d.pop("probes", None), d)[-1], "particles.dx")
    if not any(doc["domain"].get("periodic", [False])):
        add("count_walls_huge",
            lambda d: (set_at("domain.hi", big)(d),
                       set_at("walls", {"model": "dummy", "tank_lo": [0.0] * dim,
                                        "tank_hi": big})(d),
                       d.pop("probes", None), d)[-1], "particles.dx")
    if dim == 3:
        add("cells_axis_huge", lambda d: (set_at("domain.hi", [1e5, 1.0, 1.0])(d),
                                          d.pop("walls", None), d.pop("probes", None), d)[-1],
            "particles.dx")
    # Structure: unknown keys, tables of the wrong kind, missing entries.
    add("unknown_top", set_at("solver", {"x": 1}), "solver")
    add("unknown_scalar_top", set_at("threads", 4), "threads")
    for sec in ["case", "domain", "fluid", "particles", "numerics", "time"]:
        add(f"unknown_in_{sec}", set_at(f"{sec}.colour", "blue"), f"{sec}.colour")
        add(f"section_scalar_{sec}", set_at(sec, 3), sec)
    add("unknown_in_block", set_at("blocks[0].density", 1000.0), "blocks[0].density")
    add("blocks_table", lambda d: (d.__setitem__("blocks", d["blocks"][0]), d)[-1], "blocks")
    add("blocks_empty", set_at("blocks", []), "blocks")
    add("blocks_scalars", set_at("blocks", [1, 2]), "blocks[0]")
    add("block_overlap", lambda d: (d["blocks"].append(copy.deepcopy(d["blocks"][0])), d)[-1],
        "blocks[1].lo")
    add("block_no_lo", delete_at("blocks[0].lo"), "blocks[0].lo")
    add("walls_planes_zero", set_at("walls.planes", [{"point": [0.0] * dim,
                                                       "normal": [0.0] * dim}]),
        "walls.planes[0].normal")
    add("walls_planes_underflow", set_at("walls.planes", [{"point": [0.0] * dim,
                                                            "normal": [5e-324] + [0.0] * (dim - 1),
                                                            "colour": 1}]),
        "walls.planes[0].colour")
    for key in ["case.dimension", "domain.lo", "domain.hi", "fluid.rho0", "fluid.viscosity",
                "fluid.sound_speed", "particles.dx", "time.end_time"]:
        add(f"missing_{key.replace('.', '_')}", delete_at(key), key)
    if "probes" in doc:
        add("probe_name_escape", set_at("probes[0].name", "../../evil"), "probes[0].name")
        add("probe_name_slash", set_at("probes[0].name", "a/b"), "probes[0].name")
        add("probe_name_long", set_at("probes[0].name", "p" * 300), "probes[0].name")
        add("probe_name_dup", set_at("probes[1].name", doc["probes"][0]["name"]), "probes[1].name")
        add("probe_no_type", delete_at("probes[0].type"), "probes[0].type")
        add("probe_type", set_at("probes[0].type", "pressur"), "probes[0].type")
        add("probe_interval", set_at("probes[0].interval", -1.0), "probes[0].interval")
        add("probe_interval_tiny", set_at("probes[0].interval", 1e-300), "probes[0].interval")
    if base == "db2":
        # An area sensor rides with its wall: a frame on a fixed wall is refused. A free body
        # takes the default dissipation only.
        def sensor_frame_fixed(d):
            d.setdefault("walls", {})["boxes"] = [dict(SAMPLE_ENTRIES["walls.boxes"],
                                                       motion="m")]
            d["motions"] = [{"name": "m", "kind": "sway", **SAMPLE_MOTIONS["sway"]}]
            d["probes"].insert(0, dict(SAMPLE_ENTRIES["area"], frame="m"))
            return d
        add("area_sensor_frame_fixed_wall", sensor_frame_fixed, "probes[0].frame")

        def free_body_riemann(d):
            for k in ("delta_sph", "artificial_viscosity"):
                d["numerics"].pop(k, None)
            d["numerics"]["dissipation"] = "riemann"
            d.setdefault("walls", {})["boxes"] = [dict(SAMPLE_ENTRIES["walls.boxes"],
                                                       motion="m")]
            d["motions"] = [{"name": "m", "kind": "free_body", **SAMPLE_MOTIONS["free_body"]}]
            return d
        add("free_body_riemann", free_body_riemann, "motions[0].kind")
    if "probes" in doc and doc["probes"][0]["type"] == "pressure":
        add("probe_position_out", set_at("probes[0].position", [-5.0] * dim), "probes[0].position")
        add("probe_position_nan", set_at("probes[0].position", [float("nan")] * dim),
            "probes[0].position[0]")
    muts = [(n, f, k) for n, f, k in muts if applicable(doc, k, n)]
    if base != "db2":
        # The other bases add what depends on dimension, periodicity and geometry.
        keep = ("_len", "_empty", "_long", "_nested", "_scalar", "_str", "huge", "count_",
                "cells_", "dimension", "missing_", "tank", "probe", "block", "periodic")
        muts = [m for m in muts if any(t in m[0] for t in keep)]
    return muts


def applicable(doc, key, name):
    """Mutations of optional keys the base lacks still apply (they add the key); mutations of
    probes/walls need the base to have them."""
    if key.startswith("probes") and "probes" not in doc:
        return False
    if key.startswith("probes[") and not has(doc, key.split("].")[0] + "]"):
        return False
    if key.startswith("walls.restitution") or key.startswith("walls.tank_faces"):
        return doc.get("walls", {}).get("model", "none") != "none"
    return True


# ------------------------------------------------------------------------------------------
# Byte-level mutations: broken syntax, encodings, duplicates, truncation.


def harmful_cut(data, cut):
    """A position inside the key of the last key-value line that starts before cut, so that
    the truncated file ends in a key without its value: a cut elsewhere may leave a valid case
    (in a trailing comment) or a shorter valid value ("2.0e-4" cut to "2")."""
    head = data[:cut].decode("utf-8", "ignore")
    starts = [0] + [i + 1 for i, c in enumerate(head) if c == "\n"]
    for start in reversed(starts):
        line = head[start:].split("\n", 1)[0]
        if " = " in line.split("#", 1)[0] and not line.lstrip().startswith(("#", "[")):
            key_len = len(line.split(" = ", 1)[0])
            return len(head[:start].encode()) + max(1, key_len // 2)
    return cut


def raw(base, text):
    data = text.encode()
    lines = text.splitlines(keepends=True)
    muts = []

    def add(name, b, key="@syntax"):
        muts.append((name, b, key))

    # Truncated after "key =" of several lines, inside a table header, inside a string.
    eq_lines = [i for i, l in enumerate(lines) if " = " in l and not l.lstrip().startswith("#")]
    for n, i in enumerate(eq_lines[:: max(1, len(eq_lines) // 6)]):
        cut = sum(len(l.encode()) for l in lines[:i]) + len(lines[i].split(" = ")[0].encode()) + 3
        add(f"trunc_value{n}", data[:cut])
    hdr = [i for i, l in enumerate(lines) if l.startswith("[")]
    for n, i in enumerate(hdr[:3]):
        cut = sum(len(l.encode()) for l in lines[:i]) + 3
        add(f"trunc_header{n}", data[:cut])
    q = text.find('"')
    if q >= 0:
        add("trunc_string", data[: q + 3])
    # Cuts at a random line: inside the key of the last key-value line before a random byte.
    rnd = random.Random(base)
    for n in range(4):
        add(f"trunc_at{n}", data[: harmful_cut(data, rnd.randrange(1, len(data)))], "@any")
    add("empty", b"", "case.dimension")
    add("only_comment", b"# nothing here\n", "case.dimension")
    # Not UTF-8: in a comment, a string, a key; overlong encoding; lone surrogate; Latin-1.
    add("utf8_comment", data.replace(b"#", b"# \xff\xfe", 1))
    if q >= 0:
        add("utf8_string", data[: q + 1] + b"\xc3\x28" + data[q + 1:])
    add("utf8_key", data.replace(b"rho0", b"rh\xf0\x28\x8c\x28", 1))
    add("utf8_overlong", data.replace(b"rho0", b"rho\xc0\xb0", 1))
    add("utf8_surrogate", data.replace(b"[fluid]", b"[fl\xed\xa0\x80uid]", 1))
    add("latin1_name", data.replace(b"[case]\n", b"[case]\n# caf\xe9\n", 1))
    add("utf16", text.encode("utf-16"))
    add("nul_byte", data.replace(b"rho0", b"rho\x000", 1))
    add("bare_cr", data.replace(b"\n", b"\r", 5))
    # Duplicates: a key, a table.
    add("dup_key", data.replace(b"rho0 = ", b"rho0 = 1.0\nrho0 = ", 1))
    add("dup_table", data + b"\n[fluid]\nrho0 = 1.0\n")
    add("dup_header", data.replace(b"[numerics]", b"[numerics]\n[numerics]", 1))
    # Broken values.
    add("int_overflow", data.replace(b"rho0 = ", b"rho0 = 99999999999999999999 #", 1))
    add("float_garbage", data.replace(b"rho0 = ", b"rho0 = 1.0.0 #", 1))
    add("date_value", data.replace(b"rho0 = ", b"rho0 = 1979-05-27 #", 1), "fluid.rho0")
    add("unclosed_array", data.replace(b"lo = [", b"lo = [[", 1))
    add("garbage_line", data.replace(b"[fluid]", b"[fluid]\n%%% !!!", 1))
    if base != "db2":
        return [m for m in muts if m[0].startswith(("trunc", "utf8_key", "dup_key"))]
    add("binary", bytes(rnd.randrange(256) for _ in range(512)))
    # Deep nesting (a recursive parser would overflow its stack).
    add("deep_array", b"x = " + b"[" * 3000 + b"]" * 3000 + b"\n")
    add("deep_inline", b"x = " + b"{a=" * 2000 + b"1" + b"}" * 2000 + b"\n")
    add("deep_table", b"[" + b".".join([b"a"] * 2000) + b"]\n", "a")
    return muts


# ------------------------------------------------------------------------------------------
# Schema-driven mutations: every key of `sluice schema`.


def outside(spec):
    """Values just outside the key's interval (the schema's min and max; null is unbounded):
    [(tag, value)], for a number or an integer; for a vector the component values."""
    if spec["type"].split()[0] not in ("number", "integer", "vector") or \
            (spec["min"] is None and spec["max"] is None):
        return []
    integer = spec["type"] == "integer"
    out = []
    lo, hi = spec["min"], spec["max"]
    if lo is not None:
        v = lo if spec["min_open"] else (lo - 1 if integer else lo - max(abs(lo), 1.0) / 2)
        out.append(("below", int(v) if integer else v))
    if hi is not None:
        v = hi if spec["max_open"] else (hi + 1 if integer else hi + max(abs(hi), 1.0) / 2)
        out.append(("above", int(v) if integer else v))
    return out


def wrong_type(spec):
    t = spec["type"]
    if t in ("number", "integer"):
        return "heavy" if t == "number" else 1.5
    if t == "boolean":
        return "yes"
    if t == "string":
        return 3
    if t.startswith("array") or t == "vector":
        return 0.5
    return {"x": 1}  # "number or \"every_step\"": a table is neither


def toml_value(text):
    try:
        return tomllib.loads("v = " + text)["v"]
    except tomllib.TOMLDecodeError:
        return None


def locate(doc, spec):
    """The table (dict) holding the key in `doc`, made valid for it, and its display path."""
    table = spec["table"]
    if table == "motions":
        kind = re.match(r'^kind = "([a-z_]+)"', spec["when"])
        kind = kind.group(1) if kind else "sway"
        entry = {"name": "m", "kind": kind, **copy.deepcopy(SAMPLE_MOTIONS[kind])}
        doc.setdefault("motions", []).append(entry)
        return entry, f"motions[{len(doc['motions']) - 1}]"
    if table in ("blocks", "probes", "walls.planes", "walls.boxes", "walls.meshes",
                 "damping_zones"):
        parent = doc
        *outer, last = table.split(".")
        for p in outer:
            parent = parent.setdefault(p, {})
        entries = parent.setdefault(last, [])
        kind = re.match(r'^type = "([a-z_]+)"', spec["when"])
        if table == "probes" and spec["when"].endswith("with a diameter"):
            entries.append(copy.deepcopy(SAMPLE_ENTRIES["area"]))
            index = len(entries) - 1
        elif table == "probes" and kind:
            index = next((i for i, e in enumerate(entries) if e["type"] == kind.group(1)), None)
            if index is None:
                entries.append(copy.deepcopy(SAMPLE_ENTRIES[kind.group(1)]))
                index = len(entries) - 1
        else:
            if not entries:
                entries.append(copy.deepcopy(SAMPLE_ENTRIES[table]))
            index = 0
        return entries[index], f"{table}[{index}]"
    d = doc
    for p in table.split("."):
        d = d.setdefault(p, {})
    return d, table


def apply_when(doc, spec, entry):
    """Sets the key's further condition ("profile = \"rotating\"", "projection.solver =
    \"sor\""; the first of "a" | "b"), except a probe's type (chosen by locate)."""
    m = re.match(r"^([a-z_.]+) = (.+?)( \|.*)?$", spec["when"])
    if not m or m.group(1) == "type":
        return
    value = toml_value(m.group(2))
    if "." in m.group(1):
        set_at(m.group(1), value)(doc)
    else:
        entry[m.group(1)] = value


def from_schema(schema):
    """(base, name, doc, expected key) for every key of the schema."""
    docs = {scheme: (base, tomllib.loads(path.read_text()))
            for scheme, (base, path) in SCHEME_BASES.items()}
    muts = []
    for spec in schema:
        if spec["type"] in ("table", "array of tables"):
            continue
        tag = f"{spec['table']}_{spec['key']}".replace(".", "_").strip("_")
        scheme = "projection" if spec["applies"] == "projection" else "wcsph"
        base, doc0 = docs[scheme]

        def mutated(v, doc0=doc0, spec=spec):
            doc = copy.deepcopy(doc0)
            entry, path = locate(doc, spec)
            apply_when(doc, spec, entry)
            entry[spec["key"]] = v
            return doc, f"{path}.{spec['key']}" if path else spec["key"]

        values = [("type", wrong_type(spec))]
        dim = doc0["case"]["dimension"]
        for kind, v in outside(spec):
            # A vector with its first component out of range, the others 0.
            values.append((kind, [v] + [0.0] * (dim - 1) if spec["type"] == "vector" else v))
        if spec["choices"]:
            values.append(("choice", "no-such-value" if spec["type"] == "string"
                           else ["no-such-value"]))
        for kind, v in values:
            doc, key = mutated(v)
            muts.append((base, f"schema_{tag}_{kind}", doc, key))
        if spec["applies"] != "any":
            # The key in a case of the other scheme, with a value it would accept.
            other = "wcsph" if spec["applies"] == "projection" else "projection"
            obase, odoc = docs[other]
            v = toml_value(spec["default"])
            if v is None:
                v = 0.5
            doc = copy.deepcopy(odoc)
            entry, path = locate(doc, spec)
            entry[spec["key"]] = v
            # [[motions]] and [[damping_zones]] are refused as a whole under the other scheme.
            whole = spec["table"] in ("motions", "damping_zones")
            muts.append((obase, f"schema_{tag}_inapplicable", doc,
                         spec["table"] if whole else
                         f"{path}.{spec['key']}" if path else spec["key"]))
    return muts


def read_schema(args):
    if args.schema:
        return json.loads(Path(args.schema).read_text())
    return json.loads(subprocess.run([args.sluice, "schema"], check=True, capture_output=True,
                                     text=True).stdout)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--sluice", default=str(ROOT / "build" / "release" / "sluice"),
                    help="the executable whose `schema` command lists the keys")
    ap.add_argument("--schema", help="the schema as JSON (instead of running --sluice)")
    ap.add_argument("out", nargs="?", default=str(HERE / "generated"))
    args = ap.parse_args()
    OUT = Path(args.out)
    schema = read_schema(args)
    known = {f"{k['table']}.{k['key']}".strip(".") for k in schema}
    for key in list(NUMBERS) + list(CHOICES):
        plain = re.sub(r"\[\d+\]", "", key)
        assert plain in known, f"hand-listed key {key} is not in the schema"
    if OUT.exists():
        shutil.rmtree(OUT)
    OUT.mkdir()
    rows = []
    for base, name, doc, key in from_schema(schema):
        out = f"{base}_{name}.toml"
        (OUT / out).write_text(dump(doc))
        rows.append((out, key))
    for base, path in BASES.items():
        text = path.read_text()
        doc = tomllib.loads(text)
        for name, fn, key in structured(base, doc):
            out = f"{base}_{name}.toml"
            (OUT / out).write_text(dump(fn(copy.deepcopy(doc))))
            rows.append((out, key))
        for name, data, key in raw(base, text):
            out = f"{base}_{name}.toml"
            (OUT / out).write_bytes(data)
            rows.append((out, key))
    names = [r[0] for r in rows]
    assert len(names) == len(set(names)), "duplicate file names"
    (OUT / "expected.tsv").write_text("".join(f"{n}\t{k}\n" for n, k in rows))
    print(f"{len(rows)} files in {OUT}")


if __name__ == "__main__":
    main()
