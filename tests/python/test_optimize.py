"""lenslab.optimize and lenslab.tolerance against `lenslab optimize` and `lenslab tolerance`."""

import json

import pytest

import lenslab
from conftest import cli_json

COOKE = "examples/optimize/cooke.design.json"
TRIPLET_TOLERANCE = "examples/optimize/triplet.tolerance.json"


def test_optimize_is_the_command_lines(tmp_path):
    out = tmp_path / "cooke.json"
    expected = cli_json("optimize", COOKE, "-o", out, "--iterations", 3, "--global-starts", 3,
                        "--json", "-q")
    fractions = []
    got = lenslab.optimize(COOKE, iterations=3, global_starts=3, progress=fractions.append)
    scene = got.pop("scene")
    for key in ("design", "output"):
        expected.pop(key)
    assert got == expected
    assert isinstance(scene, lenslab.Scene)
    assert scene.to_dict() == json.loads(out.read_text())
    assert fractions and fractions == sorted(fractions) and fractions[-1] <= 1.0


def test_a_design_written_as_a_dict():
    with open(COOKE, encoding="utf-8") as f:
        design = json.load(f)
    design["system"] = lenslab.Scene.load("examples/optimize/cooke_start.json")
    design.pop("global_search")
    design["iterations"] = 2
    got = lenslab.optimize(design)
    assert got["iterations"] == 2
    assert got["after"]["merit"] < got["before"]["merit"]
    assert [v["variable"] for v in got["variables"]][:2] == ["curvature L1.front",
                                                             "curvature L1.back"]


def test_configurations_come_back_as_scenes(tmp_path):
    out = tmp_path / "zoom.json"
    cli_json("optimize", "examples/optimize/zoom.design.json", "-o", out, "--iterations", 2,
             "--json", "-q")
    got = lenslab.optimize("examples/optimize/zoom.design.json", iterations=2)
    assert [c["name"] for c in got["after"]["configurations"]] == ["wide", "mid", "tele"]
    assert sorted(got["configuration_scenes"]) == ["mid", "tele"]
    assert got["scene"].to_dict() == json.loads(out.read_text())
    tele = got["configuration_scenes"]["tele"]
    assert tele.to_dict() == json.loads((tmp_path / "zoom.tele.json").read_text())


def test_a_bad_design_names_where():
    with open(COOKE, encoding="utf-8") as f:
        design = json.load(f)
    design["variables"] = [{"type": "n_d", "lens": "L1"}]  # L1 is of a catalogue glass
    with pytest.raises(lenslab.SceneError) as e:
        lenslab.optimize(design, base_dir="examples/optimize")
    assert e.value.path == "variables[0].lens"
    assert "\"model\": \"abbe\"" in e.value.reason


def test_tolerance_is_the_command_lines():
    expected = cli_json("tolerance", TRIPLET_TOLERANCE, "--trials", 20, "--seed", 3, "--json",
                        "-q")
    expected.pop("design")
    assert lenslab.tolerance(TRIPLET_TOLERANCE, trials=20, seed=3) == expected
    with pytest.raises(ValueError, match="trials must be at least 1"):
        lenslab.tolerance(TRIPLET_TOLERANCE, trials=0)


def test_the_stub_has_the_signatures():
    import ast
    import inspect
    import pathlib
    stub = pathlib.Path(lenslab.__file__).with_suffix(".pyi")
    stubbed = {node.name: [a.arg for a in node.args.kwonlyargs]
               for node in ast.parse(stub.read_text()).body if isinstance(node, ast.FunctionDef)}
    for function in (lenslab.optimize, lenslab.tolerance):
        keywords = [name for name, p in inspect.signature(function).parameters.items()
                    if p.kind == p.KEYWORD_ONLY]
        assert stubbed[function.__name__] == keywords
