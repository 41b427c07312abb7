"""Reading a study's summary.json (written by the study runner) for the plots.

summary.json:
  {"scene": <name>, "study": <kind> (the head of every kind's summary.json),
   "description": ..., "problems": [...],
   "groups": [{"mesh": ..., "problem": ..., "variant": ..., "formulation": ..., "label": ...,
               "kp": ... (optional),
               "levels": [{"level": ..., "h_avg": ..., "dofs": ..., "runs": ..., "failed": ...,
                           "l2": {"mean", "std", "min", "max", "values": [...]},
                           "energy": {...} (optional), "iterations": {"mean"},
                           "seconds": {"mean"}}],
               "rate_l2": {"value", "ci95", "intercept"} (optional),
               "rate_energy": {...} (optional),
               "published": {"l2_rate", "source"} (optional)}]}
A level whose errors are missing, null, zero or negative is left out of the plots (a failed
level). The rates are the runner's least-squares fits of log(error) against log(h_avg); the
plots draw them and never fit anything themselves.
"""
import json
import math

import numpy as np

from plotting_common import InputError


def is_number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool)


def num(x):
    """A float, or NaN for a missing/null/non-numeric value."""
    return float(x) if is_number(x) else math.nan


def usable(e):
    return math.isfinite(e) and e > 0


def has_mean(lv, norm):
    return lv[norm] is not None and usable(lv[norm]["mean"])


def text_field(raw, key, where, default=None):
    """A non-empty string field; `default` when absent (an error when there is no default)."""
    value = raw.get(key)
    if isinstance(value, str) and value:
        return value
    if default is None:
        raise InputError(f"{where}: \"{key}\" must be a non-empty string")
    return default


def read_statistics(raw, where):
    """A level's error statistics {mean, min, max, values} (NaN where absent); None when the
    entry is missing or null (a level whose runs all failed)."""
    if raw is None:
        return None
    if not isinstance(raw, dict):
        raise InputError(f"{where}: expected an object with mean/min/max/values")
    values = raw.get("values") or []
    if not isinstance(values, list):
        raise InputError(f"{where}.values: expected a list")
    vals = np.array([num(v) for v in values], dtype=float)
    vals = vals[np.isfinite(vals)]
    stats = {"values": vals, "positive": vals[vals > 0]}
    for key, reduce in (("mean", np.mean), ("min", np.min), ("max", np.max)):
        value = num(raw.get(key))
        stats[key] = value if math.isfinite(value) or not len(vals) else float(reduce(vals))
    return stats


def mean_of(raw):
    return num(raw.get("mean")) if isinstance(raw, dict) else math.nan


def read_rate(raw):
    """{value, ci95, intercept} of a fitted rate (NaN for a missing interval or intercept)."""
    if isinstance(raw, dict) and is_number(raw.get("value")) and math.isfinite(raw["value"]):
        return {"value": float(raw["value"]), "ci95": num(raw.get("ci95")),
                "intercept": num(raw.get("intercept"))}
    return None


def read_level(lv, index, where):
    """One level, or None for a level whose runs all failed (no mesh size, no error)."""
    if not isinstance(lv, dict):
        raise InputError(f"{where}: expected an object")
    h = lv.get("h_avg")
    if not (is_number(h) and h > 0 and math.isfinite(h)):
        if lv.get("l2") is None:
            return None
        raise InputError(f"{where}: \"h_avg\" must be a positive number, found {h!r}")
    level = lv.get("level", index)
    if not is_number(level):
        raise InputError(f"{where}: \"level\" must be a number, found {level!r}")
    return {
        "level": int(level), "h_avg": float(h), "dofs": num(lv.get("dofs")),
        "runs": num(lv.get("runs")), "failed": num(lv.get("failed")),
        "l2": read_statistics(lv.get("l2"), f"{where}.l2"),
        "energy": read_statistics(lv.get("energy"), f"{where}.energy"),
        "iterations": mean_of(lv.get("iterations")),
        "seconds": mean_of(lv.get("seconds")),
    }


def read_group(g, where):
    if not isinstance(g, dict):
        raise InputError(f"{where}: expected an object")
    variant = text_field(g, "variant", where)
    kp = g.get("kp")
    if kp is not None and not (is_number(kp) and kp >= 0 and math.isfinite(kp)):
        raise InputError(f"{where} ({variant}): \"kp\" must be a number >= 0, found {kp!r}")
    raw_levels = g.get("levels")
    if not isinstance(raw_levels, list):
        raise InputError(f"{where} ({variant}): \"levels\" must be a list")
    levels = [read_level(lv, li, f"{where}.levels[{li}]") for li, lv in enumerate(raw_levels)]
    levels = sorted((lv for lv in levels if lv is not None), key=lambda r: -r["h_avg"])
    formulation = text_field(g, "formulation", where, variant)
    return {
        "variant": variant, "mesh": text_field(g, "mesh", where, ""),
        "problem": text_field(g, "problem", where, ""), "formulation": formulation,
        # The formulation as the scene labels it: two variants of one formulation stay apart.
        "series": text_field(g, "label", where, formulation),
        "kp": float(kp) if kp else None,  # k_p = 0 is no penalty: like CG, a reference line
        "levels": levels,
        "rate_l2": read_rate(g.get("rate_l2")), "rate_energy": read_rate(g.get("rate_energy")),
        "published": g.get("published") if isinstance(g.get("published"), dict) else {},
    }


def name_groups(groups):
    """Each group's legend name: its mesh and variant, and its problem when the study has several
    (a variant alone repeats across meshes)."""
    several_problems = len({g["problem"] for g in groups}) > 1
    several_meshes = len({g["mesh"] for g in groups}) > 1
    for g in groups:
        parts = [g["mesh"], g["variant"]] + ([g["problem"]] if several_problems else [])
        g["name"] = ", ".join(p for p in parts if p)
        series = ([g["mesh"]] if several_meshes else []) + [g["series"]] + parts[2:]
        g["series"] = ", ".join(p for p in series if p)


def read_summary(path):
    try:
        with open(path) as f:
            data = json.load(f)
    except FileNotFoundError:
        raise InputError(f"{path}: no such file") from None
    except OSError as e:
        raise InputError(f"{path}: cannot read: {e.strerror}") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: not valid JSON: {e}") from None
    if not isinstance(data, dict):
        raise InputError(f"{path}: expected a JSON object at the top")
    for key in ("scene", "study"):
        if not isinstance(data.get(key), str):
            raise InputError(f"{path}: \"{key}\" must be a text (the scene's name, the study kind)")
    raw_groups = data.get("groups")
    if not isinstance(raw_groups, list) or not raw_groups:
        raise InputError(f"{path}: \"groups\" must be a non-empty list")
    groups = [read_group(g, f"{path}: groups[{gi}]") for gi, g in enumerate(raw_groups)]
    name_groups(groups)
    if not any(has_mean(lv, "l2") for g in groups for lv in g["levels"]):
        raise InputError(f"{path}: no level has a positive L2 error")
    return {"name": data["scene"], "study": data["study"], "scene": data, "groups": groups}
