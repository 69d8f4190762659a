"""Writing an analysis to a folder: results.json, CSV tables, figures (SVG, PNG), report.html.

A thin layer over :mod:`flexbooster.present.io` (atomic writes) and
:mod:`flexbooster.present.plotting`.
"""

from __future__ import annotations

import json
import multiprocessing
import os
import shutil
import signal
import tempfile
from collections.abc import Callable, Iterator
from concurrent.futures import ProcessPoolExecutor
from contextlib import contextmanager
from pathlib import Path
from typing import TYPE_CHECKING

from ..errors import CaseError
from ..results import Results
from .figure_files import render_figure
from .flight import FLIGHT_CSVS, FLIGHT_FIGURES, flight_figure_names, write_flight_csvs
from .forced import FORCED_CSV, FORCED_FIGURES
from .io import (
    hold_signals,
    locked_folder,
    sha256_file,
    write_bytes_atomic,
    write_csv_atomic,
    write_json_atomic,
    write_text_atomic,
)

if TYPE_CHECKING:
    from matplotlib.figure import Figure

__all__ = ["OUTPUT_STAGES", "write_outputs", "make_figures", "figure_svgs",
           "figure_names", "render_figures", "MANIFEST", "STAGING_PREFIX", "publish_set",
           "check_output_set", "check_output_folder", "SET_NAMES", "FIGURE_STEMS",
           "TABLE_NAMES"]

#: The stages of :func:`write_outputs`, as passed to its ``progress`` callback.
OUTPUT_STAGES = ("results.json and CSV", "figures", "report.html")
#: The manifest of an output set, written last: every file of the set with its SHA-256.
MANIFEST = "manifest.json"
#: Resolution of the PNG files (dots per inch).

#: Prefix of the staging folder that :func:`write_outputs` makes inside the output folder.
STAGING_PREFIX = ".flexbooster-staging-"
#: The data files a set may hold (each written only when its result exists).
TABLE_NAMES = ("results.json", "shell-frequencies.csv", "unstable-frequencies.csv",
               "resonance-bands.csv", "vehicle-modes.csv", "vehicle-regions.csv", FORCED_CSV,
               *FLIGHT_CSVS, "report.html")
#: Every figure :func:`figure_names` may name (each saved as .svg and .png).
FIGURE_STEMS = ("danger-map", "ince-strutt", "beam-modes", "shell-frequencies-cylinder1",
                "shell-frequencies-cylinder2", "nodal-patterns", "pitch-band-chart",
                "beam-action-chart", "campbell", "vehicle-regions", "vehicle-mode-shapes",
                "vehicle-unrolled", *FORCED_FIGURES, *FLIGHT_FIGURES)
#: Every name a set of :func:`write_outputs` may use in its folder.
SET_NAMES = (TABLE_NAMES + tuple(f"{stem}.{ext}" for stem in FIGURE_STEMS
                                 for ext in ("svg", "png")) + (MANIFEST, ".flexbooster.lock"))


def check_output_folder(folder: str | Path, names: tuple[str, ...] = SET_NAMES, *,
                        field: str = "folder") -> Path:
    """``folder`` as a Path once it is known to take the files ``names``, before any work:
    CaseError naming ``field``, the path and the rule for an empty path, a folder that is a file
    or lies under one, a folder where no file can be created (read-only, ``/proc``: probed by
    making and removing a temporary folder there or in its nearest existing parent), or a name
    of the set that exists as anything but a regular file (a ``results.json`` folder). What can
    only fail later (a full disk) is an OSError naming the file
    (:func:`flexbooster.present.io.write_bytes_atomic`).

    Parameters
    ----------
    folder : str or pathlib.Path
        The output folder (created later if missing).
    names : tuple of str
        File names the output will use in ``folder`` (default: every name of a
        :func:`write_outputs` set).
    field : str
        The name of the folder in the message (a command-line option, or ``folder``).
    """
    if not isinstance(folder, str | os.PathLike):
        raise TypeError(f"folder = {folder!r:.60}: must be a path (str or os.PathLike)")
    if not os.fspath(folder):
        raise CaseError(field, "", "must not be empty (use '.' for the current folder)")
    path = Path(folder)
    if path.exists() and not path.is_dir():
        raise CaseError(field, str(path), "is a file, not a folder")
    parent = path
    while not parent.exists() and parent != parent.parent:
        parent = parent.parent
    if not parent.is_dir():
        raise CaseError(field, str(path), f"cannot be created: {parent} is a file")
    try:
        os.rmdir(tempfile.mkdtemp(prefix=STAGING_PREFIX, dir=parent))
    except OSError as exc:
        raise CaseError(field, str(path), f"cannot be written: no folder can be made in {parent} "
                        f"({exc.strerror or type(exc).__name__})") from None
    for name in names:
        target = path / name
        if (target.exists() or target.is_symlink()) and not target.is_file():
            raise CaseError(field, str(path), f"{target} exists and is not a regular file")
    return path


