# Command-line tests: what a user of `lenslab` sees. Included from tests/CMakeLists.txt.
# Each test runs the binary through run_lenslab.cmake, which checks the exit code, the
# message on stderr, stdout and whether an image was written. Test names start with "cli.".
#
# The commands run from the source root, so scene paths (and therefore the messages that
# name them) are the short relative ones a user would type.

set(LENSLAB_CLI_RUNNER ${CMAKE_CURRENT_LIST_DIR}/run_lenslab.cmake)
set(LENSLAB_CLI_OUT ${CMAKE_CURRENT_BINARY_DIR}/cli_out)

# lenslab_cli_test(NAME <name> ARGS <arg>... [CHECKS -DKEY=VALUE...])
function(lenslab_cli_test)
    cmake_parse_arguments(T "" "NAME" "ARGS;CHECKS" ${ARGN})
    list(JOIN T_ARGS "|" joined)
    add_test(NAME cli.${T_NAME}
        COMMAND ${CMAKE_COMMAND}
            -DLENSLAB=$<TARGET_FILE:lenslab>
            "-DARGS=${joined}"
            ${T_CHECKS}
            -P ${LENSLAB_CLI_RUNNER}
        WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
    set_tests_properties(cli.${T_NAME} PROPERTIES TIMEOUT 180 LABELS cli)
endfunction()

# A bad scene: non-zero exit, exactly one line "lenslab: error: FILE: PATH: REASON" on
# stderr, and no image written.
function(lenslab_cli_bad_scene stem message)
    set(file tests/scene/bad/${stem}.json)
    set(out ${LENSLAB_CLI_OUT}/${stem}.png)
    lenslab_cli_test(NAME render.bad.${stem}
        ARGS render ${file} -o ${out} --width 16 --height 16 --spp 1
        CHECKS -DEXPECT_EXIT=1 "-DSTDERR_LINE=lenslab: error: ${file}: ${message}"
               -DOUTPUT=${out} -DOUTPUT_CREATED=OFF)
endfunction()

lenslab_cli_bad_scene(sphere_negative_radius "objects[2].radius: must be > 0, got -1")
lenslab_cli_bad_scene(missing_camera "camera: missing (required)")
lenslab_cli_bad_scene(unknown_key_typo "objects[0].radiu: unknown key (did you mean 'radius'?)")
# (A ';' cannot pass through a CMake argument list, so the did-you-mean tail is checked in
# test_scene_errors.cpp.)
lenslab_cli_test(NAME render.bad.unknown_material_name
    ARGS render tests/scene/bad/unknown_material_name.json -o ${LENSLAB_CLI_OUT}/unknown_material_name.png
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_PREFIX=lenslab: error: tests/scene/bad/unknown_material_name.json: objects[0].material: unknown material 'glas' (not in materials"
           -DOUTPUT=${LENSLAB_CLI_OUT}/unknown_material_name.png -DOUTPUT_CREATED=OFF)
lenslab_cli_bad_scene(report_lens_aperture_too_big
    "objects[0].aperture_radius: two spheres of radius 0.9 cannot meet in a circle of radius 1.2 (must be <= curvature_radius)")
lenslab_cli_bad_scene(lens_diameter_exceeds_2r
    "objects[0].front: a sphere R=10 surface cannot span the lens diameter 30 (its largest diameter is 20)")
lenslab_cli_bad_scene(surface_formula_unknown_variable
    "objects[0].front.formula: unknown variable 'q' (use r, or x and y)")
lenslab_cli_bad_scene(surface_sag_undefined
    "objects[0].back: sag undefined at r = 10.025 inside the diameter (sqrt of a negative number)")
lenslab_cli_bad_scene(implicit_empty
    "objects[0].formula: f > 0 at every point sampled inside the bounds, so the solid is empty (the inside is where f <= 0)")
lenslab_cli_bad_scene(triangle_emission
    "objects[0].material: only spheres can emit light (the material has an emission)")
# A problem inside an OBJ file: the file's name and line after the JSON path, one line.
lenslab_cli_bad_scene(mesh_obj_nan_vertex
    "objects[0].file: ../data/obj_nan_vertex.obj:4: vertex coordinate 'nan' is not a finite number")

# A syntax error: the reason is nlohmann's text after the position, so check up to there.
set(syntax_out ${LENSLAB_CLI_OUT}/syntax_trailing_comma.png)
lenslab_cli_test(NAME render.bad.syntax_trailing_comma
    ARGS render tests/scene/bad/syntax_trailing_comma.json -o ${syntax_out}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_PREFIX=lenslab: error: tests/scene/bad/syntax_trailing_comma.json: invalid JSON: parse error at line 5, column 3:"
           -DOUTPUT=${syntax_out} -DOUTPUT_CREATED=OFF)

# `trace` refuses a bad scene the same way.
lenslab_cli_test(NAME trace.bad.lens_surfaces_cross
    ARGS trace tests/scene/bad/lens_surfaces_cross.json --origin 0,0,5 --direction 0,0,-1
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_PREFIX=lenslab: error: tests/scene/bad/lens_surfaces_cross.json: objects[0].thickness: the lens surfaces cross inside the diameter")

# Issue 15: a formula that passes the reader's grid but is not a number where a ray meets it
# stops the trace or the render (from inside its parallel loop) with one line naming the
# formula, and no image.
lenslab_cli_test(NAME trace.formula_nan_at_run_time
    ARGS trace tests/scene/data/sag_nan_between_samples.json --origin 3.005,0,-10 --direction 0,0,1
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: objects[0].back.formula: the formula '-r^2/40 + 0*sqrt(abs(r - 3.005) - 0.002)' is not a number at r = 3.005 (sqrt of a negative number), where a ray met it (the scene reader checks formulas only on a grid of sample points, so make it defined everywhere between them)")
set(nan_out ${LENSLAB_CLI_OUT}/implicit_nan_between_samples.png)
lenslab_cli_test(NAME render.formula_nan_at_run_time
    ARGS render tests/scene/data/implicit_nan_between_samples.json -o ${nan_out} --width 16 --height 16 --spp 1
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_PREFIX=lenslab: error: objects[0].formula: the formula 'x^2 + y^2 + z^2 - 0.25 + 0*sqrt(abs(z - 0.03) - 0.025)' is not a number at (x, y, z) = ("
           -DOUTPUT=${nan_out} -DOUTPUT_CREATED=OFF)

# A scene path that does not exist: a failure that names it, and no image.
set(missing_out ${LENSLAB_CLI_OUT}/missing_scene.png)
lenslab_cli_test(NAME render.missing_scene
    ARGS render tests/scene/bad/does_not_exist.json -o ${missing_out}
    CHECKS -DEXPECT_EXIT=nonzero "-DSTDERR_CONTAINS=tests/scene/bad/does_not_exist.json"
           -DOUTPUT=${missing_out} -DOUTPUT_CREATED=OFF)

# An output name with no known image type is refused before any work.
set(bad_ext_out ${LENSLAB_CLI_OUT}/image.bmp)
lenslab_cli_test(NAME render.unknown_image_type
    ARGS render -o ${bad_ext_out} --width 8 --height 8 --spp 1
    CHECKS -DEXPECT_EXIT=nonzero "-DSTDERR_CONTAINS=unknown image type"
           -DOUTPUT=${bad_ext_out} -DOUTPUT_CREATED=OFF)

# The built-in default scene renders and writes a PNG.
set(default_out ${LENSLAB_CLI_OUT}/default_scene.png)
lenslab_cli_test(NAME render.default_scene
    ARGS render -o ${default_out} --width 32 --height 24 --spp 1
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=wrote ${default_out} (32x24, 1 spp"
           -DOUTPUT=${default_out} -DOUTPUT_CREATED=ON)

# The default scene file renders too (the file, not the compiled-in copy).
set(default_file_out ${LENSLAB_CLI_OUT}/default_scene_file.png)
lenslab_cli_test(NAME render.default_scene_file
    ARGS render scenes/default.json -o ${default_file_out} --width 32 --height 24 --spp 1 -q
    CHECKS -DEXPECT_EXIT=zero -DOUTPUT=${default_file_out} -DOUTPUT_CREATED=ON)

# `trace` prints one JSON document: a tree whose root is the start and whose nodes have events.
lenslab_cli_test(NAME trace.default_scene
    ARGS trace scenes/default.json --origin 0,3,0 --direction 0,-1,0
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=\"event\"" -DSTDOUT_JSON=ON -DJSON_EVENT=start)

# Through a gradient-index solid the segment carries its curved path; a broken grin block is
# refused with its JSON path.
lenslab_cli_test(NAME trace.grin_path
    ARGS trace scenes/luneburg_lens.json --origin 0.5,0,-2 --direction 0,0,1
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=\"path\":" -DSTDOUT_JSON=ON)
lenslab_cli_test(NAME render.bad.grin_no_radius
    ARGS render tests/scene/bad/grin_luneburg_no_radius.json -o ${LENSLAB_CLI_OUT}/grin_bad.png
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: tests/scene/bad/grin_luneburg_no_radius.json: objects[0].material.grin.radius: missing (required by the luneburg profile: its sphere's radius R)")

# `analyze`: the optical bench reads lens-only files (no camera), prints a table, JSON with
# the named figures, writes an SVG ray diagram, and refuses what is not one lens system.
set(analyze_data tests/analysis/data)
lenslab_cli_test(NAME analyze.table
    ARGS analyze ${analyze_data}/lens_only.json
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=49.8258  ")
lenslab_cli_test(NAME analyze.doublet_table
    ARGS analyze scenes/achromat_doublet.json
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=objects[0].back = objects[1].front")
lenslab_cli_test(NAME analyze.json
    ARGS analyze ${analyze_data}/lens_only.json --json --wavelength 656.2725
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON
           "-DJSON_KEYS=efl,bfl,ffl,rms_spot_paraxial,rms_spot_best,best_focus,chromatic_shift_FC,wavelength_nm,principal_planes,lsa"
           "-DSTDOUT_CONTAINS=\"wavelength_nm\": 656.2725")
set(analyze_svg ${LENSLAB_CLI_OUT}/doublet.svg)
lenslab_cli_test(NAME analyze.svg
    ARGS analyze scenes/achromat_doublet.json --svg ${analyze_svg} --aperture 20 --unit mm
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=ray diagram written to ${analyze_svg}"
           -DOUTPUT=${analyze_svg} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS=<svg")
lenslab_cli_test(NAME analyze.chosen_lens
    ARGS analyze scenes/hyperbolic_lens_beam.json --lens hyperbolic
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=ignored: objects[1] ('spherical'): not on the axis of objects[0] ('hyperbolic')")
set(analyze_bad_svg ${LENSLAB_CLI_OUT}/not_coaxial.svg)
lenslab_cli_test(NAME analyze.bad.not_coaxial
    ARGS analyze ${analyze_data}/not_coaxial.json --svg ${analyze_bad_svg}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_PREFIX=lenslab: error: ${analyze_data}/not_coaxial.json: objects[1]: not on the axis of objects[0] ('left'): its centre lies 30 from that axis"
           -DOUTPUT=${analyze_bad_svg} -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME analyze.bad.no_lens
    ARGS analyze ${analyze_data}/no_lens.json
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: ${analyze_data}/no_lens.json: objects: no lens in the scene (analyze measures lens objects)")
lenslab_cli_test(NAME analyze.bad.scene
    ARGS analyze tests/scene/bad/sphere_negative_radius.json
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: tests/scene/bad/sphere_negative_radius.json: objects[2].radius: must be > 0, got -1")
lenslab_cli_test(NAME analyze.bad.wavelength_outside_glass
    ARGS analyze scenes/achromat_doublet.json --wavelength 350
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: scenes/achromat_doublet.json: objects[1].material: --wavelength 350 nm is outside the validity range 370-2500 nm of SF5")
lenslab_cli_test(NAME analyze.bad.aperture
    ARGS analyze ${analyze_data}/lens_only.json --aperture 30
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --aperture: a beam of diameter 30 does not pass the lenses (the largest that does is 25.4)")
lenslab_cli_test(NAME analyze.bad.unknown_lens
    ARGS analyze scenes/hyperbolic_lens_beam.json --lens hyperbolik
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --lens: no lens named 'hyperbolik' in scenes/hyperbolic_lens_beam.json (lenses: hyperbolic, spherical)")
# The lens-design bench: stop, pupils, fields, wavelengths and Seidel sums.
set(analyze_triplet ${analyze_data}/cooke_triplet.json)
lenslab_cli_test(NAME analyze.first_order_json
    ARGS analyze ${analyze_triplet} --json --stop 3 --epd 12.5 --fields 0,14,20
         --wavelengths 486.1327,587.5618,656.2725
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON
           "-DJSON_KEYS=first_order,seidel,efl,bfl,chromatic,wavelengths_nm,lsa"
           "-DSTDOUT_CONTAINS=\"lagrange_invariant\"")
lenslab_cli_test(NAME analyze.first_order_pupils
    ARGS analyze ${analyze_triplet} --json --stop 3 --f-number 4 --fields 20
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DSTDOUT_CONTAINS=\"exit_pupil\": {")
lenslab_cli_test(NAME analyze.seidel_table
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --fields 20 --seidel
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=Seidel sums")
lenslab_cli_test(NAME analyze.finite_object
    ARGS analyze ${analyze_data}/lens_only.json --json --object-distance 200 --field-heights 5
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DSTDOUT_CONTAINS=\"magnification\": -")
# Diffraction on the axis: the hyperbolic lens (conic -n^2) is free of spherical aberration.
lenslab_cli_test(NAME analyze.psf_mtf_json
    ARGS analyze scenes/hyperbolic_lens_beam.json --lens hyperbolic --json --psf --mtf
         --mtf-frequencies 10,20,40
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON
           "-DJSON_KEYS=psf,mtf,first_order" "-DSTDOUT_CONTAINS=\"diffraction_limit\": [")
lenslab_cli_test(NAME analyze.mtf_table
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --mtf
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=diffraction limit")
lenslab_cli_test(NAME analyze.bad.mtf_frequencies_without_mtf
    ARGS analyze ${analyze_triplet} --mtf-frequencies 10
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--mtf-frequencies requires --mtf")
lenslab_cli_test(NAME analyze.bad.stop_out_of_range
    ARGS analyze ${analyze_triplet} --stop 99
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --stop 99: the system has 6 surfaces, numbered 1 to 6")
lenslab_cli_test(NAME analyze.bad.stop_not_whole
    ARGS analyze ${analyze_triplet} --stop 1.5
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--stop: must be a whole number, got '1.5'")
lenslab_cli_test(NAME analyze.bad.epd_and_f_number
    ARGS analyze ${analyze_triplet} --epd 10 --f-number 4
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--epd excludes --f-number")
lenslab_cli_test(NAME analyze.bad.field_heights_at_infinity
    ARGS analyze ${analyze_triplet} --field-heights 5
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=requires --object-distance")
# Wavefronts at every field (--wavefront): the JSON block, the table, and bad input.
lenslab_cli_test(NAME analyze.wavefront_json
    ARGS analyze ${analyze_triplet} --json --stop 3 --epd 12.5 --fields 0,20 --wavefront
         --zernike-terms 11 --wavefront-samples 16
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=wavefront,first_order"
           "-DSTDOUT_CONTAINS=\"zernike_fringe\": [")
lenslab_cli_test(NAME analyze.wavefront_centroid
    ARGS analyze ${analyze_triplet} --json --stop 3 --epd 12.5 --fields 20 --wavefront
         --wavefront-reference centroid --wavefront-samples 16
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=wavefront"
           "-DSTDOUT_CONTAINS=\"reference\": \"centroid\"")
lenslab_cli_test(NAME analyze.wavefront_table
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --fields 0,20 --wavefront
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=Z11 spherical")
lenslab_cli_test(NAME analyze.bad.zernike_terms_without_wavefront
    ARGS analyze ${analyze_triplet} --zernike-terms 11
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--zernike-terms requires --wavefront")
lenslab_cli_test(NAME analyze.bad.wavefront_samples_odd
    ARGS analyze ${analyze_triplet} --wavefront --wavefront-samples 15
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--wavefront-samples: 15 is odd")
# The PSF of every field, its picture, and the OPD maps' picture.
set(analyze_psf_png ${LENSLAB_CLI_OUT}/triplet_psf.png)
set(analyze_opd_png ${LENSLAB_CLI_OUT}/triplet_opd.png)
lenslab_cli_test(NAME analyze.psf_fields_json
    ARGS analyze ${analyze_triplet} --json --stop 3 --epd 12.5 --fields 0,20 --psf
         --psf-png ${analyze_psf_png} --psf-log --opd-png ${analyze_opd_png}
    # The unbalanced "[" ends the list: it comes last.
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=psf,wavefront,psf_png,opd_png"
           -DOUTPUT=${analyze_psf_png} -DOUTPUT_CREATED=ON
           "-DSTDOUT_CONTAINS=\"strehl_per_wavelength\": [")
lenslab_cli_test(NAME analyze.psf_fields_table
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --fields 0,20 --psf
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=PSF per field, polychromatic")
lenslab_cli_test(NAME analyze.psf_huygens
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --psf --psf-huygens
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=PSF per field, polychromatic")
lenslab_cli_test(NAME analyze.bad.psf_huygens_alone
    ARGS analyze ${analyze_triplet} --psf-huygens
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--psf-huygens: it sets how --psf")
set(analyze_opd_fans_svg ${LENSLAB_CLI_OUT}/triplet_opd_fans.svg)
lenslab_cli_test(NAME analyze.opd_fans_json
    ARGS analyze ${analyze_triplet} --json --stop 3 --epd 12.5 --fields 0,20 --opd-fans-svg
         ${analyze_opd_fans_svg} --fan-points 7
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=opd_fans,opd_fans_svg"
           -DOUTPUT=${analyze_opd_fans_svg} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS=<svg"
           "-DSTDOUT_CONTAINS=\"unit\": \"waves\"")
lenslab_cli_test(NAME analyze.bad.psf_log_alone
    ARGS analyze ${analyze_triplet} --psf --psf-log
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--psf-log: it sets the scale of --psf-png")
lenslab_cli_test(NAME analyze.bad.opd_png_not_png
    ARGS analyze ${analyze_triplet} --opd-png ${LENSLAB_CLI_OUT}/opd.svg
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--opd-png: '${LENSLAB_CLI_OUT}/opd.svg' does not end in .png")
lenslab_cli_test(NAME analyze.through_focus_json
    ARGS analyze ${analyze_triplet} --json --stop 3 --epd 12.5 --fields 0,20 --through-focus 40
         --through-focus-points 5 --through-focus-range 0.05
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=through_focus"
           "-DSTDOUT_CONTAINS=\"shifts\": [")
lenslab_cli_test(NAME analyze.bad.through_focus_points_alone
    ARGS analyze ${analyze_triplet} --through-focus-points 5
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--through-focus-points requires --through-focus")
# Spot diagrams and ray fans per field and wavelength, their figures, and bad input.
set(analyze_spots_svg ${LENSLAB_CLI_OUT}/triplet_spots.svg)
set(analyze_fans_svg ${LENSLAB_CLI_OUT}/triplet_fans.svg)
lenslab_cli_test(NAME analyze.spots_fans_json
    ARGS analyze ${analyze_triplet} --json --stop 3 --epd 12.5 --fields 0,14,20
         --wavelengths 486.1327,587.5618,656.2725 --wavelength-weights 1,2,1 --spots --rings 4
         --fans --fan-points 11
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=spots,fans,first_order"
           "-DSTDOUT_CONTAINS=\"rays_per_beam\": 61")
lenslab_cli_test(NAME analyze.spots_table
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --fields 0,20 --spots
         --image-distance 41
    CHECKS -DEXPECT_EXIT=zero
           "-DSTDOUT_CONTAINS=Spot diagrams in the plane 41.0000 from the last vertex")
lenslab_cli_test(NAME analyze.spots_svg
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --fields 0,14,20 --unit mm
         --spots-svg ${analyze_spots_svg}
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=spot diagrams written to ${analyze_spots_svg}"
           -DOUTPUT=${analyze_spots_svg} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS=<svg")
lenslab_cli_test(NAME analyze.fans_svg
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --fields 0,20 --unit mm
         --fans-svg ${analyze_fans_svg}
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=ray fans written to ${analyze_fans_svg}"
           -DOUTPUT=${analyze_fans_svg} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS=<svg")
lenslab_cli_test(NAME analyze.bad.weights_count
    ARGS analyze ${analyze_triplet} --wavelengths 486.1327,587.5618 --wavelength-weights 1
         --spots
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --wavelength-weights: 1 weights for 2 wavelengths (one each, in the order of --wavelengths)")
lenslab_cli_test(NAME analyze.bad.weights_zero
    ARGS analyze ${analyze_triplet} --wavelength-weights 0 --spots
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --wavelength-weights: they add up to zero")
lenslab_cli_test(NAME analyze.bad.weights_negative
    ARGS analyze ${analyze_triplet} --wavelengths 486.1327,587.5618 --wavelength-weights 1,-1
         --spots
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --wavelength-weights: -1 is negative (a weight is 0 or more)")
lenslab_cli_test(NAME analyze.bad.image_distance_alone
    ARGS analyze ${analyze_triplet} --image-distance 40
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--image-distance: it places the image plane of --spots, --fans, --opd-fans, --field-map, --field-curves, --wavefront and --mtf")
lenslab_cli_test(NAME analyze.bad.field_map_on_the_axis
    ARGS analyze ${analyze_triplet} --field-map 3
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--field-map: the fields reach no further than the axis")
lenslab_cli_test(NAME analyze.bad.rings
    ARGS analyze ${analyze_triplet} --spots --rings 0
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--rings")
# Field curves and the chromatic focal shift.
lenslab_cli_test(NAME analyze.field_curves_focal_shift_json
    ARGS analyze ${analyze_triplet} --json --stop 3 --epd 12.5 --fields 20
         --field-curves --field-curve-points 5 --focal-shift --band 450,700
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=field_curves,focal_shift"
           "-DSTDOUT_CONTAINS=\"differential_pupil\": 0.01")
lenslab_cli_test(NAME analyze.focal_shift_table
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --focal-shift
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=Chromatic focal shift (paraxial image position")
set(analyze_curves_svg ${LENSLAB_CLI_OUT}/triplet_curves.svg)
set(analyze_shift_svg ${LENSLAB_CLI_OUT}/triplet_focal_shift.svg)
lenslab_cli_test(NAME analyze.curves_svg
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --fields 20 --unit mm
         --curves-svg ${analyze_curves_svg}
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=field curves written to ${analyze_curves_svg}"
           -DOUTPUT=${analyze_curves_svg} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS=<svg")
lenslab_cli_test(NAME analyze.focal_shift_svg
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --band 420,700 --unit mm
         --focal-shift-svg ${analyze_shift_svg}
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=focal shift written to ${analyze_shift_svg}"
           -DOUTPUT=${analyze_shift_svg} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS=<svg")
set(analyze_mtf_svg ${LENSLAB_CLI_OUT}/triplet_mtf.svg)
lenslab_cli_test(NAME analyze.mtf_svg
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --unit mm --mtf-frequencies 20,40
         --mtf-svg ${analyze_mtf_svg} --json
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=mtf,mtf_svg"
           -DOUTPUT=${analyze_mtf_svg} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS=<svg")
lenslab_cli_test(NAME analyze.bad.mtf_frequencies_alone
    ARGS analyze ${analyze_triplet} --mtf-frequencies 10
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--mtf-frequencies requires --mtf (or --mtf-svg)")
set(analyze_spots_png ${LENSLAB_CLI_OUT}/triplet_spots.png)
lenslab_cli_test(NAME analyze.spots_png
    ARGS analyze ${analyze_triplet} --stop 3 --epd 12.5 --fields 0,20 --unit mm
         --spots-svg ${analyze_spots_png}
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=spot diagrams written to ${analyze_spots_png}"
           -DOUTPUT=${analyze_spots_png} -DOUTPUT_CREATED=ON)
lenslab_cli_test(NAME analyze.bad.band_order
    ARGS analyze ${analyze_triplet} --focal-shift --band 700,400
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --band: two wavelengths in nm, the shorter first (e.g. 450,700)")
lenslab_cli_test(NAME analyze.bad.band_without_focal_shift
    ARGS analyze ${analyze_triplet} --band 450,700
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_LINE=lenslab: error: --band: it sets the band of --focal-shift, which was not asked for")
# The renderer still needs a camera: a lens-only file is refused there.
lenslab_cli_test(NAME render.bad.lens_only_no_camera
    ARGS render ${analyze_data}/lens_only.json -o ${LENSLAB_CLI_OUT}/lens_only.png
    CHECKS -DEXPECT_EXIT=1 "-DSTDERR_LINE=lenslab: error: ${analyze_data}/lens_only.json: camera: missing (required)"
           -DOUTPUT=${LENSLAB_CLI_OUT}/lens_only.png -DOUTPUT_CREATED=OFF)
# `detect` measures the scene's detectors: a summary with units on stdout, and per detector
# a CSV, an EXR and a false-colour PNG in the output folder.
set(detect_dir ${LENSLAB_CLI_OUT}/detect_focus)
lenslab_cli_test(NAME detect.focus_scene
    ARGS detect scenes/detector_focus.json -o ${detect_dir} --photons 20000 --threads 2 -q
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=peak irradiance" -DOUTPUT=${detect_dir}/focal_plane.png
           -DOUTPUT_CREATED=ON)
lenslab_cli_test(NAME detect.json
    ARGS detect scenes/detector_focus.json -o ${LENSLAB_CLI_OUT}/detect_json --photons 5000 --log --json -q
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DSTDOUT_CONTAINS=\"total_power\"")
# A scene without a detector, or with a bad one: one line, exit 1, nothing written.
set(no_detector_dir ${LENSLAB_CLI_OUT}/detect_none)
lenslab_cli_test(NAME detect.no_detector
    ARGS detect scenes/thick_lens_beam.json -o ${no_detector_dir}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_PREFIX=lenslab: error: scenes/thick_lens_beam.json: no detector in the scene"
           -DOUTPUT=${no_detector_dir}/screen.png -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME detect.bad.detector_on_sphere
    ARGS detect tests/scene/bad/detector_on_sphere.json -o ${LENSLAB_CLI_OUT}/detect_bad
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: tests/scene/bad/detector_on_sphere.json: objects[0].detector: only a triangle, disc or rectangle can be a detector (this is a sphere)")
lenslab_cli_bad_scene(disc_up_parallel "objects[0].up: must not be parallel to normal")
# Discs render like any other surface.
set(disc_render_out ${LENSLAB_CLI_OUT}/detector_focus_render.png)
lenslab_cli_test(NAME render.detector_focus
    ARGS render scenes/detector_focus.json -o ${disc_render_out} --width 32 --height 20 --spp 1 --photons 2000 -q
    CHECKS -DEXPECT_EXIT=zero -DOUTPUT=${disc_render_out} -DOUTPUT_CREATED=ON)
# sppm: a pass count, or a time budget alone (which lifts the pass limit); --passes 0 alone
# is refused before any work; path renders too.
set(sppm_out ${LENSLAB_CLI_OUT}/sppm.png)
lenslab_cli_test(NAME render.sppm_passes
    ARGS render scenes/caustic_room.json -o ${sppm_out} --width 24 --height 24 --passes 3 --pass-photons 2000
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=wrote ${sppm_out} (24x24, 3 passes"
           "-DSTDERR_CONTAINS=sppm: 3 passes, 7500 photons (1500 aimed" -DOUTPUT=${sppm_out} -DOUTPUT_CREATED=ON)
set(sppm_time_out ${LENSLAB_CLI_OUT}/sppm_time.png)
lenslab_cli_test(NAME render.sppm_time
    ARGS render --integrator sppm -o ${sppm_time_out} --width 16 --height 12 --time 0.2 --pass-photons 1000 -q
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=passes" -DOUTPUT=${sppm_time_out} -DOUTPUT_CREATED=ON)
set(sppm_bad_out ${LENSLAB_CLI_OUT}/sppm_bad.png)
lenslab_cli_test(NAME render.sppm_unbounded
    ARGS render --integrator sppm -o ${sppm_bad_out} --passes 0
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --passes 0 means no pass limit, which needs a time budget (--time)"
           -DOUTPUT=${sppm_bad_out} -DOUTPUT_CREATED=OFF)
set(path_out ${LENSLAB_CLI_OUT}/path.png)
lenslab_cli_test(NAME render.path
    ARGS render scenes/caustic_room.json --integrator path -o ${path_out} --width 16 --height 16 --spp 2 -q
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=wrote ${path_out} (16x16, 2 spp"
           -DOUTPUT=${path_out} -DOUTPUT_CREATED=ON)
lenslab_cli_bad_scene(render_passes_zero_without_time
    "render.passes: 0 means no pass limit, which needs a time budget: give render.time > 0")
lenslab_cli_bad_scene(photon_target_not_boolean "objects[0].photon_target: must be true or false, got a string")
lenslab_cli_bad_scene(render_caustic_photons_negative
    "render.caustic_photons: must be between 0 and 1099511627776, got -5")
lenslab_cli_bad_scene(render_aim_photons_number "render.aim_photons: must be true or false, got a number")

# Aimed photons: the stderr line says how many were aimed; --aim-photons off aims none.
set(aimed_out ${LENSLAB_CLI_OUT}/aimed.png)
lenslab_cli_test(NAME render.caustic_photons
    ARGS render scenes/default.json --integrator photon_map -o ${aimed_out} --width 32 --height 24 --spp 1
         --photons 2000 --caustic-photons 5000
    CHECKS -DEXPECT_EXIT=zero "-DSTDERR_CONTAINS=(5000 aimed at the glass and mirrors)" -DOUTPUT=${aimed_out}
           -DOUTPUT_CREATED=ON)
set(uniform_out ${LENSLAB_CLI_OUT}/uniform.png)  # its own file: the tests run in parallel
lenslab_cli_test(NAME render.aim_photons_off
    ARGS render scenes/default.json --integrator photon_map -o ${uniform_out} --width 32 --height 24 --spp 1
         --photons 2000 --caustic-photons 5000 --aim-photons off
    CHECKS -DEXPECT_EXIT=zero "-DSTDERR_CONTAINS=photons: 2000 emitted (0 aimed at the glass and mirrors)"
           -DOUTPUT=${uniform_out} -DOUTPUT_CREATED=ON)

# Limits (docs/reliability.md): refused before any work, one line, nothing written.
lenslab_cli_bad_scene(render_too_many_pixels
    "render: 16384 x 16384 is 268435456 pixels, more than the 67108864 (8192 x 8192) allowed")
set(pixels_out ${LENSLAB_CLI_OUT}/too_many_pixels.png)
lenslab_cli_test(NAME render.limit.pixels_from_options
    ARGS render -o ${pixels_out} --width 16384 --height 16384 --spp 1
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: image: 16384 x 16384 is 268435456 pixels, more than the 67108864 (8192 x 8192) allowed"
           -DOUTPUT=${pixels_out} -DOUTPUT_CREATED=OFF)
# Reading a device as a scene would never end.
set(device_out ${LENSLAB_CLI_OUT}/dev_zero.png)
lenslab_cli_test(NAME render.limit.scene_is_a_device
    ARGS render /dev/zero -o ${device_out}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: /dev/zero: cannot read scene file: it is not a regular file (a device or a pipe)"
           -DOUTPUT=${device_out} -DOUTPUT_CREATED=OFF)

# Ctrl-C stops a render at once and leaves no image and no temporary file
# (interrupt_render.sh; its 3 s bound is a responsiveness check, see there).
add_test(NAME cli.render.interrupt
    COMMAND bash ${CMAKE_CURRENT_LIST_DIR}/interrupt_render.sh $<TARGET_FILE:lenslab> ${LENSLAB_CLI_OUT}/interrupt
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.render.interrupt PROPERTIES TIMEOUT 120 LABELS cli)

# `bench povray` runs POV-Ray beside lenslab. Without POV-Ray: one line that says how to
# install it, exit 1, nothing written.
set(bench_povray_missing ${LENSLAB_CLI_OUT}/bench_povray_missing)
lenslab_cli_test(NAME bench.povray.missing_executable
    ARGS bench povray --povray /nonexistent/povray -o ${bench_povray_missing}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: --povray /nonexistent/povray: no such executable file (install POV-Ray with apt-get install povray)"
           -DOUTPUT=${bench_povray_missing}/povray.md -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME bench.povray.not_on_path
    ARGS bench povray -o ${bench_povray_missing}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: POV-Ray is not installed (no 'povray' on PATH): install it with apt-get install povray, or give its path with --povray"
           -DOUTPUT=${bench_povray_missing}/povray.md -DOUTPUT_CREATED=OFF)
set_tests_properties(cli.bench.povray.not_on_path PROPERTIES ENVIRONMENT "PATH=/nonexistent")
# A small real run where POV-Ray is installed (CI does not install it: the test is then
# disabled, and shows as "Not Run").
find_program(LENSLAB_POVRAY povray)
set(bench_povray_dir ${LENSLAB_CLI_OUT}/bench_povray)
lenslab_cli_test(NAME bench.povray.small_run
    ARGS bench povray -o ${bench_povray_dir} --width 120 --height 120 --photons 20000 --repeats 1
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=caustic photons stored"
           -DOUTPUT=${bench_povray_dir}/caustics_side_by_side.png -DOUTPUT_CREATED=ON)
if(NOT LENSLAB_POVRAY)
    set_tests_properties(cli.bench.povray.small_run PROPERTIES DISABLED ON)
endif()

# The render overrides are generated from the render block's declaration: an option is
# refused in the reader's words, and --radius takes 0, the declared "auto".
set(seed_range_out ${LENSLAB_CLI_OUT}/seed_range.png)
lenslab_cli_test(NAME render.option_out_of_declared_range
    ARGS render -o ${seed_range_out} --seed 3000000000
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_CONTAINS=--seed: must be between 0 and 2147483647, got 3000000000"
           -DOUTPUT=${seed_range_out} -DOUTPUT_CREATED=OFF)
set(radius_auto_out ${LENSLAB_CLI_OUT}/radius_auto.png)
lenslab_cli_test(NAME render.radius_zero_is_auto
    ARGS render scenes/default.json --integrator photon_map -o ${radius_auto_out} --width 16 --height 12 --spp 1
         --photons 2000 --radius 0 -q
    CHECKS -DEXPECT_EXIT=zero -DOUTPUT=${radius_auto_out} -DOUTPUT_CREATED=ON)

# Issue 15: every numeric option of every command refuses NaN and infinities with its name
# (CLI11 reads "nan" as a number, and NaN passed its Range and PositiveNumber checks).
function(lenslab_cli_not_finite name option value)
    lenslab_cli_test(NAME not_finite.${name}
        ARGS ${ARGN}
        CHECKS -DEXPECT_EXIT=2
               "-DSTDERR_CONTAINS=lenslab: error: ${option}: must be a finite number, got '${value}'")
endfunction()
lenslab_cli_not_finite(render_radius --radius nan render -o ${LENSLAB_CLI_OUT}/nan.png --radius nan)
lenslab_cli_not_finite(render_time --time inf render -o ${LENSLAB_CLI_OUT}/nan.png --time inf)
lenslab_cli_not_finite(render_exposure --exposure inf render -o ${LENSLAB_CLI_OUT}/nan.png --exposure inf)
lenslab_cli_not_finite(trace_wavelength --wavelength nan
    trace scenes/default.json --origin 0,0,5 --direction 0,0,-1 -w nan)
lenslab_cli_not_finite(trace_origin --origin nan
    trace scenes/default.json --origin 0,nan,5 --direction 0,0,-1)
lenslab_cli_not_finite(glass_wavelength --wavelength nan glass N-BK7 -w nan)
lenslab_cli_not_finite(analyze_wavelength --wavelength nan analyze scenes/achromat_doublet.json -w nan)
lenslab_cli_not_finite(analyze_aperture --aperture -inf analyze scenes/achromat_doublet.json --aperture -inf)
lenslab_cli_not_finite(bench_radii --radii 1e999 bench report --radii 1e999)
lenslab_cli_test(NAME option_whole_number_wording
    ARGS render -o ${LENSLAB_CLI_OUT}/nan.png --threads 1.5
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--threads: must be a whole number, got '1.5'")

# An empty path is an error, not the default scene (only leaving the argument out means that).
# run_lenslab.cmake cannot pass an empty argument, so these run the binary directly.
foreach(cmd render trace analyze detect)
    add_test(NAME cli.empty_scene_path.${cmd}
        COMMAND $<TARGET_FILE:lenslab> ${cmd} ""
        WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
    set_tests_properties(cli.empty_scene_path.${cmd} PROPERTIES TIMEOUT 60 LABELS cli
        PASS_REGULAR_EXPRESSION "lenslab: error: scene: must not be empty")
endforeach()
add_test(NAME cli.empty_output_path
    COMMAND $<TARGET_FILE:lenslab> render -o ""
    WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
set_tests_properties(cli.empty_output_path PROPERTIES TIMEOUT 60 LABELS cli
    PASS_REGULAR_EXPRESSION "lenslab: error: --output: must not be empty")

# Issue 15, output paths (src/util/output_path.h): every command checks where it writes before
# any work (the progress lines on stderr would break the one-line checks), and writes through
# symbolic links. Before, `detect -o FILE` measured in full and then failed as an internal error.
set(detect_onto_file ${LENSLAB_CLI_OUT}/outputs/detect_onto_a_file)
lenslab_cli_test(NAME output.detect_onto_a_regular_file
    ARGS detect scenes/detector_focus.json -o ${detect_onto_file} --photons 100000000
    CHECKS -DEXPECT_EXIT=1 -DMAKE_FILE=${detect_onto_file}
           "-DSTDERR_LINE=lenslab: error: cannot write into folder '${detect_onto_file}': is not a directory")
set(bench_onto_file ${LENSLAB_CLI_OUT}/outputs/bench_onto_a_file)
lenslab_cli_test(NAME output.bench_onto_a_regular_file
    ARGS bench report -o ${bench_onto_file}
    CHECKS -DEXPECT_EXIT=1 -DMAKE_FILE=${bench_onto_file}
           "-DSTDERR_LINE=lenslab: error: cannot write into folder '${bench_onto_file}': is not a directory")
set(read_only_out ${LENSLAB_CLI_OUT}/outputs/read_only.png)
lenslab_cli_test(NAME output.render_onto_a_read_only_file
    ARGS render -o ${read_only_out} --width 8 --height 8 --spp 1
    CHECKS -DEXPECT_EXIT=1 -DMAKE_FILE=${read_only_out} -DMAKE_FILE_READ_ONLY=ON
           "-DSTDERR_LINE=lenslab: error: cannot write '${read_only_out}': the file is read-only")
set(folder_out ${LENSLAB_CLI_OUT}/outputs/a_folder.png)
file(MAKE_DIRECTORY ${folder_out})
lenslab_cli_test(NAME output.render_onto_a_folder
    ARGS render -o ${folder_out} --width 8 --height 8 --spp 1
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: cannot write '${folder_out}': is a directory")
set(missing_folder_svg ${LENSLAB_CLI_OUT}/outputs/no_such_folder/diagram.svg)
lenslab_cli_test(NAME output.analyze_svg_into_a_missing_folder
    ARGS analyze scenes/achromat_doublet.json --svg ${missing_folder_svg}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: cannot write '${missing_folder_svg}': folder '${LENSLAB_CLI_OUT}/outputs/no_such_folder' does not exist")
# /dev/full fails every write with ENOSPC: a full disk is reported as one, never as success.
set(full_link ${LENSLAB_CLI_OUT}/outputs/full.png)
lenslab_cli_test(NAME output.render_through_a_link_to_dev_full
    ARGS render -o ${full_link} --width 8 --height 8 --spp 1 -q
    CHECKS -DEXPECT_EXIT=1 -DMAKE_LINK=${full_link} -DLINK_TO=/dev/full
           "-DSTDERR_LINE=lenslab: error: cannot write '${full_link}': no space left on device")
# ...and, in a folder that exists, the files it would write.
set(detect_read_only_dir ${LENSLAB_CLI_OUT}/outputs/detect_read_only)
lenslab_cli_test(NAME output.detect_onto_a_read_only_file
    ARGS detect scenes/detector_focus.json -o ${detect_read_only_dir} --photons 100000000
    CHECKS -DEXPECT_EXIT=1 -DMAKE_FILE=${detect_read_only_dir}/focal_plane.csv -DMAKE_FILE_READ_ONLY=ON
           "-DSTDERR_LINE=lenslab: error: cannot write '${detect_read_only_dir}/focal_plane.csv': the file is read-only")

# Issue 17: the makers' glass catalogues, searched and looked up by name.
lenslab_cli_test(NAME glass.list_names_the_catalogues
    ARGS glass
    CHECKS "-DSTDOUT_CONTAINS=and 1635 glasses of SCHOTT, OHARA, CDGM, HOYA, HIKARI, SUMITA")
lenslab_cli_test(NAME glass.search_by_maker_nd_vd
    ARGS glass --maker schott --nd 1.5:1.52 --vd 60:70
    CHECKS "-DSTDOUT_CONTAINS=N-BK7            SCHOTT    1.51680   64.17")
lenslab_cli_test(NAME glass.search_json
    ARGS glass --maker OHARA --nd 1.516:1.517 --json
    CHECKS -DSTDOUT_JSON=ON -DJSON_KEYS=count,glasses "-DSTDOUT_CONTAINS=\"name\": \"S-BSL7\"")
lenslab_cli_test(NAME glass.search_all
    ARGS glass --all
    CHECKS "-DSTDOUT_CONTAINS=K-PSFn214        SUMITA")
lenslab_cli_test(NAME glass.maker_prefix
    ARGS glass HIKARI:SF10
    CHECKS "-DSTDOUT_CONTAINS=SF10 (HIKARI) at 587.562 nm: n = 1.728250")
lenslab_cli_test(NAME glass.bad.unknown_suggests
    ARGS glass NBK7
    CHECKS -DEXPECT_EXIT=1 "-DSTDERR_PREFIX=lenslab: error: unknown glass 'NBK7'"
           "-DSTDERR_CONTAINS=did you mean N-BK7 (SCHOTT)?")  # (a ';' cannot pass through CMake)
lenslab_cli_test(NAME glass.bad.shared_name
    ARGS glass sf10
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_PREFIX=lenslab: error: glass 'sf10' is in several catalogues")
lenslab_cli_test(NAME glass.bad.range
    ARGS glass --nd 1.6
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_CONTAINS=--nd: must be MIN:MAX (e.g. 1.5:1.6, either may be left out), got '1.6'")
lenslab_cli_test(NAME glass.bad.unknown_maker
    ARGS glass --maker shott
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: --maker: unknown maker 'shott' (makers: builtin, SCHOTT, OHARA, CDGM, HOYA, HIKARI, SUMITA)")
lenslab_cli_test(NAME glass.bad.no_match
    ARGS glass --nd 3:4
    CHECKS -DEXPECT_EXIT=1 "-DSTDERR_LINE=lenslab: error: no glass matches the search")
lenslab_cli_test(NAME glass.bad.name_and_search
    ARGS glass N-BK7 --maker schott
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=excludes --maker")
# Catalogue files that cannot be found: the built-in table still prints, then one error says
# where it looked.
lenslab_cli_test(NAME glass.bad.data_missing
    ARGS glass
    CHECKS -DEXPECT_EXIT=1 "-DSTDOUT_CONTAINS=polycarbonate    builtin"
           "-DSTDERR_LINE=lenslab: error: LENSLAB_GLASS_DATA=/nonexistent/glass: no schott.json there (it must name the folder holding the glass catalogues)")
set_tests_properties(cli.glass.bad.data_missing PROPERTIES ENVIRONMENT LENSLAB_GLASS_DATA=/nonexistent/glass)

# Issue 17: a user's AGF catalogue on the command line, and the internal transmittance.
lenslab_cli_test(NAME glass.user_catalogue
    ARGS glass MY-CROWN --catalogue tests/cli/data/user.agf
    CHECKS "-DSTDOUT_CONTAINS=MY-CROWN (USER) at 587.562 nm: n = 1.516800")
lenslab_cli_test(NAME glass.search_user_catalogue
    ARGS glass --catalogue tests/cli/data/user.agf --nd 1.5167:1.5169
    CHECKS "-DSTDOUT_CONTAINS=MY-CROWN         USER      1.51680   64.17")
lenslab_cli_test(NAME glass.bad.catalogue_line
    ARGS glass N-BK7 --catalogue tests/cli/data/bad.agf
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: --catalogue: tests/cli/data/bad.agf:2: a CD coefficient must be a number, got 'oops'")
lenslab_cli_test(NAME glass.transmittance_json
    ARGS glass SCHOTT:N-SF57 --json
    CHECKS -DSTDOUT_JSON=ON -DJSON_KEYS=name,maker,wavelength_nm,n,n_d,V_d,transmittance_10mm
           "-DSTDOUT_CONTAINS=\"wavelength_nm\": 400.0")
set(glass_map_svg ${LENSLAB_CLI_OUT}/glass_map.svg)
lenslab_cli_test(NAME glass.map_svg
    ARGS glass --map ${glass_map_svg} --maker schott --nd 1.5:1.52 --vd 60:70
    CHECKS -DOUTPUT=${glass_map_svg} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS=<svg" "-DSTDOUT_CONTAINS=glasses on the map (n_d against V_d)")
lenslab_cli_test(NAME glass.bad.map_extension
    ARGS glass --map ${LENSLAB_CLI_OUT}/glass_map.jpg
    CHECKS -DEXPECT_EXIT=1 "-DSTDERR_PREFIX=lenslab: error: --map:")
# `import` and `export`: lens files in and out (tests/lensfile has the numbers).
set(lensfile_data tests/lensfile/data)
set(import_out ${LENSLAB_CLI_OUT}/AC254-100-A.json)
lenslab_cli_test(NAME import.zmx
    ARGS import ${lensfile_data}/AC254-100-A.zmx -o ${import_out}
    CHECKS -DEXPECT_EXIT=zero
           "-DSTDERR_CONTAINS=2 element(s) from ${lensfile_data}/AC254-100-A.zmx written to ${import_out}"
           -DOUTPUT=${import_out} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS={")
lenslab_cli_test(NAME import.seq_to_stdout
    ARGS import ${lensfile_data}/cooke_triplet.seq
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DSTDOUT_CONTAINS=\"glass\": \"SCHOTT:SF2\"")
lenslab_cli_test(NAME import.configuration
    ARGS import ${lensfile_data}/cooke_configurations.zmx --configuration 2
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DSTDOUT_CONTAINS=\"gap\": 10.5")
lenslab_cli_test(NAME import.bad.configuration
    ARGS import ${lensfile_data}/cooke_configurations.zmx --configuration 7 -o ${LENSLAB_CLI_OUT}/bad_configuration.json
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: ${lensfile_data}/cooke_configurations.zmx: configuration 7: the file has 3 (MNUM), numbered from 1"
           -DOUTPUT=${LENSLAB_CLI_OUT}/bad_configuration.json -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME import.bad.unknown_surface_type
    ARGS import ${lensfile_data}/bad_unknown_surface.zmx -o ${LENSLAB_CLI_OUT}/bad_surface.json
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: ${lensfile_data}/bad_unknown_surface.zmx:14: surface type 'GRID_SAG' cannot be represented (lenslab reads STANDARD, EVENASPH, BICONICX, TOROIDAL, SZERNSAG, XPOLYNOM and COORDBRK)"
           -DOUTPUT=${LENSLAB_CLI_OUT}/bad_surface.json -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME analyze.lens_file
    ARGS analyze ${lensfile_data}/triplet_scene.json
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=3 lenses, 7 surfaces on one axis")
set(export_out ${LENSLAB_CLI_OUT}/triplet.zmx)
lenslab_cli_test(NAME export.zmx
    ARGS export ${lensfile_data}/cooke_triplet.json --object triplet -o ${export_out}
    CHECKS -DEXPECT_EXIT=zero "-DSTDERR_CONTAINS=triplet written to ${export_out}"
           -DOUTPUT=${export_out} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS=MODE SEQ")

# `optimize`: damped least squares on a design file (docs/optimizer.md). The near start of
# the triplet, a few iterations: progress on stderr, the before/after table or JSON on
# stdout, the optimised scene written; bad designs named by file and JSON path.
set(optimize_data tests/optimize/data)
set(optimize_out ${LENSLAB_CLI_OUT}/triplet_optimized.json)
lenslab_cli_test(NAME optimize.table
    ARGS optimize ${optimize_data}/triplet_near.design.json -o ${optimize_out} --iterations 2
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=after: merit" "-DSTDERR_CONTAINS=iteration 1: merit"
           -DOUTPUT=${optimize_out} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS={")
set(optimize_json_out ${LENSLAB_CLI_OUT}/triplet_optimized_json.json)
lenslab_cli_test(NAME optimize.json
    ARGS optimize ${optimize_data}/triplet_near.design.json -o ${optimize_json_out} --iterations 1
         --json --quiet
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=before,after,variables,stopped"
           -DOUTPUT=${optimize_json_out} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS={")
set(optimize_bad_out ${LENSLAB_CLI_OUT}/not_written.json)
lenslab_cli_test(NAME optimize.bad.unknown_lens
    ARGS optimize ${optimize_data}/unknown_lens.design.json -o ${optimize_bad_out}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: ${optimize_data}/unknown_lens.design.json: variables[0].lens: no prescription lens named 'L9' in the system (lenses: L1, L2, L3)"
           -DOUTPUT=${optimize_bad_out} -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME optimize.bad.no_output
    ARGS optimize ${optimize_data}/triplet_near.design.json
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--output is required")
lenslab_cli_test(NAME optimize.bad.iterations
    ARGS optimize ${optimize_data}/triplet_near.design.json -o ${optimize_bad_out} --iterations 1.5
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--iterations: must be a whole number, got '1.5'")
lenslab_cli_test(NAME optimize.bad.output_is_a_folder
    ARGS optimize ${optimize_data}/triplet_near.design.json -o tests
    CHECKS -DEXPECT_EXIT=1 "-DSTDERR_LINE=lenslab: error: cannot write 'tests': is a directory")
set(optimize_glass_out ${LENSLAB_CLI_OUT}/triplet_glass.json)
lenslab_cli_test(NAME optimize.glass_choice
    ARGS optimize ${optimize_data}/triplet_glass.design.json -o ${optimize_glass_out} --iterations 1
    CHECKS -DEXPECT_EXIT=zero "-DSTDERR_CONTAINS=glass L2 SF5: merit" "-DSTDOUT_CONTAINS=glass choice"
           -DOUTPUT=${optimize_glass_out} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS={")
# The global search on the Cooke exercise: three starts, two iterations polished.
set(optimize_global_out ${LENSLAB_CLI_OUT}/cooke_global.json)
lenslab_cli_test(NAME optimize.global_search
    ARGS optimize examples/optimize/cooke.design.json -o ${optimize_global_out} --iterations 2
         --global-starts 3 --quiet
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=global search: 3 starts"
           -DOUTPUT=${optimize_global_out} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS={")
lenslab_cli_test(NAME optimize.global_search.json
    ARGS optimize examples/optimize/cooke.design.json -o ${optimize_global_out} --iterations 1
         --global-starts 2 --json --quiet
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=before,after,global_search,stopped")
lenslab_cli_test(NAME optimize.bad.global_starts
    ARGS optimize examples/optimize/cooke.design.json -o ${optimize_bad_out} --global-starts -1
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--global-starts")
lenslab_cli_test(NAME optimize.bad.bounds
    ARGS optimize ${optimize_data}/bad_bounds.design.json -o ${optimize_bad_out}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: ${optimize_data}/bad_bounds.design.json: variables[0].max: must be above min (3), got 2"
           -DOUTPUT=${optimize_bad_out} -DOUTPUT_CREATED=OFF)
# Model glasses substituted by catalogue glasses: the Cooke example, briefly (a few
# iterations, its five candidates a lens at 40 iterations each).
set(optimize_model_out ${LENSLAB_CLI_OUT}/cooke_glass.json)
lenslab_cli_test(NAME optimize.glass_substitution
    ARGS optimize examples/optimize/cooke_model.design.json -o ${optimize_model_out} --iterations 3
         --json --quiet
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON "-DJSON_KEYS=before,after,glass_trials,glass_substitution"
           -DOUTPUT=${optimize_model_out} -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS={")
lenslab_cli_test(NAME optimize.bad.model_glass
    ARGS optimize ${optimize_data}/model_glass_bad.design.json -o ${optimize_bad_out}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_CONTAINS=variables[0].lens: the lens 'L2' needs its material written inline with an \"ior\""
           -DOUTPUT=${optimize_bad_out} -DOUTPUT_CREATED=OFF)
# A multi-configuration design: the zoom example briefly, each configuration's scene written.
set(optimize_zoom_out ${LENSLAB_CLI_OUT}/zoom.json)
lenslab_cli_test(NAME optimize.configurations
    ARGS optimize examples/optimize/zoom.design.json -o ${optimize_zoom_out} --iterations 2 --quiet
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=configuration tele written to"
           -DOUTPUT=${LENSLAB_CLI_OUT}/zoom.tele.json -DOUTPUT_CREATED=ON "-DOUTPUT_STARTS={")
# `tolerance`: the triplet example's sensitivity table and a small Monte Carlo; a design
# without tolerances and a bad --trials refused.
lenslab_cli_test(NAME tolerance.table
    ARGS tolerance examples/optimize/triplet.tolerance.json --trials 6
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=radius L2.back ± 0.05"
           "-DSTDERR_CONTAINS=Monte Carlo: 6 of 6")
set(tolerance_figure ${LENSLAB_CLI_OUT}/tolerance.png)
lenslab_cli_test(NAME tolerance.figure
    ARGS tolerance examples/optimize/triplet.tolerance.json --trials 5 -q --figure ${tolerance_figure}
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=Monte Carlo figure written to"
           -DOUTPUT=${tolerance_figure} -DOUTPUT_CREATED=ON)
lenslab_cli_test(NAME tolerance.json
    ARGS tolerance examples/optimize/triplet.tolerance.json --trials 4 --seed 7 --json --quiet
    CHECKS -DEXPECT_EXIT=zero -DSTDOUT_JSON=ON
           "-DJSON_KEYS=nominal,sensitivity,rss_change,predicted_mean,predicted_sd,monte_carlo")
lenslab_cli_test(NAME tolerance.bad.none_given
    ARGS tolerance ${optimize_data}/triplet_near.design.json
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: ${optimize_data}/triplet_near.design.json: tolerances: no tolerance to try (give radius, thickness or air_gap in mm)")
lenslab_cli_test(NAME tolerance.bad.trials
    ARGS tolerance examples/optimize/triplet.tolerance.json --trials 0
    CHECKS -DEXPECT_EXIT=2 "-DSTDERR_CONTAINS=--trials: must be")
lenslab_cli_test(NAME bench.optimize
    ARGS bench optimize ${optimize_data}/triplet_near.design.json --threads 2
    CHECKS -DEXPECT_EXIT=zero "-DSTDOUT_CONTAINS=median" "-DSTDOUT_CONTAINS=rms_spot 20°")

# `sweep`: one scene per value of a swept number (test_sweep_command.cpp runs the sweeps
# through: every frame once, resuming, the CSV). Here: a small one, and the bad inputs, each
# refused before any frame is written with a message naming the problem.
set(sweep_out ${LENSLAB_CLI_OUT}/sweep)
set(sweep_tiny --width|24|--height|16|--spp|1|--photons|2000|--caustic-photons|2000|--threads|1)
lenslab_cli_test(NAME sweep.render
    ARGS sweep scenes/lens_caustic.json --set /objects/1/center/1=1.5:4.5:3 -o ${sweep_out}
         ${sweep_tiny} --overwrite
    CHECKS -DEXPECT_EXIT=zero "-DSTDERR_CONTAINS=frame 3/3 (/objects/1/center/1 = 4.5)"
           "-DSTDOUT_CONTAINS=wrote ${sweep_out}/sweep.json (3 frames)"
           -DOUTPUT=${sweep_out}/frames/00002.png -DOUTPUT_CREATED=ON)
set(sweep_bad ${LENSLAB_CLI_OUT}/sweep_bad)
lenslab_cli_test(NAME sweep.bad.pointer
    ARGS sweep scenes/lens_caustic.json --set /objects/5/center/1=1:2:3 -o ${sweep_bad}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: --set /objects/5/center/1: the scene has nothing at /objects/5 (/objects holds 2 elements, 0 to 1)"
           -DOUTPUT=${sweep_bad}/frames/00000.png -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME sweep.bad.not_a_number
    ARGS sweep scenes/lens_caustic.json --set /objects/1/material=1:2:3 -o ${sweep_bad}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: --set /objects/1/material: the scene has \"glass\" there, not a number"
           -DOUTPUT=${sweep_bad}/frames/00000.png -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME sweep.bad.range
    ARGS sweep scenes/lens_caustic.json --set /objects/1/center/1=1:2 -o ${sweep_bad}
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_PREFIX=lenslab: error: --set '/objects/1/center/1=1:2': the range '1:2' is not FROM:TO:COUNT"
           -DOUTPUT=${sweep_bad}/frames/00000.png -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME sweep.bad.count
    ARGS sweep scenes/lens_caustic.json --set /objects/1/center/1=1:2:0 -o ${sweep_bad}
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --set '/objects/1/center/1=1:2:0': COUNT '0' is not a whole number from 1 to 100000")
lenslab_cli_test(NAME sweep.bad.counts_differ
    ARGS sweep scenes/lens_caustic.json --set /objects/1/center/1=1:2:3
         --set /objects/1/thickness=0.2:0.3:4 -o ${sweep_bad}
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --set: /objects/1/thickness has 4 frames but /objects/1/center/1 has 3 (the parameters change together, so their COUNTs must agree)")
lenslab_cli_test(NAME sweep.bad.missing_scene
    ARGS sweep tests/scene/bad/no_such_scene.json --set /objects/1/center/1=1:2:3 -o ${sweep_bad}
    CHECKS -DEXPECT_EXIT=1 "-DSTDERR_PREFIX=lenslab: error: tests/scene/bad/no_such_scene.json: cannot open scene file")
lenslab_cli_test(NAME sweep.bad.frame_scene
    ARGS sweep scenes/lens_caustic.json --set /objects/1/thickness=-1:0.3:3 -o ${sweep_bad}
         ${sweep_tiny} --quiet
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: frame 1/3 (/objects/1/thickness = -1): scenes/lens_caustic.json: objects[1].thickness: must be > 0, got -1"
           -DOUTPUT=${sweep_bad}/frames/00000.png -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME sweep.bad.bench_option_without_analyze
    ARGS sweep scenes/lens_caustic.json --set /objects/1/center/1=1:2:3 -o ${sweep_bad} --stop 2
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --stop: an option of the optical bench, which needs --analyze")
lenslab_cli_test(NAME sweep.bad.no_ffmpeg
    ARGS sweep scenes/lens_caustic.json --set /objects/1/center/1=1:2:3 -o ${sweep_bad}
         --animation ${sweep_bad}/sweep.gif --ffmpeg ${sweep_bad}/no_ffmpeg
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: --ffmpeg '${sweep_bad}/no_ffmpeg': not an executable file"
           -DOUTPUT=${sweep_bad}/frames/00000.png -DOUTPUT_CREATED=OFF)
lenslab_cli_test(NAME sweep.bad.animation_kind
    ARGS sweep scenes/lens_caustic.json --set /objects/1/center/1=1:2:3 -o ${sweep_bad}
         --animation ${sweep_bad}/sweep.avi
    CHECKS -DEXPECT_EXIT=2
           "-DSTDERR_LINE=lenslab: error: --animation '${sweep_bad}/sweep.avi': unknown kind of animation (use a .gif or .mp4 file name)")
lenslab_cli_test(NAME sweep.bad.last_frame
    ARGS sweep scenes/lens_caustic.json --set /objects/1/thickness=0.3:-1:3 -o ${sweep_bad}
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: frame 3/3 (/objects/1/thickness = -1): scenes/lens_caustic.json: objects[1].thickness: must be > 0, got -1"
           -DOUTPUT=${sweep_bad}/frames/00000.png -DOUTPUT_CREATED=OFF)

# `lenslab spectra` prints the CIE tables' values (CIE 1931 at 550 nm: 0.433450 0.994950
# 0.008750) and refuses a wavelength outside them.
lenslab_cli_test(NAME spectra.cie_row ARGS spectra --wavelengths 550
    CHECKS -DEXPECT_EXIT=0 "-DSTDOUT_CONTAINS= 550.000  0.433450  0.994950  0.008750  1.040460")
lenslab_cli_test(NAME spectra.json ARGS spectra --wavelengths 400:440:20 --blackbody 3000 --json
    CHECKS -DEXPECT_EXIT=0 -DSTDOUT_JSON=ON "-DSTDOUT_CONTAINS=\"blackbody\"")
lenslab_cli_test(NAME spectra.out_of_range ARGS spectra --wavelengths 900
    CHECKS -DEXPECT_EXIT=1
           "-DSTDERR_LINE=lenslab: error: --wavelengths: wavelength 900 nm: outside 360 to 830 nm, the range of the CIE tables")

# `lenslab colour-speckle` measures a disc of a PNG: the default render's floor, lit by
# white light through no glass, has no colour speckle; a disc off the picture is refused.
lenslab_cli_test(NAME colour_speckle.grey_floor ARGS colour-speckle docs/images/default.png 320 450 20
    CHECKS -DEXPECT_EXIT=0 "-DSTDOUT_CONTAINS=0.00")
lenslab_cli_test(NAME colour_speckle.off_picture ARGS colour-speckle docs/images/default.png 5000 10 20
    CHECKS -DEXPECT_EXIT=1 "-DSTDERR_CONTAINS=lies outside the")
# `--rgb` adds the smooth spectrum a light of that colour gets: white is D65 itself.
lenslab_cli_test(NAME spectra.rgb_white ARGS spectra --wavelengths 550 --rgb 1,1,1
    CHECKS -DEXPECT_EXIT=0 "-DSTDOUT_CONTAINS=0.929120   1.040460")
lenslab_cli_test(NAME spectra.rgb_negative ARGS spectra --rgb=-1,0,0
    CHECKS -DEXPECT_EXIT=1 "-DSTDERR_LINE=lenslab: error: --rgb -1,0,0: a light's colour needs channels >= 0, not all 0")

# `lenslab types` lists every type from the tables, the area lights among them.
lenslab_cli_test(NAME types.lists_area_lights ARGS types
    CHECKS -DEXPECT_EXIT=0 "-DSTDOUT_CONTAINS=disc_light      center, normal, radius, power, color, spectrum")
# ... and every lens surface shape from its table, with the keys besides "shape".
lenslab_cli_test(NAME types.lists_surface_shapes ARGS types
    CHECKS -DEXPECT_EXIT=0 "-DSTDOUT_CONTAINS=biconic         radius_x, radius_y, k_x, k_y")
lenslab_cli_test(NAME types.json ARGS types --json
    CHECKS -DEXPECT_EXIT=0 -DSTDOUT_JSON=ON "-DSTDOUT_CONTAINS=\"rectangle_light\"")
