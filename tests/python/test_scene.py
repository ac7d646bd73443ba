import json

import pytest

import lenslab
from conftest import cli_error

BAD = "tests/scene/bad/sphere_negative_radius.json"


def test_load_keeps_the_file_as_a_dict():
    scene = lenslab.Scene.load("scenes/default.json")
    with open("scenes/default.json", encoding="utf-8") as f:
        assert scene.to_dict() == json.load(f)
    assert list(scene) == list(scene.to_dict())
    assert scene.path == "scenes/default.json"
    assert scene["camera"] == scene.to_dict()["camera"]


def test_from_dict_round_trips_and_copies():
    d = lenslab.Scene.load("scenes/default.json").to_dict()
    scene = lenslab.Scene.from_dict(d)
    d["camera"]["fov"] = 1.0
    assert scene.to_dict() != d
    assert lenslab.Scene.from_dict(scene.to_dict()).to_dict() == scene.to_dict()


def test_default_is_the_built_in_scene():
    assert lenslab.Scene.default().to_dict() == lenslab.Scene.load("scenes/default.json").to_dict()


def test_a_bad_file_raises_the_cli_message(tmp_path):
    with pytest.raises(lenslab.SceneError) as e:
        lenslab.Scene.load(BAD)
    assert str(e.value) == cli_error("render", BAD, "-o", tmp_path / "x.png")
    assert isinstance(e.value, ValueError)
    assert e.value.path == BAD + ": objects[2].radius"
    assert e.value.reason == "must be > 0, got -1"


def test_a_bad_dict_names_the_json_path():
    with open(BAD, encoding="utf-8") as f:
        d = json.load(f)
    with pytest.raises(lenslab.SceneError, match=r"^objects\[2\]\.radius: must be > 0, got -1$"):
        lenslab.Scene.from_dict(d)


def test_a_file_the_json_parser_refuses_raises_the_cli_message(tmp_path):
    bad = "tests/scene/bad/duplicate_key.json"
    with pytest.raises(lenslab.SceneError) as e:
        lenslab.Scene.load(bad)
    assert str(e.value) == cli_error("render", bad, "-o", tmp_path / "x.png")


def test_a_refused_edit_leaves_the_scene_unchanged():
    scene = lenslab.Scene.default()
    camera = scene.to_dict()["camera"]
    with pytest.raises(lenslab.SceneError, match=r"^camera\.fvo: unknown key \(did you mean 'fov'\?\)"):
        scene["camera"] = {**camera, "fvo": 30}
    assert scene["camera"] == camera
    scene["camera"] = {**camera, "fov": 30}
    assert scene["camera"]["fov"] == 30
    with pytest.raises(lenslab.SceneError, match=r"^camera: missing \(required\)"):
        lenslab.render(lenslab.Scene.from_dict({k: v for k, v in scene.items() if k != "camera"}))


def test_nested_edits_are_checked_by_validate():
    scene = lenslab.Scene.default()
    scene["render"]["spp"] = 0
    with pytest.raises(lenslab.SceneError, match=r"^render\.spp: "):
        scene.validate()


def test_save_writes_a_scene_file_the_cli_reads(tmp_path):
    scene = lenslab.Scene.default()
    scene.save(tmp_path / "copy.json")
    assert lenslab.Scene.load(tmp_path / "copy.json").to_dict() == scene.to_dict()


def test_types_list_the_area_lights_and_a_scene_with_one_renders():
    types = lenslab.types()
    assert types["lights"]["disc_light"] == ["center", "normal", "radius", "power", "color",
                                             "spectrum"]
    assert "size" in types["lights"]["rectangle_light"]
    assert "sphere" in types["objects"]
    assert types["surfaces"]["conic"] == ["radius", "k"]
    assert list(types["surfaces"])[:4] == ["flat", "sphere", "conic", "asphere"]
    scene = lenslab.Scene.from_dict({
        "camera": {"position": [0, 3, 3], "look_at": [0, 0, 0]},
        "objects": [{"type": "rectangle", "center": [0, 0, 0], "normal": [0, 1, 0],
                     "size": [4, 4], "material": {"color": 0.8}}],
        "lights": [{"type": "rectangle_light", "center": [0, 2, 0], "normal": [0, -1, 0],
                    "size": [1, 1], "power": 20}]})
    image = lenslab.render(scene, width=16, height=16, spp=1)
    assert image.mean() > 0.01