def publish_set(stage: str | Path, folder: str | Path, names: list[str]) -> list[Path]:
    """Move the files ``names`` of ``stage`` into ``folder`` as one set, :data:`MANIFEST` last;
    returns their paths.

    Parameters
    ----------
    stage : str or pathlib.Path
        Staging folder on the same file system as ``folder``.
    folder : str or pathlib.Path
        Output folder.
    names : list of str
        File names of the set (in ``stage``).
    """
    stage, folder = Path(stage), Path(folder)
    hashes = {name: sha256_file(stage / name) for name in names}
    manifest = {"files": hashes}
    with locked_folder(folder), hold_signals():
        old = _manifest_files(folder)
        for name in names:
            os.replace(stage / name, folder / name)
        for name in sorted(set(old) - set(names)):  # files of the previous set only
            (folder / name).unlink(missing_ok=True)
        write_json_atomic(folder / MANIFEST, manifest)
    return [folder / name for name in names] + [folder / MANIFEST]


def _manifest_files(folder: Path) -> dict[str, str]:
    try:
        data = json.loads((folder / MANIFEST).read_text("utf-8"))
        files = data["files"]
    except (OSError, ValueError, KeyError, TypeError):
        return {}
    return {str(k): str(v) for k, v in files.items() if "/" not in str(k)} \
        if isinstance(files, dict) else {}


def check_output_set(folder: str | Path) -> dict[str, str]:
    """Verify that ``folder`` holds one complete output set: file name -> SHA-256; ValueError for
    no manifest or a file missing or different (a mixed set).

    Parameters
    ----------
    folder : str or pathlib.Path
        An output folder of :func:`write_outputs`.
    """
    folder = Path(folder)
    files = _manifest_files(folder)
    if not files:
        raise ValueError(f"folder = {str(folder)!r}: no {MANIFEST} (not a complete output set)")
    for name, digest in files.items():
        path = folder / name
        if not path.is_file() or sha256_file(path) != digest:
            raise ValueError(f"folder = {str(folder)!r}: {name} differs from {MANIFEST} "
                             "(a mixed or damaged output set)")
    return files


def write_outputs(
    results: Results,
    folder: str | Path,
    figures: bool = True,
    progress: Callable[[str], None] | None = None,
) -> list[Path]:
    """Write every output of an analysis into ``folder`` as one set: results.json, the CSV tables,
    the figures, report.html and last :data:`MANIFEST`, staged and moved together
    (:func:`publish_set`). Returns the files written.

    Parameters
    ----------
    results : Results
        The analysis.
    folder : str or pathlib.Path
        Output folder (created if needed; checked first by :func:`check_output_folder`).
    figures : bool
        Also draw and save the figures (SVG and PNG); the report then embeds them.
    progress : callable, optional
        Called with the name of each stage (:data:`OUTPUT_STAGES`) as it starts.
    """
    folder = check_output_folder(folder)
    folder.mkdir(parents=True, exist_ok=True)
    stage = Path(tempfile.mkdtemp(prefix=STAGING_PREFIX, dir=folder))
    try:
        staged = _write_files(results, stage, figures, progress or (lambda stage: None))
        return publish_set(stage, folder, [p.name for p in staged])
    finally:
        shutil.rmtree(stage, ignore_errors=True)


