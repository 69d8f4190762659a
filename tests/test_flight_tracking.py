"""flexbooster.flight.tracking: modes keep their identity across frozen times (MAC and the
Hungarian assignment; docs/theory/flight.md).

Evidence: (1) a 2-DOF system built from fixed mass-orthonormal shapes whose stiffnesses vary
linearly, so the frequencies cross while the shapes stay fixed (closed form); (2) a rod
with axial and torsional freedoms and a propellant mass that drains (axial only): the
subsystems are uncoupled, so each mode's type is an invariant and the axial frequencies are
those of the axial rod alone (an independent model); (3) MAC values in closed form; bad input.
"""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg

from flexbooster.flight import MODE_COLUMNS, mac_matrix, mode_rows, track_modes


def test_mac_closed_form():
    """Closed form: MAC of e1 with (1, 1) / sqrt 2 is 1/2; with M = diag(1, 3) it is
    (1)^2 / (1 * 4) = 1/4; a shape with itself times -2 has MAC 1 (scale and sign free)."""
    a = np.array([[1.0], [0.0]])
    b = np.array([[1.0], [1.0]]) / np.sqrt(2.0)
    assert mac_matrix(a, b)[0, 0] == pytest.approx(0.5, rel=1e-14)
    assert mac_matrix(a, b, mass=np.diag([1.0, 3.0]))[0, 0] == pytest.approx(0.25, rel=1e-14)
    assert mac_matrix(b, -2.0 * b)[0, 0] == pytest.approx(1.0, rel=1e-14)


def test_two_dof_crossing_frequencies_keep_identities():
    """Closed form: K(t) = M Phi diag(k1 + a t, k2 + b t) Phi^T M with Phi^T M Phi = I fixed,
    so mode j has the shape Phi[:, j] and omega_j^2 = k_j + (a, b)_j t at every time; the two
    cross at t = 0.5. The tracked frequencies equal that closed form (1e-10 relative), the
    MAC between neighbouring times is 1 (1e-10) and the sorted order swaps at the crossing."""
    M = np.array([[2.0, 0.3], [0.3, 1.0]])
    L = np.linalg.cholesky(np.linalg.inv(M))
    Q = np.array([[np.cos(0.4), -np.sin(0.4)], [np.sin(0.4), np.cos(0.4)]])
    Phi = L @ Q  # Phi^T M Phi = Q^T L^T M L Q = I
    np.testing.assert_allclose(Phi.T @ M @ Phi, np.eye(2), atol=1e-14)
    times = np.linspace(0.0, 1.0, 12)  # no frozen time on the crossing at 0.5
    k = np.stack([1.0 + 2.0 * times, 2.0 + 0.0 * times], axis=1)  # linear parameters
    shapes, freqs = [], []
    for kt in k:
        K = M @ Phi @ np.diag(kt) @ Phi.T @ M
        w2, V = scipy.linalg.eigh(K, M)  # ascending: the order swaps at t = 0.5
        shapes.append(V)
        freqs.append(np.sqrt(w2))
    tracked = track_modes(shapes, freqs, mass=M)
    np.testing.assert_allclose(tracked.frequencies, np.sqrt(k), rtol=1e-10)
    np.testing.assert_allclose(tracked.mac, 1.0, atol=1e-10)
    assert tracked.order[0].tolist() == [0, 1] and tracked.order[-1].tolist() == [1, 0]
    assert tracked.crossings() == [(5, 0, 1)]
    # plain MAC (no mass) keeps the identities too: the shapes are distinct
    plain = track_modes(shapes, freqs)
    assert plain.order.tolist() == tracked.order.tolist()
    # the MAC given by the caller (every mode of t against every mode of t + 1, M-weighted as
    # the flight stage does with the DOF vectors it holds): the closed-form identities again
    given = [mac_matrix(shapes[t], shapes[t + 1], mass=M) for t in range(times.size - 1)]
    via_macs = track_modes(shapes, freqs, macs=given)
    assert via_macs.order.tolist() == tracked.order.tolist()
    np.testing.assert_allclose(via_macs.mac, 1.0, atol=1e-10)
    # the flight-modes.csv rows: one per time and mode, hz = omega / (2 pi)
    rows = mode_rows(times, tracked, k=0, types=["axial", "bending"])
    assert len(rows) == 24 and tuple(rows[0]) == MODE_COLUMNS
    assert rows[-1] == {"time_s": 1.0, "k": 0, "mode": 2, "hz": pytest.approx(
        np.sqrt(2.0) / (2 * np.pi), rel=1e-10), "type": "bending"}


def _rod(n_el: int, added: float, tip: float):
    """Fixed-free rod, DOFs interleaved (u_1, theta_1, ..., u_n, theta_n): axial EA = 1,
    torsion GJ = 0.6, structural mass 1 and polar inertia 1 per length, length 1; the
    propellant adds ``added`` per length and ``tip`` at the free end to the axial mass only
    (an inviscid liquid does not turn with the wall). Consistent mass, linear elements."""
    h = 1.0 / n_el
    n = 2 * n_el
    K = np.zeros((n, n))
    M = np.zeros((n, n))
    ke = np.array([[1.0, -1.0], [-1.0, 1.0]]) / h
    me = np.array([[2.0, 1.0], [1.0, 2.0]]) * h / 6.0
    for e in range(n_el):
        for dof, stiff, mass in ((0, 1.0, 1.0 + added), (1, 0.6, 1.0)):
            idx = [2 * (e - 1) + dof, 2 * e + dof] if e > 0 else [2 * e + dof]
            sl = slice(2 - len(idx), 2)
            K[np.ix_(idx, idx)] += stiff * ke[sl, sl]
            M[np.ix_(idx, idx)] += mass * me[sl, sl]
    M[n - 2, n - 2] += tip
    return K, M


