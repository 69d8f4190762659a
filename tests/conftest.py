"""Shared fixtures: a valid case mapping that tests modify one field at a time."""

from __future__ import annotations

import copy
import signal
import tomllib

import matplotlib
import pytest

matplotlib.use("Agg")


@pytest.fixture(autouse=True, scope="session")
def _sigint_raises_keyboard_interrupt():
    """Ctrl-C's usual action in the test process and the commands it starts.

    A non-interactive shell starts a background job (``make test &``, ``nohup``) with SIGINT
    ignored (POSIX), Python then installs no KeyboardInterrupt handler, and the ignore is
    inherited by every ``flexbooster`` the tests start: the tests that interrupt a run would
    then see exit 0 instead of 130.  The flexbooster command itself is right to keep an
    inherited ignore (a background job must not die by the terminal's Ctrl-C); the tests need
    the interactive disposition, which a child started from here inherits as SIG_DFL.
    """
    if signal.getsignal(signal.SIGINT) == signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)
    yield


@pytest.fixture(scope="session")
def memo_results():
    """``analyze(memo_case())``, computed once per test process and shared by every test
    that reads the full analysis of the memo case (figures' data and vehicle regions
    included).  Read it, never modify it: the next test sees the same object."""
    from flexbooster import analyze, memo_case

    return analyze(memo_case())


@pytest.fixture
def memo_case_dict() -> dict:
    """The embedded memo case as a fresh, mutable mapping."""
    from flexbooster.case import memo_case_text

    return copy.deepcopy(tomllib.loads(memo_case_text()))


@pytest.fixture(scope="session")
def memo_svgs(memo_results):
    """The SVG of every figure of :func:`memo_results` (``figure_svgs``), drawn once per
    test process: the report's and the figures' tests read the same drawings."""
    from flexbooster.present.outputs import figure_svgs

    return figure_svgs(memo_results)


@pytest.fixture
def small_memo_case_file(memo_case_dict, tmp_path):
    """The memo case with a small truncation and 40 Omega points, as a case file: every
    stage of a run in about a second, for tests whose evidence needs no full truncation."""
    memo_case_dict["truncation"].update(M1=3, N1=3, M2=3, N2=3, N=3, S=2, R=2)
    memo_case_dict["thrust"]["n_omega"] = 40
    path = tmp_path / "small.toml"
    path.write_text(dump_toml(memo_case_dict))
    return path


def dump_toml(data: dict, prefix: str = "") -> str:
    """A minimal TOML writer for test cases: scalars, lists and inline tables (a table inside
    a list, e.g. ``[[flight.points]]`` rows) first, then sub-tables."""
    import json
    import math

    def scalar(value):
        if isinstance(value, bool):
            return "true" if value else "false"
        if isinstance(value, float) and not math.isfinite(value):
            return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
        if isinstance(value, int | float):
            return repr(value)
        if isinstance(value, str):
            return json.dumps(value)
        if isinstance(value, list):
            return "[" + ", ".join(scalar(v) for v in value) + "]"
        if isinstance(value, dict):
            return "{" + ", ".join(f"{k} = {scalar(v)}" for k, v in value.items()) + "}"
        raise TypeError(type(value))

    lines = [f"{k} = {scalar(v)}" for k, v in data.items() if not isinstance(v, dict)]
    for key, value in data.items():
        if isinstance(value, dict):
            name = f"{prefix}.{key}" if prefix else key
            lines += ["", f"[{name}]", dump_toml(value, name)]
    return "\n".join(lines)


def run_cli(argv) -> int:
    """Run the command in-process; return the exit code."""
    from flexbooster.cli import main

    with pytest.raises(SystemExit) as info:
        main(argv)
    return info.value.code


@pytest.fixture
def alarm():
    """A call that hangs fails instead of blocking the suite: a hang guard (10 min, far above
    any machine's load), not a measurement; the bounds themselves are the deterministic caps
    the tests check."""
    def handler(signum, frame):
        raise TimeoutError("the call did not return within 600 s")

    previous = signal.signal(signal.SIGALRM, handler)
    signal.alarm(600)
    yield
    signal.alarm(0)
    signal.signal(signal.SIGALRM, previous)


def case_with(data: dict, **fields):
    """The validated case of the mapping ``data`` with dotted fields set (``thrust__F0=1e6``)."""
    import flexbooster
    from test_case import _set

    for dotted, value in fields.items():
        _set(data, dotted.replace("__", "."), value)
    return flexbooster.load_case(data)
