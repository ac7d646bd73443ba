"""lenslab.Scene: a scene file's JSON as a dict-like object, checked by lenslab's own reader."""

from __future__ import annotations

import copy
import json
import os
from collections.abc import Iterator, Mapping, MutableMapping
from typing import Any, Union

from . import _lenslab

PathLike = Union[str, "os.PathLike[str]"]


def _json_default(value: Any) -> Any:
    # numpy numbers and arrays (a camera position from a computation) as plain JSON values.
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    raise TypeError(f"{type(value).__name__} is not a JSON value")


# One encoder for every scene: json.dumps with these options would build a new one each call.
_ENCODER = json.JSONEncoder(allow_nan=False, default=_json_default)


def _dumps(data: Any) -> str:
    return _ENCODER.encode(data)


class Scene(MutableMapping):
    """A scene: the keys and values of the scene format (docs/scene-format.md).

    Build one with Scene.load(path), Scene.from_dict(d) or Scene.default(). Setting or
    deleting a top-level key checks the whole scene at once and leaves it unchanged when the
    check fails (lenslab.SceneError, naming the JSON path). Edits inside a value
    (scene["camera"]["fov"] = 30) are checked by validate() or when the scene is next used.
    """

    def __init__(self, data: Mapping[str, Any] | None = None, *, path: str = "") -> None:
        self._data: dict[str, Any] = copy.deepcopy(dict(data or {}))
        self._path = path
        self.validate()

    @classmethod
    def _unchecked(cls, data: dict[str, Any], path: str = "") -> Scene:
        scene = cls.__new__(cls)
        scene._data, scene._path = data, path
        return scene

    @classmethod
    def _read(cls, path: PathLike) -> Scene:
        path = os.fspath(path)
        if os.path.splitext(path)[1].lower() in (".zmx", ".zar", ".seq"):
            # A lens file stands for a scene holding it alone, as `lenslab analyze FILE` reads it.
            return cls._unchecked({"objects": [{"type": "lens_file",
                                                "file": os.path.abspath(path),
                                                "vertex": [0, 0, 0], "axis": [0, 0, 1]}]}, path)
        _lenslab.check_scene_file(path)  # unreadable, too large, not JSON: as the CLI says it
        with open(path, encoding="utf-8") as f:
            return cls._unchecked(json.load(f), path)

    @classmethod
    def load(cls, path: PathLike) -> Scene:
        """The scene file at `path`; its relative paths (OBJ meshes) are relative to its folder
        and errors name the file, as `lenslab render FILE` does."""
        scene = cls._read(path)
        scene.validate()
        return scene

    @classmethod
    def from_dict(cls, d: Mapping[str, Any]) -> Scene:
        """A scene from a dict holding what a scene file holds (copied)."""
        return cls(d)

    @classmethod
    def default(cls) -> Scene:
        """The built-in default scene, the one `lenslab render` renders without a file."""
        return cls._unchecked(json.loads(_lenslab.default_scene_text()))

    @property
    def path(self) -> str | None:
        """The file the scene was loaded from, or None."""
        return self._path or None

    def to_dict(self) -> dict[str, Any]:
        """A deep copy of the scene's JSON, ready for json.dump."""
        return copy.deepcopy(self._data)

    def to_json(self, indent: int | None = 2) -> str:
        return json.dumps(self._data, allow_nan=False, default=_json_default, indent=indent)

    def save(self, path: PathLike) -> None:
        """Writes the scene as a scene file."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.to_json() + "\n")

    def validate(self) -> None:
        """Raises lenslab.SceneError if the scene is not valid. A camera is not required
        here (lenslab.analyze reads lens-only files); lenslab.render asks for one."""
        _lenslab.check_scene(_dumps(self._data), self._path, False)

    def _checked_edit(self, edit: Any) -> None:
        before = copy.deepcopy(self._data)
        edit()
        try:
            self.validate()
        except Exception:
            self._data = before
            raise

    def __getitem__(self, key: str) -> Any:
        return self._data[key]

    def __setitem__(self, key: str, value: Any) -> None:
        self._checked_edit(lambda: self._data.__setitem__(key, copy.deepcopy(value)))

    def __delitem__(self, key: str) -> None:
        if key not in self._data:
            raise KeyError(key)
        self._checked_edit(lambda: self._data.__delitem__(key))

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)

    def __repr__(self) -> str:
        where = f" from {self._path!r}" if self._path else ""
        return f"<lenslab.Scene{where}: {', '.join(self._data)}>"


SceneSource = Union[Scene, Mapping[str, Any], str, "os.PathLike[str]"]


def types() -> dict[str, dict[str, list[str]]]:
    """The object and light types a scene may hold and the shapes a lens surface may take,
    each with the keys it takes (besides "type" or "shape"), from lenslab's own type tables:
    {"objects": {"sphere": [...]}, "lights": {...}, "surfaces": {"asphere": [...]}}. The
    same as `lenslab types --json`."""
    listing = json.loads(_lenslab.types_json())
    return {kind: {row["type"]: row["keys"] for row in rows} for kind, rows in listing.items()}


def as_scene(source: SceneSource) -> Scene:
    """A Scene from a Scene, a dict or a scene file's path. A file is read, not yet checked:
    building it for the work checks it, with the same messages."""
    if isinstance(source, Scene):
        return source
    if isinstance(source, Mapping):
        return Scene._unchecked(copy.deepcopy(dict(source)))
    if isinstance(source, (str, os.PathLike)):
        return Scene._read(source)
    raise TypeError(f"expected a lenslab.Scene, a dict or a scene file's path, "
                    f"got {type(source).__name__}")


def scene_json(scene: Scene) -> tuple[str, str]:
    """The scene's JSON text and its file ("" for none), as the compiled module takes them."""
    return _dumps(scene._data), scene._path


def source_json(source: SceneSource) -> tuple[str, str]:
    """scene_json(as_scene(source)) without copying a dict first: what a sweep of many
    calls (bench/python_sweep.py) saves."""
    if isinstance(source, Mapping) and not isinstance(source, Scene):
        return _dumps(source), ""
    return scene_json(as_scene(source))
