# Type stub of the `lenslab` package (docs/python.md).
import os
from collections.abc import Iterable, Iterator, Mapping, MutableMapping
from typing import Any, Callable, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

_PathLike = Union[str, os.PathLike[str]]
_SceneSource = Union[Scene, Mapping[str, Any], str, os.PathLike[str]]

class Error(RuntimeError): ...

class SceneError(ValueError):
    path: str
    reason: str

class Scene(MutableMapping[str, Any]):
    def __init__(self, data: Optional[Mapping[str, Any]] = ..., *, path: str = ...) -> None: ...
    @classmethod
    def load(cls, path: _PathLike) -> Scene: ...
    @classmethod
    def from_dict(cls, d: Mapping[str, Any]) -> Scene: ...
    @classmethod
    def default(cls) -> Scene: ...
    @property
    def path(self) -> Optional[str]: ...
    def to_dict(self) -> dict[str, Any]: ...
    def to_json(self, indent: Optional[int] = ...) -> str: ...
    def save(self, path: _PathLike) -> None: ...
    def validate(self) -> None: ...
    def __getitem__(self, key: str) -> Any: ...
    def __setitem__(self, key: str, value: Any) -> None: ...
    def __delitem__(self, key: str) -> None: ...
    def __iter__(self) -> Iterator[str]: ...
    def __len__(self) -> int: ...

class Glass:
    @property
    def name(self) -> str: ...
    @property
    def maker(self) -> str: ...
    @property
    def description(self) -> str: ...
    @property
    def source(self) -> str: ...
    @property
    def n_d(self) -> float: ...
    @property
    def V_d(self) -> float: ...
    @property
    def min_nm(self) -> float: ...
    @property
    def max_nm(self) -> float: ...
    def n(self, wavelengths_nm: Union[float, npt.ArrayLike]) -> Union[float, npt.NDArray[np.float64]]: ...

def glass(name: str) -> Glass: ...
def types() -> dict[str, dict[str, list[str]]]: ...
def render(
    scene: _SceneSource,
    *,
    width: Optional[int] = ...,
    height: Optional[int] = ...,
    spp: Optional[int] = ...,
    integrator: Optional[str] = ...,
    seed: Optional[int] = ...,
    threads: Optional[int] = ...,
    progress: Optional[Callable[[float], Any]] = ...,
    **settings: Any,
) -> npt.NDArray[np.float32]: ...
def write_image(image: npt.ArrayLike, path: _PathLike, exposure: float = ...) -> None: ...
def spectral_data(
    wavelengths: Iterable[float], blackbody: Optional[float] = ...
) -> dict[str, npt.NDArray[np.float64]]: ...
def colour_speckle(
    picture: Union[_PathLike, npt.NDArray[np.uint8]], cx: float, cy: float, radius: float
) -> float: ...
def trace(
    scene: _SceneSource,
    origin: Sequence[float],
    direction: Sequence[float],
    *,
    wavelength: float = ...,
    max_depth: int = ...,
    min_weight: float = ...,
) -> dict[str, Any]: ...
class Analysis(Mapping[str, Any]):
    @property
    def spot_points(self) -> dict[tuple[float, float], npt.NDArray[np.float64]]: ...
    @property
    def opd_maps(self) -> dict[tuple[float, float], npt.NDArray[np.float64]]: ...
    @property
    def psf_images(self) -> dict[float, npt.NDArray[np.float64]]: ...
    def figure(self, name: str) -> str: ...
    def __getitem__(self, key: str) -> Any: ...
    def __iter__(self) -> Iterator[str]: ...
    def __len__(self) -> int: ...

