"""The public library API: every bad call a ValueError (or TypeError) naming the parameter.

Source of the expected values: the list of bad calls below, each with the parameter the
error must name.
"""

from __future__ import annotations

import functools
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

import flexbooster
from flexbooster import analysis, checks, cost, units
from flexbooster.analysis import analyze
from flexbooster.dynamics import axial as vaxial
from flexbooster.dynamics import bending as vbending
from flexbooster.dynamics import regions as vregions
from flexbooster.floquet import bounds as fbounds
from flexbooster.floquet import hill as fhill
from flexbooster.floquet import mathieu
from flexbooster.floquet import multipliers as fmult
from flexbooster.floquet import regions as fregions
from flexbooster.memo import beam, charts, pitch, responses, severity, shell, stability
from flexbooster.memo import beam_action as ba
from flexbooster.memo import geometry as geo
from flexbooster.memo import model as mm
from flexbooster.memo import shell_coefficients as sc
from flexbooster.memo.responses import closed_form as cf
from flexbooster.memo.responses import excitation as rex
from flexbooster.memo.responses import fields, modal, secular
from flexbooster.model import model_from_case, vehicle_from_case
from flexbooster.shell_of_revolution import assembly as sor_assembly
from flexbooster.shell_of_revolution import elements as sor_elements
from flexbooster.shell_of_revolution import geometry as sor_geometry
from flexbooster.shell_of_revolution import modes as sor_modes
from flexbooster.shell_of_revolution import prestress as sor_prestress
from flexbooster.shell_of_revolution import survey as sor_survey
from reference import donnell

nan, inf = math.nan, math.inf
SRC = str(Path(flexbooster.__file__).parents[1])


_G = dict(R1=5.0, L1=21.0, R2=3.3, L2=9.0, h=0.02, rho=2768.0)
_SHELL = dict(R1=5.0, L1=21.0, R2=3.3, L2=9.0, h=0.02, E=7e10, nu=0.3, rho=2768.0,
              omega_1=100.0)


def _system():
    return ba.beam_action_system(100.0, 1e5, 30.0, 20.0, 1e8, 1e6, 0.5, 3)


@functools.cache
def _model():
    return model_from_case(flexbooster.memo_case())


