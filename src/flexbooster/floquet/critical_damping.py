"""The smallest modal damping that closes an instability region of a linear periodic system.

M q'' + (C0 + zeta C1) q' + (A + B cos Omega t) q = 0: the region's largest growth rate g(zeta) =
max over Omega in the region of log|rho|_max / T falls as the damping grows (Bolotin 1964,
sec. 6); its root in zeta is the critical damping ratio.  Theory: ``docs/theory/verdicts.md``.
"""

from __future__ import annotations

import numpy as np

from .mathieu import ZETA_SEARCH_MAX
from .multipliers import MAX_STEPS, growth_rate
from .optimize import brent_max, illinois_root

__all__ = ["critical_damping", "CLOSED_GROWTH"]

#: A growth rate below this times Omega_hi counts as closed: round-off of log|rho| / T with
#: multipliers of unit modulus to ~1e-12 (an undamped rigid mode keeps the growth at 0 outside
#: every region).
CLOSED_GROWTH = 1e-10
#: Omega samples across the region (ends included) besides the previous maximiser before each
#: Brent maximum: outside the shrinking region the growth is flat, and Brent started there
#: would stay on the plateau.
_SAMPLES = 7
#: Rounds of the root search in zeta, and the first round's bracket relative to its upper
#: end when the lower one is 0 (an undamped start).
_ROUNDS, _FIRST_ROUND = 4, 1e-3
#: Omega tolerance of each maximum, relative to the region's width.
_OMEGA_XTOL = 1e-4


def critical_damping(M, C1, A, B, *, omega_lo: float, omega_hi: float, zeta: float = 0.0,
                     C0=None,
                     zeta_max: float = ZETA_SEARCH_MAX, omega_start: float | None = None,
                     rtol: float = 1e-6,
                     step_phase: float = 0.06, max_steps: int = MAX_STEPS) -> float | None:
    """Smallest zeta >= ``zeta`` at which the region open in [omega_lo, omega_hi] at damping
    C0 + zeta C1 closes, or None when it is still open at ``zeta_max``.

    The damped region lies inside the less damped one (damping narrows a region about its
    centre, Bolotin 1964, sec. 6), so the search stays in the given interval: the region's edges
    at damping ``zeta``.  Illinois root of g(zeta) - CLOSED_GROWTH Omega_hi, each g a Brent
    maximum over Omega.

    Parameters
    ----------
    M, C1, A, B : array_like, shape (n, n)
        Mass, damping per unit damping ratio (1/s), stiffness and excitation (1/s^2).
    omega_lo, omega_hi : float
        The region's edges at ``zeta`` (rad/s), 0 < omega_lo < omega_hi.
    zeta : float
        The damping ratio at which the region is open, 0 <= zeta < zeta_max.
    C0 : array_like, shape (n, n), optional
        Damping that does not scale with zeta (1/s; e.g. the rigid pitch's own), default 0.
    zeta_max : float
        Largest damping ratio searched, <= 1.
    omega_start : float, optional
        Where the growth is largest at ``zeta`` (rad/s), if known: the first maximum's start.
    rtol : float
        Tolerance on zeta, relative, 1e-12..1e-2.
    step_phase, max_steps
        Monodromy step control (:func:`flexbooster.floquet.monodromy`).
    """
    lo, hi = float(omega_lo), float(omega_hi)
    if not (np.isfinite(lo) and np.isfinite(hi) and 0.0 < lo < hi):
        raise ValueError(f"omega_lo, omega_hi = {omega_lo!r}, {omega_hi!r}: must be finite "
                         "with 0 < omega_lo < omega_hi")
    if not (np.isfinite(zeta_max) and 0.0 < zeta_max <= 1.0):
        raise ValueError(f"zeta_max = {zeta_max!r}: must be in (0, 1]")
    if not (np.isfinite(zeta) and 0.0 <= zeta < zeta_max):
        raise ValueError(f"zeta = {zeta!r}: must be in [0, zeta_max)")
    if not (np.isfinite(rtol) and 1e-12 <= rtol <= 1e-2):
        raise ValueError(f"rtol = {rtol!r}: must be in 1e-12..1e-2")
    C1 = np.asarray(C1, dtype=float)
    if not np.all(np.isfinite(C1)) or not np.any(C1):
        raise ValueError("C1: must be finite and not zero (the damping per unit ratio)")
    C0 = np.zeros_like(C1) if C0 is None else np.asarray(C0, dtype=float)
    if C0.shape != C1.shape or not np.all(np.isfinite(C0)):
        raise ValueError(f"C0: must be finite with the shape of C1 {C1.shape}")
    floor = CLOSED_GROWTH * hi
    xtol = np.array([max(_OMEGA_XTOL * (hi - lo), 1e-15 * hi)])
    best = [0.5 * (lo + hi) if omega_start is None or not lo <= omega_start <= hi
            else float(omega_start)]

    def g(z: float) -> float:
        def f(x, idx):
            return growth_rate(M, C0 + z * C1, A, B, np.asarray(x, dtype=float),
                               step_phase=step_phase, max_steps=max_steps)

        starts = np.concatenate([[best[0]], np.linspace(lo, hi, _SAMPLES)])
        x0 = starts[int(np.argmax(f(starts, None)))]
        x, gx = brent_max(f, np.array([lo]), np.array([hi]), np.array([x0]), xtol)
        best[0] = float(x[0])
        return float(gx[0]) - floor

    g_in = g(zeta)
    if not g_in > 0.0:
        raise ValueError(f"zeta = {zeta!r}: the region [{lo!r}, {hi!r}] is not open there")
    z_in, z_out = zeta, max(2.0 * zeta, 1e-3)
    while True:  # bracket upwards by doubling, at most log2(zeta_max / 1e-3) + 1 steps
        z_out = min(z_out, zeta_max)
        g_out = g(z_out)
        if g_out <= 0.0:
            break
        if z_out >= zeta_max:
            return None
        z_in, g_in, z_out = z_out, g_out, 2.0 * z_out

    def root_f(z, idx):
        return np.array([g(float(z[0]))])

    # rounds of Illinois, each to rtol of the bracket's open (lower) end, so that the root is
    # found to rtol of itself even far below the first bracket (zeta_cr ~ 1e-6 in [0, 1e-3]):
    # at most _ROUNDS, each ending with a narrower bracket and a larger open end
    a, fa, b, fb = (np.array([v]) for v in (z_in, g_in, z_out, g_out))
    for _ in range(_ROUNDS):
        if b[0] - a[0] <= rtol * a[0]:
            break
        xtol = rtol * a[0] if a[0] > 0.0 else _FIRST_ROUND * b[0]
        a, fa, b, fb = illinois_root(root_f, a, fa, b, fb, np.array([xtol]), bracket=True)
    return float(0.5 * (a[0] + b[0]))
