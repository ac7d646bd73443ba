"""A command's JSON document as a read-only dict (lenslab.Analysis, lenslab.Detection)."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from typing import Any


class JsonDocument(Mapping):
    """Reads as the dict `_data`, the document the command line prints with --json."""

    _data: dict[str, Any]

    def __getitem__(self, key: str) -> Any:
        return self._data[key]

    def __iter__(self) -> Iterator[str]:
        return iter(self._data)

    def __len__(self) -> int:
        return len(self._data)
