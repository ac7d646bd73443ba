import numpy as np
import pytest

import lenslab
from conftest import cli_error, cli_json, run_cli

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


def test_a_lens_file_with_mirrors_is_analysed_as_the_cli_does():
    telescope = "scenes/ritchey_chretien.zmx"
    expected = cli_json("analyze", telescope, "--json", "--spots")
    report = lenslab.analyze(telescope, spots=True)
    assert report == expected
    # F = 2000 from the textbook formulas the file's mirrors were typed from.
    assert report["efl"] == pytest.approx(2000, rel=1e-9)
    assert report["bfl"] == pytest.approx(700, rel=1e-9)
    assert report["surfaces"][0]["mirror"] is True
    assert report["surfaces"][0]["n_after"] == -1


def test_wavefronts_equal_the_cli_and_come_as_arrays():
    expected = cli_json("analyze", SCENE, "--json", "--fields", "0,2.5", "--wavelengths",
                        "486.1327,656.2725", "--wavefront", "--zernike-terms", "15",
                        "--wavefront-samples", "32")
    report = lenslab.analyze(SCENE, fields=[0, 2.5], wavelengths=[486.1327, 656.2725],
                             wavefront=True, zernike_terms=15, wavefront_samples=32)
    assert report == expected
    block = report["wavefront"]
    assert [(f["field"], f["wavelength_nm"]) for f in block["fields"]] == [
        (0, 486.1327), (0, 656.2725), (2.5, 486.1327), (2.5, 656.2725)]
    assert all(len(f["zernike_noll"]) == 15 for f in block["fields"])
    maps = report.opd_maps
    assert list(maps) == [(f["field"], f["wavelength_nm"]) for f in block["fields"]]
    opd = maps[(2.5, 486.1327)]
    assert opd.shape == (32, 32)
    assert np.isnan(opd[0, 0])  # a corner lies outside the pupil
    inside = opd[~np.isnan(opd)]
    assert inside.size == block["fields"][2]["rays_passed"]
    assert inside.std() == pytest.approx(block["fields"][2]["rms_waves"], rel=1e-9)
    assert lenslab.analyze(SCENE).opd_maps == {}
    fans = lenslab.analyze(SCENE, fields=[0, 2.5], opd_fans=True, fan_points=5)
    assert fans == cli_json("analyze", SCENE, "--json", "--fields", "0,2.5", "--opd-fans",
                            "--fan-points", "5")
    assert fans["opd_fans"]["unit"] == "waves"
    assert fans.figure("opd_fans").startswith("<svg")


def test_psfs_at_every_field_equal_the_cli_and_come_as_arrays():
    expected = cli_json("analyze", SCENE, "--json", "--fields", "0,2.5", "--wavelengths",
                        "486.1327,587.5618,656.2725", "--psf")
    report = lenslab.analyze(SCENE, fields=[0, 2.5], wavelengths=[486.1327, 587.5618, 656.2725],
                             psf=True)
    assert report == expected
    fields = report["psf"]["fields"]
    images = report.psf_images
    assert list(images) == [0, 2.5]
    for f in fields:
        image = images[f["field"]]
        assert image.shape == (f["grid"]["size"], f["grid"]["size"])
        assert image.shape[0] % 2 == 1
        assert image.max() == f["strehl"]
        assert len(f["strehl_per_wavelength"]) == 3
        assert 0 < f["encircled_energy"]["fraction"][0] <= f["encircled_energy"]["fraction"][-1] <= 1
    assert lenslab.analyze(SCENE).psf_images == {}


def test_options_equal_the_cli():
    expected = cli_json("analyze", SCENE, "--json", "--wavelength", "550", "--stop", "2",
                        "--f-number", "8", "--fields", "0,2.5")
    report = lenslab.analyze(lenslab.Scene.load(SCENE), wavelength=550, stop=2, f_number=8,
                             fields=[0, 2.5])
    assert report == expected


