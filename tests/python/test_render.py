import _thread
import os
import signal
import threading
import time

import numpy as np
import pytest

import lenslab
from conftest import cli_json, run_cli

SCENE = "scenes/default.json"
# Tiny, and with 20 000 photons instead of the scene's million: the photon map's work is most
# of a small render's time.
SMALL = dict(width=32, height=24, spp=4, seed=7, photons=20000)
SMALL_CLI = ["--width", 32, "--height", 24, "--spp", 4, "--seed", 7, "--photons", 20000]
# Long enough that only an interruption ends it within the tests' time.
LONG = dict(width=320, height=240, spp=4096, photons=20000)


def test_shape_and_type():
    image = lenslab.render(SCENE, **SMALL)
    assert image.shape == (24, 32, 3) and image.dtype == np.float32
    assert image.flags.c_contiguous and np.all(np.isfinite(image)) and image.mean() > 0


def test_byte_for_byte_the_cli_image(tmp_path):
    # The CLI's lossless output is EXR (linear float): the Python render written by the same
    # writer must be the same file.
    cli_exr, py_exr = tmp_path / "cli.exr", tmp_path / "py.exr"
    run_cli("render", SCENE, "-o", cli_exr, "-q", *SMALL_CLI)
    lenslab.write_image(lenslab.render(lenslab.Scene.load(SCENE), **SMALL), py_exr)
    assert py_exr.read_bytes() == cli_exr.read_bytes()


def test_same_image_for_any_thread_count_and_source():
    one = lenslab.render(SCENE, threads=1, **SMALL)
    assert np.array_equal(one, lenslab.render(lenslab.Scene.load(SCENE), threads=2, **SMALL))
    assert np.array_equal(one, lenslab.render(lenslab.Scene.default(), **SMALL))
    assert not np.array_equal(one, lenslab.render(SCENE, **{**SMALL, "seed": 8}))


def test_other_render_keys_override_the_scene():
    image = lenslab.render(SCENE, max_depth=0, **SMALL)
    assert not np.array_equal(image, lenslab.render(SCENE, **SMALL))
    with pytest.raises(lenslab.SceneError, match=r"render\.max_dept: unknown key"):
        lenslab.render(SCENE, max_dept=2, **SMALL)


def test_override_errors_name_the_json_path():
    with pytest.raises(lenslab.SceneError, match=r"render\.spp: "):
        lenslab.render(SCENE, **{**SMALL, "spp": 0})
    with pytest.raises(lenslab.SceneError, match=r"render\.integrator: "):
        lenslab.render(SCENE, integrator="pathh", **SMALL)
    with pytest.raises(ValueError, match="threads"):
        lenslab.render(SCENE, threads=0, **SMALL)
    assert lenslab.render(SCENE, threads=np.int64(2), **SMALL).shape == (24, 32, 3)


def test_progress_runs_up_to_one():
    seen = []
    lenslab.render(SCENE, progress=seen.append, **SMALL)
    assert seen and seen == sorted(seen) and seen[-1] == 1.0


def test_an_exception_in_progress_cancels_the_render():
    def stop(fraction):
        raise KeyboardInterrupt

    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        lenslab.render(SCENE, progress=stop, **LONG)
    assert time.monotonic() - start < 10


def _send_sigint():
    os.kill(os.getpid(), signal.SIGINT)


# What Ctrl-C does: a terminal's SIGINT, and the notebook's interrupt button (interrupt_main).
@pytest.mark.parametrize("interrupt", [_send_sigint, _thread.interrupt_main])
def test_ctrl_c_cancels_the_render(interrupt):
    timer = threading.Timer(0.3, interrupt)
    timer.start()
    start = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            lenslab.render(SCENE, **LONG)
    finally:
        timer.cancel()
    assert time.monotonic() - start < 10
    # The module is still usable afterwards.
    assert lenslab.render(SCENE, **SMALL).shape == (24, 32, 3)


def test_write_image_png_equals_the_cli(tmp_path):
    run_cli("render", SCENE, "-o", tmp_path / "cli.png", "-q", *SMALL_CLI, "--exposure", 1)
    lenslab.write_image(lenslab.render(SCENE, **SMALL), tmp_path / "py.png", exposure=1)
    assert (tmp_path / "py.png").read_bytes() == (tmp_path / "cli.png").read_bytes()


