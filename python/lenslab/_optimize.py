"""lenslab.optimize and lenslab.tolerance: lens design as `lenslab optimize` and `lenslab
tolerance` do it, from a design file or a design written as a dict (docs/optimizer.md)."""

from __future__ import annotations

import json
import os
from typing import Any, Callable, Mapping, Optional, Union

from . import _lenslab
from ._scene import PathLike, Scene

DesignSource = Union[Mapping[str, Any], str, "os.PathLike[str]"]


def _design_json(design: DesignSource, base_dir: Optional[PathLike]) -> tuple[str, str]:
    """The design's JSON text and the folder its relative paths (the system's scene file)
    resolve against: a file's own folder, else `base_dir` (default: the working folder)."""
    if isinstance(design, Mapping):
        d = dict(design)
        if isinstance(d.get("system"), Scene):
            d["system"] = d["system"].to_dict()
        return json.dumps(d), os.fspath(base_dir) if base_dir is not None else ""
    path = os.fspath(design)
    with open(path, encoding="utf-8") as f:
        d = json.load(f)  # a malformed file: json.JSONDecodeError with its line and column
    folder = os.path.dirname(path) if base_dir is None else os.fspath(base_dir)
    return json.dumps(d), folder


def optimize(design: DesignSource, *, iterations: Optional[int] = None,
             global_starts: Optional[int] = None, base_dir: Optional[PathLike] = None,
             progress: Optional[Callable[[float], Any]] = None) -> dict[str, Any]:
    """Optimises a lens design as `lenslab optimize` does and returns its report: the dict
    `lenslab optimize --json` prints (before, after, variables, glass_trials,
    glass_substitution, global_search, iterations, evaluations, stopped) with "scene", the
    optimised system as a lenslab.Scene (what `-o OUT` writes); a design with
    configurations adds "configuration_scenes", each other configuration's Scene by name.

    design: a design file's path, or the design as a dict (its "system" a scene file's path,
    a scene dict or a lenslab.Scene). iterations and global_starts override the design's, as
    --iterations and --global-starts do. progress is called on the calling thread with the
    finished fraction. Ctrl-C stops the optimisation and raises KeyboardInterrupt."""
    text, folder = _design_json(design, base_dir)
    scene_text, report_text = _lenslab.optimize(
        text, folder, -1 if iterations is None else int(iterations),
        -1 if global_starts is None else int(global_starts), progress)
    report = json.loads(report_text)
    report["scene"] = Scene(json.loads(scene_text))
    if "configuration_scenes" in report:
        report["configuration_scenes"] = {
            name: Scene(scene) for name, scene in report["configuration_scenes"].items()}
    return report


def tolerance(design: DesignSource, *, trials: Optional[int] = None, seed: Optional[int] = None,
              base_dir: Optional[PathLike] = None,
              progress: Optional[Callable[[float], Any]] = None) -> dict[str, Any]:
    """Tolerances a lens design as `lenslab tolerance` does and returns the dict
    `lenslab tolerance --json` prints: the sensitivity table, its root-sum-square and
    predictions, and the Monte Carlo (with every trial's criterion).

    trials and seed override the design's `tolerances` block, as --trials and --seed do; the
    result is the command line's for the same design, trials and seed. progress and Ctrl-C
    as for lenslab.optimize."""
    text, folder = _design_json(design, base_dir)
    if trials is not None and int(trials) < 1:
        raise ValueError(f"trials must be at least 1, got {trials}")
    if seed is not None and int(seed) < 0:
        raise ValueError(f"seed must be at least 0, got {seed}")
    return json.loads(_lenslab.tolerance(text, folder, 0 if trials is None else int(trials),
                                         -1 if seed is None else int(seed), progress))
