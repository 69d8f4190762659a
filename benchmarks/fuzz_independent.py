"""An independent fuzz of valid cases through the command line (not hypothesis, not the
strategies of tests/test_fuzz.py): the shipped cases mutated by ``numpy.random.default_rng``.

Each case starts from one of the shipped files (``src/flexbooster/data/default_case.toml``,
``memo_case.toml``, ``examples/*.toml``) and has its every table mutated: ``[booster]``,
``[thrust]`` (F0, gamma, K, the Omega range), ``[damping]``, ``[truncation]``, ``[vehicle]``
(material, ends, theory, k_max, n_modes, damping_ratio, junctions, the segments' lengths,
radii, thicknesses, kinds, pressures, stiffeners and non-structural mass, the rigid masses,
the tanks), ``[flight]`` (stations, times, thrust, fills, oscillation), ``[severity]``,
``[output]``, ``max_seconds``.  Lengths change with the stations of the masses, tanks and
output stations scaled along, so that most cases stay valid; a mutation that breaks a rule is
a refusal, which must be one line with exit 2 like any other.

Each case runs in a child process, one at a time:

1. ``python -m flexbooster run CASE -o DIR -q --no-figures --max-seconds 1e-9``: refused at
   once (exit 2) with the case's own up-front estimate in its one line ("the estimated run
   time X s exceeds the budget"); the child's CPU time is the start-up, the case's
   validation, model and estimate (the baseline subtracted below);
2. ``python -m flexbooster run CASE -o DIR -q --no-figures`` with the case's own budget.

Outcome of step 2: ``ok`` (exit 0, results.json finite), ``refused`` (exit 2, one line on
stderr, tallied by the field it names), ``internal`` (exit 1, a traceback, or more than one
line), ``nan`` (NaN or inf in results.json), ``hang`` (still running after
``HANG_FACTOR`` x the budget + 60 s wall), ``over-estimate`` (CPU of step 2 minus that of step
1 over ``ESTIMATE_FACTOR`` x the estimate and over ``ESTIMATE_FLOOR``, with no
``cost-estimate`` warning in results.json).  CPU time (``os.wait4``), not wall: other users
of the machine do not count.

Run:  OPENBLAS_NUM_THREADS=1 python benchmarks/fuzz_independent.py [--seed 36] [--cases 200]
      [--minutes 40] [--log /tmp/fuzz-indep.jsonl] [--keep DIR]
Prints one line per case and the tally; ``--keep`` saves the case file of every failure.
"""

from __future__ import annotations

import argparse
import copy
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time
import tomllib
from collections import Counter
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
from conftest import dump_toml  # noqa: E402  (the tests' TOML writer: one copy)

__all__: list[str] = []

BASES = [ROOT / "src/flexbooster/data/default_case.toml",
         ROOT / "src/flexbooster/data/memo_case.toml",
         *sorted((ROOT / "examples").glob("*.toml"))]
ESTIMATE_FACTOR = 1.5  # acceptance: at most 0.5 % of the cases beyond it unwarned
ESTIMATE_FLOOR = 1.0  # s of CPU: below it start-up noise, not the cost model, decides
HANG_FACTOR = 3
_NUMBER = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*)$")


# --------------------------------------------------------------------------------------------
# Mutations
# --------------------------------------------------------------------------------------------
def scaled(value, factor: float):
    """``value`` (a number or a string "number unit") times ``factor``, unit kept."""
    if isinstance(value, bool):
        return value
    if isinstance(value, int | float):
        return float(value) * factor
    m = _NUMBER.match(value)
    if not m:
        return value
    return f"{float(m.group(1)) * factor:.6g} {m.group(2)}".strip()


def magnitude(value) -> float:
    return float(value) if isinstance(value, int | float) else float(_NUMBER.match(value)[1])


def log_uniform(rng, lo: float, hi: float) -> float:
    return float(10.0 ** rng.uniform(math.log10(lo), math.log10(hi)))


