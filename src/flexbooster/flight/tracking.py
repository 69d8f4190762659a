"""Mode tracking across frozen times by the modal assurance criterion (MAC): each mode of one
time is assigned to one mode of the next by the Hungarian method on 1 - MAC, so a mode keeps
its identity where frequencies cross. Theory: docs/theory/flight.md.

References: R. J. Allemang, D. L. Brown, "A correlation coefficient for modal vector analysis",
Proc. 1st IMAC (1982) 110-116; R. J. Allemang, Sound and Vibration 37 (2003) 14-23; H. W. Kuhn,
Naval Res. Logist. Q. 2 (1955) 83-97 (assignment).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from ..checks import finite, finite_array

__all__ = ["MODE_COLUMNS", "TrackedModes", "mac_matrix", "mode_rows", "track_modes"]

#: Columns of flight-modes.csv, in order (the keys of :func:`mode_rows`).
MODE_COLUMNS = ("time_s", "k", "mode", "hz", "type")


def mac_matrix(a: Any, b: Any, *, mass: Any = None) -> np.ndarray:
    """MAC_ij = |a_i^T M b_j|^2 / ((a_i^T M a_i)(b_j^T M b_j)) (Allemang & Brown 1982), in
    [0, 1]; M = I without ``mass``.

    Parameters
    ----------
    a, b : array_like
        Mode shapes as columns, (n_dof, m_a) and (n_dof, m_b), real or complex, no zero column.
    mass : array_like, optional
        Symmetric positive definite (n_dof, n_dof) weight (the mass matrix).
    """
    a = _shapes("a", a)
    b = _shapes("b", b)
    if a.shape[0] != b.shape[0]:
        raise ValueError(f"a, b: {a.shape[0]} and {b.shape[0]} rows, must be the same DOFs")
    Mb = b if mass is None else _mass(mass, a.shape[0]) @ b
    Ma = a if mass is None else _mass(mass, a.shape[0]) @ a
    cross = np.abs(a.conj().T @ Mb) ** 2  # |a_i^H M b_j|^2
    na = np.real(np.einsum("ij,ij->j", a.conj(), Ma))
    nb = np.real(np.einsum("ij,ij->j", b.conj(), Mb))
    if np.any(na <= 0.0) or np.any(nb <= 0.0):
        raise ValueError("a, b: every shape needs a positive norm a^T M a (no zero column)")
    return np.clip(cross / np.outer(na, nb), 0.0, 1.0)


def _shapes(name: str, value: Any) -> np.ndarray:
    try:
        arr = np.asarray(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} = {value!r:.60}: must be an (n_dof, n_modes) array") from None
    if arr.ndim != 2 or 0 in arr.shape:
        raise ValueError(f"{name} = shape {arr.shape}: must be a non-empty (n_dof, n_modes) "
                         "array")
    if np.iscomplexobj(arr):
        if not np.all(np.isfinite(arr)):
            raise ValueError(f"{name}: must be finite")
        return arr
    return finite_array(name, arr)


def _mass(value: Any, n: int) -> np.ndarray:
    M = finite_array("mass", value)
    if M.shape != (n, n):
        raise ValueError(f"mass = shape {M.shape}: must be ({n}, {n})")
    return M


@dataclass(frozen=True)
class TrackedModes:
    """Mode identities across frozen times.

    Identity j is the j-th lowest mode at the first time for j < m; a mode that enters the
    computed set later (a higher mode coming down, or one without a continuation) gets the
    next identity, and an identity ends where its best assignment has MAC < ``min_mac``.

    Attributes
    ----------
    order : numpy.ndarray
        (T, N) int: ``order[t, j]`` is the column, in the shapes given at time t, of identity
        j; -1 where identity j is not in the set at time t.
    mac : numpy.ndarray
        (T - 1, N): MAC between identity j at times t and t + 1; NaN where it is absent at
        either.
    frequencies : numpy.ndarray
        (T, N): the frequency of identity j at time t (units of the input); NaN where absent.
    """

    order: np.ndarray
    mac: np.ndarray
    frequencies: np.ndarray

    @property
    def present(self) -> np.ndarray:
        """(T, N) bool: identity j is in the set at time t."""
        return self.order >= 0

    @property
    def min_mac(self) -> float:
        """The smallest MAC of any continued identity (1.0 where none is continued)."""
        values = self.mac[np.isfinite(self.mac)]
        return float(values.min()) if values.size else 1.0

    def crossings(self) -> list[tuple[int, int, int]]:
        """(t, i, j): identities i < j, present at t and t + 1, swap frequency order between
        times t and t + 1."""
        f = self.frequencies
        out = []
        for t in range(f.shape[0] - 1):
            d0 = f[t][:, None] - f[t][None, :]
            d1 = f[t + 1][:, None] - f[t + 1][None, :]
            with np.errstate(invalid="ignore"):
                swapped = np.triu(d0 * d1 < 0.0, 1)
            i, j = np.nonzero(swapped)
            out += [(t, int(a), int(b)) for a, b in zip(i, j, strict=True)]
        return out


def track_modes(shapes_per_time: Any, frequencies_per_time: Any, *, mass: Any = None,
                macs: Any = None, min_mac: float = 0.5) -> TrackedModes:
    """Follow the modes through the frozen times: at each step the assignment of the next
    time's modes to the present identities that maximises the total MAC (Hungarian method,
    scipy.optimize.linear_sum_assignment on 1 - MAC, Kuhn 1955); an assignment with
    MAC < ``min_mac`` is no continuation (the mode left the computed set and another entered).

    Parameters
    ----------
    shapes_per_time : sequence of array_like
        Per frozen time, the mode shapes as columns (n_dof, m_t) on a common set of DOFs
        (n_dof fixed, the number of modes m_t may change).
    frequencies_per_time : sequence of array_like
        Per frozen time, the m_t frequencies of those columns (any unit, finite).
    mass : array_like or sequence of array_like, optional
        One mass matrix, or one per frozen time; the MAC between times t and t + 1 is
        weighted by their mean (M_t + M_t+1) / 2. Without it the plain MAC.
    macs : sequence of array_like, optional
        Per step t = 0..T-2, the MAC (m_t, m_t+1) between every mode of time t and every mode
        of time t + 1, computed by the caller (e.g. :func:`mac_matrix` with the mass matrices
        it holds), used instead of the MAC of the shapes; not with ``mass``.
    min_mac : float
        Smallest MAC of a continuation, in (0, 1].
    """
    # scipy.optimize here, not at import: a run without [flight] does not load it
    from scipy.optimize import linear_sum_assignment

    shapes = [_shapes(f"shapes_per_time[{t}]", s) for t, s in enumerate(shapes_per_time)]
    freqs = [finite_array(f"frequencies_per_time[{t}]", f).ravel()
             for t, f in enumerate(frequencies_per_time)]
    if not shapes:
        raise ValueError("shapes_per_time: empty, need at least one frozen time")
    if len(freqs) != len(shapes):
        raise ValueError(f"frequencies_per_time: {len(freqs)} times, must be {len(shapes)} "
                         "like shapes_per_time")
    min_mac = finite("min_mac", min_mac)
    if not 0.0 < min_mac <= 1.0:
        raise ValueError(f"min_mac = {min_mac!r}: must be in (0, 1]")
    n_dof = shapes[0].shape[0]
    for t, (s, f) in enumerate(zip(shapes, freqs, strict=True)):
        if s.shape[0] != n_dof:
            raise ValueError(f"shapes_per_time[{t}] = shape {s.shape}: must have {n_dof} rows "
                             "(DOFs) like the first time")
        if f.size != s.shape[1]:
            raise ValueError(f"frequencies_per_time[{t}]: {f.size} values, must be "
                             f"{s.shape[1]} like its shapes' columns")
    masses = _masses(mass, len(shapes), n_dof)
    T = len(shapes)
    given = None if macs is None else _given_macs(macs, [s.shape[1] for s in shapes])
    if given is not None and masses is not None:
        raise ValueError("macs: give the MAC or the mass matrices, not both")
    first = np.argsort(freqs[0], kind="stable")  # identities: ascending at the first time
    history = {j: [(0, int(c))] for j, c in enumerate(first)}  # identity -> (time, column)
    links: list[list[tuple[int, float]]] = [[] for _ in first]  # identity -> (time, MAC)
    active = list(range(first.size))  # the identities present at the current time
    for t in range(T - 1):
        weight = None if masses is None else 0.5 * (masses[t] + masses[t + 1])
        cols_now = [history[j][-1][1] for j in active]
        mac = mac_matrix(shapes[t][:, cols_now], shapes[t + 1], mass=weight) if given is None \
            else given[t][cols_now]
        rows, cols = linear_sum_assignment(1.0 - mac)  # maximal total MAC
        taken = set()
        continued = []
        for r, c in zip(rows, cols, strict=True):
            if mac[r, c] >= min_mac:
                j = active[r]
                history[j].append((t + 1, int(c)))
                links[j].append((t, float(mac[r, c])))
                continued.append(j)
                taken.add(int(c))
        entering = [c for c in np.argsort(freqs[t + 1], kind="stable") if int(c) not in taken]
        for c in entering:  # an identity of its own for each mode without a continuation
            j = len(history)
            history[j] = [(t + 1, int(c))]
            links.append([])
            continued.append(j)
        active = continued
    N = len(history)
    order = np.full((T, N), -1, dtype=int)
    macs = np.full((T - 1, N), np.nan)
    frequencies = np.full((T, N), np.nan)
    for j, visits in history.items():
        for t, c in visits:
            order[t, j] = c
            frequencies[t, j] = freqs[t][c]
        for t, value in links[j]:
            macs[t, j] = value
    return TrackedModes(order=order, mac=macs, frequencies=frequencies)


def _given_macs(macs: Any, sizes: list[int]) -> list[np.ndarray]:
    """The caller's MAC matrices, one per step, checked: (m_t, m_t+1), finite, in [0, 1]."""
    out = [finite_array(f"macs[{t}]", m) for t, m in enumerate(macs)]
    if len(out) != len(sizes) - 1:
        raise ValueError(f"macs: {len(out)} matrices, must be {len(sizes) - 1} (one per step "
                         "between frozen times)")
    for t, m in enumerate(out):
        if m.shape != (sizes[t], sizes[t + 1]):
            raise ValueError(f"macs[{t}] = shape {m.shape}: must be ({sizes[t]}, "
                             f"{sizes[t + 1]}) like the modes of times {t} and {t + 1}")
        if np.any(m < 0.0) or np.any(m > 1.0):
            raise ValueError(f"macs[{t}]: must lie in [0, 1]")
    return out


