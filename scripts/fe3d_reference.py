"""Independent 3-D shell FE reference for tests/test_shell_of_revolution.py (pyfe3d Quad4).

Two clamped-free steel vehicles (aft edge clamped, nose free), defined in ``VEHICLES``:

* ``ccc``: cylinder R 1.0 m, 1.5 m, h 10 mm - cone 1.0 -> 0.7 m over 1.0 m, h 8 mm -
  cylinder R 0.7 m, 1.2 m, h 6 mm;
* ``step``: cylinder R 1.0 m, 1.5 m, h 10 mm - cylinder R 1.0 m, 1.5 m, h 5 mm.

Each is meshed on its true mid-surface with 4-node shell elements (pyfe3d ``Quad4``,
first-order shear deformation, consistent mass, drilling stiffness K6ROT = 100), ``ntheta``
elements around and square-ish elements along the meridian, for a sequence of meshes; the
lowest modes are found by shift-invert Lanczos (``scipy.sparse.linalg.eigsh``).  Each mode's
circumferential wave number k is the dominant Fourier harmonic of its radial displacement;
degenerate pairs (cos / sin) are merged.  For every k >= 2 the first ``N_PER_K`` frequencies
of the three finest meshes are Richardson-extrapolated (observed order from the three
values; if that is not in 1..6, order 2 from the two finest is used).

Needs pyfe3d (not a project dependency): ``python3 -m venv .venv-fe &&
.venv-fe/bin/pip install pyfe3d numpy scipy``, then from the worktree root
``.venv-fe/bin/python scripts/fe3d_reference.py`` (writes
tests/data/shell_of_revolution_fe3d.json; a few minutes on 1 core).
"""

from __future__ import annotations

import json
import sys
import time

import numpy as np
from scipy.sparse import coo_matrix
from scipy.sparse.linalg import eigsh

__all__: list[str] = []

E, NU, RHO = 210e9, 0.3, 7850.0
#: segments: (radius_aft, radius_fwd, axial length, thickness)
VEHICLES = {
    "ccc": [(1.0, 1.0, 1.5, 0.010), (1.0, 0.7, 1.0, 0.008), (0.7, 0.7, 1.2, 0.006)],
    "step": [(1.0, 1.0, 1.5, 0.010), (1.0, 1.0, 1.5, 0.005)],
}
NTHETA = (64, 96, 128, 160)
N_MODES = 40
N_PER_K = 2
K_MAX_REPORT = 10


def build_mesh(segments, ntheta):
    """Node coordinates (n, 3), node thickness of each element and connectivity."""
    rmax = max(max(s[0], s[1]) for s in segments)
    ds = 2 * np.pi * rmax / ntheta
    ring_x, ring_r, elem_h = [0.0], [segments[0][0]], []
    x0 = 0.0
    for r1, r2, length, h in segments:
        lm = np.hypot(length, r2 - r1)
        n = max(2, int(np.ceil(lm / ds)))
        t = np.linspace(0, 1, n + 1)[1:]
        ring_x.extend(x0 + t * length)
        ring_r.extend(r1 + t * (r2 - r1))
        elem_h.extend([h] * n)
        x0 += length
    ring_x, ring_r = np.array(ring_x), np.array(ring_r)
    theta = 2 * np.pi * np.arange(ntheta) / ntheta
    nr = ring_x.size
    coords = np.zeros((nr, ntheta, 3))
    coords[..., 0] = ring_r[:, None] * np.cos(theta)[None, :]
    coords[..., 1] = ring_r[:, None] * np.sin(theta)[None, :]
    coords[..., 2] = ring_x[:, None]
    ids = np.arange(nr * ntheta).reshape(nr, ntheta)
    jp = (np.arange(ntheta) + 1) % ntheta
    quads = []
    for i in range(nr - 1):
        for j in range(ntheta):
            quads.append((ids[i, j], ids[i + 1, j], ids[i + 1, jp[j]], ids[i, jp[j]],
                          elem_h[i]))
    return coords.reshape(-1, 3), ring_x, theta, quads


