"""lenslab.trace and lenslab.analyze: a ray's tree and the optical bench's report."""

from __future__ import annotations

import json
import math
import numbers
from collections.abc import Iterable
from typing import Any, Callable, Optional, Sequence

import numpy as np

from . import _lenslab
from ._document import JsonDocument
from ._render import _thread_count
from ._scene import SceneSource, source_json


def trace(scene: SceneSource, origin: Sequence[float], direction: Sequence[float], *,
          wavelength: float = _lenslab.LINE_D, max_depth: int = _lenslab.TRACE_MAX_DEPTH,
          min_weight: float = _lenslab.TRACE_MIN_WEIGHT) -> dict[str, Any]:
    """The tree of one ray's paths, as `lenslab trace` prints it: {tree: {from, to, object,
    event, weight, direction, children: [...]}, summary: {escaped, absorbed, truncated}}."""
    text, path = source_json(scene)
    return json.loads(_lenslab.trace(text, path, [float(v) for v in origin],
                                     [float(v) for v in direction], wavelength, max_depth,
                                     min_weight))


# A plain float or int skips the abstract number classes' isinstance checks, the slow part
# of a call in a sweep of many (bench/python_sweep.py); bool is neither type.
def _number(name: str, value: Any, *, positive: bool = False) -> float:
    if type(value) is not float and type(value) is not int and (
            isinstance(value, bool) or not isinstance(value, numbers.Real)):
        raise ValueError(f"{name}: must be a number, got {value!r}")
    value = float(value)
    if positive and not value > 0:
        raise ValueError(f"{name}: must be a positive number, got {value!r}")
    if not math.isfinite(value):
        raise ValueError(f"{name}: must be a finite number, got {value!r}")
    return value


def _numbers(name: str, values: Any, *, positive: bool = False) -> list[float]:
    if isinstance(values, np.ndarray):
        values = values.ravel().tolist()
    if isinstance(values, (str, bytes)) or not isinstance(values, Iterable):
        raise ValueError(f"{name}: must be a sequence of numbers, got {values!r}")
    return [_number(name, v, positive=positive) for v in values]


def _whole(name: str, value: Any, low: Optional[int] = None, high: Optional[int] = None) -> int:
    if type(value) is not int and (isinstance(value, bool) or
                                   not isinstance(value, numbers.Integral)):
        raise ValueError(f"{name}: must be a whole number, got {value!r}")
    if (low is not None and value < low) or (high is not None and value > high):
        raise ValueError(f"{name}: must be from {low} to {high}, got {value!r}")
    return int(value)


class Analysis(JsonDocument):
    """The result of lenslab.analyze: a read-only dict equal to what `lenslab analyze FILE
    --json` prints with the same options (less the names of figure files, which Python asks
    for with figure()); spot_points, the spot diagrams' ray hits; opd_maps and psf_images, the
    wavefronts and PSFs as arrays; figure(name), a figure as SVG text."""

    def __init__(self, run: Any) -> None:
        self._run = run
        self._data: dict[str, Any] = json.loads(run.document())
        self._spot_points: Optional[dict[tuple[float, float], np.ndarray]] = None

    @property
    def spot_points(self) -> dict[tuple[float, float], np.ndarray]:
        """The spot diagrams' ray hits, {(field, wavelength_nm): (N, 2) array of (x, y) in the
        image plane}, in the order of self["spots"]["per_wavelength"]; empty without
        spots=True."""
        if self._spot_points is None:
            self._spot_points = {(field, nm): xy for field, nm, xy in self._run.spot_points()}
        return self._spot_points

    @property
    def opd_maps(self) -> dict[tuple[float, float], np.ndarray]:
        """The wavefronts' OPD maps in waves, {(field, wavelength_nm): (samples, samples) array,
        a row per pupil y from -1 to 1, NaN where no ray passed}, in the order of
        self["wavefront"]["fields"] (those measured); empty without wavefront=True."""
        block = self._data.get("wavefront", {})
        return {(f["field"], f["wavelength_nm"]):
                np.array([[np.nan if v is None else v for v in row] for row in f["opd_map"]])
                for f in block.get("fields", []) if "opd_map" in f}

    @property
    def psf_images(self) -> dict[float, np.ndarray]:
        """The polychromatic PSF of every field, {field: (size, size) array}, a row per image y
        rising, about self["psf"]["fields"][k]["centre"], relative to the aberration-free peak
        (its largest value is the Strehl ratio); empty without psf=True."""
        block = self._data.get("psf", {})
        return {f["field"]: np.array(f["image"], dtype=np.float64)
                for f in block.get("fields", []) if "image" in f}

    def figure(self, name: str) -> str:
        """The figure `name` as the SVG text `lenslab analyze` writes to a file: "ray_diagram"
        (--svg), "spots" (--spots-svg), "fans" (--fans-svg), "opd_fans" (--opd-fans-svg),
        "field_curves" (--curves-svg), "focal_shift" (--focal-shift-svg), "mtf" (--mtf-svg).
        All but the ray diagram need their table asked for (spots=True, ...)."""
        return self._run.figure(name)

    def __eq__(self, other: object) -> bool:
        if isinstance(other, Analysis):
            return self._data == other._data
        return self._data == other

    def __repr__(self) -> str:
        return f"<lenslab.Analysis: {', '.join(self._data)}>"


