"""lenslab from Python: scenes, renders, ray trees, the optical bench and the glass catalogues.

    import lenslab
    scene = lenslab.Scene.load("scenes/default.json")
    image = lenslab.render(scene, width=320, height=240, spp=16)   # float32, (240, 320, 3)

See docs/python.md.
"""

from ._lenslab import Error, Glass, SceneError, glass
from ._detect import Detection, Detector, detect
from ._optics import Analysis, analyze, analyze_many, analyze_options, spectral_data, trace
from ._optimize import optimize, tolerance
from ._render import colour_speckle, render, write_image
from ._scene import Scene, types

# Named as the package exposes them, not after the compiled module that defines them.
for _exported in (Error, Glass, SceneError):
    _exported.__module__ = __name__
del _exported

__all__ = ["Analysis", "Detection", "Detector", "Error", "Glass", "Scene", "SceneError",
           "analyze", "analyze_many", "analyze_options", "colour_speckle", "detect", "glass",
           "optimize", "render", "spectral_data", "tolerance", "trace", "types", "write_image"]
