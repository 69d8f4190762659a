"""Case files: units, validation rules and the embedded default and memo cases."""

from __future__ import annotations

import math
import tomllib

import pytest

from flexbooster.case import (
    MAX_MODES,
    default_case,
    default_case_text,
    load_case,
    memo_case,
    memo_case_text,
)
from flexbooster.errors import CaseError
from flexbooster.units import to_si, to_us

# Exact unit definitions: 1 in = 0.0254 m (international inch, 1959); 1 lbf = 4.4482216152605 N
# (NIST SP 811, appendix B); 1 psi = 1 lbf/in^2.
INCH = 0.0254
LBF = 4.4482216152605
PSI = LBF / INCH**2


@pytest.mark.parametrize(
    ("value", "kind", "expected"),
    [
        ("120 in", "length", 120 * INCH),
        ("3 ft", "length", 36 * INCH),
        ("20 mm", "length", 0.020),
        (5.05, "length", 5.05),
        ("10.5e6 psi", "pressure", 10.5e6 * PSI),
        ("72.4 GPa", "pressure", 72.4e9),
        ("2.59e-4 lbf*s^2/in^4", "density", 2.59e-4 * LBF / INCH**4),
        ("2.8 MN", "force", 2.8e6),
        ("1000 lbf", "force", 1000 * LBF),
        ("500 lbf/in", "force_per_length", 500 * LBF / INCH),
        ("5 rad/s", "angular_frequency", 5.0),
        ("2 Hz", "angular_frequency", 4 * math.pi),  # cycles per second -> 2 pi rad/s
        ("1 kHz", "angular_frequency", 2000 * math.pi),
        ("60 rpm", "angular_frequency", 2 * math.pi),
        ("0.33", "dimensionless", 0.33),
        # aerospace units beyond pint's own (units.EXTRA_UNITS): exact definitions
        ("10.5 Msi", "pressure", 10.5e6 * PSI),
        ("10 ksi", "pressure", 10e3 * PSI),
        ("3 lbm", "mass", 3 * 0.45359237),  # the international pound, exact
        ("2 slug", "mass", 2 * LBF / 0.3048),  # 1 slug = 1 lbf s^2/ft
        ("1.5 g", "acceleration", 1.5 * 9.80665),  # standard gravity, exact (CGPM 1901)
        ("2 m/s^2", "acceleration", 2.0),
        ("3 g", "mass", 0.003),  # a gram where a mass is asked
        ("1e20 Pa", "pressure", 1e20),  # the ends of units.MAGNITUDE_RANGE
        ("1e-20 m", "length", 1e-20),
        (0.0, "length", 0.0),  # zero: its sign rule is the field's
        (1e-300, "dimensionless", 1e-300),  # no range for a ratio (a gimbal gain K ~ 0)
    ],
)
def test_unit_conversion(value, kind, expected):
    assert to_si("f", value, kind) == pytest.approx(expected, rel=1e-14)


@pytest.mark.parametrize(
    ("value", "kind", "rule"),
    [
        ("12 furlongz", "length", "unknown unit"),
        ("12 s", "length", "wrong dimension"),
        ("3 kg", "pressure", "wrong dimension"),
        ("12 ++ //", "length", "cannot read"),
        # what pint would read other than as meant
        ("5,05 m", "length", "comma"),  # pint: 505 m
        ("1,5e6 psi", "pressure", "comma"),
        ("mm 20", "length", "must start with a number"),  # pint: 0.02 m
        ("psi", "pressure", "must start with a number"),  # pint: 1 psi
        ("abc def ++", "length", "must start with a number"),
        ("5\u200b m", "length", "invisible"),  # zero-width space; pint: 5 m
        ("5 \u200dm", "length", "invisible"),  # zero-width joiner
        ("\ufeff5 m", "length", "invisible"),  # a byte-order mark inside the value
        ("5\u00a0m", "length", "non-standard space"),
        ("5\tm", "length", "invisible"),
        (True, "length", "must be a number"),
        ([1, 2], "length", "must be a number"),
        (float("nan"), "length", "must be finite"),
        (float("inf"), "pressure", "must be finite"),
        (10**400, "length", "must be finite"),  # a 400-digit TOML integer: OverflowError
        ("1e400 m", "length", "must be finite"),
        # units.MAGNITUDE_RANGE (1e-20..1e20 SI) for dimensional values
        (1.7e308, "pressure", "magnitude must lie in 1e-20..1e+20 Pa"),
        ("1e-21 m", "length", "magnitude"),
        (-1e21, "force", "magnitude"),
    ],
)
def test_unit_errors_name_field_value_rule(value, kind, rule):
    with pytest.raises(CaseError) as info:
        to_si("booster.x", value, kind)
    assert info.value.field == "booster.x"
    assert rule in info.value.rule
    assert "booster.x" in str(info.value)