# The analysis request's options as the compiled module declares them (one list for the
# command line, this module and its stub: analysis/report/analyze_request_spec.h).
_DECLARED = {o["name"]: o for o in json.loads(_lenslab.analyze_options())}
_OPTIONS = frozenset(_DECLARED)


def analyze_options() -> list[dict[str, Any]]:
    """The options of lenslab.analyze as declared once for it and `lenslab analyze`: name
    (the keyword), option (the command line's), value (flag, number, positive_number, whole,
    numbers, positive_numbers, text, texts or choice), default, help, and where they apply
    low and high, choices, excludes and excludes_why, needs and needs_why."""
    return json.loads(_lenslab.analyze_options())


def _checked(option: dict[str, Any], value: Any) -> Any:
    name, kind = option["name"], option["value"]
    if kind == "flag":
        return bool(value)
    if kind in ("number", "positive_number"):
        return _number(name, value, positive=kind == "positive_number")
    if kind in ("numbers", "positive_numbers"):
        return _numbers(name, value, positive=kind == "positive_numbers")
    if kind == "whole":
        return _whole(name, value, option["low"], option["high"])
    if kind == "choice":
        if value not in option["choices"]:
            quoted = [repr(c) for c in option["choices"]]
            raise ValueError(f"{name}: must be {', '.join(quoted[:-1])} or {quoted[-1]}, "
                             f"got {value!r}")
        return value
    if kind == "text":
        if not isinstance(value, str):
            raise ValueError(f"{name}: must be a string, got {value!r}")
        return value
    if isinstance(value, str) or not all(isinstance(v, str) for v in value):  # texts
        raise ValueError(f"{name}: must be a list of strings, got {value!r}")
    return list(value)


def _request_json(options: dict[str, Any]) -> str:
    """The options checked against their declarations, as the JSON the compiled module takes;
    bad ones raise ValueError."""
    given = {name: value for name, value in options.items() if value is not None}
    # Chosen: given and not the default (a keyword left at its default chose nothing).
    chosen = {name for name, value in given.items()
              if not (isinstance(value, (bool, int, float, str))
                      and value == _DECLARED[name].get("default"))}
    for name in chosen:
        option = _DECLARED[name]
        for other in option.get("excludes", []):
            if other in chosen:
                raise ValueError(f"{name} excludes {other} ({option['excludes_why']})")
        if "needs" in option and option["needs"] not in chosen:
            raise ValueError(f"{name} needs {option['needs']} ({option['needs_why']})")
    return json.dumps({name: _checked(_DECLARED[name], value) for name, value in given.items()})