def _masses(mass: Any, T: int, n: int) -> list[np.ndarray] | None:
    if mass is None:
        return None
    if np.ndim(mass) == 2:
        M = _mass(mass, n)
        return [M] * T
    masses = [finite_array(f"mass[{t}]", M) for t, M in enumerate(mass)]
    if len(masses) != T:
        raise ValueError(f"mass: {len(masses)} matrices, must be one or {T} (one per time)")
    for t, M in enumerate(masses):
        if M.shape != (n, n):
            raise ValueError(f"mass[{t}] = shape {M.shape}: must be ({n}, {n})")
    return masses


def mode_rows(times: Any, tracked: TrackedModes, *, k: int,
              types: Any = None) -> list[dict[str, Any]]:
    """The rows of flight-modes.csv (:data:`MODE_COLUMNS`) of one harmonic: one per frozen
    time and present identity, ``mode`` its number j + 1 (1-based as "mode N" in every text:
    mode 1 is the lowest at the first time), ``hz`` its frequency / (2 pi).

    Parameters
    ----------
    times : array_like
        The frozen times (s), one per row of ``tracked.order``.
    tracked : TrackedModes
        The identities, frequencies in rad/s.
    k : int
        The circumferential harmonic.
    types : array_like of str, optional
        (T, N) or (N,): each identity's type ("axial", "bending", ...); default None.
    """
    t = finite_array("times", times).ravel()
    T, N = tracked.order.shape
    if t.size != T:
        raise ValueError(f"times: {t.size} values, must be {T} like tracked.order")
    kinds = None if types is None else np.broadcast_to(np.asarray(types, dtype=object), (T, N))
    return [{"time_s": float(t[i]), "k": int(k), "mode": int(j) + 1,
             "hz": float(tracked.frequencies[i, j] / (2.0 * np.pi)),
             "type": None if kinds is None else kinds[i, j]}
            for i in range(T) for j in range(N) if tracked.order[i, j] >= 0]