def maybe(rng, p: float = 0.5) -> bool:
    return bool(rng.random() < p)


def choice(rng, options):
    return options[int(rng.integers(len(options)))]


def mutate_thrust(rng, t: dict) -> None:
    for key in ("F0", "T0"):
        if key in t and maybe(rng):
            t[key] = scaled(t[key], log_uniform(rng, 0.1, 10.0))
    if maybe(rng):
        t["gamma"] = choice(rng, [0.0, 1e-4, 0.01, 0.05, 0.2, 0.5, 0.9, 0.99])
    if maybe(rng):
        t["K"] = choice(rng, [0.0, 0.1, 0.5, 1.0, 3.0])
    if maybe(rng):  # the Omega range: scaled together, widened or narrowed
        f = log_uniform(rng, 0.1, 10.0)
        t["omega_min"] = scaled(t["omega_min"], f)
        t["omega_max"] = (scaled(t["omega_max"], f * log_uniform(rng, 0.3, 3.0)) if maybe(rng)
                          else scaled(t["omega_min"], log_uniform(rng, 1.05, 3.0)))
        if magnitude(t["omega_max"]) <= magnitude(t["omega_min"]) and \
                t["omega_max"].split()[-1:] == t["omega_min"].split()[-1:]:
            t["omega_max"] = scaled(t["omega_min"], 1.5)
    t["n_omega"] = int(choice(rng, [2, 5, 20, 50, int(t.get("n_omega", 50))]))
    if maybe(rng, 0.2):
        t["misalignment"] = choice(rng, ["0.1 deg", "1 deg", 0.0])
    if maybe(rng, 0.2):
        t["duration"] = choice(rng, ["10 s", "150 s", 1.0])
    if maybe(rng, 0.1):
        t["spectrum"] = [{"frequency": f"{f:.4g} Hz", "amplitude": a} for f, a in
                         zip(sorted(rng.uniform(1.0, 30.0, 2)), (0.01, 0.005), strict=True)]


def mutate_booster(rng, b: dict) -> None:
    for key in ("E", "rho"):
        if maybe(rng):
            b[key] = scaled(b[key], log_uniform(rng, 0.1, 10.0))
    if maybe(rng):
        b["nu"] = float(rng.uniform(0.01, 0.49))
    for cyl in ("cylinder1", "cylinder2"):
        for key in ("radius", "half_length"):
            if maybe(rng):
                b[cyl][key] = scaled(b[cyl][key], log_uniform(rng, 0.2, 5.0))
    if maybe(rng):
        b["thickness"] = scaled(b["thickness"], log_uniform(rng, 0.05, 3.0))


def mutate_truncation(rng, tr: dict) -> None:
    for key in ("M1", "N1", "M2", "N2"):
        tr[key] = int(choice(rng, [1, 2, 3, 4, 6, 10]))
    tr["N"] = int(choice(rng, [1, 2, 3, 4, 6, 10]))
    tr["S"] = int(choice(rng, [0, 1, 2, 3, 5]))
    tr["R"] = int(rng.integers(1, min(tr["N"] + 1, 4) + 1))


def _remap_value(x, old, new):
    """A station (m) moved with its segment (piecewise linear in the segment boundaries)."""
    unit = "" if isinstance(x, int | float) else (_NUMBER.match(x)[2] or "")
    value = magnitude(x) * {"m": 1.0, "": 1.0, "mm": 1e-3, "in": 0.0254, "ft": 0.3048}.get(
        unit, 1.0)
    return float(np.interp(value, old, new))


def _length_m(value) -> float:
    unit = "" if isinstance(value, int | float) else (_NUMBER.match(value)[2] or "")
    return magnitude(value) * {"m": 1.0, "": 1.0, "mm": 1e-3}[unit]


