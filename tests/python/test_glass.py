import numpy as np
import pytest

import lenslab
from conftest import cli_error, cli_json


def test_indices_equal_the_cli_over_an_array():
    wavelengths = np.array([404.6561, 486.1327, 587.5618, 656.2725, 1014.0])
    n = lenslab.glass("N-BK7").n(wavelengths)
    assert n.shape == wavelengths.shape and n.dtype == np.float64
    for nm, value in zip(wavelengths, n):
        assert value == cli_json("glass", "N-BK7", "--wavelength", repr(float(nm)), "--json")["n"]


def test_a_number_gives_a_number_and_an_array_keeps_its_shape():
    g = lenslab.glass("n-bk7")  # names ignore case, as on the command line
    assert isinstance(g.n(587.5618), float)
    grid = np.linspace(450.0, 650.0, 6).reshape(2, 3)
    assert g.n(grid).shape == (2, 3)
    assert g.n(grid)[1, 2] == g.n(650.0)
    assert g.n([500, 600]).tolist() == [g.n(500.0), g.n(600.0)]


def test_catalogue_figures_equal_the_cli():
    g = lenslab.glass("HIKARI:SF10")
    expected = cli_json("glass", "HIKARI:SF10", "--json")
    assert (g.name, g.maker, g.n_d, g.V_d) == (expected["name"], expected["maker"],
                                               expected["n_d"], expected["V_d"])


def test_unknown_glass_raises_the_cli_message():
    with pytest.raises(ValueError) as e:
        lenslab.glass("NBK7")
    assert str(e.value) == cli_error("glass", "NBK7")


def test_wavelength_outside_the_data_raises():
    with pytest.raises(ValueError, match="outside N-BK7's validity range"):
        lenslab.glass("N-BK7").n(np.array([500.0, 5000.0]))