#: A matrix of NaN in flexbooster.floquet: its ValueError prints the whole array (several
#: lines) instead of one line (floquet/multipliers.py _matrix: f"{name} = {a!r}").
#: (id, parameter the message must name, call).  Source: a review's list of bad calls (the
#: four named ones first: reduced_exponents([nan]), characteristic_exponent(1e12, 0.01),
#: psi_numerical([0, nan]) and mass_properties(R1=nan)) and one probe per rule of each public
#: function of memo/ (finite, sign, range, shape, empty, choice).
BAD_CALLS = [
    ("reduced_exponents-nan", "alpha", lambda: ba.reduced_exponents([nan])),
    ("characteristic_exponent-1e12-hangs", "a", lambda: mathieu.characteristic_exponent(1e12, .01)),
    ("psi_numerical-nan-hangs", "tau1", lambda: pitch.psi_numerical([0, nan], 0.5, 0.01)),
    ("mass_properties-R1-nan", "R1", lambda: geo.mass_properties(**{**_G, "R1": nan})),
    ("mass_properties-R1-neg", "R1", lambda: geo.mass_properties(**{**_G, "R1": -5.0})),
    ("mass_properties-h-inf", "h", lambda: geo.mass_properties(**{**_G, "h": inf})),
    ("moment_of_inertia_memo-L1-nan", "L1",
     lambda: geo.moment_of_inertia_memo(**{**_G, "L1": nan})),
    ("moment_of_inertia_memo-form", "form", lambda: geo.moment_of_inertia_memo(**_G, form="x")),
    ("dimensionless_groups-E-nan", "E",
     lambda: geo.dimensionless_groups(L=30., R1=5., R2=3., h=.02, E=nan, rho=2768.,
                                      omega_1=100., T0=1e5)),
    ("free_free_eigenvalues-0", "n", lambda: beam.free_free_eigenvalues(0)),
    ("free_free_eigenvalues-float", "n", lambda: beam.free_free_eigenvalues(2.5)),
    ("free_free_alpha-neg", "n", lambda: beam.free_free_alpha(-1)),
    ("first_bending_frequency-L-neg", "L",
     lambda: beam.first_bending_frequency(-1.0, 5.0, 7e10, 2768.)),
    ("first_bending_frequency-E-nan", "E",
     lambda: beam.first_bending_frequency(30.0, 5.0, nan, 2768.)),
    ("mode_shape-zeta-nan", "zeta", lambda: beam.mode_shape(1, np.array([nan]))),
    ("mode_shape-n-0", "n", lambda: beam.mode_shape(0, np.array([0.5]))),
    ("beam_modes-N-0", "N", lambda: beam.beam_modes(0)),
    ("pitch_frequency-F0-nan", "F0", lambda: pitch.pitch_frequency(nan, 20., 0.5, 1e8)),
    ("pitch_frequency-I_cm-0", "I_cm", lambda: pitch.pitch_frequency(1e6, 20., 0.5, 0.0)),
    ("mathieu_parameters-Omega-0", "Omega",
     lambda: pitch.mathieu_parameters(np.array([0.0]), 1.0, 0.1)),
    ("mathieu_parameters-gamma-nan", "gamma",
     lambda: pitch.mathieu_parameters(np.array([1.0]), 1.0, nan)),
    ("characteristic_exponent-hill-1e12", "a",
     lambda: mathieu.characteristic_exponent(1e12, 0.01, "hill")),
    ("characteristic_exponent-nan", "a", lambda: mathieu.characteristic_exponent(nan, 0.1)),
    ("characteristic_exponent-method", "method",
     lambda: mathieu.characteristic_exponent(0.5, 0.1, "x")),
    ("characteristic_exponent-n_steps-0", "n_steps",
     lambda: mathieu.characteristic_exponent(0.5, 0.1, n_steps=0)),
    ("floquet_discriminant-q-inf", "q", lambda: mathieu.floquet_discriminant(0.5, inf)),
    ("psi_numerical-too-long", "tau1", lambda: pitch.psi_numerical([0, 1e9], 0.5, 0.01)),
    ("psi_numerical-psi0-0", "psi0", lambda: pitch.psi_numerical([0, 1.0], 0.5, .01, psi0=0.)),
    ("psi_three_term-a-nan", "a", lambda: pitch.psi_three_term([0, 1.0], nan, 0.01)),
    ("transition_curves-q-nan", "q", lambda: mathieu.transition_curves([nan])),
    ("transition_curves-r_max-neg", "r_max", lambda: mathieu.transition_curves([0.1], r_max=-1)),
    ("three_term_error-n_times-0", "n_times",
     lambda: pitch.three_term_error(0.5, 0.01, n_times=0)),
    ("pitch_band_edges-tongue-0", "tongue", lambda: pitch.pitch_band_edges(1.0, 0.1, tongue=0)),
    ("pitch_bands-omega_psi-nan", "omega_psi",
     lambda: pitch.pitch_bands(nan, 0.1, omega_min=1., omega_max=2.)),
    ("pitch_analysis-Omega-nan", "Omega", lambda: pitch.pitch_analysis([nan], 1.0, 0.1)),
    ("pitch_analysis-Omega-empty", "Omega", lambda: pitch.pitch_analysis([], 1.0, 0.1)),
    ("pitch_analysis-gamma-1.5", "gamma", lambda: pitch.pitch_analysis([1.0, 2.0], 1.0, 1.5)),
    ("pitch_analysis-omega_psi-nan", "omega_psi",
     lambda: pitch.pitch_analysis([1.0, 2.0], nan, 0.1)),
    ("beam_action_system-N-neg", "N",
     lambda: ba.beam_action_system(100., 1e5, 30., 20., 1e8, 1e6, 0.5, -1)),
    ("beam_action_system-omega_1-nan", "omega_1",
     lambda: ba.beam_action_system(nan, 1e5, 30., 20., 1e8, 1e6, 0.5, 3)),
    ("beam_action_system-n_quad-0", "n_quad",
     lambda: ba.beam_action_system(100., 1e5, 30., 20., 1e8, 1e6, 0.5, 3, n_quad=0)),
    ("uniform_beam_system-p-nan", "p", lambda: ba.uniform_beam_system(nan, 0.5, 3)),
    ("uniform_beam_system-N-neg", "N", lambda: ba.uniform_beam_system(1.0, 0.5, -2)),
    ("follower_flutter_load-n_modes-0", "n_modes", lambda: ba.follower_flutter_load(n_modes=0)),
    ("reduced_exponents-empty", "alpha", lambda: ba.reduced_exponents([])),
    ("natural_branch-nan", "Omega_bar",
     lambda: ba.natural_branch(np.zeros((1, 4)), np.array([nan]), np.ones(4))),
    ("hill_exponents-Omega-nan", "Omega", lambda: ba.hill_exponents(_system(), [nan], 0.1, 3)),
    ("hill_exponents-S-neg", "S", lambda: ba.hill_exponents(_system(), [1.0], 0.1, -1)),
    ("monodromy_exponents-gamma-1.5", "gamma",
     lambda: ba.monodromy_exponents(_system(), [1.0], 1.5)),
    ("monodromy_exponents-max_steps-0", "max_steps",
     lambda: ba.monodromy_exponents(_system(), [1.0], 0.1, max_steps=0)),
    ("monodromy_exponents-step_phase-0", "step_phase",
     lambda: ba.monodromy_exponents(_system(), [1.0], 0.1, step_phase=0.0)),
    ("monodromy_steps-Omega-neg", "Omega", lambda: ba.monodromy_steps(_system(), [-1.0], 0.1)),
    ("modal_damping-beam_ratio-1", "beam_ratio",
     lambda: ba.modal_damping(_system(), beam_ratio=1.0)),
    ("beam_action_bands-gamma-nan", "gamma",
     lambda: ba.beam_action_bands(_system(), nan, omega_min=10., omega_max=20.)),
    ("beam_action_bands-range", "omega_min",
     lambda: ba.beam_action_bands(_system(), 0.1, omega_min=30., omega_max=20.)),
    ("stability_chart-step_phase-neg", "step_phase",
     lambda: ba.stability_chart(_system(), [10.0], [0.1], step_phase=-1.0)),
    ("shell_parameters-R1-nan", "R1", lambda: sc.shell_parameters(**{**_SHELL, "R1": nan})),
    ("shell_parameters-nu-0.7", "nu", lambda: sc.shell_parameters(**{**_SHELL, "nu": 0.7})),
    ("memo_coefficients-d-3", "d",
     lambda: sc.memo_coefficients(sc.shell_parameters(**_SHELL), 3, 2, 2)),
    ("memo_coefficients-M-0", "M",
     lambda: sc.memo_coefficients(sc.shell_parameters(**_SHELL), 1, 0, 2)),
    ("galerkin_coefficients-phase", "phase",
     lambda: sc.galerkin_coefficients(sc.shell_parameters(**_SHELL), 1, 2, 2, phase="x")),
    ("composite_frequencies-M1-0", "M1",
     lambda: shell.composite_frequencies(5., 21., 3.3, 9., .02, 7e10, .3, 2768., 100.,
                                         0, 2, 2, 2)),
    ("composite_frequencies-method", "method",
     lambda: shell.composite_frequencies(5., 21., 3.3, 9., .02, 7e10, .3, 2768., 100.,
                                         2, 2, 2, 2, method="x")),
    ("generalized_eigen-nan", "mass",
     lambda: shell.generalized_eigen(np.full((2, 2), nan), np.eye(2))),
    ("generalized_eigen-shape", "stiff", lambda: shell.generalized_eigen(np.eye(2), np.eye(3))),
    ("nodal_lines-j-neg", "j", lambda: charts.nodal_lines(-1, 0)),
    ("beam_mode_shapes-N-0", "N", lambda: charts.beam_mode_shapes(_model().mass, N=0)),
    ("pitch_band_chart-n_gamma-1", "n_gamma", lambda: charts.pitch_band_chart(_model(),
                                                                               n_gamma=1)),
    ("excitation_curves-S-neg", "S", lambda: stability.excitation_curves(2, -1)),
    ("check_case_cost-max_seconds-nan", "max_seconds",
     lambda: cost.check_case_cost(_model(), nan)),
]