def test_ray_aiming_equals_the_cli():
    expected = cli_json("analyze", SCENE, "--json", "--fields", "0,3", "--spots",
                        "--ray-aiming", "paraxial")
    report = lenslab.analyze(SCENE, fields=[0, 3], spots=True, ray_aiming="paraxial")
    assert report == expected
    assert report["first_order"]["ray_aiming"] == "paraxial"
    assert report["spots"] != lenslab.analyze(SCENE, fields=[0, 3], spots=True)["spots"]
    with pytest.raises(ValueError, match=r"^ray_aiming: must be 'real' or 'paraxial'"):
        lenslab.analyze(SCENE, ray_aiming="off")


def test_bad_stop_raises():
    with pytest.raises(ValueError, match=r"^stop 9: the system has 3 surfaces, numbered 1 to 3$"):
        lenslab.analyze(SCENE, stop=9)


def test_a_scene_without_lenses_raises_the_cli_message():
    with pytest.raises(lenslab.SceneError) as e:
        lenslab.analyze("scenes/prism.json")
    assert str(e.value) == cli_error("analyze", "scenes/prism.json")
    assert e.value.path == "scenes/prism.json: objects"


def test_unknown_lens_raises_the_cli_message():
    message = cli_error("analyze", SCENE, "--lens", "nope")
    assert message.startswith("--lens: no lens named 'nope' in " + SCENE)
    with pytest.raises(ValueError) as e:
        lenslab.analyze(SCENE, lens="nope")
    assert str(e.value) == message[2:]  # "lens: ...": the option as Python names it
    with pytest.raises(ValueError, match=r"^lens: no lens named 'nope' in the scene \(lenses: "):
        lenslab.analyze(lenslab.Scene.load(SCENE).to_dict(), lens="nope")


# Option sets of the command line and the same as Python arguments.
OPTION_SETS = [
    (["--wavelengths", "486.1327,587.5618,656.2725", "--spots", "--rings", "3", "--fans",
      "--fan-points", "5", "--fields", "0,1.5", "--f-number", "10"],
     dict(wavelengths=[486.1327, 587.5618, 656.2725], spots=True, rings=3, fans=True,
          fan_points=5, fields=[0, 1.5], f_number=10)),
    (["--object-distance", "400", "--field-heights", "0,3", "--field-curves",
      "--field-curve-points", "3", "--focal-shift", "--band", "450,700",
      "--focal-shift-points", "5", "--stop", "2", "--epd", "12"],
     dict(object_distance=400, field_heights=[0, 3], field_curves=True, field_curve_points=3,
          focal_shift=True, band=[450, 700], focal_shift_points=5, stop=2, epd=12)),
    (["--psf", "--mtf", "--mtf-frequencies", "10,20,40", "--wavelength", "550"],
     dict(psf=True, mtf=True, mtf_frequencies=[10, 20, 40], wavelength=550)),
    (["--fields", "0,2", "--field-map", "3", "--rings", "2"],
     dict(fields=[0, 2], field_map=3, rings=2)),
    (["--aperture", "10", "--unit", "mm", "--spots", "--rings", "2", "--image-distance", "95",
      "--wavelengths", "486.1327,587.5618,656.2725", "--wavelength-weights", "1,2,1",
      "--seidel", "--lens", "crown"],
     dict(aperture=10, unit="mm", spots=True, rings=2, image_distance=95,
          wavelengths=np.array([486.1327, 587.5618, 656.2725]), wavelength_weights=[1, 2, 1],
          seidel=True, lens="crown")),
]


@pytest.mark.parametrize("cli_options, options", OPTION_SETS)
def test_every_option_equals_the_cli(cli_options, options):
    expected = cli_json("analyze", SCENE, "--json", *cli_options)
    analysis = lenslab.analyze(SCENE, **options)
    assert isinstance(analysis, lenslab.Analysis)
    assert dict(analysis) == expected
    assert analysis == expected


def test_a_dict_scene_has_no_scene_key():
    expected = cli_json("analyze", SCENE, "--json", "--spots")
    expected.pop("scene")
    assert lenslab.analyze(lenslab.Scene.load(SCENE).to_dict(), spots=True) == expected


def test_report_keys_choose_the_document():
    full = cli_json("analyze", SCENE, "--json", "--f-number", "8")
    part = lenslab.analyze(SCENE, f_number=8, report=["rms_spot_best", "efl"])
    assert list(part) == [k for k in full if k in ("efl", "rms_spot_best")]
    assert part["efl"] == full["efl"] and part["rms_spot_best"] == full["rms_spot_best"]
    with pytest.raises(ValueError, match=r"^report: no key 'nope' in this analysis \(keys: "):
        lenslab.analyze(SCENE, report=["nope"])
    with pytest.raises(ValueError, match="report: must be a list"):
        lenslab.analyze(SCENE, report="efl")