@pytest.mark.parametrize(("value", "unit", "expected"), [
    (0.0254, "m", (1.0, "in")), (PSI, "Pa", (1.0, "psi")), (LBF, "N", (1.0, "lbf")),
    (-2.0 * INCH, "m", (-2.0, "in")), (3.0, "rad/s", None)])
def test_to_us_against_exact_definitions(value, unit, expected):
    got = to_us(value, unit)
    if expected is None:
        assert got is None
    else:
        assert got[1] == expected[1] and got[0] == pytest.approx(expected[0], rel=1e-14)


@pytest.mark.parametrize(("value", "unit", "rule"), [
    (float("nan"), "m", "value = nan: must be finite"),  # returned (nan, 'in') before
    (float("inf"), "N", "value = inf: must be finite"),
    (1e308, "m", "beyond the float range"),  # 3.9e309 in: returned (inf, 'in') before
    (1.0, ["m"], "si_unit = ['m']: must be a string")])
def test_to_us_rejects_non_finite_values_in_one_line(value, unit, rule):
    with pytest.raises(ValueError) as info:
        to_us(value, unit)
    assert rule in str(info.value) and "\n" not in str(info.value)


def _documented(text: str) -> None:
    """Every field line of an embedded case file carries a comment."""
    for line in text.splitlines():
        if "=" in line and not line.lstrip().startswith("#") and not line.startswith("name"):
            assert "#" in line, line


def test_default_case_is_the_launch_vehicle_through_its_flight_and_documented():
    """The default case (`flexbooster init`): a [vehicle] with tanks and a [flight]; the
    numbers against the sources tagged in the file (exact unit definitions: 1 lbf =
    4.4482216152605 N, 1 Hz = 2 pi rad/s), to 1e-15 relative."""
    case = default_case()
    assert case.booster is None and case.has_segments
    assert case.F0 == pytest.approx(430000 * LBF, rel=1e-15)  # [W] LR87 thrust
    assert [t.name for t in case.vehicle.tanks] == ["stage-1 fuel", "stage-1 oxidiser",
                                                    "stage-2 fuel", "stage-2 oxidiser"]
    flight = case.flight
    assert flight.duration == 156.0 and [p.time for p in flight.points] == [0.0, 156.0]
    for point in flight.points:  # [H] the pogo band 10-12 Hz; one fill per tank
        assert point.oscillation == pytest.approx((20 * math.pi, 24 * math.pi), rel=1e-15)
        assert len(point.fill) == len(case.vehicle.tanks)
    _documented(default_case_text())


def test_default_case_round_trips():
    """The default case through its SI mapping and through TOML text gives the same case
    (the validated case is a function of its content; frozen models compare by value)."""
    case = default_case()
    assert load_case(case.model_dump(exclude_none=True)) == case
    assert load_case(tomllib.loads(default_case_text())) == case


def test_memo_case_is_valid_and_documented():
    case = memo_case()
    assert case.booster.cylinder1.radius == 5.05
    assert case.thrust.F0 == 2.8e6 and case.thrust.T0 is None
    assert case.T0 == pytest.approx(2.8e6 / (2 * math.pi * 5.05), rel=1e-15)
    _documented(memo_case_text())


def test_T0_instead_of_F0(memo_case_dict):
    del memo_case_dict["thrust"]["F0"]
    memo_case_dict["thrust"]["T0"] = "500 lbf/in"
    case = load_case(memo_case_dict)
    assert case.F0 == pytest.approx(2 * math.pi * 5.05 * 500 * LBF / INCH, rel=1e-14)