@pytest.mark.parametrize(("name", "call"), [(n, c) for _, n, c in BAD_CALLS],
                         ids=[i for i, _, _ in BAD_CALLS])
def test_bad_call_raises_value_error_naming_the_parameter(alarm, name, call):
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)  # no numpy overflow on the way
        with pytest.raises(ValueError) as info:
            call()
    assert name in str(info.value) and "\n" not in str(info.value)


@functools.cache
def _vehicle():
    return vehicle_from_case(flexbooster.memo_case())


def _plate_vehicle():
    """A cylinder closed by a flat annular plate (a cone of length 0)."""
    mat = {"E": 7e10, "nu": 0.3, "rho": 2700.0}
    return sor_geometry.Vehicle([sor_geometry.Cylinder(1.0, 2.0, 0.01, **mat),
                                 sor_geometry.Cone(1.0, 0.5, 0.0, 0.01, **mat)])


@functools.cache
def _small() -> dict:
    """A small analysis (the memo case, truncations 2/2/2/2, N = 2, S = R = 1, 20 points)
    and the objects the result-taking functions need."""
    d = flexbooster.memo_case().model_dump(exclude_none=True)
    d["truncation"].update(M1=2, N1=2, M2=2, N2=2, N=2, S=1, R=1)
    d["thrust"]["n_omega"] = 20
    res = analyze(flexbooster.load_case(d), figures=False, vehicle=False)
    params = responses.excitation_parameters(res.model, res.beam_action)
    sh = res.shell
    return {"model": res.model, "table": res.stability, "params": params, "shell": sh,
            "modes": stability.ShellModes(sh.cylinder, sh.j, sh.k, sh.branch, sh.omega_bar),
            "sev": severity.root_severity(res.model, res.stability, params),
            "sim": responses.simulate(res.model, 300.0, 10.0, params=params)}


