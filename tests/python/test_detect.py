import _thread
import json
import os
import signal
import threading
import time

import numpy as np
import pytest

import lenslab
from conftest import cli_error, run_cli

SCENE = "scenes/detector_focus.json"
SMALL = dict(photons=20000, seed=3)
SMALL_CLI = ["--photons", 20000, "--seed", 3]
# Long enough that only an interruption ends it within the tests' time.
LONG = dict(photons=2_000_000_000)


def _cli_detect(folder, *options):
    """`lenslab detect SCENE -o folder --json`'s summary."""
    return json.loads(run_cli("detect", SCENE, "-o", folder, "--json", "-q", *SMALL_CLI,
                              *options).stdout)


def _csv_maps(path):
    """The CSV's columns (u, v, area, E_total, E_<band>...) as (cells_v, cells_u) maps, row 0
    the highest v; and the header's names."""
    lines = [line for line in path.read_text().splitlines() if not line.startswith("#")]
    names = lines[0].split(",")
    rows = np.array([[float(x) for x in line.split(",")] for line in lines[1:]])
    nu = len(np.unique(rows[:, 0]))
    maps = rows.T.reshape(len(names), -1, nu)[:, ::-1, :]
    return names, maps


def test_values_equal_the_cli_csv(tmp_path):
    expected = _cli_detect(tmp_path)
    d = lenslab.detect(SCENE, **SMALL)
    names, maps = _csv_maps(tmp_path / "focal_plane.csv")
    assert names[:4] == ["u", "v", "area", "E_total"]
    assert d.irradiance.shape == (128, 128) and d.irradiance.dtype == np.float64
    assert np.array_equal(d.irradiance, maps[3])  # exactly: the CSV holds every digit
    assert np.array_equal(d.cell_area, maps[2])
    assert np.array_equal(d.band_irradiance, maps[4:])
    assert d.band_irradiance.shape == (len(d.detectors[0].band_edges) - 1, 128, 128)
    # The summary is the command line's, less its files and its time.
    summary = dict(d)
    for dict_ in (summary, expected):
        dict_.pop("seconds")
    for det in expected["detectors"]:
        det.pop("files")
    assert summary == expected
    assert d.total_power == expected["detectors"][0]["total_power"] > 0
    assert d.units == expected["detectors"][0]["units"]
    assert d.units["length"] == "mm" and d.units["power"] == "W"


def test_extent_and_axes():
    d = lenslab.detect(SCENE, **SMALL)
    u0, u1, v0, v1 = d.extent
    assert u0 == pytest.approx(-0.25) and u1 == pytest.approx(0.25)
    assert v0 == pytest.approx(-0.25) and v1 == pytest.approx(0.25)
    det = d.detectors[0]
    assert det.name == "focal plane" and d.detector("focal plane") is det
    assert det.origin == pytest.approx((0, 0, 49.08))
    # The irradiance integrates to the power.
    assert np.sum(d.irradiance * d.cell_area) == pytest.approx(d.total_power, rel=1e-9)


def test_saved_files_are_the_cli_files(tmp_path):
    _cli_detect(tmp_path / "cli", "--log")
    files = lenslab.detect(lenslab.Scene.load(SCENE), **SMALL).save(tmp_path / "py", log=True)
    assert [os.path.basename(f) for f in files[0]] == ["focal_plane.csv", "focal_plane.exr",
                                                       "focal_plane.png"]
    for name in ("focal_plane.csv", "focal_plane.exr", "focal_plane.png"):
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes()


def test_same_values_for_any_thread_count_and_seed_matters():
    one = lenslab.detect(SCENE, threads=1, **SMALL)
    assert np.array_equal(one.irradiance, lenslab.detect(SCENE, threads=2, **SMALL).irradiance)
    other = lenslab.detect(SCENE, **{**SMALL, "seed": 4})
    assert not np.array_equal(one.irradiance, other.irradiance)


def test_options_override_the_scene():
    base = lenslab.detect(SCENE, **SMALL)
    assert base["photons_per_light"] == 20000
    shallow = lenslab.detect(SCENE, max_depth=0, **SMALL)
    assert shallow.total_power < base.total_power
    unaimed = lenslab.detect(SCENE, aim_photons=False, caustic_photons=1000, **SMALL)
    assert unaimed["photons_aimed"] == 0


def test_bad_options_raise_with_the_json_path():
    with pytest.raises(lenslab.SceneError, match=r"render\.photons: ") as e:
        lenslab.detect(SCENE, photons=0)
    assert e.value.path == f"{SCENE}: render.photons"
    with pytest.raises(lenslab.SceneError, match=r"render\.max_depth: "):
        lenslab.detect(SCENE, max_depth=-1, **{**SMALL})
    with pytest.raises(ValueError, match="threads"):
        lenslab.detect(SCENE, threads=0, **SMALL)


def test_nothing_to_measure_raises_the_cli_message(tmp_path):
    with pytest.raises(lenslab.Error) as e:
        lenslab.detect("scenes/prism.json", **SMALL)
    assert str(e.value) == cli_error("detect", "scenes/prism.json", "-o", tmp_path)
    scene = lenslab.Scene.load(SCENE).to_dict()
    scene["lights"] = []
    with pytest.raises(lenslab.Error, match=r"^scene: no light to measure"):
        lenslab.detect(scene, **SMALL)


def test_several_detectors_need_a_choice():
    scene = lenslab.Scene.load(SCENE).to_dict()
    second = dict(scene["objects"][1], name="second", center=[0, 0, 60])
    scene["objects"].append(second)
    d = lenslab.detect(scene, **SMALL)
    assert [x.name for x in d.detectors] == ["focal plane", "second"]
    with pytest.raises(ValueError, match="2 detectors"):
        d.irradiance
    with pytest.raises(KeyError, match="no detector named 'third'"):
        d.detector("third")


def test_progress_runs_up_to_one():
    seen = []
    lenslab.detect(SCENE, progress=seen.append, **SMALL)
    assert seen and seen == sorted(seen) and seen[-1] == 1.0


@pytest.mark.parametrize("interrupt", [lambda: os.kill(os.getpid(), signal.SIGINT),
                                       _thread.interrupt_main])
def test_ctrl_c_cancels_the_detection(interrupt):
    timer = threading.Timer(0.3, interrupt)
    timer.start()
    start = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            lenslab.detect(SCENE, **LONG)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 10
    assert lenslab.detect(SCENE, **SMALL).total_power > 0
