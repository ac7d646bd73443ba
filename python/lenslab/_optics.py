"""lenslab.trace and lenslab.analyze: a ray's tree and the optical bench's report."""

from __future__ import annotations

import json
from typing import Any, Optional, Sequence

from . import _lenslab
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


def _positive(name: str, value: Optional[float]) -> float:
    if value is None:
        return 0.0
    if not value > 0:
        raise ValueError(f"{name}: must be a positive number, got {value!r}")
    return float(value)


def analyze(scene_or_file: SceneSource, *, wavelength: Optional[float] = None,
            lens: Optional[str] = None, stop: int = 1, epd: Optional[float] = None,
            f_number: Optional[float] = None,
            fields: Optional[Sequence[float]] = None) -> dict[str, Any]:
    """The optical bench's report, the dict `lenslab analyze FILE --json` prints: efl, bfl,
    ffl, first_order {efl, bfl, f_number, entrance_pupil {position, diameter}, exit_pupil,
    lagrange_invariant, ...}, seidel, spot sizes. The options are the command line's."""
    if epd is not None and f_number is not None:
        raise ValueError("f_number excludes epd (both set the entrance pupil)")
    text, path = source_json(scene_or_file)
    nm = _positive("wavelength", wavelength) or _lenslab.LINE_D
    return json.loads(_lenslab.analyze(text, path, nm, lens or "", stop,
                                       _positive("epd", epd), _positive("f_number", f_number),
                                       [float(a) for a in fields or []]))