_M2, _C2, _A2, _B2 = np.eye(2), 0.01 * np.eye(2), np.diag([1.0, 4.0]), 0.1 * np.eye(2)
_NAN2 = np.full((2, 2), nan)
_BM = dict(R1=5.0, L1=21.0, R2=3.3, L2=9.0, h=0.02, E=7e10, nu=0.3, rho=2768.0, F0=1e6,
           gamma=0.1, K=0.5, Omega=np.array([10.0, 20.0]))


def _booster_model(**bad):
    return mm.booster_model(**{**_BM, **bad}, truncation=_model().truncation)


#: The public functions of every package's __all__ that BAD_CALLS does not probe (the list:
#: scripts/api_probe_list.py prints each public function and whether a test probes it), one
#: bad argument each (NaN, negative, empty, out of range, unknown choice): a ValueError
#: naming the parameter, on one line, no RuntimeWarning, no hang.
API_CALLS = [
    ("checks.finite", "x", lambda: checks.finite("x", nan)),
    ("checks.positive", "x", lambda: checks.positive("x", -1.0)),
    ("checks.nonnegative", "x", lambda: checks.nonnegative("x", -1.0)),
    ("checks.choice", "x", lambda: checks.choice("x", "z", ("a", "b"))),
    ("checks.finite_array-nan", "x", lambda: checks.finite_array("x", np.full(50, nan))),
    ("checks.finite_array-empty", "x", lambda: checks.finite_array("x", [])),
    ("checks.finite_array-positive", "x", lambda: checks.finite_array("x", [1, 0],
                                                                      positive=True)),
    ("units.to_si-nan", "f", lambda: units.to_si("f", nan, "length")),
    ("units.to_si-kind", "kind", lambda: units.to_si("f", 1.0, "lenght")),
    ("units.to_si-huge-int", "f", lambda: units.to_si("f", 10**400, "length")),
    ("units.to_us-nan", "value", lambda: units.to_us(nan, "m")),  # returned (nan, 'in')
    ("units.to_us-inf", "value", lambda: units.to_us(inf, "Pa")),
    ("units.to_us-str", "value", lambda: units.to_us("abc", "m")),
    ("units.to_us-overflow", "value", lambda: units.to_us(1e308, "m")),  # was (inf, 'in')
    ("units.to_us-unit", "si_unit", lambda: units.to_us(1.0, ["m"])),
    ("simulate_case-Omega-nan", "Omega",
     lambda: analysis.simulate_case(flexbooster.memo_case(), nan, tau_max=10.0)),
    ("simulate_case-n_out-1", "n_out",
     lambda: analysis.simulate_case(flexbooster.memo_case(), 10.0, tau_max=10.0,
                                    n_out=1)),
    ("analyze_vehicle-k_max-neg", "k_max",
     lambda: analysis.analyze_vehicle(flexbooster.memo_case(), k_max=-1)),
    ("analyze_vehicle-f_max-nan", "f_max",
     lambda: analysis.analyze_vehicle(flexbooster.memo_case(), f_max=nan)),
    ("analyze_vehicle_regions-k_min-neg", "k_min",
     lambda: analysis.analyze_vehicle_regions(flexbooster.memo_case(), k_min=-1)),
    ("booster_model-R1-nan", "R1", lambda: _booster_model(R1=nan)),
    ("booster_model-Omega-empty", "Omega", lambda: _booster_model(Omega=np.array([]))),
    ("booster_model-gamma-neg", "gamma", lambda: _booster_model(gamma=-0.1)),
    ("ince_strutt_data-n_q-0", "n_q",
     lambda: charts.ince_strutt_data(pitch.pitch_analysis([10., 20.], 1.0, 0.1), n_q=0)),
    ("beam_action_chart-n_gamma-0", "n_gamma",
     lambda: charts.beam_action_chart(_model(), n_gamma=0)),
    ("nodal_pattern_data-cylinder-3", "cylinder",
     lambda: charts.nodal_pattern_data(shell.natural_frequencies(_model()), cylinder=3, j=1,
                                       k=1, radius=5.0, half_length=21.0)),
    ("natural_frequencies-method", "method",
     lambda: shell.natural_frequencies(_model(), method="x")),
    ("cylinder_coefficients-d-3", "d",
     lambda: shell.cylinder_coefficients(sc.shell_parameters(**_SHELL), 3, 2, 2)),
    ("edge_arguments-d-3", "d",
     lambda: sc.edge_arguments(sc.shell_parameters(**_SHELL), 3, np.array([1]), "zero")),
    ("overlap_matrices-M-0", "M",
     lambda: sc.overlap_matrices(sc.shell_parameters(**_SHELL), 1, 0, "zero")),
    ("excitation-Omega_bar-nan", "Omega_bar",
     lambda: stability.excitation(stability.excitation_curves(2, 1), np.array([nan]),
                                  np.array([0.1]), np.zeros((1, 2)))),
    ("closed_form_0k-omega-nan", "omega",
     lambda: cf.closed_form_0k(nan, 1.0, [2.0], [[0.0]], np.array([0.0, 1.0]))),
    ("closed_form_0k-P-shape", "P",
     lambda: cf.closed_form_0k([1.0], 1.0, [2.0, 3.0], [[0.0]], np.array([0.0, 1.0]))),
    ("closed_form_0k-tau-nan", "tau",
     lambda: cf.closed_form_0k(1.0, 1.0, [2.0], [[0.0]], np.array([nan]))),
    ("modal_groups-N-neg", "N",
     lambda: modal.modal_groups(sc.shell_parameters(**_SHELL), (2, 2), (2, 2), -1)),
    ("make_excitation-Omega-nan", "Omega", lambda: rex.make_excitation(_model(), nan)),
    ("make_excitation-psi0-nan", "psi0",
     lambda: rex.make_excitation(_model(), 10.0, psi0=nan)),
    ("secular_growth-Omega-nan", "Omega",
     lambda: secular.secular_growth(_model(), nan, 1, 1, 1, 0, tau_max=10.0)),
    ("simulate-Omega-nan", "Omega", lambda: responses.simulate(_model(), nan, 10.0)),
    ("simulate-tau_max-neg", "tau_max", lambda: responses.simulate(_model(), 10.0, -1.0)),
    ("floquet_vectors-S-neg", "S",
     lambda: severity.floquet_vectors(np.eye(2), np.eye(2), np.array([1.0]),
                                      np.array([0.5]), 0.1, -1)),
    ("donnell_frequencies-radius-nan", "radius",
     lambda: donnell.donnell_frequencies(10., nan, .02, 7e10, .3, 2768., 1, 2)),
    ("donnell_frequencies-m-0", "m",
     lambda: donnell.donnell_frequencies(10., 5., .02, 7e10, .3, 2768., 0, 2)),
    ("mesh_vehicle-order-0", "order", lambda: sor_assembly.mesh_vehicle(_vehicle(), order=0)),
    ("mesh_vehicle-elements-0", "elements_per_segment",
     lambda: sor_assembly.mesh_vehicle(_vehicle(), elements_per_segment=0)),
    ("system_matrices-k-neg", "k", lambda: sor_assembly.system_matrices(_vehicle(), -1)),
    ("system_matrices-F0-nan", "prestress_F0",
     lambda: sor_assembly.system_matrices(_vehicle(), 1, prestress_F0=nan)),
    ("theta_weight-k-neg", "k", lambda: sor_elements.theta_weight(-1)),
    ("vehicle_modes-k_max-neg", "k_max", lambda: sor_modes.vehicle_modes(_vehicle(), k_max=-1)),
    ("vehicle_modes-f_max-nan", "f_max",
     lambda: sor_modes.vehicle_modes(_vehicle(), k_max=2, f_max=nan)),
    ("buckling_load-k-neg", "k", lambda: sor_modes.buckling_load(_vehicle(), -1)),
    ("buckling_load-F0-nan", "F0", lambda: sor_modes.buckling_load(_vehicle(), 1, F0=nan)),
    ("modal_system-n_modes-0", "n_modes",
     lambda: sor_modes.modal_system(_vehicle(), 1, n_modes=0, F0=1e6)),
    ("membrane_prestate-aft_force-nan", "aft_force",
     lambda: sor_prestress.membrane_prestate(sor_assembly.mesh_vehicle(_vehicle()),
                                             "inertia relief", aft_force=nan)),
    ("membrane_prestate-path", "path",
     lambda: sor_prestress.membrane_prestate(sor_assembly.mesh_vehicle(_vehicle()),
                                             "relief", aft_force=1e6)),
    ("membrane_prestate-axial-nan", "axial",
     lambda: sor_prestress.membrane_prestate(sor_assembly.mesh_vehicle(_vehicle()),
                                             "inertia relief", aft_force=1e6, axial=nan)),
    ("load_path-flag", "supported_forward_end",
     lambda: sor_prestress.load_path(_vehicle(), "yes")),
    ("vehicle_survey-k_max-neg", "k_max",
     lambda: sor_survey.vehicle_survey(_vehicle(), k_max=-1, F0=1e6)),
    ("vehicle_survey-F0-nan", "F0", lambda: sor_survey.vehicle_survey(_vehicle(), k_max=2,
                                                                       F0=nan)),
    ("closed_form_jk-tau-nan", "tau",
     lambda: cf.closed_form_jk(np.eye(3), 2 * np.eye(3), np.zeros(3), [2.0],
                               np.zeros((3, 1)), [nan])),
    ("closed_form_jk-stiff-nan", "stiff",
     lambda: cf.closed_form_jk(np.eye(3), np.full((3, 3), nan), np.zeros(3), [2.0],
                               np.zeros((3, 1)), [0.0, 1.0])),
    ("displacement_fields-xi-nan", "xi",
     lambda: fields.displacement_fields(_small()["sim"], [nan], [0.0])),
    ("edge_conditions-n_theta-0", "n_theta",
     lambda: fields.edge_conditions(_small()["sim"], n_theta=0)),
    ("modal_forcing_spectrum-Omega-nan", "Omega",
     lambda: secular.modal_forcing_spectrum(_model(), nan, 1, 1, 1, 0)),
    ("secular_rates-psi0-nan", "psi0", lambda: secular.secular_rates(_model(), [], psi0=nan)),
    ("root_severity-threshold-nan", "threshold",
     lambda: severity.root_severity(_small()["model"], _small()["table"], _small()["params"],
                                    threshold=nan)),
    ("root_severity-psi0-nan", "psi0",
     lambda: severity.root_severity(_small()["model"], _small()["table"], _small()["params"],
                                    psi0=nan)),
    ("resonance_bands-resolution-nan", "resolution",
     lambda: severity.resonance_bands(_small()["table"], _small()["sev"], resolution=nan)),
    ("severity_analysis-threshold-neg", "threshold",
     lambda: severity.severity_analysis(_small()["model"], _small()["table"],
                                        _small()["params"], threshold=-1.0)),
    ("unstable_frequencies-range-nan", "Omega_bar_range",
     lambda: stability.unstable_frequencies(_small()["modes"], _small()["params"],
                                            Omega_bar_range=(nan, 1.0), omega_1=100.0, R=1,
                                            S=1, gamma=0.1, K=0.5)),
    ("unstable_frequencies-omega_1-0", "omega_1",
     lambda: stability.unstable_frequencies(_small()["modes"], _small()["params"],
                                            Omega_bar_range=(0.1, 1.0), omega_1=0.0, R=1,
                                            S=1, gamma=0.1, K=0.5)),
    ("campbell_data-n_points-0", "n_points",
     lambda: charts.campbell_data(params=_small()["params"], omega_range=(10.0, 100.0),
                                  omega_1=_small()["model"].omega_1,
                                  shell=_small()["shell"], table=_small()["table"], R=1, S=1,
                                  n_points=0)),
    ("membrane_prestate-flat-plate", "cos_phi",
     lambda: sor_prestress.membrane_prestate(sor_assembly.mesh_vehicle(_plate_vehicle()),
                                             "forward support", aft_force=1e6)),
    ("thrust_prestate-F0-nan", "prestress_F0",
     lambda: sor_assembly.thrust_prestate(_vehicle(), sor_assembly.mesh_vehicle(_vehicle()),
                                          nan)),
    ("dof_map-k-neg", "k", lambda: sor_assembly.dof_map(
        _vehicle(), sor_assembly.mesh_vehicle(_vehicle()), -1)),
    ("rigid_body_fields-k-neg", "k",
     lambda: sor_assembly.rigid_body_fields(sor_assembly.mesh_vehicle(_vehicle()), -1)),
    ("step_counts-step_phase-0", "step_phase",
     lambda: fmult.step_counts(fmult.periodic_system(_M2, _C2, _A2, _B2), [1.0],
                               step_phase=0.0)),
    ("pitch_tongue_bands-gamma-nan", "gamma",
     lambda: ba.pitch_tongue_bands(_system(), nan, omega_min=1., omega_max=10.)),
    ("tongue_search_seconds-gamma-nan", "gamma",
     lambda: cost.tongue_search_seconds(_system(), nan, omega_min=1., omega_max=10.)),
    ("tongue_search_seconds-range", "omega_min",
     lambda: cost.tongue_search_seconds(_system(), 0.1, omega_min=10., omega_max=1.)),
    ("beam_action_analysis-n_hill-0", "n_hill",
     lambda: ba.beam_action_analysis(_model(), n_hill=0)),
    ("pitch_tongue_omega_bound-tongue-0", "tongue",
     lambda: pitch.pitch_tongue_omega_bound(1.0, 0.1, tongue=0)),
    ("pitch_tongue_omega_bound-gamma-nan", "gamma",
     lambda: pitch.pitch_tongue_omega_bound(1.0, nan, tongue=1)),
    ("cubic_spline-x-not-increasing", "x",
     lambda: responses.excitation.cubic_spline(np.array([0.0, 2.0, 1.0, 3.0]),
                                               np.zeros((4, 1)))),
    # flexbooster.floquet (owner: bands2) and flexbooster.dynamics (owner: vk1)
    ("periodic_boundaries-period", "period",
     lambda: fhill.periodic_boundaries(_M2, _C2, _A2, _B2, period="x")),
    ("periodic_boundaries-n_harmonics-0", "n_harmonics",
     lambda: fhill.periodic_boundaries(_M2, _C2, _A2, _B2, n_harmonics=0)),
    ("converged_periodic_boundaries-rtol-nan", "rtol",
     lambda: fhill.converged_periodic_boundaries(_M2, _C2, _A2, _B2, period="2T",
                                                 omega_min=0.5, omega_max=5., rtol=nan)),
    ("floquet.hill_exponents-Omega-nan", "Omega",
     lambda: fhill.hill_exponents(_M2, _C2, _A2, _B2, [nan])),
    ("floquet_multipliers-Omega-nan", "Omega",
     lambda: fmult.floquet_multipliers(_M2, _C2, _A2, _B2, [nan])),
    ("floquet_exponents-Omega-neg", "Omega",
     lambda: fmult.floquet_exponents(_M2, _C2, _A2, _B2, [-1.0])),
    ("monodromy-n_steps-0", "n_steps", lambda: fmult.monodromy(_M2, _C2, _A2, _B2, [1.0],
                                                                n_steps=0)),
    ("instability_regions-omega_min-nan", "omega_min",
     lambda: fregions.instability_regions(_M2, _C2, _A2, _B2, nan, 10.)),
    ("instability_regions-range", "omega_max",
     lambda: fregions.instability_regions(_M2, _C2, _A2, _B2, 5., 1.)),
    ("region_boundaries-gamma_max-nan", "gamma_max",
     lambda: fregions.region_boundaries(_M2, _C2, _A2, _B2, gamma_max=nan, omega_min=0.5,
                                        omega_max=5.)),
    ("critical_amplitude-omega_min-neg", "omega_min",
     lambda: fregions.critical_amplitude(_M2, _C2, _A2, _B2, gamma_max=0.5, omega_min=-1.,
                                         omega_max=5.)),
    pytest.param("periodic_boundaries-A-nan", "A",
                 lambda: fhill.periodic_boundaries(_M2, _C2, _NAN2, _B2)),
    pytest.param("steady_frequencies-M-nan", "M",
                 lambda: fmult.steady_frequencies(_NAN2, _A2)),
    pytest.param("stability_certificate-B-nan", "B",
                 lambda: fbounds.stability_certificate(_M2, _C2, _A2, _NAN2)),
    ("forced_axial-F0-nan", "F0",
     lambda: vaxial.forced_axial(_vehicle(), F0=nan, omega_min=1., omega_max=10.)),
    ("forced_axial-range", "omega_max",
     lambda: vaxial.forced_axial(_vehicle(), F0=1e6, omega_min=10., omega_max=1.)),
    ("bending_system-F0-nan", "F0", lambda: vbending.bending_system(_vehicle(), F0=nan)),
    ("bending_system-n_modes-0", "n_modes",
     lambda: vbending.bending_system(_vehicle(), F0=1e6, n_modes=0)),
    ("bending_regions-gamma-nan", "gamma",
     lambda: vbending.bending_regions(_vehicle(), F0=1e6, gamma=nan, omega_min=1.,
                                      omega_max=10., gimbal_gain=0.0)),
    ("follower_flutter_thrust-nan", "thrust_max",
     lambda: vbending.follower_flutter_thrust(_vehicle(), thrust_max=nan)),
    ("harmonic_system-k-neg", "k", lambda: vregions.harmonic_system(_vehicle(), -1, F0=1e6)),
    ("harmonic_system-F0-nan", "F0", lambda: vregions.harmonic_system(_vehicle(), 2, F0=nan)),
    ("vehicle_regions-gamma-nan", "gamma",
     lambda: vregions.vehicle_regions(_vehicle(), F0=1e6, gamma=nan, omega_min=1.,
                                      omega_max=10., k_max=3)),
    ("vehicle_regions-k_max-neg", "k_max",
     lambda: vregions.vehicle_regions(_vehicle(), F0=1e6, gamma=0.1, omega_min=1.,
                                      omega_max=10., k_max=-1)),
]