def test_spot_points_are_the_spot_diagrams_hits():
    analysis = lenslab.analyze(SCENE, spots=True, rings=4, fields=[0, 2],
                               wavelengths=[486.1327, 587.5618, 656.2725])
    per_wavelength = analysis["spots"]["per_wavelength"]
    points = analysis.spot_points
    assert list(points) == [(s["field"], s["wavelength"]) for s in per_wavelength]
    for s in per_wavelength:
        xy = points[(s["field"], s["wavelength"])]
        assert xy.shape == (s["rays"] - s["vignetted"], 2) and xy.dtype == np.float64
        centroid = [s["centroid"]["x"], s["centroid"]["y"]]
        assert xy.mean(axis=0) == pytest.approx(centroid, abs=1e-12)
        rms = np.sqrt(np.mean(np.sum((xy - xy.mean(axis=0)) ** 2, axis=1)))
        assert rms == pytest.approx(s["rms_radius"], rel=1e-9)
    assert lenslab.analyze(SCENE).spot_points == {}


@pytest.mark.parametrize("name, cli_option, options", [
    ("ray_diagram", "--svg", dict(unit="mm")),
    ("spots", "--spots-svg", dict(spots=True, unit="mm")),
    ("fans", "--fans-svg", dict(fans=True)),
    ("field_curves", "--curves-svg", dict(field_curves=True, fields=[0, 2])),
    ("focal_shift", "--focal-shift-svg", dict(focal_shift=True)),
    ("mtf", "--mtf-svg", dict(mtf=True)),
])
def test_figures_are_the_cli_files(tmp_path, name, cli_option, options):
    out = tmp_path / f"{name}.svg"
    cli_options = ["--unit", "mm"] if "unit" in options else []
    cli_options += ["--fields", "0,2"] if "fields" in options else []
    run_cli("analyze", SCENE, cli_option, out, *cli_options)
    svg = lenslab.analyze(SCENE, **options).figure(name)
    assert svg.startswith("<svg") and svg == out.read_text()


def test_a_figure_not_asked_for_raises():
    with pytest.raises(ValueError, match=r"^figure 'spots': it needs spots, which was not "):
        lenslab.analyze(SCENE).figure("spots")
    with pytest.raises(ValueError, match=r"^figure 'nope': unknown \(known: ray_diagram, "):
        lenslab.analyze(SCENE).figure("nope")


@pytest.mark.parametrize("options, message", [
    (dict(rings=0), r"^rings: must be from 1 to 200, got 0$"),
    (dict(rings=2.5), r"^rings: must be a whole number, got 2.5$"),
    (dict(fan_points=1), r"^fan_points: must be from 2 to 10001"),
    (dict(wavelength=-5), r"^wavelength: must be a positive number, got -5.0$"),
    (dict(wavelengths=[500, 0]), r"^wavelengths: must be a positive number, got 0.0$"),
    (dict(wavelength=550, wavelengths=[500, 600]), r"^wavelengths excludes wavelength"),
    (dict(epd=5, f_number=8), r"^f_number excludes epd"),
    (dict(aperture=5, epd=8), r"^epd excludes aperture"),
    (dict(fields=[0, 1], object_distance=100), r"^fields excludes object_distance"),
    (dict(field_heights=[0, 1]), r"^field_heights needs object_distance"),
    (dict(fields="0,1"), r"^fields: must be a sequence of numbers"),
    (dict(image_distance=90), r"^image_distance: it places the image plane of spots, fans, "
                              r"opd_fans, field_map, field_curves, wavefront and mtf, none of "
                              r"which was asked for$"),
    (dict(mtf_frequencies=[10]), r"^mtf_frequencies requires mtf \(or mtf_svg\)$"),
    (dict(zernike_terms=11), r"^zernike_terms needs wavefront \(the terms of the wavefront's fit\)$"),
    (dict(through_focus_points=5), r"^through_focus_points needs through_focus "),
    (dict(focal_shift=True, band=[700, 450]), r"^band: two wavelengths in nm, the shorter "),
    (dict(wavelength_weights=[1, 2]), r"^wavelength_weights: 2 weights for 1 wavelengths"),
    (dict(aperture=1000), r"^aperture: a beam of diameter 1000 does not pass the lenses"),
    (dict(fields=[95]), r"^fields: 95 degrees is not a field angle"),
])
def test_bad_options_raise_value_error(options, message):
    with pytest.raises(ValueError, match=message):
        lenslab.analyze(SCENE, **options)