def mutate_vehicle(rng, v: dict, flight: dict | None, output: dict | None) -> None:
    if maybe(rng, 0.8):  # small mostly, so that most cases run within their budget
        v["k_max"] = int(choice(rng, [0, 1, 1, 2, 2, 3, 4, 6, 10, 20]))
    if maybe(rng, 0.8):
        v["n_modes"] = int(choice(rng, [1, 2, 2, 3, 4, 4, 6, 8, 12, 20, 40]))
    if maybe(rng, 0.4):
        v["damping_ratio"] = choice(rng, [0.0, 1e-4, 0.01, 0.02, 0.1, 0.3, 0.9, 0.99])
    for end in ("aft_end", "fwd_end"):
        if maybe(rng, 0.3):
            v[end] = choice(rng, ["free", "shear-diaphragm", "clamped", "hinged"])
    if maybe(rng, 0.3):
        v["theory"] = choice(rng, ["sanders", "donnell"])
    for key in ("E", "rho"):
        if key in v and maybe(rng, 0.3):
            v[key] = scaled(v[key], log_uniform(rng, 0.3, 3.0))
    if "nu" in v and maybe(rng, 0.2):
        v["nu"] = float(rng.uniform(0.05, 0.45))
    if "junction" in v and maybe(rng):
        v["junction"] = choice(rng, ["memo-bulkhead", "rigid-bulkhead"])
    segs = v.get("segments")
    if not segs:
        return
    # drop forward segments (with what sits on them), 0 or more
    keep = len(segs) if maybe(rng, 0.7) else int(rng.integers(1, len(segs) + 1))
    old_st = np.concatenate([[0.0], np.cumsum([_length_m(s["length"]) for s in segs])])
    kept_len = old_st[keep]
    segs[:] = segs[:keep]
    for s in segs:
        if maybe(rng, 0.4):
            s["length"] = scaled(s["length"], log_uniform(rng, 0.1, 5.0))
        if maybe(rng, 0.3):
            f = log_uniform(rng, 0.3, 3.0)
            for key in ("radius", "radius_aft", "radius_fwd", "thickness"):
                if key in s:
                    s[key] = scaled(s[key], f)
        if maybe(rng, 0.3):
            s["thickness"] = scaled(s["thickness"], log_uniform(rng, 0.2, 5.0))
        if maybe(rng, 0.2):
            s["pressure"] = choice(rng, ["-0.2 bar", "0 bar", "1 bar", "3 bar", "20 bar"])
        if maybe(rng, 0.2):
            s["nonstructural_mass"] = choice(rng, ["1 kg/m^2", "10 kg/m^2", "100 kg/m^2"])
        for name, spacing in (("rings", "0.5 m"), ("stringers", "0.2 m")):
            if maybe(rng, 0.15):
                s[name] = {"spacing": scaled(spacing, log_uniform(rng, 0.3, 3.0)),
                           "area": f"{log_uniform(rng, 0.3, 30):.3g} cm^2",
                           "inertia": choice(rng, ["0 cm^4", "20 cm^4", "400 cm^4"]),
                           "eccentricity": choice(rng, ["0 cm", "-2 cm", "2 cm"])}
            elif name in s and maybe(rng, 0.2):
                del s[name]
        if maybe(rng, 0.15) and s["kind"] == "cylinder":  # a cylinder made a cone
            r = s.pop("radius")
            s.update(kind="cone", radius_aft=r, radius_fwd=scaled(r, log_uniform(rng, 0.5, 2.0)))
        if "junction" in s and maybe(rng, 0.3):
            s["junction"] = choice(rng, ["continuous", "rigid-bulkhead", "memo-bulkhead"])
    # a continuous junction needs the radii to meet: make them meet where it is continuous
    for prev, s in zip(segs, segs[1:], strict=False):
        if s.get("junction", "continuous") == "continuous":
            fwd = prev.get("radius", prev.get("radius_fwd"))
            s["radius" if s["kind"] == "cylinder" else "radius_aft"] = fwd
    new_st = np.concatenate([[0.0], np.cumsum([_length_m(s["length"]) for s in segs])])
    old = list(old_st[: keep + 1])
    masses = [m for m in v.get("masses", []) if _length_m(m["station"]) <= kept_len + 1e-9]
    for m in masses:
        m["station"] = _remap_value(m["station"], old, list(new_st))
        if maybe(rng, 0.3):
            m["mass"] = scaled(m["mass"], log_uniform(rng, 0.1, 10.0))
        if "transverse_inertia" in m and maybe(rng, 0.2):
            m["transverse_inertia"] = scaled(m["transverse_inertia"], log_uniform(rng, 0.1, 10))
        if "offset" in m and maybe(rng, 0.2):
            m["offset"] = scaled(m["offset"], float(rng.uniform(-2.0, 2.0)))
    if maybe(rng, 0.2) and len(masses) > 1:
        masses.pop(int(rng.integers(len(masses))))
    if "masses" in v:
        v["masses"] = masses
        if not masses:
            del v["masses"]
    tanks = v.get("tanks", [])
    kept = [i for i, t in enumerate(tanks) if _length_m(t["fwd"]) <= kept_len + 1e-9]
    if maybe(rng, 0.2) and len(kept) > 1:
        kept.pop(int(rng.integers(len(kept))))
    new_tanks = []
    for i in kept:
        t = tanks[i]
        t["aft"] = _remap_value(t["aft"], old, list(new_st))
        t["fwd"] = _remap_value(t["fwd"], old, list(new_st))
        if maybe(rng, 0.3):
            t["fill"] = choice(rng, [0.0, 0.02, 0.5, 0.95, 1.0])
        if maybe(rng, 0.2):
            t["density"] = scaled(t["density"], log_uniform(rng, 0.1, 3.0))
        new_tanks.append(t)
    if "tanks" in v:
        v["tanks"] = new_tanks
        if not new_tanks:
            del v["tanks"]
    if output is not None:  # the output stations moved along, dropped off the vehicle
        rows = [r for r in output.get("stations", []) if _length_m(r["station"]) <= kept_len]
        for r in rows:
            r["station"] = _remap_value(r["station"], old, list(new_st))
        if "stations" in output:
            output["stations"] = rows
            if not rows:
                del output["stations"]
    if flight is not None:
        if not new_tanks:
            for p in flight.get("points", []):
                p.pop("fill", None)
        else:
            for p in flight.get("points", []):
                if "fill" in p:
                    p["fill"] = [p["fill"][i] for i in kept]
    v["_length"] = float(new_st[-1])


