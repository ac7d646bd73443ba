// Every malformed scene in tests/scene/bad must be refused with one SceneError that names
// the JSON path of the problem and says why. The table below is the specification: each file
// has exactly one expectation, and a file without one fails the coverage test.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "scene/json_reader.h"
#include "scene/scene_json.h"

namespace {

namespace fs = std::filesystem;

struct BadScene {
    const char* file;    // in tests/scene/bad
    const char* path;    // JSON path the error must name ("" for a JSON syntax error)
    const char* reason;  // text the reason must contain
};

// clang-format off
const BadScene kBadScenes[] = {
    // JSON syntax: the reason gives line and column; the path is the file alone.
    {"syntax_trailing_comma.json", "",
     "invalid JSON: parse error at line 5, column 3"},
    {"number_overflow.json", "", "invalid JSON: number overflow parsing '1e400'"},
    {"duplicate_key.json", "objects[1].radius", "key given twice in the same object"},
    {"top_level_array.json", "", "the top level must be a JSON object"},
    // Top level.
    {"missing_camera.json", "camera", "missing (required)"},
    {"top_level_typo.json", "object", "unknown key (did you mean 'objects'?)"},
    {"unsupported_version.json", "version", "this lenslab reads version 1 scene files"},
    {"objects_not_array.json", "objects", "must be an array"},
    // Camera.
    {"fov_out_of_range.json", "camera.fov",
     "must be between 0 and 180 degrees (exclusive), got 180"},
    {"camera_look_at_and_direction.json", "camera.direction",
     "give either look_at or direction, not both"},
    {"camera_no_direction.json", "camera", "give look_at (a point) or direction (a vector)"},
    {"camera_up_parallel.json", "camera.up", "must not be parallel to the view direction"},
    // Render block.
    {"min_weight_zero.json", "render.min_weight", "must be at least 1e-06"},
    {"render_width_fraction.json", "render.width", "must be a whole number, got 320.5"},
    {"render_unknown_integrator.json", "render.integrator",
     "unknown integrator 'bdpt' (known: whitted, photon_map, sppm, path)"},
    {"render_passes_zero_without_time.json", "render.passes",
     "0 means no pass limit, which needs a time budget: give render.time > 0"},
    {"render_alpha_one.json", "render.alpha", "must be between 0 and 1 (exclusive), got 1"},
    {"render_time_negative.json", "render.time", "must be >= 0 seconds (0: no time limit), got -5"},
    {"render_pass_photons_negative.json", "render.pass_photons", "must be between 0 and 1073741824, got -5"},
    {"render_caustic_photons_negative.json", "render.caustic_photons", "must be between 0 and 1099511627776, got -5"},
    {"render_aim_photons_number.json", "render.aim_photons", "must be true or false, got a number"},
    {"photon_target_not_boolean.json", "objects[0].photon_target", "must be true or false, got a string"},
    {"render_initial_radius_negative.json", "render.initial_radius", "must be > 0, got -0.01"},
    // Materials.
    {"unknown_material_name.json", "objects[0].material",
     "unknown material 'glas' (not in materials; did you mean 'glass'?)"},
    // Glass names (issue 17): the closest catalogue names, or the makers to choose between.
    {"glass_unknown_name.json", "materials.crown.glass",
     "unknown glass 'NBK7'; did you mean N-BK7 (SCHOTT)?"},
    {"glass_shared_name.json", "objects[0].material.glass",
     "glass 'SF10' is in several catalogues; name one of SCHOTT:SF10, HIKARI:SF10"},
    {"transparency_plus_specular.json", "materials.half_mirror.specular",
     "transparency + specular must be at most 1, got 1.2"},
    {"color_negative.json", "objects[0].material.color[1]", "must be >= 0, got -0.1"},
    // Gradient index.
    {"grin_luneburg_no_radius.json", "objects[0].material.grin.radius",
     "missing (required by the luneburg profile: its sphere's radius R)"},
    {"grin_unknown_profile.json", "objects[0].material.grin.profile", "unknown"},
    {"grin_formula_syntax.json", "objects[0].material.grin.formula", "cannot parse at position"},
    {"grin_open_surface.json", "objects[0].material",
     "a GRIN material fills a solid: this object is an open surface"},
    {"grin_not_transparent.json", "objects[0].material.grin",
     "a GRIN index needs a transparent material (transparency > 0)"},
    {"grin_radial_negative_index.json", "objects[0].material",
     "its GRIN index: the index is -4.5 at (x, y, z) = (-1, -1, -1) from its centre, in the object: it must be a number > 0 there"},
    // A shape's medium.
    {"medium_open_mesh.json", "objects[0].medium",
     "a medium fills a solid: this mesh is an open surface"},
    {"albedo_above_one.json", "materials.glowing_paint.color[1]",
     "must be <= 1 (a surface cannot reflect more than it receives), got 1.5"},
    {"emission_negative_intensity.json", "materials.lamp.emission.intensity",
     "must be >= 0, got -5"},
    {"ior_zero.json", "materials.weird.ior", "must be > 0, got 0"},
    // Spheres and keys.
    {"number_too_large.json", "objects[0].radius", "must be between -1e15 and 1e15, got 1e+155"},
    {"material_number.json", "objects[0].material",
     "must be a material name or a material object { ... }"},
    {"sphere_missing_radius.json", "objects[0].radius", "missing (required)"},
    {"sphere_negative_radius.json", "objects[2].radius", "must be > 0, got -1"},
    {"unknown_key_typo.json", "objects[0].radiu", "unknown key (did you mean 'radius'?)"},
    {"wrong_type_string.json", "objects[0].radius", "must be a number, got a string"},
    {"unknown_object_type.json", "objects[0].type",
     "unknown object type 'cube' (known: sphere, triangle, disc, rectangle, lens, lens_group, mesh, prism, implicit, box, mirror, lens_file)"},
    {"sphere_with_lens_key.json", "objects[0].axis", "not a property of a sphere"},
    // Triangles.
    {"triangle_collinear.json", "objects[0].vertices",
     "the three vertices are collinear (zero area)"},
    {"triangle_two_vertices.json", "objects[0].vertices", "must be an array of 3 points"},
    {"triangle_emission.json", "objects[0].material",
     "only spheres can emit light (the material has an emission)"},
    // Discs, rectangles and detectors.
    {"disc_zero_radius.json", "objects[0].radius", "must be > 0, got 0"},
    {"disc_missing_normal.json", "objects[0].normal", "missing (required)"},
    {"disc_up_parallel.json", "objects[0].up", "must not be parallel to normal"},
    {"rectangle_size_one_number.json", "objects[0].size", "must be [width, height]"},
    {"rectangle_negative_height.json", "objects[0].size[1]", "must be > 0, got -2"},
    {"rectangle_with_radius.json", "objects[0].radius", "not a property of a rectangle"},
    {"detector_on_sphere.json", "objects[0].detector",
     "only a triangle, disc or rectangle can be a detector (this is a sphere)"},
    {"detector_not_object.json", "objects[0].detector",
     "must be true, false or an object {\"resolution\": ..., \"bands\": ...}"},
    {"detector_resolution_zero.json", "objects[0].detector.resolution",
     "must be a whole number of cells from 1 to 1024, got 0"},
    {"detector_resolution_three.json", "objects[0].detector.resolution",
     "must be a number of cells or [cells along u, cells along v]"},
    {"detector_bands_not_increasing.json", "objects[0].detector.bands[2]",
     "band edges must increase, got 500 after 600"},
    {"detector_bands_out_of_range.json", "objects[0].detector.bands[0]",
     "300 nm: outside 360 to 830 nm, the range of the CIE tables"},
    {"detector_bands_too_many.json", "objects[0].detector.bands",
     "must be a whole number of bands from 1 to 16 (or an array of band edges in nm), got 17"},
    {"detector_unknown_key.json", "objects[0].detector.resolutoin", "unknown key (did you mean 'resolution'?)"},
    // Issue 15: cells whose area (or its reciprocal) is not an ordinary number.
    {"detector_disc_underflow.json", "objects[0].radius",
     "too small for a detector: its cells would be 3.125e-162 across, and each must be at "
     "least 1e-100"},
    {"detector_rectangle_underflow.json", "objects[0].size",
     "too small for a detector: its cells would be 1.25e-161 across"},
    {"detector_side_unknown.json", "objects[0].detector.side", "unknown side 'top' (known: front, back, both)"},
    {"detector_unit_not_letters.json", "objects[0].detector.unit",
     "must be the name of a length unit in 1 to 16 letters (e.g. \"mm\"), got 'm m'"},
    // Lenses.
    {"lens_zero_axis.json", "objects[0].axis", "must be a non-zero vector"},
    {"lens_surfaces_cross.json", "objects[0].thickness",
     "the lens surfaces cross inside the diameter: at 5 from the axis the back surface lies "
     "2.179491924 in front of the front surface; the centre thickness must be at least "
     "2.679491924 for diameter 10"},
    {"lens_no_form.json", "objects[0]",
     "a lens needs either curvature_radius and aperture_radius (the report's form) or "
     "thickness, diameter, front and back (a prescription)"},
    {"lens_diameter_exceeds_2r.json", "objects[0].front",
     "a sphere R=10 surface cannot span the lens diameter 30 (its largest diameter is 20)"},
    {"report_lens_aperture_too_big.json", "objects[0].aperture_radius",
     "two spheres of radius 0.9 cannot meet in a circle of radius 1.2 "
     "(must be <= curvature_radius)"},
    {"lens_mixed_forms.json", "objects[0].thickness",
     "belongs to the prescription form; the report form (curvature_radius, aperture_radius) "
     "cannot take it"},
    {"surface_flat_with_radius.json", "objects[0].back.radius", "a flat surface has no radius"},
    {"surface_zero_radius.json", "objects[0].front.radius",
     "must not be 0 (use {\"shape\": \"flat\"} for a plane)"},
    {"surface_unknown_shape.json", "objects[0].front.shape",
     "unknown surface shape 'parabola' (known: flat, sphere, conic, asphere, biconic, toroidal, xy_polynomial, zernike, sag)"},
    // Meshes and prisms.
    {"mesh_open_transparent.json", "objects[0].faces",
     "the mesh is not closed: edge (0, 2) belongs to 1 face (face 0): the surface has a hole "
     "there; only a closed mesh can be transparent (an open one would be a set of thin panes, "
     "not a solid)"},
    {"mesh_faces_disagree.json", "objects[0].faces",
     "the mesh is not closed: faces 0 and 1 both run along edge (1, 0) in the same direction"},
    {"mesh_index_out_of_range.json", "objects[0].faces[1][2]",
     "must be a vertex index from 0 to 3 (there are 4 vertices), got 4"},
    {"mesh_face_two_indices.json", "objects[0].faces[2]",
     "a face must be an array of at least 3 vertex indices, got 2 indices"},
    {"mesh_file_and_vertices.json", "objects[0].file",
     "give either vertices and faces (inline) or file (an OBJ file), not both"},
    {"mesh_missing_obj.json", "objects[0].file",
     "cannot read 'missing.obj': No such file or directory"},
    {"mesh_broken_obj.json", "objects[0].file",
     "../data/broken.obj:5: face 1 refers to vertex 0, but OBJ numbers them from 1 (or back "
     "from the last with -1)"},
    // OBJ input the reader before lenslab's own (tinyobjloader) took silently; the line
    // numbers count comments, blank lines and CRLF endings.
    {"mesh_obj_nan_vertex.json", "objects[0].file",
     "../data/obj_nan_vertex.obj:4: vertex coordinate 'nan' is not a finite number"},
    {"mesh_obj_word_coordinates.json", "objects[0].file",
     "../data/obj_word_coordinates.obj:5: vertex coordinate 'abc' is not a number"},
    {"mesh_obj_fractional_index.json", "objects[0].file",
     "../data/obj_fractional_index.obj:6: vertex index '1.7' is not a whole number"},
    {"mesh_obj_index_beyond_int.json", "objects[0].file",
     "../data/obj_index_beyond_int.obj:6: vertex index '99999999999' is beyond the integer range"},
    {"mesh_obj_two_corner_face.json", "objects[0].file",
     "../data/obj_two_corner_face.obj:6: a face needs at least 3 corners, got 2"},
    {"mesh_obj_negative_index.json", "objects[0].file",
     "../data/obj_negative_index.obj:7: face 1 refers to vertex -9, but only 4 vertices are "
     "defined before this line (-1 is the last, -4 the first)"},
    {"mesh_facing_not_perpendicular.json", "objects[0].facing",
     "must be perpendicular to up (the angle between them is 45 degrees)"},
    {"prism_apex_angle_180.json", "objects[0].apex_angle",
     "must be between 0 and 180 degrees (exclusive), got 180"},
    {"prism_default_facing_along_axis.json", "objects[0].facing",
     "the default facing [0, 0, 1] is not perpendicular to axis; give facing"},
    {"prism_with_mesh_key.json", "objects[0].vertices", "not a property of a prism"},
    // Found by fuzz_scene (tests/fuzz/regressions/scene/crash-546b...): the prism's faces
    // collapsed, and the open-mesh check asked for a key a prism does not have.
    {"prism_collapses.json", "objects[0]",
     "side 1 and height 1.1e-307 are too small to build a closed prism at this position (its faces collapse)"},
    // Equation-defined surfaces (issue 6).
    {"surface_formula_syntax.json", "objects[0].front.formula",
     "cannot parse at position 5: Unexpected operator \"*\""},
    {"surface_formula_unknown_variable.json", "objects[0].front.formula",
     "unknown variable 'q' (use r, or x and y)"},
    {"surface_formula_empty.json", "objects[0].front.formula", "must not be empty"},
    {"surface_formula_not_zero_on_axis.json", "objects[0].front.formula",
     "must be 0 on the axis (z is measured from the vertex), got 1 at r = 0"},
    {"surface_sag_undefined.json", "objects[0].back",
     "sag undefined at r = 10.025 inside the diameter (sqrt of a negative number)"},
    {"surface_sag_undefined_xy.json", "objects[0].front",
     "sag undefined at (x, y) = (-5, 0) inside the diameter (log of a number <= 0)"},
    {"surface_conic_missing_k.json", "objects[0].front.k", "missing (required)"},
    {"surface_sphere_with_k.json", "objects[0].front.k", "a sphere surface has no k (it takes radius)"},
    {"surface_asphere_coefficients.json", "objects[0].front.coefficients",
     "must be an array of 1 to 7 numbers [A4, A6, ..., A16]"},
    {"surface_asphere_coefficient_string.json", "objects[0].front.coefficients[1]",
     "must be a number, got a string"},
    {"lens_conic_too_wide.json", "objects[0].front",
     "a conic R=10 k=1 surface cannot span the lens diameter 20 (its largest diameter is "
     "14.14213562)"},
    {"lens_formula_surfaces_cross.json", "objects[0].thickness",
     "the lens surfaces cross inside the diameter: at (x, y) = (0, 10) the back surface lies 4 "
     "in front of the front surface; the centre thickness must be at least 5 for diameter 20"},
    {"lens_x_axis_parallel.json", "objects[0].x_axis", "must not be parallel to the axis"},
    // Implicit solids.
    {"implicit_syntax.json", "objects[0].formula",
     "cannot parse at position 12: Unexpected operator \"*\""},
    {"implicit_unknown_variable.json", "objects[0].formula", "unknown variable 'r' (use x, y and z)"},
    {"implicit_empty.json", "objects[0].formula",
     "f > 0 at every point sampled inside the bounds, so the solid is empty (the inside is "
     "where f <= 0)"},
    {"implicit_undefined.json", "objects[0].formula",
     "f undefined at (x, y, z) = (-1, -1, -1) inside the bounds (sqrt of a negative number)"},
    {"implicit_bounds_inverted.json", "objects[0].bounds",
     "the second corner must exceed the first in y, got 1 and -1"},
    {"implicit_missing_bounds.json", "objects[0].bounds", "missing (required)"},
    {"implicit_steps_too_few.json", "objects[0].steps", "must be between 8 and 65536, got 2"},
    // Limits (src/scene/limits.h, docs/reliability.md).
    {"render_too_many_pixels.json", "render",
     "16384 x 16384 is 268435456 pixels, more than the 67108864 (8192 x 8192) allowed"},
    {"render_width_too_large.json", "render.width", "must be between 1 and 16384, got 20000"},
    {"render_spp_too_large.json", "render.spp", "must be between 1 and 1048576, got 2000000"},
    {"render_max_depth_too_large.json", "render.max_depth", "must be between 0 and 1000, got 1001"},
    {"render_photons_too_many.json", "render.photons",
     "must be between 1 and 1099511627776, got 2e+12"},
    {"surface_formula_too_long.json", "objects[0].front.formula",
     "is 4101 characters long, more than the 4096 allowed"},
    {"implicit_formula_too_long.json", "objects[0].formula",
     "is 4419 characters long, more than the 4096 allowed"},
    {"mesh_obj_device.json", "objects[0].file",
     "cannot read '/dev/zero': is not a regular file (a device or a pipe)"},
    // Lights.
    {"unknown_light_type.json", "lights[1].type", "unknown light type 'torch' (known: point, beam, laser, spot, rectangle_light, disc_light)"},
    {"beam_with_position.json", "lights[0].position", "not a property of a beam"},
    {"beam_slit_wider_than_beam.json", "lights[0].slit_width", "must be at most 2 radius (1), got 1.5"},
    {"beam_slit_axis_along_beam.json", "lights[0].slit_axis", "must not be parallel to direction"},
    {"laser_fan_angle_180.json", "lights[0].fan_angle", "must be at least 0 and below 180 degrees, got 180"},
    {"laser_fan_axis_zero.json", "lights[0].fan_axis", "must be a non-zero vector"},
    {"laser_fan_axis_along_beam.json", "lights[0].fan_axis", "must not be parallel to direction"},
    {"laser_slit_and_fan.json", "lights[0].slit_width", "a slit and a fan (fan_angle) do not go together"},
    {"point_light_zero_power.json", "lights[0].power", "must be > 0, got 0"},
    {"lens_group_cemented_with_back.json", "objects[0].elements[0].back",
     "an element with no gap after it is cemented: its back is the next element's front "
     "(give a gap, or leave out back)"},
    {"lens_group_last_without_back.json", "objects[0].elements[1]",
     "the last element needs a back surface"},
    {"lens_group_negative_gap.json", "objects[0].elements[0].gap",
     "must be >= 0 (the air space after the element)"},
    {"lens_group_no_elements.json", "objects[0].elements",
     "must be a non-empty array of elements, front to back"},
    {"lens_group_shared_surface_crossing.json", "objects[0].elements[1].thickness",
     "the lens surfaces cross inside the diameter: at 10 from the axis the back surface lies "
     "3.366750419 in front of the front surface; the centre thickness must be at least "
     "5.366750419 for diameter 20 (or reduce the diameter)"},
    {"lens_group_material_on_group.json", "objects[0].material", "not a property of a lens group"},
    // Issue 15: neighbouring elements apart on the axis but crossing towards the rim, over
    // the smaller element's aperture.
    {"lens_group_rim_overlap.json", "objects[0].elements[0].gap",
     "objects[0].elements[0] and objects[0].elements[1] overlap: at 5 from the axis the front "
     "of objects[0].elements[1] lies 1.260166538 in front of the back of objects[0].elements[0] "
     "(the gap must be at least 1.270166538 for a common diameter of 10, or reduce the "
     "diameters)"},
    {"lens_group_rim_overlap_smaller_element.json", "objects[0].elements[0].gap",
     "objects[0].elements[0] and objects[0].elements[1] overlap: at 4 from the axis the front "
     "of objects[0].elements[1] lies 0.3 in front of the back of objects[0].elements[0] (the "
     "gap must be at least 0.8 for a common diameter of 8, or reduce the diameters)"},
    // Issue 15: messages quote keys escaped, suggest the right case, and read as English.
    {"key_with_nul.json", "objects[0].ra\\x00dius", "unknown key (did you mean 'radius'?)"},
    {"key_with_terminal_escape.json", "\\x1b[2J\\x1b[31mred", "unknown key"},
    {"key_wrong_case.json", "objects[0].Type", "unknown key (did you mean 'type'?)"},
    {"key_all_capitals.json", "objects[0].RADIUS", "unknown key (did you mean 'radius'?)"},
    {"formula_number_out_of_range.json", "objects[0].formula",
     "cannot parse at position 19: number out of range '1e999'"},
    {"surface_asphere_formula.json", "objects[0].front.formula",
     "an asphere surface has no formula"},
    {"sellmeier_pole_visible.json", "materials.odd.ior.C[1]",
     "n² = 1 + Σ B·λ²/(λ² − C) has a pole at λ = √C = 455 nm, inside 360-830 nm (C is in µm²: "
     "each must be below 0.1296 or above 0.6889)"},
};
// clang-format on

// What GoogleTest prints for a parameter (and what ctest lists): the file name.
void PrintTo(const BadScene& c, std::ostream* os) { *os << c.file; }

std::string bad_dir() { return std::string(LENSLAB_TEST_DATA) + "/scene/bad"; }

class BadSceneFile : public ::testing::TestWithParam<BadScene> {};

TEST_P(BadSceneFile, IsRefusedWithPathAndReason) {
    const BadScene& c = GetParam();
    const std::string file = bad_dir() + "/" + c.file;
    ASSERT_TRUE(fs::is_regular_file(file)) << file << " is in the table but not on disk";

    try {
        (void)lenslab::load_scene_file(file);
        FAIL() << c.file << " loaded without an error";
    } catch (const lenslab::SceneError& e) {
        const std::string what = e.what();
        // The path is the file name, then the JSON path (none for a syntax error).
        const std::string expected_path = std::string(c.path).empty() ? file : file + ": " + c.path;
        EXPECT_EQ(e.path(), expected_path) << what;
        EXPECT_NE(e.reason().find(c.reason), std::string::npos)
            << "reason \"" << e.reason() << "\" lacks \"" << c.reason << "\"";
        // The whole message reads "FILE: JSON.PATH: REASON", on one line.
        EXPECT_EQ(what, expected_path + ": " + e.reason());
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    } catch (const std::exception& e) {
        FAIL() << c.file << " threw a non-SceneError: " << e.what();
    }
}

std::string file_stem(const ::testing::TestParamInfo<BadScene>& info) {
    return fs::path(info.param.file).stem().string();
}

// Names start with "scene" so that `ctest -R scene` selects them.
INSTANTIATE_TEST_SUITE_P(scene_errors, BadSceneFile, ::testing::ValuesIn(kBadScenes), file_stem);

// A new bad file without an expectation in the table is an error, and so is a duplicate.
TEST(scene_errors, EveryBadFileHasOneExpectation) {
    std::multiset<std::string> in_table;
    for (const BadScene& c : kBadScenes) in_table.insert(c.file);

    std::vector<std::string> on_disk;
    for (const auto& entry : fs::directory_iterator(bad_dir())) {
        if (entry.path().extension() == ".json")
            on_disk.push_back(entry.path().filename().string());
    }
    std::sort(on_disk.begin(), on_disk.end());
    ASSERT_GE(on_disk.size(), 14u) << "expected at least 14 bad scenes in " << bad_dir();

    for (const std::string& name : on_disk) {
        EXPECT_EQ(in_table.count(name), 1u)
            << name << " has " << in_table.count(name)
            << " expectations in kBadScenes (test_scene_errors.cpp); it needs exactly one";
    }
    for (const std::string& name : in_table) {
        EXPECT_TRUE(std::binary_search(on_disk.begin(), on_disk.end(), name))
            << name << " is in kBadScenes but not in " << bad_dir();
    }
}

// The same texts through parse_scene (no file): the path has no file prefix.
TEST(scene_errors, ParseSceneNamesThePathWithoutAFile) {
    try {
        (void)lenslab::parse_scene(R"({"camera": {"position": [0, 0, 5], "fov": 40,
                                       "look_at": [0, 0, 0]},
                                       "objects": [{"type": "sphere", "center": [0, 0, 0],
                                                    "radius": -1, "material": {}}]})");
        FAIL() << "a negative radius was accepted";
    } catch (const lenslab::SceneError& e) {
        EXPECT_STREQ(e.what(), "objects[0].radius: must be > 0, got -1");
        EXPECT_EQ(e.path(), "objects[0].radius");
        EXPECT_EQ(e.reason(), "must be > 0, got -1");
    }
}

// A missing file is a SceneError too, naming the file.
TEST(scene_errors, MissingFileIsASceneError) {
    const std::string file = bad_dir() + "/no_such_scene.json";
    try {
        (void)lenslab::load_scene_file(file);
        FAIL() << "loading a missing file succeeded";
    } catch (const lenslab::SceneError& e) {
        EXPECT_EQ(e.path(), file);
        EXPECT_NE(e.reason().find("cannot open scene file"), std::string::npos) << e.what();
    }
}

}  // namespace
