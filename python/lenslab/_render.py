"""lenslab.render, lenslab.write_image and lenslab.colour_speckle."""

from __future__ import annotations

import copy
import math
import numbers
import os
from typing import Any, Callable, Optional, Union

import numpy as np

from . import _lenslab
from ._scene import PathLike, SceneSource, as_scene, scene_json, _dumps


def render(scene: SceneSource, *, width: Optional[int] = None, height: Optional[int] = None,
           spp: Optional[int] = None, integrator: Optional[str] = None,
           seed: Optional[int] = None, threads: Optional[int] = None,
           progress: Optional[Callable[[float], Any]] = None, **settings: Any) -> np.ndarray:
    """Renders `scene` as `lenslab render` does: linear RGB, float32, shape (height, width, 3).

    width ... seed and any other key of the scene's `render` block (passed by name, e.g.
    passes=, max_depth=) override the scene's, as the command line's options do. threads:
    worker threads (None: all cores); the image is the same for any count. progress is
    called on the calling thread with the finished fraction. Ctrl-C stops the render and
    raises KeyboardInterrupt; so does any exception the progress callback raises."""
    s = as_scene(scene)
    data = copy.deepcopy(s._data)
    overrides = {k: v for k, v in dict(width=width, height=height, spp=spp,
                                       integrator=integrator, seed=seed).items()
                 if v is not None}
    overrides.update(settings)
    render_block = data.setdefault("render", {})
    if isinstance(render_block, dict):  # anything else is the reader's to refuse
        render_block.update(overrides)
        # As `--time` alone does: a time budget without a pass count lifts the pass limit.
        if "time" in overrides and "passes" not in overrides:
            render_block["passes"] = 0
    return _lenslab.render(_dumps(data), scene_json(s)[1], _thread_count(threads), progress)


def _thread_count(threads: Optional[int]) -> int:
    """The compiled module's count: 0 for all cores; 1 to 1024 as `--threads` takes."""
    if threads is None:
        return 0
    if not isinstance(threads, bool) and isinstance(threads, numbers.Integral) \
            and 1 <= threads <= 1024:
        return int(threads)
    raise ValueError(f"threads: must be a whole number from 1 to 1024, got {threads!r}")


def write_image(image: np.ndarray, path: PathLike, exposure: float = 0.0,
                tone_map: str = "clip", highlight_stops: float = 8.0) -> None:
    """Writes an (H, W, 3) linear image with the writer `lenslab render -o` uses: .png (sRGB,
    scaled by 2**exposure, then `tone_map`: "clip" at white, or "log", highlights on a log
    scale up to `highlight_stops` stops above the knee, their colour kept) or .exr (linear
    float, the exposure alone), atomically."""
    path = os.fspath(path)
    if not _lenslab.is_supported_image_path(path):
        raise ValueError(f"path '{path}': unknown image type (use a .png or .exr file name)")
    _lenslab.write_image(np.asarray(image, dtype=np.float32), path, exposure, tone_map,
                         highlight_stops)


def colour_speckle(picture: Union[PathLike, np.ndarray], cx: float, cy: float,
                   radius: float) -> float:
    """The colour-speckle index of a PNG file or an (H, W, 3) 8-bit sRGB picture in the disc of
    `radius` pixels about (cx, cy) (x right, y down): each pixel's chroma (R - G, G - B), read
    as 0 to 1, against its 5 x 5 neighbourhood's mean, averaged over the disc. Near 0 for a
    smooth picture, near 1 for one random colour per pixel; `lenslab bench povray` reports it
    inside the report scene's glass sphere and its caustic."""
    for name, value in (("cx", cx), ("cy", cy), ("radius", radius)):
        if isinstance(value, bool) or not isinstance(value, numbers.Real) \
                or not math.isfinite(value):
            raise ValueError(f"{name}: must be a finite number, got {value!r}")
    if radius < 0:
        raise ValueError(f"radius: must be >= 0, got {radius!r}")
    if isinstance(picture, (str, os.PathLike)):
        return _lenslab.colour_speckle_png(os.fspath(picture), cx, cy, radius)
    array = np.asarray(picture)
    if array.dtype != np.uint8:
        raise ValueError(f"picture: must be 8-bit (dtype uint8), got {array.dtype}")
    return _lenslab.colour_speckle_rgb8(array, cx, cy, radius)