def test_a_bad_scene_raises_with_the_json_path():
    scene = lenslab.Scene.load(SCENE).to_dict()
    scene["objects"][0]["thickness"] = -1
    with pytest.raises(lenslab.SceneError) as e:
        lenslab.analyze(scene)
    assert e.value.path == "objects[0].thickness"


def test_calls_on_threads_give_the_same_documents():
    # The GIL is released while the bench computes, so a thread pool runs calls side by side.
    from concurrent.futures import ThreadPoolExecutor
    stops = [1, 2, 3] * 4
    alone = [lenslab.analyze(SCENE, stop=s, spots=True) for s in stops]
    with ThreadPoolExecutor(4) as pool:
        pooled = list(pool.map(lambda s: lenslab.analyze(SCENE, stop=s, spots=True), stops))
    assert pooled == alone


def test_a_lens_file_is_measured_as_its_file_says():
    # AC254-100-A.zmx: F, d and C, a 25.4 mm entrance pupil; the CLI takes the same.
    imported = "scenes/imported_achromat.json"
    report = lenslab.analyze(imported)
    assert report == cli_json("analyze", imported, "--json")
    assert report["lens_file_bench"]["taken"] == ["wavelengths", "fields", "epd", "stop",
                                                  "ray_aiming"]
    assert report["first_order"]["entrance_pupil"]["diameter"] == 25.4
    # A wavelength asked for wins over the file's.
    assert "wavelengths" not in lenslab.analyze(imported, wavelength=550)["lens_file_bench"]["taken"]


# What each kind of declared value is annotated as, in the signature and the stub.
_ANNOTATIONS = {"flag": "bool", "number": "Optional[float]", "positive_number": "Optional[float]",
                "numbers": "Optional[Sequence[float]]",
                "positive_numbers": "Optional[Sequence[float]]", "text": "Optional[str]",
                "texts": "Optional[Sequence[str]]", "choice": "Optional[str]"}


def _annotation(option):
    if option["value"] == "whole":
        return "int" if option["default"] is not None else "Optional[int]"
    return _ANNOTATIONS[option["value"]]


def _stub_keywords(function):
    import ast
    import pathlib
    stub = pathlib.Path(lenslab.__file__).with_suffix(".pyi")
    for node in ast.parse(stub.read_text()).body:
        if isinstance(node, ast.FunctionDef) and node.name == function:
            return {a.arg: ast.unparse(a.annotation) for a in node.args.kwonlyargs}
    raise AssertionError(f"{function} not in {stub}")


def test_the_signature_and_the_stub_follow_the_declared_options():
    import inspect
    declared = lenslab.analyze_options()
    assert [o["name"] for o in declared][:3] == ["wavelength", "wavelengths", "aperture"]
    expected = {o["name"]: _annotation(o) for o in declared}
    parameters = inspect.signature(lenslab.analyze).parameters
    signature = {name: p.annotation for name, p in parameters.items() if name != "scene_or_file"}
    assert signature == expected
    defaults = {name: p.default for name, p in parameters.items() if name != "scene_or_file"}
    assert defaults == {o["name"]: o["default"] for o in declared}
    assert _stub_keywords("analyze") == expected
    many = _stub_keywords("analyze_many")
    assert {k: v for k, v in many.items() if k not in ("threads", "progress")} == expected


def test_every_declared_option_reaches_the_cli_under_the_same_name():
    help_text = run_cli("analyze", "--help").stdout
    for option in lenslab.analyze_options():
        if option["name"] != "report":  # Python's alone
            assert option["option"] + " " in help_text or option["option"] + "," in help_text \
                or option["option"] + "\n" in help_text, option["option"]
