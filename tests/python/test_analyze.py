import pytest

import lenslab
from conftest import cli_error, cli_json

SCENE = "scenes/achromat_doublet.json"


def test_report_equals_the_cli():
    expected = cli_json("analyze", SCENE, "--json")
    report = lenslab.analyze(SCENE)
    for key in ("efl", "bfl", "ffl", "first_order"):
        assert report[key] == expected[key]
    assert report == expected
    first = report["first_order"]
    assert {"efl", "bfl", "f_number", "entrance_pupil", "exit_pupil",
            "lagrange_invariant"} <= set(first)
    assert set(first["entrance_pupil"]) >= {"position", "diameter"}


def test_options_equal_the_cli():
    expected = cli_json("analyze", SCENE, "--json", "--wavelength", "550", "--stop", "2",
                        "--f-number", "8", "--fields", "0,2.5")
    report = lenslab.analyze(lenslab.Scene.load(SCENE), wavelength=550, stop=2, f_number=8,
                             fields=[0, 2.5])
    assert report == expected


def test_bad_stop_raises():
    with pytest.raises(ValueError, match=r"^stop 9: the system has 3 surfaces, numbered 1 to 3$"):
        lenslab.analyze(SCENE, stop=9)


def test_a_scene_without_lenses_raises_the_cli_message():
    with pytest.raises(lenslab.SceneError) as e:
        lenslab.analyze("scenes/prism.json")
    assert str(e.value) == cli_error("analyze", "scenes/prism.json")
    assert e.value.path == "scenes/prism.json: objects"


def test_unknown_lens_raises():
    with pytest.raises(ValueError, match=r"^lens: no lens named 'nope' in the scene \(lenses: "):
        lenslab.analyze(SCENE, lens="nope")