def mutate_flight(rng, f: dict) -> None:
    if maybe(rng):
        f["stations"] = int(choice(rng, [2, 3, 5, 11]))
    pts = f.get("points", [])
    if maybe(rng, 0.3) and len(pts) > 2:
        pts.pop(int(rng.integers(1, len(pts) - 1)))
    if maybe(rng, 0.3):  # the time axis scaled: the duration follows
        k = log_uniform(rng, 0.1, 5.0)
        for p in pts:
            p["time"] = scaled(p["time"], k)
        f["duration"] = scaled(f["duration"], k)
    for p in pts:
        if maybe(rng, 0.3):
            p["F0"] = scaled(p["F0"], log_uniform(rng, 0.5, 2.0))
        if maybe(rng, 0.3):
            p["gamma"] = choice(rng, [0.0, 0.005, 0.02, 0.2])
        if "fill" in p and maybe(rng, 0.3):
            p["fill"] = [float(rng.uniform(0.0, 1.0)) for _ in p["fill"]]
        if maybe(rng, 0.3):
            lo = log_uniform(rng, 0.5, 40.0)
            p["oscillation"] = (f"{lo:.4g} Hz" if maybe(rng, 0.3)
                                else [f"{lo:.4g} Hz", f"{lo * log_uniform(rng, 1.05, 3):.4g} Hz"])


