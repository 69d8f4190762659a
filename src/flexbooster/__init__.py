"""flexbooster: whether a launch vehicle is safe under its oscillating thrust. The vehicle as
one shell of revolution (tanks, masses, pressure, stiffeners), its parametric instability
regions and forced response through its flight, and the method of Research & Analysis Section
Tech Memo 104 (two bare cylinders under a gimbaled, periodically varying end thrust).

Public API::

    import flexbooster
    case = flexbooster.default_case()            # or memo_case(), or load_case("case.toml" or dict)
    results = flexbooster.analyze(case)
    results.to_dict()                            # what results.json holds

The top-level names are loaded lazily (PEP 562), so that importing a numerical module such as
``flexbooster.memo.beam`` pulls in numpy and scipy only, not the input layer (pydantic, pint).
"""

from importlib import import_module

__version__ = "0.1.0"

_LAZY = {
    "AnalysisWarning": "errors",
    "CaseError": "errors",
    "Case": "case",
    "default_case": "case",
    "load_case": "case",
    "memo_case": "case",
    "Results": "analysis",
    "analyze": "analysis",
    "sweep": "sweep.run",
}

__all__ = ["__version__", *sorted(_LAZY)]


def __getattr__(name: str):
    if name in _LAZY:
        return getattr(import_module(f".{_LAZY[name]}", __name__), name)
    raise AttributeError(f"module 'flexbooster' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
