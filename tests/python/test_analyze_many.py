import json

import numpy as np
import pytest

import lenslab

SINGLET = "scenes/thick_lens_beam.json"
DOUBLET = "scenes/achromat_doublet.json"


def bendings(count):
    """The singlet of SINGLET bent through `count` shape factors, its power kept (as
    bench/python_sweep.py bends it)."""
    base = json.loads(open(SINGLET, encoding="utf-8").read())
    power = 1 / 50 - 1 / -50
    scenes = []
    for shape in np.linspace(-1.9, 1.9, count):
        c1, c2 = (shape + 1) * power / 2, (shape - 1) * power / 2
        scene = json.loads(json.dumps(base))
        lens = scene["objects"][0]
        lens["front"] = {"shape": "sphere", "radius": 1 / c1} if c1 else {"shape": "flat"}
        lens["back"] = {"shape": "sphere", "radius": 1 / c2} if c2 else {"shape": "flat"}
        scenes.append(scene)
    return scenes


def broken(scene):
    scene = json.loads(json.dumps(scene))
    scene["objects"][0]["thickness"] = -1
    return scene


@pytest.mark.parametrize("threads", [1, 2, None])
def test_a_batch_equals_one_call_each(threads):
    scenes = bendings(7) + [DOUBLET, lenslab.Scene.load(DOUBLET)]
    options = dict(f_number=8, spots=True, rings=3, fans=True, fan_points=5)
    alone = [lenslab.analyze(s, **options) for s in scenes]
    batch = lenslab.analyze_many(scenes, threads=threads, **options)
    assert all(isinstance(a, lenslab.Analysis) for a in batch)
    assert batch == alone
    assert [dict(a) for a in batch] == [dict(a) for a in alone]  # the keys' order too
    # The JSON text itself: bit for bit, -0.0 included.
    assert [a._run.document() for a in batch] == [a._run.document() for a in alone]
    assert batch[-2]["scene"] == DOUBLET
    for many, one in zip(batch, alone):
        assert many.spot_points.keys() == one.spot_points.keys()
        for key, xy in one.spot_points.items():
            assert np.array_equal(many.spot_points[key], xy)
        assert many.figure("spots") == one.figure("spots")


def test_report_keys_in_a_batch():
    scenes = bendings(5)
    keys = ["efl", "rms_spot_best"]
    batch = lenslab.analyze_many(scenes, threads=2, f_number=8, report=keys)
    assert batch == [lenslab.analyze(s, f_number=8, report=keys) for s in scenes]
    assert list(batch[0]) == keys


def test_an_empty_list_gives_an_empty_list():
    assert lenslab.analyze_many([]) == []
    assert lenslab.analyze_many(iter(()), threads=2, spots=True) == []


def test_a_broken_scene_names_its_index_and_json_path():
    scenes = bendings(6)
    scenes[3] = broken(scenes[3])
    with pytest.raises(lenslab.SceneError) as e:
        lenslab.analyze_many(scenes, threads=2)
    with pytest.raises(lenslab.SceneError) as alone:
        lenslab.analyze(scenes[3])
    assert str(e.value) == "scenes[3]: " + str(alone.value)
    assert e.value.path == "objects[0].thickness" == alone.value.path
    assert e.value.reason == alone.value.reason
    assert e.value.index == 3


@pytest.mark.parametrize("threads", [1, 2])
def test_the_first_broken_scene_in_the_list_raises(threads):
    scenes = bendings(8)
    for i in (2, 5, 7):
        scenes[i] = broken(scenes[i])
    for _ in range(5):  # whatever the workers' timing
        with pytest.raises(lenslab.SceneError, match=r"^scenes\[2\]: objects\[0\]\.thickness"):
            lenslab.analyze_many(scenes, threads=threads)


def test_a_missing_file_names_its_index():
    with pytest.raises(lenslab.SceneError, match=r"^scenes\[1\]: .*no_such_scene\.json"):
        lenslab.analyze_many([SINGLET, "scenes/no_such_scene.json"])


def test_something_not_a_scene_names_its_index():
    with pytest.raises(TypeError, match=r"^scenes\[2\]: expected a lenslab.Scene, a dict or a "):
        lenslab.analyze_many([SINGLET, DOUBLET, 42])


def test_a_scene_the_bench_cannot_measure_names_its_index():
    with pytest.raises(lenslab.SceneError) as e:
        lenslab.analyze_many([DOUBLET, "scenes/prism.json"])
    assert e.value.path == "scenes/prism.json: objects"
    assert str(e.value).startswith("scenes[1]: scenes/prism.json: objects")


def test_an_option_a_scene_does_not_fit_names_its_index():
    with pytest.raises(ValueError, match=r"^scenes\[1\]: stop 3: the system has 2 surfaces"):
        lenslab.analyze_many([DOUBLET, SINGLET], stop=3)
    with pytest.raises(ValueError, match=r"^scenes\[0\]: report: no key 'nope'"):
        lenslab.analyze_many([SINGLET, DOUBLET], report=["nope"])


@pytest.mark.parametrize("options, error, message", [
    (dict(rings=0), ValueError, r"^rings: must be from 1 to 200, got 0$"),
    (dict(epd=5, f_number=8), ValueError, r"^f_number excludes epd"),
    (dict(threads=0), ValueError, r"^threads: must be a whole number from 1 to 1024, got 0$"),
    (dict(spot=True), TypeError, r"^analyze_many\(\) got an unexpected keyword argument 'spot'$"),
])
def test_a_bad_option_raises_before_any_scene_is_read(options, error, message):
    read = []

    def scenes():
        read.append(True)
        yield SINGLET

    with pytest.raises(error, match=message):
        lenslab.analyze_many(scenes(), **options)
    assert not read
    with pytest.raises(error, match=message):
        lenslab.analyze_many([], **options)


def test_progress_reaches_one_and_its_exception_stops_the_batch():
    fractions = []
    lenslab.analyze_many(bendings(4), threads=2, progress=fractions.append)
    assert fractions and fractions[-1] == 1.0 and fractions == sorted(fractions)

    def stop(fraction):
        raise RuntimeError("stop")

    with pytest.raises(RuntimeError, match="^stop$"):
        lenslab.analyze_many(bendings(50), progress=stop)
