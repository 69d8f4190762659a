"""The data of the figures: what each figure draws is the stored results' data, in the units and
views the figures promise (one quantity per axes, the path in view, the regions at the case's
damping, stations in metres, frequencies in Hz), and no two of its texts overprint.

Most checks read the memo case's analysis (``memo_results``, shared by the session).
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from matplotlib.patches import Rectangle
from matplotlib.text import Text

from flexbooster.bands import Band, BandMode
from flexbooster.danger import NEGLIGIBLE_GROWTH, DangerSummary, RankedBand
from flexbooster.present.figure_files import render_figure

TWO_PI = 2.0 * math.pi


def _texts(fig) -> list[Text]:
    """Every visible, non-empty text of a drawn figure with a drawn box, tick labels only where
    their tick lies in the view (matplotlib keeps labels of ticks beyond it, not drawn)."""
    hidden = set()
    for ax in fig.axes:
        for axis in (ax.xaxis, ax.yaxis):
            lo, hi = sorted(axis.get_view_interval())
            tol = 1e-9 * max(abs(lo), abs(hi))
            for tick in axis.get_major_ticks() + axis.get_minor_ticks():
                if not lo - tol <= tick.get_loc() <= hi + tol:
                    hidden.update({id(tick.label1), id(tick.label2)})
    renderer = fig.canvas.get_renderer()
    out = []
    for t in fig.findobj(Text):
        if not (t.get_visible() and t.get_text().strip()) or id(t) in hidden:
            continue
        box = t.get_window_extent(renderer)
        if box.width > 0 and box.height > 0:
            out.append(t)
    return out


def _overprinted(fig) -> list[tuple[str, str]]:
    """Pairs of texts whose drawn boxes overlap (each shrunk by one pixel a side), the texts of
    one legend apart (a legend lays its own texts out)."""
    renderer = fig.canvas.get_renderer()
    texts = _texts(fig)
    boxes = [t.get_window_extent(renderer).padded(-1.0) for t in texts]
    pairs = []
    for i in range(len(texts)):
        for j in range(i + 1, len(texts)):
            if boxes[i].overlaps(boxes[j]):
                pairs.append((texts[i].get_text(), texts[j].get_text()))
    return pairs


def _band(lo_hz: float, hi_hz: float, *, growth: float | None = None,
          amplitude: float | None = None) -> RankedBand:
    """A beam-action region (``growth``, 1/s) or a damped resonance (``amplitude``, m) over
    [lo_hz, hi_hz], in the operating range."""
    mode = BandMode("bending 1", index=1, omega=TWO_PI * lo_hz)
    band = Band(mechanism="beam_action" if amplitude is None else "resonance",
                Omega_lo=TWO_PI * lo_hz, Omega_hi=TWO_PI * hi_hz,
                kind="simple" if amplitude is None else "resonance", order=1, modes=(mode,),
                growth_rate_max=growth or 0.0, Omega_at_max=TWO_PI * lo_hz,
                Omega_center=TWO_PI * lo_hz, critical_gamma=0.0,
                severity=None if amplitude is None else amplitude,
                steady_amplitude=amplitude)
    return RankedBand(band=band, in_operating_range=True)


# ------------------------------------------------------------------------------ danger map


def test_danger_map_one_quantity_per_panel(memo_results):
    # the default case has beam-action regions (growth rates) and damped resonances (steady
    # amplitudes): two panels, one y quantity each, never two scales on one axes (no twin:
    # the panels' rectangles are disjoint)
    from flexbooster.present.plotting.danger import danger_map, danger_quantities

    danger = memo_results.danger
    regions = [b for b in danger.bands if b.growth_rate is not None]
    stems = [b for b in danger.bands if b.growth_rate is None]
    assert regions and stems
    fig = danger_map(danger)
    render_figure(fig)
    assert [k for k, _ in danger_quantities(danger)] == ["growth", "response", "acceleration"]
    top, bottom, responses = fig.axes  # the vehicle's forced responses in a third panel
    assert not top.get_position().overlaps(bottom.get_position())
    assert not bottom.get_position().overlaps(responses.get_position())
    assert top.get_ylabel() == "growth rate (1/s)"
    assert bottom.get_ylabel() == "resonance: damped response (mm)"
    assert top.get_yscale() == bottom.get_yscale() == "log"
    assert top.get_xlim() == bottom.get_xlim() == responses.get_xlim()  # one frequency axis
    assert responses.get_xlabel() == "thrust frequency Omega (Hz)"
    assert top.get_xlabel() == bottom.get_xlabel() == ""
    # the bars are the regions: each bar's top is its band's growth rate (the stored value,
    # exact), the negligible growth dotted in the same panel
    bars = {p.get_gid(): p for p in top.patches if isinstance(p, Rectangle) and p.get_gid()}
    assert len(bars) == len(regions)
    for n, b in enumerate(danger.bands):
        gid = f"danger-band-{n + 1}"
        if b.growth_rate is not None:
            r = bars[gid]
            assert r.get_y() + r.get_height() == pytest.approx(b.growth_rate, rel=1e-12)
    assert any(np.allclose(ln.get_ydata(), NEGLIGIBLE_GROWTH) for ln in top.get_lines())
    # the stems are the resonances at the damped steady amplitude in mm: the single-mode
    # closed form |G| / (2 zeta omega^2) = v / (zeta omega) (Meirovitch 1986, sec. 3.3) from the
    # band's undamped severity v (m/s), the case's modal damping and the mode's omega, 1e-12
    zeta = memo_results.case.damping.modal_ratio
    stem = {ln.get_gid(): ln for ln in bottom.get_lines() if ln.get_gid()}
    assert len(stem) == len(stems)
    for n, b in enumerate(danger.bands):
        if b.growth_rate is None:
            expected_mm = 1e3 * b.severity / (zeta * b.band.modes[0].omega)
            assert stem[f"danger-band-{n + 1}"].get_ydata()[1] == pytest.approx(
                expected_mm, rel=1e-12)
            x = stem[f"danger-band-{n + 1}"].get_xdata()[0]
            assert b.hz[0] * (1 - 1e-12) <= x <= b.hz[1] * (1 + 1e-12)  # in Hz
    # the five most dangerous numbered with their rank in the list (danger.ranking: bands
    # and responses in one order), in the panel of their quantity
    numbers = {t.get_text(): ax for ax in fig.axes for t in ax.texts}
    for n, item in enumerate(danger.ranking[:5]):
        expected = (responses if not isinstance(item, RankedBand)
                    else top if item.growth_rate is not None else bottom)
        assert numbers[str(n + 1)] is expected


def test_danger_map_labels_never_overprinted(memo_results):
    # every text of the drawn map (tick labels in view, axis labels, title, legends, the rank
    # numbers) apart from every other
    from flexbooster.present.plotting.danger import danger_map

    fig = danger_map(memo_results.danger)
    render_figure(fig)
    assert _overprinted(fig) == []


def test_danger_map_crowded_numbers_are_stacked():
    # five resonances and five regions at nearly the same frequency and level: their rank
    # numbers would print on one spot; drawn, no two overlap and all lie inside the figure
    from flexbooster.present.plotting.danger import danger_map

    bands = [_band(50.0 * (1 + 1e-3 * i), 50.1 * (1 + 1e-3 * i),
                   amplitude=1e-3 * (1 + 1e-3 * i)) for i in range(5)]
    bands += [_band(20.0 * (1 + 1e-3 * i), 20.1 * (1 + 1e-3 * i), growth=1e-2 * (1 + 1e-3 * i))
              for i in range(5)]
    danger = DangerSummary(operating_range=(TWO_PI * 5.0, TWO_PI * 200.0), verdicts=(),
                           bands=tuple(bands))
    fig = danger_map(danger)
    render_figure(fig)
    assert _overprinted(fig) == []
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:  # every number inside its panel
        frame = ax.get_window_extent(renderer)
        for t in ax.texts:
            box = t.get_window_extent(renderer)
            assert frame.y0 <= box.y0 and box.y1 <= frame.y1 + 1.0, t.get_text()
    assert sorted(t.get_text() for ax in fig.axes for t in ax.texts) == list("12345")


def test_danger_map_draws_the_vehicle_responses_numbered_as_listed():
    # the default case's danger list holds only forced responses of the vehicle (no unstable
    # band): drawn as stems at their Omega (Hz) up to their stored acceleration (g, exact), in
    # a panel of their own, each numbered with its rank in danger.ranking (the list's "#"), a
    # region ranked among them numbered likewise; no text overprinted
    from flexbooster.danger import ResponsePeak, danger_summary
    from flexbooster.present.plotting.danger import danger_map, danger_quantities

    def peak(hz: float, g: float) -> ResponsePeak:
        return ResponsePeak(source="forced response", k=0, Omega=TWO_PI * hz, acceleration_g=g,
                            station="aft-edge", station_m=0.0, modes="k = 0",
                            in_operating_range=True)

    region = _band(10.5, 10.7, growth=2e-2).band
    danger = danger_summary(operating_range=(TWO_PI * 8.0, TWO_PI * 16.0),
                            bands={"beam_action": [region]},
                            responses=[peak(9.82, 0.918), peak(12.61, 0.633)])
    assert [k for k, _ in danger_quantities(danger)] == ["growth", "acceleration"]
    fig = danger_map(danger)
    render_figure(fig)
    assert _overprinted(fig) == []
    bottom = fig.axes[-1]
    assert bottom.get_ylabel() == "forced response:\nacceleration (g)"
    stems = {ln.get_gid(): ln for ln in bottom.get_lines() if ln.get_gid()}
    for i, r in enumerate(danger.responses):
        line = stems[f"danger-response-{i + 1}"]
        assert line.get_xdata()[0] == pytest.approx(r.Omega / TWO_PI, rel=1e-12)
        assert line.get_ydata()[1] == pytest.approx(r.acceleration_g, rel=1e-12)
    numbers = {t.get_text(): (ax, t.xy) for ax in fig.axes for t in ax.texts}
    for n, item in enumerate(danger.ranking):
        ax, (x, y) = numbers[str(n + 1)]
        if isinstance(item, ResponsePeak):
            assert ax is bottom and (x, y) == pytest.approx((item.hz, item.acceleration_g))
        else:
            assert ax is fig.axes[0] and y == pytest.approx(item.growth_rate)

    # the operating range 8-16 Hz is under a decade, with a single 1-2-5 tick (10) in view:
    # the frequency axis is labelled with round linear steps, at least three, all in view
    # and placed at their values
    for ax in fig.axes:
        lo, hi = ax.get_xlim()
        ticks = [(t.get_loc(), t.label1.get_text()) for t in ax.xaxis.get_major_ticks()
                 if lo <= t.get_loc() <= hi and t.label1.get_text()]
        assert len(ticks) >= 3, ticks
        for loc, text in ticks:
            assert float(text) == pytest.approx(loc, rel=1e-12)
            assert float(text) == pytest.approx(round(float(text) * 2) / 2)  # round numbers


def test_danger_map_without_bands_says_so():
    from flexbooster.present.plotting.danger import danger_map

    fig = danger_map(DangerSummary(operating_range=(10.0, 100.0), verdicts=(), bands=()))
    assert len(fig.axes) == 1
    assert any("no unstable or resonant band" in t.get_text() for t in fig.axes[0].texts)


# ------------------------------------------------------------------------- Ince-Strutt


def test_ince_strutt_view_holds_the_path_and_is_at_most_a_stated_factor_wider(memo_results):
    # the view contains the whole operating path (a, |q|) of eq. (4.2-4), stored in
    # results.pitch, and is at most 1.1 x its q extent (from q = 0) and 1.2 x its a extent
    # (10 % margins each side; PATH_MARGIN), never the fixed [0, 0.1] x [-0.2, 1.5] frame
    from flexbooster.present.plotting.pitch import ince_strutt_chart

    pitch = memo_results.pitch
    q_path, a_path = np.abs(pitch.q), pitch.a
    fig = ince_strutt_chart(memo_results.figures.ince_strutt, Omega=pitch.Omega)
    render_figure(fig)
    ax = fig.axes[0]
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
    assert x0 <= q_path.min() and q_path.max() <= x1 <= 1.1 * q_path.max() * (1 + 1e-12)
    assert y0 <= a_path.min() and a_path.max() <= y1
    assert (y1 - y0) <= 1.2 * (a_path.max() - a_path.min()) * (1 + 1e-12)
    # the path's labels are in Hz and name frequencies of the stored grid's range
    hz = [float(t.get_text().split()[0]) for t in ax.texts if t.get_text().endswith(" Hz")]
    assert hz and all(pitch.Omega.min() / TWO_PI <= f <= pitch.Omega.max() / TWO_PI for f in hz)
    assert _overprinted(fig) == []


# ---------------------------------------------------------------- beam-action band chart


def test_beam_action_chart_draws_the_regions_at_the_case_damping(memo_results):
    # the thick bars on the case's gamma are the stored beam-action bands (computed at the
    # case's damping: [damping] modal_ratio for the beam, pitch_ratio for the rigid pitch),
    # their edges in Hz exactly; the title states that damping; each region's outline passes
    # through its band's edges at the case's gamma (the outline agrees with the band)
    from flexbooster.present.outputs import make_figures

    r = memo_results
    ba = r.beam_action
    assert ba.beam_damping_ratio == r.case.damping.modal_ratio
    assert ba.pitch_damping_ratio == r.case.damping.pitch_ratio
    fig = make_figures(r, names=("beam-action-chart",))["beam-action-chart"]
    ax = fig.axes[0]
    gamma = r.figures.beam_action_chart.gamma_operating
    assert gamma == r.case.thrust.gamma
    bars = [ln for ln in ax.get_lines() if ln.get_linewidth() == 5]
    assert len(bars) == len(ba.bands) > 0
    for ln, b in zip(bars, ba.bands, strict=True):
        np.testing.assert_allclose(ln.get_xdata(), [b.Omega_lo / TWO_PI, b.Omega_hi / TWO_PI],
                                   rtol=1e-14)
        np.testing.assert_array_equal(ln.get_ydata(), [gamma, gamma])
    assert f"modal damping ratio {r.case.damping.modal_ratio:g}" in ax.get_title()
    assert f"rigid pitch {r.case.damping.pitch_ratio:g}" in ax.get_title()
    keys = {(b.kind, tuple(m.index for m in b.modes), b.order): b for b in ba.bands}
    outlines = [p for p in ax.patches if p.get_label() != "not searched"]
    matched = 0
    for reg, patch in zip(r.figures.beam_action_chart.regions, outlines, strict=False):
        b = keys.get(tuple(reg.key))
        if b is None:
            continue
        xy = patch.get_xy()
        at = xy[np.isclose(xy[:, 1], gamma, rtol=1e-12, atol=0.0), 0]
        np.testing.assert_allclose(sorted(at), [b.Omega_lo / TWO_PI, b.Omega_hi / TWO_PI],
                                   rtol=1e-12)
        matched += 1
    assert matched >= 1


# -------------------------------------------------------------------- vehicle regions


def _vehicle_regions():
    from flexbooster.dynamics import RegionCurve, VehicleRegions

    regs, curves = [], []
    for i, (lo, rate) in enumerate(((10.0, 1e-8), (20.0, 1e-4), (40.0, 2e-2))):
        mode = BandMode("radial 0", index=i, k=2, order=0, type="radial", omega=lo / 2,
                        share=1.0)
        regs.append(Band(mechanism="vehicle", k=2, kind="simple", order=1, modes=(mode,),
                         Omega_lo=lo, Omega_hi=lo * 1.01, growth_rate_max=rate,
                         Omega_at_max=lo * 1.005, Omega_center=lo * 1.005, critical_gamma=0.0))
        curves.append(RegionCurve(k=2, kind="simple", order=1, modes=(i,),
                                  gamma=np.array([0.0, 0.1, 0.2]),
                                  omega_lo=np.array([lo, lo * 0.99, lo * 0.98]),
                                  omega_hi=np.array([lo, lo * 1.01, lo * 1.02])))
    return VehicleRegions(regions=tuple(regs), harmonics=(), curves=tuple(curves), F0=1.0,
                          gamma=0.2, damping_ratio=0.0, omega_min=5.0, omega_max=500.0,
                          supported_forward_end=False)


def test_vehicle_region_chart_axes_and_scale_labels_placed():
    # the case's gamma (0.2, the traced top) lies at 1/1.35 of the height: its dots clear the
    # frame and the legend; growth rates over six decades: a log colour scale with its label;
    # no text overprints another, every text inside the figure
    from flexbooster.present.plotting.vehicle_regions import HEADROOM, vehicle_region_chart

    regions = _vehicle_regions()
    fig = vehicle_region_chart(regions)
    render_figure(fig)
    ax, cax = fig.axes
    assert ax.get_ylim() == pytest.approx((0.0, HEADROOM * 0.2), rel=1e-12)
    assert cax.get_yscale() == "log" and cax.get_ylabel().endswith("(1/s, log)")
    assert cax.get_ylim() == pytest.approx((2e-8, 2e-2), rel=1e-9)  # max / 1e6 .. max
    renderer = fig.canvas.get_renderer()
    legend = ax.get_legend().get_window_extent(renderer)
    dots = ax.collections[-1]  # the regions at the case's gamma
    px = ax.transData.transform(dots.get_offsets())
    assert not any(legend.contains(x, y) for x, y in px)
    np.testing.assert_allclose(dots.get_offsets()[:, 0],
                               [b.Omega_at_max / TWO_PI for b in regions.regions], rtol=1e-14)
    assert ax.get_xlabel() == "thrust frequency Omega (Hz)"
    assert _overprinted(fig) == []
    page = fig.bbox.padded(1.0)
    for t in _texts(fig):
        box = t.get_window_extent(renderer)
        assert page.x0 <= box.x0 and box.x1 <= page.x1 and page.y0 <= box.y0 \
            and box.y1 <= page.y1, t.get_text()


# ------------------------------------------------------------------------- beam modes


def test_beam_modes_against_the_station_in_metres(memo_results):
    # zeta = xi_bar - d4/L + 1 with xi_bar = (x - x_cm)/L and d4 = L - x_cm gives x = L zeta
    # (C-6): the default booster (L1 = 21 m, L2 = 9 m, L = 30 m) spans 0..60 m, the junction
    # at 2 L1 = 42 m from the aft edge (exact to 1e-12)
    from flexbooster.present.plotting.beam import mode_shape_plot

    data = memo_results.figures.beam_modes
    b = memo_results.case.booster
    L1, L2 = b.cylinder1.half_length, b.cylinder2.half_length
    fig = mode_shape_plot(data)
    ax = fig.axes[0]
    assert ax.get_xlabel() == "station x from the aft edge (m)"
    curves = [ln for ln in ax.get_lines() if ln.get_label().startswith("φ")]
    assert len(curves) == data.phi.shape[0]
    for ln, phi in zip(curves, data.phi, strict=True):
        x = ln.get_xdata()
        assert x[0] == 0.0 and x[-1] == pytest.approx(2 * (L1 + L2), rel=1e-12)
        np.testing.assert_array_equal(ln.get_ydata(), phi)
    junction = [ln for ln in ax.get_lines() if ln.get_label() == "junction"][0]
    assert junction.get_xdata()[0] == pytest.approx(2 * L1, rel=1e-12)


# --------------------------------------------------------------------- Hz everywhere


def _frequency_labels(fig) -> list[str]:
    labels = []
    for ax in fig.axes:
        parts = [ax, *ax.child_axes]
        for a in parts:
            labels += [a.get_xlabel(), a.get_ylabel()]
    return [t for t in labels if t]


@pytest.mark.slow
def test_every_frequency_axis_in_hz(memo_results):
    # every axis of every figure of the default case that carries a frequency names it in Hz:
    # no "rad/s" axis; a "frequency" or "Omega (" axis says "(Hz)" (the memo's dimensionless
    # Omega / omega_1 on the top of its own charts is a ratio, not a frequency axis)
    from flexbooster.present.outputs import figure_names, make_figures

    seen = 0
    for name in figure_names(memo_results):
        fig = make_figures(memo_results, names=(name,))[name]
        for label in _frequency_labels(fig):
            assert "rad/s" not in label, (name, label)
            if "frequency" in label or "Omega (" in label:
                assert "(Hz)" in label, (name, label)
                seen += 1
    assert seen >= 8


@pytest.mark.slow
def test_flight_and_forced_frequency_axes_in_hz():
    # the flight's Campbell diagram (frequency in Hz against time) and the forced response's
    # acceleration chart (Omega in Hz): the constant flight of test_flight_pipeline
    import sys
    from pathlib import Path

    sys.path.insert(0, str(Path(__file__).parent))
    from flexbooster import analyze
    from flexbooster.case import load_case
    from flexbooster.present.outputs import make_figures
    from test_flight_pipeline import CASE

    results = analyze(load_case(CASE), beam_action=False, stability=False, figures=False)
    figs = make_figures(results, names=("flight-campbell",))
    fig = figs["flight-campbell"]
    ax = fig.axes[0]
    assert ax.get_ylabel() == "frequency (Hz)"
    # the oscillation band drawn is the stored one in Hz
    band = ax.collections[0].get_paths()[0].vertices
    lo = results.flight.oscillation[:, 0] / TWO_PI
    hi = results.flight.oscillation[:, 1] / TWO_PI
    assert band[:, 1].min() == pytest.approx(lo.min(), rel=1e-12)
    assert band[:, 1].max() == pytest.approx(hi.max(), rel=1e-12)
    render_figure(fig)
    page = fig.bbox.padded(1.0)
    title = ax.title.get_window_extent(fig.canvas.get_renderer())
    assert page.x0 <= title.x0 and title.x1 <= page.x1  # the title is not cut
    if results.forced_response is not None:
        acc = make_figures(results, names=("forced-acceleration",))["forced-acceleration"]
        assert acc.axes[0].get_xlabel().endswith("(Hz)")


def test_forced_envelopes_one_quantity_per_panel():
    # axial force and bending moment each in a panel of its own (no twin axes), drawn from the
    # stored envelopes: a hand-made ForcedLoads-like object with both harmonics forced
    from types import SimpleNamespace

    from flexbooster.present.plotting.forced import forced_envelope_chart

    x = np.linspace(0.0, 10.0, 5)
    env = [SimpleNamespace(quantity="axial_force", k=0, x=x, at_worst=-2.0 * x, peak=2.5 * x,
                           worst_omega=TWO_PI * 3.0),
           SimpleNamespace(quantity="bending_moment", k=1, x=x, at_worst=x ** 2,
                           peak=1.5 * x ** 2, worst_omega=TWO_PI * 7.0)]
    response = SimpleNamespace(harmonics=(0, 1), envelopes=env,
                               stations=(SimpleNamespace(x=5.0, name="mid"),))
    loads = SimpleNamespace(response=response, convergence=((3, 0.0), (3, 0.0)))
    fig = forced_envelope_chart(loads)
    render_figure(fig)
    top, bottom = fig.axes
    assert not top.get_position().overlaps(bottom.get_position())
    assert top.get_ylabel() == "axial force amplitude (N)"
    assert bottom.get_ylabel() == "bending moment amplitude (N m)"
    np.testing.assert_array_equal(top.get_lines()[0].get_ydata(), 2.0 * x)  # |at_worst|
    np.testing.assert_array_equal(bottom.get_lines()[1].get_ydata(), 1.5 * x ** 2)
    assert "3 Hz" in top.get_lines()[0].get_label()
    assert _overprinted(fig) == []
