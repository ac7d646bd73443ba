#!/usr/bin/python3
"""A sweep of 100 bendings of a singlet, EFL and RMS spot each: from Python (lenslab.analyze)
against the command line (`lenslab analyze FILE --json`, a process and a file per bending).

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_sweep.py build/release/lenslab

Prints the times and their ratios (docs/performance.md records them): the Python sweep one call
after another, asking only for the two figures (report=[...]); the same over a thread pool (the
module releases the GIL while it computes); one lenslab.analyze_many call for the 100 bendings,
on one worker thread and on one per core; and the command line. Each Python sweep is the best
of five runs, the command line's the best of two. Not part of the test suite: a wall-clock
figure depends on the machine.
"""

import json
import os
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor
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


KEYS = ["efl", "rms_spot_best"]


def efl_and_spot(scene: dict) -> tuple[float, float]:
    r = lenslab.analyze(scene, f_number=8, report=KEYS)
    return r["efl"], r["rms_spot_best"]


def batch(scenes: list[dict], threads=None) -> list[tuple[float, float]]:
    results = lenslab.analyze_many(scenes, threads=threads, f_number=8, report=KEYS)
    return [(r["efl"], r["rms_spot_best"]) for r in results]


def best_of(runs: int, sweep) -> tuple[float, list]:
    best, result = float("inf"), None
    for _ in range(runs):
        start = time.perf_counter()
        result = sweep()
        best = min(best, time.perf_counter() - start)
    return best, result


def cli_sweep(cli: str, scenes: list[dict]) -> list[tuple[float, float]]:
    out = []
    with tempfile.TemporaryDirectory() as folder:
        for i, scene in enumerate(scenes):
            path = Path(folder) / f"bend{i}.json"
            path.write_text(json.dumps(scene))
            text = subprocess.run([cli, "analyze", str(path), "--json", "--f-number", "8"],
                                  check=True, capture_output=True, text=True).stdout
            r = json.loads(text)
            out.append((r["efl"], r["rms_spot_best"]))
    return out


def main() -> None:
    cli = sys.argv[1] if len(sys.argv) > 1 else "build/release/lenslab"
    base = json.loads(SCENE.read_text())
    scenes = [bent(base, s) for s in np.linspace(-1.9, 1.9, 100)]

    python_s, from_python = best_of(5, lambda: [efl_and_spot(s) for s in scenes])
    workers = os.cpu_count() or 1
    with ThreadPoolExecutor(workers) as pool:
        pooled_s, from_pool = best_of(5, lambda: list(pool.map(efl_and_spot, scenes)))
    batch1_s, from_batch1 = best_of(5, lambda: batch(scenes, threads=1))
    batch_s, from_batch = best_of(5, lambda: batch(scenes))
    cli_s, from_cli = best_of(2, lambda: cli_sweep(cli, scenes))

    assert from_python == from_cli == from_pool == from_batch1 == from_batch, \
        "the module and the command line disagree"
    print(f"100 bendings, EFL and RMS spot: command line {cli_s * 1e3:.1f} ms; "
          f"Python {python_s * 1e3:.1f} ms ({cli_s / python_s:.0f}x); "
          f"Python on {workers} threads {pooled_s * 1e3:.1f} ms ({cli_s / pooled_s:.0f}x); "
          f"analyze_many on 1 thread {batch1_s * 1e3:.1f} ms ({cli_s / batch1_s:.0f}x); "
          f"analyze_many on {workers} threads {batch_s * 1e3:.1f} ms ({cli_s / batch_s:.0f}x); "
          f"a call {python_s * 10:.3f} ms, a command-line run {cli_s * 10:.2f} ms")


if __name__ == "__main__":
    main()