def _api_param(entry):
    if hasattr(entry, "marks"):  # pytest.param(id, name, call, marks=...)
        return pytest.param(*entry.values[1:], id=entry.values[0], marks=entry.marks)
    return pytest.param(entry[1], entry[2], id=entry[0])


@pytest.mark.parametrize(("name", "call"), [_api_param(e) for e in API_CALLS])
def test_public_function_rejects_bad_argument_naming_it(alarm, name, call):
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(ValueError) as info:
            call()
    assert name in str(info.value) and "\n" not in str(info.value), str(info.value)




#: Bad library calls (from an independent review's 103): (id, exception type, the parameter
#: the message must name, call). Each probes a failure: the call accepted, an inf returned, a
#: hang, or another exception type (noted); the expected rule is the function's documented contract.
TYPED_BAD_CALLS = [
    ("mass_properties-h-above-R", ValueError, "h",
     lambda: geo.mass_properties(**{**_G, "h": 6.0})),  # accepted: h > R1 = 5
    ("mass_properties-R1-str", ValueError, "R1",
     lambda: geo.mass_properties(**{**_G, "R1": "5"})),  # accepted: float("5")
    ("Cylinder-thickness-above-radius", ValueError, "thickness",
     lambda: sor_geometry.Cylinder(1.0, 1.0, 2.0, E=7e10, nu=0.3, rho=2700.0)),
    ("Cone-thickness-above-radius", ValueError, "thickness",
     lambda: sor_geometry.Cone(1.0, 0.5, 1.0, 0.6, E=7e10, nu=0.3, rho=2700.0)),
    ("floquet.hill_exponents-M-complex", ValueError, "M",  # imaginary part dropped
     lambda: fhill.hill_exponents(np.eye(2) * (1 + 1j), None, _A2, _B2, [1.0])),
    ("excitation-alpha-shape", ValueError, "alpha",  # reshaped (2, 3) -> (3, 2)
     lambda: stability.excitation(stability.excitation_curves(2, 1), np.array([1., 2., 3.]),
                                  np.zeros(3), np.zeros((2, 3)))),
    ("mode_shape-derivative-7", ValueError, "derivative",
     lambda: beam.mode_shape(1, np.array([0.5]), derivative=7)),
    ("pitch_frequency-overflow", ValueError, "F0",  # returned inf
     lambda: pitch.pitch_frequency(F0=1e308, d2=1.0, K=1e308, I_cm=1.0)),
    ("mathieu_parameters-Omega-denormal", ValueError, "Omega",  # returned inf
     lambda: pitch.mathieu_parameters(Omega=[5e-324], omega_psi=1.0, gamma=0.1)),
    ("load_case-int", TypeError, "source", lambda: flexbooster.load_case(42)),
    ("analyze-str", TypeError, "case", lambda: analyze("x")),  # AttributeError
    ("bending_search_steps-type", TypeError, "work",
     lambda: cost.bending_search_steps({"n": 2}, damping_ratio=0.3)),  # was ValueError
    ("analyze_vehicle-str", TypeError, "case", lambda: analysis.analyze_vehicle("x")),
    ("simulate_case-str", TypeError, "case",
     lambda: analysis.simulate_case("x", 10.0, tau_max=1.0)),
    ("transition_curves-r_max-huge", ValueError, "r_max",  # MemoryError (7 TiB)
     lambda: mathieu.transition_curves([0.5], r_max=10**6)),
    ("transition_curves-q-huge", ValueError, "q",
     lambda: mathieu.transition_curves([1e12], r_max=2)),
    ("excitation_curves-huge", ValueError, "R",  # hung
     lambda: stability.excitation_curves(R=10**6, S=10**6)),
    ("characteristic_exponent-shapes", ValueError, "a, q",  # numpy's broadcast message
     lambda: mathieu.characteristic_exponent([1.0, 2.0], [0.1, 0.2, 0.3])),
    ("monodromy_exponents-shapes", ValueError, "Omega, gamma",
     lambda: ba.monodromy_exponents(_system(), [10.0, 20.0], [0.1, 0.2, 0.3])),
]