def solve(segments, ntheta):
    """Frequencies (Hz) and dominant k of the lowest N_MODES modes, clamped aft edge."""
    from pyfe3d import DOF, DOUBLE, INT, Quad4, Quad4Data, Quad4Probe
    from pyfe3d.shellprop_utils import isotropic_plate

    coords, ring_x, theta, quads = build_mesh(segments, ntheta)
    data, probe = Quad4Data(), Quad4Probe()
    props = {h: isotropic_plate(thickness=h, E=E, nu=NU, rho=RHO)
             for h in {q[4] for q in quads}}
    ne = len(quads)
    n = DOF * coords.shape[0]
    kr = np.zeros(data.KC0_SPARSE_SIZE * ne, dtype=INT)
    kc = np.zeros_like(kr)
    kv = np.zeros(data.KC0_SPARSE_SIZE * ne, dtype=DOUBLE)
    mr = np.zeros(data.M_SPARSE_SIZE * ne, dtype=INT)
    mc = np.zeros_like(mr)
    mv = np.zeros(data.M_SPARSE_SIZE * ne, dtype=DOUBLE)
    flat = coords.ravel().copy()
    for e, (n1, n2, n3, n4, h) in enumerate(quads):
        quad = Quad4(probe)
        quad.n1, quad.n2, quad.n3, quad.n4 = n1, n2, n3, n4
        quad.c1, quad.c2, quad.c3, quad.c4 = DOF * n1, DOF * n2, DOF * n3, DOF * n4
        quad.init_k_KC0 = e * data.KC0_SPARSE_SIZE
        quad.init_k_M = e * data.M_SPARSE_SIZE
        quad.K6ROT = 100.0
        quad.update_rotation_matrix(flat)  # isotropic: no material direction needed
        quad.update_probe_xe(flat)
        quad.update_KC0(kr, kc, kv, props[h])
        quad.update_M(mr, mc, mv, props[h], mtype=0)
    K = coo_matrix((kv, (kr, kc)), shape=(n, n)).tocsc()
    M = coo_matrix((mv, (mr, mc)), shape=(n, n)).tocsc()
    fixed = np.zeros(n, dtype=bool)
    aft = np.isclose(coords[:, 2], 0.0)
    for d in range(DOF):
        fixed[d::DOF][aft] = True
    free = ~fixed
    vals, vecs = eigsh(K[free][:, free], k=N_MODES, M=M[free][:, free], sigma=-1.0,
                       which="LM", tol=1e-10)
    order = np.argsort(vals)
    vals, vecs = vals[order], vecs[:, order]
    full = np.zeros((n, vals.size))
    full[free] = vecs
    ux = full[0::DOF].reshape(ring_x.size, theta.size, -1)
    uy = full[1::DOF].reshape(ring_x.size, theta.size, -1)
    ur = ux * np.cos(theta)[None, :, None] + uy * np.sin(theta)[None, :, None]
    ut = -ux * np.sin(theta)[None, :, None] + uy * np.cos(theta)[None, :, None]
    spec = (np.abs(np.fft.rfft(ur, axis=1)) ** 2 + np.abs(np.fft.rfft(ut, axis=1)) ** 2).sum(0)
    ks = np.argmax(spec, axis=0)
    return np.sqrt(np.maximum(vals, 0)) / (2 * np.pi), ks, len(quads), int(free.sum())


def per_k(hz, ks):
    """{k: ascending distinct frequencies} (the cos / sin pairs of k >= 1 merged)."""
    out = {}
    for k in np.unique(ks):
        f = np.sort(hz[ks == k])
        keep = [f[0]]
        for val in f[1:]:
            if val / keep[-1] - 1 > 1e-5:
                keep.append(val)
        out[int(k)] = keep
    return out


def richardson(h, f):
    """Extrapolated value and order from values f on mesh sizes h (last three used)."""
    h, f = np.asarray(h[-3:], float), np.asarray(f[-3:], float)
    d1, d2 = f[0] - f[1], f[1] - f[2]
    order = np.nan
    if d1 * d2 > 0 and abs(d2) > 0:
        # solve d1 / d2 = (r1^p - 1) r2^p / (r2^p - 1) for p by bisection (r1 ~ r2)
        def g(p):
            return (h[0] ** p - h[1] ** p) / (h[1] ** p - h[2] ** p) - d1 / d2
        lo, hi = 0.5, 8.0
        if g(lo) * g(hi) < 0:
            for _ in range(200):
                mid = 0.5 * (lo + hi)
                if g(lo) * g(mid) <= 0:
                    hi = mid
                else:
                    lo = mid
            order = 0.5 * (lo + hi)
    p = order if np.isfinite(order) and 1.0 <= order <= 6.0 else 2.0
    fx = f[2] - (f[1] - f[2]) / ((h[1] / h[2]) ** p - 1)
    return float(fx), (float(order) if np.isfinite(order) else None), float(p)


def main() -> None:
    out = {"command": "python " + " ".join(sys.argv), "E": E, "nu": NU, "rho": RHO,
           "ends": "aft clamped, forward free", "element": "pyfe3d Quad4 (FSDT, consistent "
           "mass, K6ROT = 100)", "ntheta": list(NTHETA), "vehicles": {}}
    try:
        import pyfe3d
        out["pyfe3d"] = pyfe3d.__version__
    except ImportError:  # pragma: no cover
        raise SystemExit("pyfe3d is needed: see the module docstring") from None
    for name, segs in VEHICLES.items():
        runs, meshes = [], []
        for nt in NTHETA:
            t0 = time.perf_counter()
            hz, ks, n_el, n_dof = solve(segs, nt)
            runs.append(per_k(hz, ks))
            seconds = time.perf_counter() - t0
            meshes.append({"ntheta": nt, "elements": n_el, "dofs": n_dof, "seconds": seconds})
            print(f"{name} ntheta={nt}: {n_el} elements, {n_dof} DOFs, {seconds:.1f} s",
                  flush=True)
        sizes = [1.0 / nt for nt in NTHETA]
        table = {}
        for k in range(2, K_MAX_REPORT + 1):
            cols = []
            for j in range(N_PER_K):
                vals = [run.get(k, [])[j] if len(run.get(k, [])) > j else None for run in runs]
                if any(v is None for v in vals[-3:]):
                    continue
                fx, order, used = richardson(sizes, vals)
                cols.append({"mesh_hz": vals, "extrapolated_hz": fx, "observed_order": order,
                             "order_used": used})
            if cols:
                table[str(k)] = cols
        out["vehicles"][name] = {"segments": segs, "meshes": meshes, "modes": table}
    path = "tests/data/shell_of_revolution_fe3d.json"
    with open(path, "w") as fh:
        json.dump(out, fh, indent=1)
    print("written", path)


if __name__ == "__main__":
    main()
