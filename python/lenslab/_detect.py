"""lenslab.detect: the irradiance on a scene's detectors, as `lenslab detect` measures it."""

from __future__ import annotations

import copy
import json
import os
from typing import Any, Callable, Optional

import numpy as np

from . import _lenslab
from ._document import JsonDocument
from ._render import _thread_count
from ._scene import PathLike, SceneSource, _dumps, as_scene, scene_json


class Detector:
    """One detector's measurement: its summary (the entry of `lenslab detect --json`'s
    "detectors", without "files") and its maps as numpy arrays.

    irradiance: float64 (cells_v, cells_u) in units["irradiance"] (W per length unit²), row
    0 at the highest v and column 0 at the lowest u, as in the detector's EXR and PNG, so
    matplotlib's imshow(d.irradiance, extent=d.extent) shows it upright; the values are the
    CSV's E_total exactly. band_irradiance: (bands, cells_v, cells_u), band i over
    [band_edges[i], band_edges[i + 1]) nm. cell_area: (cells_v, cells_u), the area of each
    cell on the surface (a disc's rim cells are partly off it)."""

    def __init__(self, run: Any, index: int, summary: dict[str, Any]) -> None:
        self._run, self._index = run, index
        self.summary = summary
        geometry = run.geometry(index)
        self.extent: tuple[float, float, float, float] = geometry["extent"]
        self.origin: tuple[float, float, float] = geometry["origin"]
        self.u_axis: tuple[float, float, float] = geometry["u_axis"]
        self.v_axis: tuple[float, float, float] = geometry["v_axis"]
        self.band_edges: list[float] = geometry["band_edges"]

    @property
    def name(self) -> str:
        return self.summary["name"]

    @property
    def units(self) -> dict[str, str]:
        return self.summary["units"]

    @property
    def total_power(self) -> float:
        return self.summary["total_power"]

    @property
    def irradiance(self) -> np.ndarray:
        return self._run.irradiance(self._index)

    @property
    def band_irradiance(self) -> np.ndarray:
        return self._run.band_irradiance(self._index)

    @property
    def cell_area(self) -> np.ndarray:
        return self._run.cell_area(self._index)

    def __repr__(self) -> str:
        shape = "x".join(map(str, self.summary["resolution"]))
        return f"<lenslab.Detector {self.name!r}: {shape} cells, {self.total_power:.6g} W>"


class Detection(JsonDocument):
    """The result of lenslab.detect: a read-only dict equal to what `lenslab detect --json`
    prints (scene, photons_per_light, photons_emitted, photons_aimed, seed, seconds,
    detectors), less each detector's "files"; `detectors`, the measurements with their maps
    (lenslab.Detector); and for a scene with one detector, its irradiance, band_irradiance,
    cell_area, extent, units and total_power directly. save(folder) writes the command
    line's files."""

    def __init__(self, run: Any) -> None:
        self._run = run
        self._data: dict[str, Any] = json.loads(run.summary_json())
        self.detectors: list[Detector] = [Detector(run, i, d)
                                          for i, d in enumerate(self._data["detectors"])]

    def detector(self, name: str) -> Detector:
        """The detector named `name`."""
        for d in self.detectors:
            if d.name == name:
                return d
        names = ", ".join(repr(d.name) for d in self.detectors)
        raise KeyError(f"no detector named {name!r} (detectors: {names})")

    def _only(self) -> Detector:
        if len(self.detectors) != 1:
            raise ValueError(f"the scene has {len(self.detectors)} detectors: use "
                             f"detection.detectors[i] or detection.detector(name)")
        return self.detectors[0]

    @property
    def irradiance(self) -> np.ndarray:
        return self._only().irradiance

    @property
    def band_irradiance(self) -> np.ndarray:
        return self._only().band_irradiance

    @property
    def cell_area(self) -> np.ndarray:
        return self._only().cell_area

    @property
    def extent(self) -> tuple[float, float, float, float]:
        return self._only().extent

    @property
    def units(self) -> dict[str, str]:
        return self._only().units

    @property
    def total_power(self) -> float:
        return self._only().total_power

    def save(self, folder: PathLike, *, log: bool = False) -> list[list[str]]:
        """Writes <detector>.csv, .exr and .png into `folder` (created if missing), the files
        `lenslab detect -o FOLDER` writes (log: the PNG on a log scale, as --log); returns
        their paths, per detector."""
        return self._run.save(os.fspath(folder), bool(log))

    def __repr__(self) -> str:
        return f"<lenslab.Detection of {self._data['scene']!r}: {self.detectors!r}>"


def detect(scene: SceneSource, *, photons: Optional[int] = None,
           caustic_photons: Optional[int] = None, aim_photons: Optional[bool] = None,
           seed: Optional[int] = None, max_depth: Optional[int] = None,
           threads: Optional[int] = None,
           progress: Optional[Callable[[float], Any]] = None) -> Detection:
    """Measures the irradiance on every detector of `scene` as `lenslab detect` does.

    photons, caustic_photons, aim_photons, seed and max_depth override the scene's `render`
    block, as the command line's --photons ... --max-depth do. threads: worker threads (None:
    all cores); the result is the same for any count and equals the command line's at the
    same seed. progress is called on the calling thread with the finished fraction. Ctrl-C
    stops the measurement and raises KeyboardInterrupt."""
    s = as_scene(scene)
    overrides = {k: v for k, v in dict(photons=photons, caustic_photons=caustic_photons,
                                       aim_photons=aim_photons, seed=seed,
                                       max_depth=max_depth).items() if v is not None}
    text, path = scene_json(s)
    if overrides:
        data = copy.deepcopy(s._data)
        render_block = data.setdefault("render", {})
        if isinstance(render_block, dict):  # anything else is the reader's to refuse
            render_block.update(overrides)
        text = _dumps(data)
    return Detection(_lenslab.detect(text, path, _thread_count(threads), progress))