@pytest.mark.parametrize(("kind", "name", "call"), [c[1:] for c in TYPED_BAD_CALLS],
                         ids=[c[0] for c in TYPED_BAD_CALLS])
def test_bad_call_raises_the_documented_type_naming_the_parameter(alarm, kind, name,
                                                                          call):
    """Source: the list above; a ValueError (a TypeError for a wrong type) on one line naming
    the parameter, without a RuntimeWarning (no silent inf) and without a hang (alarm)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        with pytest.raises(Exception) as info:  # noqa: PT011 - the exact type is checked below
            call()
    assert type(info.value) is kind or (kind is ValueError and isinstance(info.value, kind)), \
        repr(info.value)
    assert name in str(info.value) and "\n" not in str(info.value), str(info.value)


def test_transition_curves_within_the_bounds_match_the_tables():
    """Source: scipy.special.mathieu_a / mathieu_b (an independent continued-fraction
    implementation; A&S table 20.1 at q = 1: a0 = -0.45513860, b1 = -0.11024882,
    a1 = 1.85910807), tolerance 1e-9 relative; the batched solve (several batches of
    _TRANSITION_ENTRIES) gives the same values as scipy over a grid of 1500 q."""
    from scipy.special import mathieu_a, mathieu_b

    curves = mathieu.transition_curves(np.ones(3), r_max=1)
    assert curves["a0"] == pytest.approx([-0.45513860] * 3, abs=1e-8)
    assert curves["b1"] == pytest.approx([-0.11024882] * 3, abs=1e-8)
    assert curves["a1"] == pytest.approx([1.85910807] * 3, abs=1e-8)
    q = np.linspace(0.0, 4.0, 1500)  # two batches of 1438 (54 x 54 matrices)
    big = mathieu.transition_curves(q, r_max=40)
    every = slice(None, None, 97)  # points of each batch
    assert big["a40"][every] == pytest.approx(mathieu_a(40, q[every]), rel=1e-9)
    assert big["b7"][every] == pytest.approx(mathieu_b(7, q[every]), rel=1e-9)