def _write_files(results: Results, folder: Path, figures: bool,
                 step: Callable[[str], None]) -> list[Path]:
    """Every output file of :func:`write_outputs`, written into ``folder``; the figures are
    drawn by other processes meanwhile (:func:`_drawn`)."""
    from .report import write_report

    names = figure_names(results) if figures else ()
    with _drawn(results, names, _usable_cpus()) as drawn:
        step(OUTPUT_STAGES[0])
        written = [write_json_atomic(folder / "results.json", results.to_dict())]
        if results.shell is not None:  # the memo's shells ([booster] only)
            written.append(write_csv_atomic(folder / "shell-frequencies.csv",
                                            results.shell.to_rows()))
        if results.stability is not None:
            written.append(write_csv_atomic(folder / "unstable-frequencies.csv",
                                            results.stability.to_columns()))
        if results.severity is not None:  # every band, most severe first
            written.append(write_csv_atomic(folder / "resonance-bands.csv",
                                            results.severity.band_rows()))
        if results.vehicle is not None:  # a case with [vehicle] only
            written.append(write_csv_atomic(folder / "vehicle-modes.csv",
                                            results.vehicle.to_columns()))
        if results.vehicle_regions is not None:
            from .vehicle import vehicle_region_columns

            written.append(write_csv_atomic(folder / "vehicle-regions.csv",
                                            vehicle_region_columns(results.vehicle_regions)))
        if results.forced_response is not None:
            written.append(write_csv_atomic(folder / FORCED_CSV,
                                            results.forced_response.csv_columns()))
        written += write_flight_csvs(results.flight, folder)  # [flight]
        svgs: dict[str, str] = {}
        if names:
            step(OUTPUT_STAGES[1])
            for name, (svg, png) in zip(names, drawn, strict=True):
                svgs[name] = svg
                written.append(write_text_atomic(folder / f"{name}.svg", svg))
                written.append(write_bytes_atomic(folder / f"{name}.png", png))
    step(OUTPUT_STAGES[2])
    written.append(write_report(results, folder / "report.html", svgs))
    return written


def _usable_cpus() -> int:
    """The CPUs this process may run on (``os.sched_getaffinity``, else ``os.cpu_count``)."""
    try:
        return len(os.sched_getaffinity(0))
    except (AttributeError, OSError):  # not Linux
        return os.cpu_count() or 1


def _figure_files(results: Results, name: str) -> tuple[str, bytes]:
    """Draw and render one figure: SVG text (with its tooltips) and PNG bytes."""
    fig = make_figures(results, names=(name,))[name]
    svg, png = render_figure(fig)
    return _svg_titles(fig, svg), png


#: The results whose figures a drawing process draws (set by :func:`_adopt` as it starts).
_ADOPTED: list[Results] = []


