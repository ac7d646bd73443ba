import pytest

import lenslab
from conftest import cli_json

SCENE = "scenes/thick_lens_beam.json"


def test_tree_equals_the_cli():
    origin, direction = (0.3, 0.2, -5.0), (0.0, 0.0, 1.0)
    expected = cli_json("trace", SCENE, "--origin", "0.3,0.2,-5", "--direction", "0,0,1",
                        "--wavelength", "500")
    assert lenslab.trace(SCENE, origin, direction, wavelength=500) == expected
    scene = lenslab.Scene.load(SCENE)
    assert lenslab.trace(scene, origin, direction, wavelength=500) == expected


def test_zero_direction_raises():
    with pytest.raises(ValueError, match="direction: must be a non-zero vector"):
        lenslab.trace(SCENE, (0, 0, 0), (0, 0, 0))
