#!/usr/bin/python3
"""A sweep of 100 bendings of a singlet, EFL and RMS spot each: from Python (lenslab.analyze)
against the command line (`lenslab analyze FILE --json`, a process and a file per bending).

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_sweep.py build/release/lenslab

Prints both times and their ratio (docs/performance.md records it). Not part of the test suite:
a wall-clock figure depends on the machine.
"""

import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import lenslab

SCENE = Path(__file__).resolve().parents[1] / "scenes" / "thick_lens_beam.json"
POWER = 1 / 50 - 1 / -50  # c1 - c2 of the scene's biconvex lens, kept as it bends


def bent(base: dict, shape: float) -> dict:
    """The scene with its lens bent to the shape factor (c1 + c2) / (c1 - c2)."""
    c1, c2 = (shape + 1) * POWER / 2, (shape - 1) * POWER / 2
    scene = json.loads(json.dumps(base))
    lens = scene["objects"][0]
    lens["front"] = {"shape": "sphere", "radius": 1 / c1} if c1 else {"shape": "flat"}
    lens["back"] = {"shape": "sphere", "radius": 1 / c2} if c2 else {"shape": "flat"}
    return scene


def main() -> None:
    cli = sys.argv[1] if len(sys.argv) > 1 else "build/release/lenslab"
    base = json.loads(SCENE.read_text())
    scenes = [bent(base, s) for s in np.linspace(-1.9, 1.9, 100)]

    start = time.perf_counter()
    from_python = [(r["efl"], r["rms_spot_best"])
                   for r in (lenslab.analyze(s, f_number=8) for s in scenes)]
    python_s = time.perf_counter() - start

    start = time.perf_counter()
    from_cli = []
    with tempfile.TemporaryDirectory() as folder:
        for i, scene in enumerate(scenes):
            path = Path(folder) / f"bend{i}.json"
            path.write_text(json.dumps(scene))
            out = subprocess.run([cli, "analyze", str(path), "--json", "--f-number", "8"],
                                 check=True, capture_output=True, text=True).stdout
            r = json.loads(out)
            from_cli.append((r["efl"], r["rms_spot_best"]))
    cli_s = time.perf_counter() - start

    assert from_python == from_cli, "the module and the command line disagree"
    print(f"100 bendings, EFL and RMS spot: Python {python_s * 1e3:.1f} ms, "
          f"command line {cli_s * 1e3:.1f} ms, ratio {cli_s / python_s:.0f}x")


if __name__ == "__main__":
    main()