def analyze(scene_or_file: SceneSource, *, wavelength: Optional[float] = None,
            wavelengths: Optional[Sequence[float]] = None, aperture: Optional[float] = None,
            lens: Optional[str] = None, unit: Optional[str] = None,
            stop: Optional[int] = None, ray_aiming: Optional[str] = None,
            epd: Optional[float] = None, f_number: Optional[float] = None,
            object_distance: Optional[float] = None,
            fields: Optional[Sequence[float]] = None,
            field_heights: Optional[Sequence[float]] = None, seidel: bool = False,
            psf: bool = False, psf_huygens: bool = False, mtf: bool = False,
            wavefront: bool = False,
            zernike_terms: int = 37, wavefront_samples: int = 64,
            wavefront_reference: Optional[str] = None,
            mtf_frequencies: Optional[Sequence[float]] = None,
            through_focus: Optional[float] = None,
            through_focus_range: Optional[float] = None, through_focus_points: int = 11,
            spots: bool = False,
            rings: int = 6, fans: bool = False, opd_fans: bool = False, fan_points: int = 21,
            image_distance: Optional[float] = None, field_curves: bool = False,
            field_curve_points: int = 11, focal_shift: bool = False,
            band: Optional[Sequence[float]] = None, focal_shift_points: int = 21,
            wavelength_weights: Optional[Sequence[float]] = None,
            field_map: int = 0,
            report: Optional[Sequence[str]] = None) -> Analysis:
    """The optical bench: `lenslab analyze FILE --json` with the same options (named as the
    command line's, "-" as "_"), as a lenslab.Analysis. report: only these top-level keys of
    the document (e.g. ["efl", "rms_spot_best"]), and only what they need is computed.
    seidel changes nothing here (the document always has the Seidel sums). Bad options raise
    ValueError; a scene the bench cannot measure raises lenslab.SceneError with the JSON
    path. lenslab.analyze_many analyzes a list of scenes across the cores."""
    options = dict(locals())
    del options["scene_or_file"]
    request = _request_json(options)
    text, path = source_json(scene_or_file)
    return Analysis(_lenslab.analyze(text, path, request))


def _name_the_scene(error: BaseException, index: int) -> None:
    """Puts "scenes[INDEX]: " before the message of the error a scene of a list raised."""
    error.index = index  # type: ignore[attr-defined]
    if len(error.args) == 1 and isinstance(error.args[0], str):
        error.args = (f"scenes[{index}]: {error.args[0]}",)
    else:
        error.add_note(f"raised by scenes[{index}]")


def analyze_many(scenes: Iterable[SceneSource], *, threads: Optional[int] = None,
                 progress: Optional[Callable[[float], Any]] = None,
                 **options: Any) -> list[Analysis]:
    """lenslab.analyze(scene, **options) for each scene of `scenes`, in their order, the
    scenes shared out over `threads` worker threads (None: one per core) with the GIL
    released; the same documents bit for bit, the options checked once. The first scene in
    the list's order that fails raises what analyze would, its message beginning
    "scenes[INDEX]: " (and `index` set); no scene after it is started once it failed, and
    nothing is returned. progress: called with the fraction of scenes done; Ctrl-C cancels."""
    unknown = options.keys() - _OPTIONS
    if unknown:
        raise TypeError(f"analyze_many() got an unexpected keyword argument "
                        f"'{sorted(unknown)[0]}'")
    request = _request_json(options)
    workers = _thread_count(threads)
    texts, paths = [], []
    for index, scene in enumerate(scenes):
        try:
            text, path = source_json(scene)
        except (ValueError, TypeError) as e:  # unreadable file, not a scene, NaN in the dict
            _name_the_scene(e, index)
            raise
        texts.append(text)
        paths.append(path)
    batch = _lenslab.analyze_many(texts, paths, request, workers, progress)
    if batch.failed is not None:
        try:
            batch.raise_failure()
        except Exception as e:
            _name_the_scene(e, batch.failed)
            raise
    return [Analysis(run) for run in batch.runs()]


def spectral_data(wavelengths: Iterable[float], blackbody: Optional[float] = None,
                  rgb: Optional[Iterable[float]] = None) -> dict[str, np.ndarray]:
    """The spectral data the renderer uses at `wavelengths` (nm, 360 to 830), as
    `lenslab spectra --json` prints it: {"nm", "x_bar", "y_bar", "z_bar" (CIE 1931 2-degree
    colour-matching functions), "d65" (the renderer's white light) and "illuminant_a" (CIE A), relative to 560 nm,
    "blackbody" (with `blackbody` in kelvin, 500 to 100000, relative to 560 nm),
"rgb_light" (with `rgb`, a light's linear RGB colour: the smooth spectrum such a light gets,
    relative to D65 at 560 nm), "air_index" (standard air, 20 degC, 101325 Pa, at the
    wavelength in air)}, each an array."""
    nm = [float(w) for w in wavelengths]
    if blackbody is not None and (isinstance(blackbody, bool)
                                  or not isinstance(blackbody, numbers.Real)):
        raise ValueError(f"blackbody: must be a temperature in kelvin, got {blackbody!r}")
    channels = [] if rgb is None else [float(c) for c in rgb]
    columns = json.loads(_lenslab.spectral_data_json(nm, float(blackbody or 0), channels))
    return {key: np.asarray(values, dtype=np.float64) for key, values in columns.items()}