def _set(data, dotted, value):
    *parents, last = dotted.split(".")
    for key in parents:
        data = data[key]
    if value is _DELETE:
        del data[last]
    else:
        data[last] = value


_DELETE = object()

# (field to change, new value, field named in the message, words of the rule)
BAD_INPUTS = [
    ("booster.cylinder1.radius", _DELETE, "booster.cylinder1.radius", "required"),
    ("booster.E", _DELETE, "booster.E", "required"),
    ("booster.cylinder1.radius", -5.0, "booster.cylinder1.radius", "positive"),
    ("booster.cylinder2.half_length", "0 m", "booster.cylinder2.half_length", "positive"),
    ("booster.thickness", "-1 mm", "booster.thickness", "positive"),
    ("booster.E", 0, "booster.E", "positive"),
    ("booster.rho", "-2700 kg/m^3", "booster.rho", "positive"),
    ("booster.nu", 0.5, "booster.nu", "(0, 0.5)"),
    ("booster.nu", -0.1, "booster.nu", "(0, 0.5)"),
    ("booster.thickness", "4 m", "booster.thickness", "smaller than cylinder2.radius"),
    ("thrust.T0", "1000 N/m", "thrust.F0/thrust.T0", "exactly one"),
    ("thrust.F0", _DELETE, "thrust.F0/thrust.T0", "exactly one"),
    ("thrust.omega_min", "3000 rad/s", "thrust.omega_min", "smaller than thrust.omega_max"),
    ("thrust.omega_max", "5 rad/s", "thrust.omega_min", "smaller than thrust.omega_max"),
    ("booster.E", "10.5e6 psx", "booster.E", "unknown unit"),
    ("booster.E", "10.5e6 m", "booster.E", "wrong dimension"),
    ("thrust.F0", "3 kg", "thrust.F0", "wrong dimension"),
    ("thrust.omega_min", "5 m", "thrust.omega_min", "wrong dimension"),
    ("truncation.M1", MAX_MODES + 1, "truncation.M1", "[1, 500]"),
    ("truncation.N", 0, "truncation.N", "[1, 500]"),
    ("truncation.S", -1, "truncation.S", "[0, 500]"),
    ("truncation.R", 12, "truncation.R", "N + 1"),
    ("truncation.M2", 2.5, "truncation.M2", "whole number"),
    ("truncation.N2", "ten", "truncation.N2", "whole number"),
    ("booster.radius", 3.0, "booster.radius", "unknown key"),
    ("thrust.gimbal", 0.5, "thrust.gimbal", "unknown key"),
    ("thrust.gamma", 1.0, "thrust.gamma", "[0, 1)"),
    ("thrust.K", -0.5, "thrust.K", ">= 0"),
    ("thrust.n_omega", 1, "thrust.n_omega", "[2, 100000]"),
    ("booster.cylinder1.radius", float("nan"), "booster.cylinder1.radius", "finite"),
    ("booster.cylinder1", 5.0, "booster.cylinder1", "table"),
]


@pytest.mark.parametrize(("path", "value", "field", "rule"), BAD_INPUTS)
def test_bad_input_names_field_value_and_rule(memo_case_dict, path, value, field, rule):
    _set(memo_case_dict, path, value)
    with pytest.raises(CaseError) as info:
        load_case(memo_case_dict)
    assert info.value.field == field
    assert rule in info.value.rule
    message = str(info.value)
    assert "\n" not in message and field in message


def test_file_not_toml(tmp_path):
    path = tmp_path / "case.toml"
    path.write_text("[booster\nradius = ")
    with pytest.raises(CaseError, match="not a valid TOML file"):
        load_case(path)


def test_file_missing(tmp_path):
    with pytest.raises(CaseError, match="file not found"):
        load_case(tmp_path / "absent.toml")


def test_case_is_frozen():
    case = memo_case()
    with pytest.raises(Exception):  # noqa: B017 - pydantic raises ValidationError for frozen models
        case.booster.E = 1.0