def _adopt(results: Results) -> None:
    """Start of a drawing process: its results (inherited by ``fork``, not pickled); the
    parent alone handles Ctrl-C and SIGTERM."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    _ADOPTED[:] = [results]


def _adopted_figure_files(name: str) -> tuple[str, bytes]:
    return _figure_files(_ADOPTED[0], name)


@contextmanager
def _drawn(results: Results, names: tuple[str, ...],
           processes: int) -> Iterator[Iterator[tuple[str, bytes]]]:
    """The figures ``names`` as (SVG, PNG), in order: a ``concurrent.futures`` map over up to
    ``processes`` forked processes, started on entry; without ``fork``, in a daemonic process
    or with one process, drawn here as the iterator is read.  The bytes are the same."""
    processes = min(processes, len(names))
    if (processes < 2 or "fork" not in multiprocessing.get_all_start_methods()
            or multiprocessing.current_process().daemon):
        yield (_figure_files(results, name) for name in names)
        return
    pool = ProcessPoolExecutor(processes, mp_context=multiprocessing.get_context("fork"),
                               initializer=_adopt, initargs=(results,))
    try:
        yield pool.map(_adopted_figure_files, names)
    except BaseException:  # an error or Ctrl-C here: no figure is waited for
        pool.shutdown(wait=False, cancel_futures=True)
        raise
    pool.shutdown()


def render_figures(results: Results, *, processes: int = 1) -> dict[str, tuple[str, bytes]]:
    """SVG text and PNG bytes of every figure of :func:`make_figures`, by name, in the order of
    :func:`figure_names`.

    Parameters
    ----------
    results : Results
        The analysis.
    processes : int
        Processes that draw the figures (>= 1; 1: this one); the bytes are the same.
    """
    names = figure_names(results)
    with _drawn(results, names, processes) as drawn:
        return dict(zip(names, drawn, strict=True))


def figure_svgs(results: Results) -> dict[str, str]:
    """SVG text of every figure of :func:`make_figures`, by name (for the report).

    Parameters
    ----------
    results : Results
        The analysis.
    """
    return {name: svg for name, (svg, _) in render_figures(results).items()}


def _svg_titles(fig, svg: str) -> str:
    """The SVG with the figure's tooltips (the danger map's ``<title>`` per band), if any."""
    from .plotting.danger import SVG_TITLES_ATTRIBUTE, add_svg_titles

    return add_svg_titles(svg, getattr(fig, SVG_TITLES_ATTRIBUTE, {}))


def figure_names(results: Results) -> tuple[str, ...]:
    """The names (file stems) of the figures :func:`make_figures` draws for these results.

    Parameters
    ----------
    results : Results
        The analysis.
    """
    data = results.figures
    if data is None and results.not_applicable is None:
        return ()
    names = ["danger-map"] if results.danger is not None else []  # the answer first
    if data is not None:  # the memo's figures ([booster] only)
        names += ["ince-strutt", "beam-modes", "shell-frequencies-cylinder1",
                  "shell-frequencies-cylinder2", "nodal-patterns"]
        for name, part in (("pitch-band-chart", data.pitch_band_chart),
                           ("beam-action-chart", data.beam_action_chart),
                           ("campbell", data.campbell)):
            if part is not None:
                names.append(name)
    if results.vehicle_regions is not None:  # the vehicle's (Omega, gamma) chart
        names.append("vehicle-regions")
    if results.vehicle is not None:  # a case with [vehicle] only
        from .vehicle import vehicle_figure_names

        names += vehicle_figure_names(results.vehicle)
    from .forced import forced_figure_names

    names += forced_figure_names(results)
    names += flight_figure_names(results.flight)  # [flight] only
    return tuple(names)


def make_figures(results: Results, *, names=None) -> dict[str, Figure]:
    """Draw the figures of an analysis (matplotlib, Agg) from its stored data, by file stem:
    ``danger-map``, ``ince-strutt``, ``beam-modes``, ``shell-frequencies-cylinder1/2``,
    ``nodal-patterns``, ``pitch-band-chart``, ``beam-action-chart``, ``campbell`` and the
    vehicle's ``vehicle-mode-shapes``, ``vehicle-unrolled``, ``vehicle-regions``,
    ``forced-acceleration``, ``forced-envelopes`` as computed.

    Parameters
    ----------
    results : Results
        The analysis; ``results.figures`` holds every curve drawn.
    names : iterable of str, optional
        Draw only these (names from :func:`figure_names`); default all.
    """
    import matplotlib

    matplotlib.use("Agg")
    from .plotting.bands import plot_band_chart
    from .plotting.beam import mode_shape_plot
    from .plotting.danger import danger_map
    from .plotting.flight import flight_campbell
    from .plotting.patterns import nodal_patterns
    from .plotting.pitch import ince_strutt_chart
    from .plotting.shell import frequency_curves
    from .plotting.stability import campbell_diagram
    from .vehicle import vehicle_region_figures

    data = results.figures
    if data is None and results.not_applicable is None:
        raise ValueError("results.figures: no figure data (the results were not made by analyze)")
    available = figure_names(results)
    wanted = available if names is None else tuple(names)
    for name in wanted:
        if name not in available:
            raise ValueError(f"names = {name!r}: not a figure of these results "
                             f"({', '.join(available)})")
    makers: dict[str, Callable[[], Figure]] = {
        "danger-map": lambda: danger_map(results.danger),
        "ince-strutt": lambda: ince_strutt_chart(data.ince_strutt, Omega=results.pitch.Omega),
        "beam-modes": lambda: mode_shape_plot(data.beam_modes),
        "shell-frequencies-cylinder1": lambda: frequency_curves(results.shell, 1),
        "shell-frequencies-cylinder2": lambda: frequency_curves(results.shell, 2),
        "nodal-patterns": lambda: nodal_patterns(data.nodal_patterns),
        "pitch-band-chart": lambda: plot_band_chart(
            data.pitch_band_chart, omega_1=results.omega_1, bands=results.pitch.bands,
            damping_text=f"rigid-pitch damping ratio {results.pitch.damping_ratio:g}"),
        "beam-action-chart": lambda: plot_band_chart(
            data.beam_action_chart, omega_1=results.omega_1, bands=results.beam_action.bands,
            damping_text=(f"modal damping ratio {results.beam_action.beam_damping_ratio:g}, "
                          f"rigid pitch {results.beam_action.pitch_damping_ratio:g}"),
            searched=results.beam_action.band_range),
        "campbell": lambda: campbell_diagram(data.campbell),
        "vehicle-regions": lambda: vehicle_region_figures(results)["vehicle-regions"],
        "flight-campbell": lambda: flight_campbell(results.flight),
    }
    from .forced import FORCED_FIGURES, forced_figures

    figs: dict[str, Figure] = forced_figures(
        results, names=[name for name in wanted if name in FORCED_FIGURES])
    vehicle = [name for name in wanted if name not in makers and name not in FORCED_FIGURES]
    for name in wanted:
        if name in makers:
            figs[name] = makers[name]()
    if vehicle:  # a case with [vehicle] only
        from .vehicle import vehicle_figures

        figs.update(vehicle_figures(results.vehicle, names=vehicle))
    return {name: figs[name] for name in wanted}