def analyze(
    scene_or_file: _SceneSource,
    *,
    wavelength: Optional[float] = ...,
    wavelengths: Optional[Sequence[float]] = ...,
    aperture: Optional[float] = ...,
    lens: Optional[str] = ...,
    unit: Optional[str] = ...,
    stop: Optional[int] = ...,
    ray_aiming: Optional[str] = ...,
    epd: Optional[float] = ...,
    f_number: Optional[float] = ...,
    object_distance: Optional[float] = ...,
    fields: Optional[Sequence[float]] = ...,
    field_heights: Optional[Sequence[float]] = ...,
    seidel: bool = ...,
    psf: bool = ...,
    psf_huygens: bool = ...,
    mtf: bool = ...,
    wavefront: bool = ...,
    zernike_terms: int = ...,
    wavefront_samples: int = ...,
    wavefront_reference: Optional[str] = ...,
    mtf_frequencies: Optional[Sequence[float]] = ...,
    through_focus: Optional[float] = ...,
    through_focus_range: Optional[float] = ...,
    through_focus_points: int = ...,
    spots: bool = ...,
    rings: int = ...,
    fans: bool = ...,
    opd_fans: bool = ...,
    fan_points: int = ...,
    image_distance: Optional[float] = ...,
    field_curves: bool = ...,
    field_curve_points: int = ...,
    focal_shift: bool = ...,
    band: Optional[Sequence[float]] = ...,
    focal_shift_points: int = ...,
    wavelength_weights: Optional[Sequence[float]] = ...,
    field_map: int = ...,
    report: Optional[Sequence[str]] = ...,
) -> Analysis: ...
def analyze_options() -> list[dict[str, Any]]: ...
def analyze_many(
    scenes: Iterable[_SceneSource],
    *,
    threads: Optional[int] = ...,
    progress: Optional[Callable[[float], Any]] = ...,
    wavelength: Optional[float] = ...,
    wavelengths: Optional[Sequence[float]] = ...,
    aperture: Optional[float] = ...,
    lens: Optional[str] = ...,
    unit: Optional[str] = ...,
    stop: Optional[int] = ...,
    ray_aiming: Optional[str] = ...,
    epd: Optional[float] = ...,
    f_number: Optional[float] = ...,
    object_distance: Optional[float] = ...,
    fields: Optional[Sequence[float]] = ...,
    field_heights: Optional[Sequence[float]] = ...,
    seidel: bool = ...,
    psf: bool = ...,
    psf_huygens: bool = ...,
    mtf: bool = ...,
    wavefront: bool = ...,
    zernike_terms: int = ...,
    wavefront_samples: int = ...,
    wavefront_reference: Optional[str] = ...,
    mtf_frequencies: Optional[Sequence[float]] = ...,
    through_focus: Optional[float] = ...,
    through_focus_range: Optional[float] = ...,
    through_focus_points: int = ...,
    spots: bool = ...,
    rings: int = ...,
    fans: bool = ...,
    opd_fans: bool = ...,
    fan_points: int = ...,
    image_distance: Optional[float] = ...,
    field_curves: bool = ...,
    field_curve_points: int = ...,
    focal_shift: bool = ...,
    band: Optional[Sequence[float]] = ...,
    focal_shift_points: int = ...,
    wavelength_weights: Optional[Sequence[float]] = ...,
    field_map: int = ...,
    report: Optional[Sequence[str]] = ...,
) -> list[Analysis]: ...

class Detector:
    summary: dict[str, Any]
    extent: tuple[float, float, float, float]
    origin: tuple[float, float, float]
    u_axis: tuple[float, float, float]
    v_axis: tuple[float, float, float]
    band_edges: list[float]
    @property
    def name(self) -> str: ...
    @property
    def units(self) -> dict[str, str]: ...
    @property
    def total_power(self) -> float: ...
    @property
    def irradiance(self) -> npt.NDArray[np.float64]: ...
    @property
    def band_irradiance(self) -> npt.NDArray[np.float64]: ...
    @property
    def cell_area(self) -> npt.NDArray[np.float64]: ...

class Detection(Mapping[str, Any]):
    detectors: list[Detector]
    def detector(self, name: str) -> Detector: ...
    @property
    def irradiance(self) -> npt.NDArray[np.float64]: ...
    @property
    def band_irradiance(self) -> npt.NDArray[np.float64]: ...
    @property
    def cell_area(self) -> npt.NDArray[np.float64]: ...
    @property
    def extent(self) -> tuple[float, float, float, float]: ...
    @property
    def units(self) -> dict[str, str]: ...
    @property
    def total_power(self) -> float: ...
    def save(self, folder: _PathLike, *, log: bool = ...) -> list[list[str]]: ...
    def __getitem__(self, key: str) -> Any: ...
    def __iter__(self) -> Iterator[str]: ...
    def __len__(self) -> int: ...

def detect(
    scene: _SceneSource,
    *,
    photons: Optional[int] = ...,
    caustic_photons: Optional[int] = ...,
    aim_photons: Optional[bool] = ...,
    seed: Optional[int] = ...,
    max_depth: Optional[int] = ...,
    threads: Optional[int] = ...,
    progress: Optional[Callable[[float], Any]] = ...,
) -> Detection: ...

_DesignSource = Union[Mapping[str, Any], str, os.PathLike[str]]

def optimize(
    design: _DesignSource,
    *,
    iterations: Optional[int] = ...,
    global_starts: Optional[int] = ...,
    base_dir: Optional[_PathLike] = ...,
    progress: Optional[Callable[[float], Any]] = ...,
) -> dict[str, Any]: ...
def tolerance(
    design: _DesignSource,
    *,
    trials: Optional[int] = ...,
    seed: Optional[int] = ...,
    base_dir: Optional[_PathLike] = ...,
    progress: Optional[Callable[[float], Any]] = ...,
) -> dict[str, Any]: ...
