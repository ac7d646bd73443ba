# The library's layers, lowest first. A layer may include the headers of the layers before it
# in this list and of none after it; the build enforces it (below) and tests/layers/
# check_layers.py names every include that breaks it. docs/architecture.md says what each
# layer holds.
set(LENSLAB_LAYERS
    util        # errors, files, text: no physics
    cluster     # ranks and their messages (MPI or local)
    math        # vectors, frames, rays, boxes, sampling, the formula parser
    optics      # spectra, glasses, Fresnel, refraction, GRIN profiles
    image       # films, PNG/EXR, the tone map, the bitmap font, colour maps, the glass map
    accel       # bounding-volume and point hierarchies, photon k-d trees, hash grids
    geometry    # shapes, lens surfaces and solids, meshes, the shapes' BVH
    lensfile    # Zemax and CODE V files read into prescriptions and lens groups, and written
    scene       # the scene model, its JSON reader and declarations, lights, media
    render      # integrators, photon maps, the render session
    analysis    # the optical bench: systems, first order, aberrations, diffraction, detectors
    optimize)   # lens design: variables, merit functions, the optimiser
list(GET LENSLAB_LAYERS -1 LENSLAB_TOP_LAYER)

# lenslab_layer(NAME sources...): the static library lenslab_NAME, linking the layer before it.
# Its headers are reached through an include root of its own, ${binary}/layer_roots/NAME,
# which holds only the link NAME -> src/NAME; a layer's compile sees its own root and those of
# the layers below it (through the links), so an include of a higher layer's header is "No
# such file" when the build compiles it.
function(lenslab_layer name)
    list(FIND LENSLAB_LAYERS ${name} position)
    if(position LESS 0)
        message(FATAL_ERROR "lenslab_layer(${name}): not in LENSLAB_LAYERS (cmake/layers.cmake)")
    endif()
    if(position GREATER 0)
        math(EXPR below "${position} - 1")
        list(GET LENSLAB_LAYERS ${below} below)
    endif()
    add_library(lenslab_${name} STATIC ${ARGN})
    set(root ${CMAKE_BINARY_DIR}/layer_roots/${name})
    file(MAKE_DIRECTORY ${root})
    file(CREATE_LINK ${CMAKE_CURRENT_SOURCE_DIR}/${name} ${root}/${name} SYMBOLIC)
    target_include_directories(lenslab_${name} PUBLIC ${root})
    if(position GREATER 0)
        target_link_libraries(lenslab_${name} PUBLIC lenslab_${below})
    endif()
    target_link_libraries(lenslab_${name} PRIVATE lenslab_warnings)
    # The Python module (python/) is a shared object that links the library in, so the
    # library is then position-independent. -fno-semantic-interposition keeps GCC inlining and
    # calling the library's own functions directly, as it does without -fPIC.
    if(LENSLAB_BUILD_PYTHON)
        set_target_properties(lenslab_${name} PROPERTIES POSITION_INDEPENDENT_CODE ON)
        target_compile_options(lenslab_${name} PRIVATE -fno-semantic-interposition)
    endif()
    # Precompiled json + standard headers, only with -DLENSLAB_PCH=ON (cmake/build_speed.cmake).
    lenslab_precompile_core(lenslab_${name})
    lenslab_unity(lenslab_${name})
    lenslab_fuzz_coverage(lenslab_${name} ${name})
endfunction()