def mutate(rng, base: dict) -> dict:
    """One mutated case from a shipped case (a deep copy)."""
    case = copy.deepcopy(base)
    case["name"] = "fuzz-independent"
    case["max_seconds"] = choice(rng, [10.0, 20.0, 30.0, 60.0])
    mutate_thrust(rng, case["thrust"])
    if "booster" in case:
        mutate_booster(rng, case["booster"])
    if "truncation" in case or maybe(rng, 0.3) and "booster" in case:
        case["truncation"] = case.get("truncation", {})
        mutate_truncation(rng, case["truncation"])
    if "damping" in case and maybe(rng):
        d = case["damping"]
        for key in list(d):
            if maybe(rng):
                d[key] = choice(rng, [0.0, 0.001, 0.01, 0.1, 0.3, 0.9])
    if "vehicle" in case:
        mutate_vehicle(rng, case["vehicle"], case.get("flight"), case.get("output"))
        case["vehicle"].pop("_length", None)
    elif "booster" in case and maybe(rng, 0.3):  # the memo vehicle from [booster]
        case["vehicle"] = {"k_max": int(choice(rng, [0, 1, 2, 4])),
                           "n_modes": int(choice(rng, [1, 2, 4, 8])),
                           "junction": choice(rng, ["memo-bulkhead", "rigid-bulkhead"]),
                           "damping_ratio": choice(rng, [0.0, 0.01, 0.3, 0.99])}
    if "flight" in case:
        if maybe(rng, 0.3):
            del case["flight"]
        else:
            mutate_flight(rng, case["flight"])
    if maybe(rng, 0.3):
        case["output"] = {**case.get("output", {}), "units": choice(rng, ["SI", "US"])}
    if maybe(rng, 0.2):
        case["severity"] = {"psi0": float(rng.uniform(-0.1, 0.1)),
                            "beam_amplitude": choice(rng, [0.0, 1e-6, 1e-4]),
                            "threshold": float(rng.uniform(0.0, 1.0)),
                            "resolution": float(log_uniform(rng, 1e-4, 0.5))}
    return case


# --------------------------------------------------------------------------------------------
# Running
# --------------------------------------------------------------------------------------------
def run_child(argv: list[str], timeout: float) -> tuple[int | None, str, float, float]:
    """(exit code or None after the timeout, stderr, CPU s of the child, wall s)."""
    env = {**os.environ, "PYTHONPATH": str(ROOT / "src"), "OPENBLAS_NUM_THREADS": "1"}
    start = time.perf_counter()
    with tempfile.TemporaryFile() as err:
        proc = subprocess.Popen([sys.executable, "-m", "flexbooster", *argv], env=env,
                                stdout=subprocess.DEVNULL, stderr=err,
                                start_new_session=True)
        deadline = start + timeout
        while True:
            pid, status, usage = os.wait4(proc.pid, os.WNOHANG)
            if pid:
                break
            if time.perf_counter() > deadline:
                os.killpg(proc.pid, 9)
                pid, status, usage = os.wait4(proc.pid, 0)
                proc.returncode = 0
                err.seek(0)
                return None, err.read().decode(errors="replace"), \
                    usage.ru_utime + usage.ru_stime, time.perf_counter() - start
            time.sleep(0.05)
        proc.returncode = os.waitstatus_to_exitcode(status)
        err.seek(0)
        return (proc.returncode, err.read().decode(errors="replace"),
                usage.ru_utime + usage.ru_stime, time.perf_counter() - start)


_EST = re.compile(r"estimated run time ([0-9.e+-]+) s exceeds")


def _finite(obj) -> bool:
    if isinstance(obj, float):
        return math.isfinite(obj)
    if isinstance(obj, dict):
        return all(_finite(v) for v in obj.values())
    if isinstance(obj, list):
        return all(_finite(v) for v in obj)
    return True