def test_rod_with_draining_propellant_keeps_identities():
    """Independent model: the rod's axial and torsional freedoms are uncoupled, so every mode
    is purely axial or purely torsional, and the axial modes are the axial rod's alone. As
    the propellant drains the axial frequencies rise through the torsional ones (crossings
    happen) and leave the computed set of the m lowest at its top. Every identity keeps its
    type (axial share 0 or 1 to 1e-12), an axial identity's frequency is an eigenvalue of the
    separate axial rod (1e-9 relative) and rises at every step, MAC > 0.9 between
    neighbouring times (the acceptance threshold), and identities enter and leave
    only among the two highest of the set."""
    n_el, m = 30, 8
    times = np.linspace(0.0, 1.0, 41)
    shapes, freqs, masses, axial_rod = [], [], [], []
    for t in times:
        K, M = _rod(n_el, added=3.0 * (1.0 - t), tip=0.5 * (1.0 - t))
        w2, V = scipy.linalg.eigh(K, M, subset_by_index=[0, m - 1])
        shapes.append(V)
        freqs.append(np.sqrt(w2))
        masses.append(M)
        axial_rod.append(np.sqrt(scipy.linalg.eigh(K[0::2, 0::2], M[0::2, 0::2],
                                                   eigvals_only=True)))
    tracked = track_modes(shapes, freqs, mass=masses)
    assert tracked.crossings(), "the drain must make an axial mode cross a torsional one"
    assert tracked.min_mac > 0.9
    present = tracked.present
    assert present[:, :4].all(), "the four lowest at lift-off stay in the set"
    for j in range(tracked.order.shape[1]):
        ts = np.nonzero(present[:, j])[0]
        share = np.array([np.sum(shapes[i][0::2, tracked.order[i, j]] ** 2)
                          / np.sum(shapes[i][:, tracked.order[i, j]] ** 2) for i in ts])
        assert np.allclose(share, 0.0, atol=1e-12) or np.allclose(share, 1.0, atol=1e-12)
        assert np.all(np.diff(ts) == 1), "an identity is present on one interval of time"
        if share[0] > 0.5:  # axial: an eigenvalue of the axial rod, rising
            for i in ts:
                gap = np.min(np.abs(axial_rod[i] / tracked.frequencies[i, j] - 1.0))
                assert gap < 1e-9
            assert np.all(np.diff(tracked.frequencies[ts, j]) > 0.0)
        rank_first = np.sum(freqs[ts[0]] > tracked.frequencies[ts[0], j])
        rank_last = np.sum(freqs[ts[-1]] > tracked.frequencies[ts[-1], j])
        if ts[0] > 0:
            assert rank_first <= 1, "an identity enters at the top of the set"
        if ts[-1] < times.size - 1:
            assert rank_last <= 1, "an identity leaves at the top of the set"


def test_bad_input_names_the_parameter():
    """Bad input: ValueError naming the parameter."""
    a = np.eye(3)[:, :2]
    with pytest.raises(ValueError, match="^shapes_per_time"):
        track_modes([], [])
    with pytest.raises(ValueError, match="^frequencies_per_time"):
        track_modes([a, a], [[1.0, 2.0]])
    with pytest.raises(ValueError, match=r"^shapes_per_time\[1\]"):
        track_modes([a, np.eye(4)], [[1.0, 2.0], [1.0, 2.0, 3.0, 4.0]])
    with pytest.raises(ValueError, match=r"^frequencies_per_time\[1\]"):
        track_modes([a, np.eye(3)], [[1.0, 2.0], [1.0, 2.0]])
    with pytest.raises(ValueError, match="^min_mac"):
        track_modes([a], [[1.0, 2.0]], min_mac=0.0)
    with pytest.raises(ValueError, match="^mass"):
        track_modes([a, a], [[1.0, 2.0]] * 2, mass=np.eye(2))
    with pytest.raises(ValueError, match=r"^macs\[0\] = shape"):
        track_modes([a, a], [[1.0, 2.0]] * 2, macs=[np.eye(3)])
    with pytest.raises(ValueError, match="^macs: 2 matrices"):
        track_modes([a, a], [[1.0, 2.0]] * 2, macs=[np.eye(2)] * 2)
    with pytest.raises(ValueError, match=r"^macs\[0\]: must lie"):
        track_modes([a, a], [[1.0, 2.0]] * 2, macs=[2.0 * np.eye(2)])
    with pytest.raises(ValueError, match="^macs: give"):
        track_modes([a, a], [[1.0, 2.0]] * 2, macs=[np.eye(2)], mass=np.eye(3))
    with pytest.raises(ValueError, match="^a, b"):
        mac_matrix(np.zeros((3, 1)), a)
    with pytest.raises(ValueError, match="^frequencies_per_time"):
        track_modes([a], [[1.0, np.nan]])