def test_write_image_tone_map_log_equals_the_cli(tmp_path):
    run_cli("render", SCENE, "-o", tmp_path / "cli.png", "-q", *SMALL_CLI, "--exposure", 3,
            "--tone-map", "log", "--highlight-stops", 6)
    image = lenslab.render(SCENE, **SMALL)
    lenslab.write_image(image, tmp_path / "log.png", exposure=3, tone_map="log",
                        highlight_stops=6)
    assert (tmp_path / "log.png").read_bytes() == (tmp_path / "cli.png").read_bytes()
    # Three stops up the default scene has highlights: the log map keeps them apart.
    lenslab.write_image(image, tmp_path / "clip.png", exposure=3)
    assert (tmp_path / "clip.png").read_bytes() != (tmp_path / "log.png").read_bytes()


def test_write_image_refuses_an_unknown_tone_map(tmp_path):
    image = np.zeros((2, 2, 3), dtype=np.float32)
    with pytest.raises(ValueError, match="tone_map: unknown"):
        lenslab.write_image(image, tmp_path / "x.png", tone_map="filmic")
    with pytest.raises(ValueError, match="highlight_stops"):
        lenslab.write_image(image, tmp_path / "x.png", tone_map="log", highlight_stops=0)


def test_colour_speckle_of_an_array_and_of_the_png_written_from_it(tmp_path):
    # Columns of pure red and pure green in turn: every inner pixel's 5 x 5 window holds three
    # of its own colour and two of the other, so each scores |1 - 0.2| + |0 - 0.4| = 1.2.
    rgb = np.zeros((40, 40, 3), dtype=np.uint8)
    rgb[:, 0::2, 0] = 255
    rgb[:, 1::2, 1] = 255
    assert lenslab.colour_speckle(rgb, 20, 20, 10) == pytest.approx(1.2, abs=1e-12)
    # The same picture as linear radiance, written as sRGB (0 and 1 stay 0 and 255).
    path = tmp_path / "columns.png"
    lenslab.write_image(rgb.astype(np.float32) / 255, path)
    assert lenslab.colour_speckle(path, 20, 20, 10) == pytest.approx(1.2, abs=1e-12)
    assert lenslab.colour_speckle(np.full((9, 9, 3), 77, np.uint8), 4, 4, 4) == \
        pytest.approx(0, abs=1e-12)
    with pytest.raises(ValueError, match="radius: must be >= 0"):
        lenslab.colour_speckle(rgb, 20, 20, -1)
    with pytest.raises(ValueError, match="uint8"):
        lenslab.colour_speckle(rgb.astype(np.float32), 20, 20, 5)
    with pytest.raises(lenslab.Error):
        lenslab.colour_speckle(tmp_path / "missing.png", 1, 1, 1)


def test_spectral_data_holds_the_cie_tables_as_the_cli_prints_them():
    data = lenslab.spectral_data([500, 550], blackbody=2856)
    # CIE 1931 at 550 nm: 0.433450 0.994950 0.008750; D65 relative: 104.046 / 100.
    assert data["x_bar"][1] == pytest.approx(0.43345, abs=5e-7)
    assert data["y_bar"][1] == pytest.approx(0.99495, abs=5e-7)
    assert data["d65"][1] == pytest.approx(1.04046, abs=1e-6)
    assert list(data) == ["nm", "x_bar", "y_bar", "z_bar", "d65", "illuminant_a", "blackbody",
                          "air_index"]
    expected = cli_json("spectra", "--wavelengths", "500,550", "--blackbody", "2856", "--json")
    for key, values in expected.items():
        assert list(data[key]) == values
    with pytest.raises(ValueError, match="outside 360 to 830 nm"):
        lenslab.spectral_data([900])
    with pytest.raises(ValueError, match="between 500 and 100000 K"):
        lenslab.spectral_data([550], blackbody=10)


def test_spectral_data_gives_the_smooth_spectrum_of_a_light_colour():
    # White is D65 itself; a red light is smooth, small in the blue and large in the red.
    white = lenslab.spectral_data([450, 550, 650], rgb=(1, 1, 1))
    assert list(white["rgb_light"]) == pytest.approx(list(white["d65"]), rel=1e-9)
    red = lenslab.spectral_data(range(450, 651, 10), rgb=(1, 0, 0))["rgb_light"]
    assert red[0] < 0.05 * red[-1]
    assert all(b >= a for a, b in zip(red[8:], red[9:]))  # rising through the red
    expected = cli_json("spectra", "--wavelengths", "600", "--rgb", "1,0.5,0.2", "--json")
    assert lenslab.spectral_data([600], rgb=(1, 0.5, 0.2))["rgb_light"][0] == \
        expected["rgb_light"][0]
    with pytest.raises(ValueError, match="channels >= 0"):
        lenslab.spectral_data([550], rgb=(-1, 0, 0))