def classify(case: dict, work: Path, budget: float) -> dict:
    """Run one case (estimate, then the run); its outcome and numbers."""
    path = work / "case.toml"
    path.write_text(dump_toml(case))
    out = work / "out"
    code, err, cpu0, _ = run_child(["run", str(path), "-o", str(out), "-q", "--no-figures",
                                    "--max-seconds", "1e-9"], timeout=300.0)
    lines = err.strip().splitlines()
    m = _EST.search(err)
    rec = {"estimate": float(m[1]) if m else None, "baseline_cpu": round(cpu0, 2)}
    if code is None:
        return {**rec, "outcome": "hang", "detail": "estimate still running after 300 s"}
    if code != 2 or len(lines) != 1:
        return {**rec, "outcome": "internal", "detail": f"estimate: exit {code}: " +
                " | ".join(lines[-3:])[:400]}
    if not m:  # refused before the estimate (a rule of the case): one line, exit 2
        return {**rec, "outcome": "refused", "detail": lines[0][:300]}
    est = float(m[1])
    timeout = HANG_FACTOR * max(budget, est) + 60.0
    code, err, cpu, wall = run_child(["run", str(path), "-o", str(out), "-q", "--no-figures"],
                                     timeout=timeout)
    lines = err.strip().splitlines()
    rec.update(cpu=round(cpu, 2), wall=round(wall, 2))
    if code is None:
        return {**rec, "outcome": "hang", "detail": f"killed after {timeout:.0f} s wall"}
    if code == 2 and len(lines) == 1:
        return {**rec, "outcome": "refused", "detail": lines[0][:300]}
    if code != 0 or "Traceback" in err:
        return {**rec, "outcome": "internal", "detail": f"exit {code}: " +
                " | ".join(lines[-3:])[:400]}
    text = (out / "results.json").read_text()
    if not _finite(json.loads(text)):  # json reads NaN / Infinity as floats
        return {**rec, "outcome": "nan", "detail": "NaN or inf in results.json"}
    warned = '"cost-estimate"' in text
    analysis = cpu - cpu0  # the start-up, validation and estimate counted once
    if analysis > max(ESTIMATE_FACTOR * est, ESTIMATE_FLOOR) and not warned:
        return {**rec, "outcome": "over-estimate",
                "detail": f"{analysis:.1f} s CPU against {est:.2f} s estimated"}
    return {**rec, "outcome": "ok", "detail": f"{analysis:.1f} s CPU, est. {est:.2f} s"}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seed", type=int, default=36)
    ap.add_argument("--cases", type=int, default=1000)
    ap.add_argument("--minutes", type=float, default=40.0)
    ap.add_argument("--start", type=int, default=0, help="first case index (to replay one)")
    ap.add_argument("--log", type=Path, default=None)
    ap.add_argument("--keep", type=Path, default=None)
    args = ap.parse_args()
    bases = [(p.name, tomllib.loads(p.read_text())) for p in BASES]
    tally: Counter = Counter()
    fields: Counter = Counter()
    stop = time.perf_counter() + 60.0 * args.minutes
    for i in range(args.start, args.cases):
        if time.perf_counter() > stop:
            break
        rng = np.random.default_rng([args.seed, i])  # case i alone replays: --start i
        name, base = bases[int(rng.integers(len(bases)))]
        case = mutate(rng, base)
        with tempfile.TemporaryDirectory() as tmp:
            rec = classify(case, Path(tmp), case["max_seconds"])
        tally[rec["outcome"]] += 1
        if rec["outcome"] == "refused":
            fields[rec["detail"].removeprefix("flexbooster: error: ").split(" = ")[0]] += 1
        print(f"{i:5d} {name:24s} {rec['outcome']:13s} {rec['detail'][:160]}", flush=True)
        if args.log:
            with args.log.open("a") as log:
                log.write(json.dumps({"i": i, "base": name, **rec}) + "\n")
        if args.keep and rec["outcome"] not in ("ok", "refused"):
            args.keep.mkdir(parents=True, exist_ok=True)
            (args.keep / f"case-{i}.toml").write_text(dump_toml(case))
    n = sum(tally.values())
    print(f"\nindependent fuzz (seed {args.seed}, {n} cases): "
          + ", ".join(f"{k} {v}" for k, v in sorted(tally.items())))
    print("refusals by field: " + ", ".join(f"{k} {v}" for k, v in fields.most_common()))


if __name__ == "__main__":
    main()
