"""Artifact storage: atomic writes with checksums behind one interface.

``LocalStorage`` keeps objects under a folder; an object-store backend can implement the
same :class:`Storage` protocol later. Keys are relative, slash-separated names
(``jobs/<id>/animation.glb``); the engine never sees them.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import tempfile
import threading
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path, PurePosixPath
from typing import Protocol


class StorageError(Exception):
    """A key is invalid or an object is missing."""


@dataclass(frozen=True)
class StoredObject:
    key: str
    size: int
    sha256: str


class Storage(Protocol):
    def put_bytes(self, key: str, data: bytes) -> StoredObject: ...

    def put_file(self, key: str, source: Path) -> StoredObject: ...

    def get_bytes(self, key: str) -> bytes: ...

    def local_path(self, key: str) -> Path: ...

    def exists(self, key: str) -> bool: ...

    def delete_prefix(self, prefix: str) -> None: ...

    def iter_keys(self, prefix: str) -> Iterator[str]: ...


def _check_key(key: str) -> PurePosixPath:
    path = PurePosixPath(key)
    if not key or path.is_absolute() or ".." in path.parts or "\\" in key:
        raise StorageError(f"invalid storage key {key!r}")
    return path


class LocalStorage:
    """Objects as files under ``root``; writes go through a temporary file and a rename."""

    def __init__(self, root: Path) -> None:
        self.root = root.expanduser().resolve()
        self.root.mkdir(parents=True, exist_ok=True)

    def local_path(self, key: str) -> Path:
        return self.root / _check_key(key)

    def _commit(self, key: str, write: Callable[[], Iterator[bytes]]) -> StoredObject:
        target = self.local_path(key)
        target.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(prefix=".tmp-", dir=target.parent)
        digest = hashlib.sha256()
        size = 0
        try:
            with os.fdopen(handle, "wb") as out:
                for chunk in write():
                    digest.update(chunk)
                    size += len(chunk)
                    out.write(chunk)
                out.flush()
                os.fsync(out.fileno())
            os.chmod(temporary, 0o644)
            os.replace(temporary, target)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise
        return StoredObject(key=key, size=size, sha256=digest.hexdigest())

    def put_bytes(self, key: str, data: bytes) -> StoredObject:
        return self._commit(key, lambda: iter([data]))

    def put_file(self, key: str, source: Path) -> StoredObject:
        def chunks() -> Iterator[bytes]:
            with open(source, "rb") as handle:
                while block := handle.read(1 << 20):
                    yield block

        return self._commit(key, chunks)

    def get_bytes(self, key: str) -> bytes:
        path = self.local_path(key)
        if not path.is_file():
            raise StorageError(f"no object {key!r}")
        return path.read_bytes()

    def exists(self, key: str) -> bool:
        return self.local_path(key).is_file()

    def delete_prefix(self, prefix: str) -> None:
        path = self.local_path(prefix)
        if path.is_dir():
            shutil.rmtree(path)
        elif path.is_file():
            path.unlink()

    def iter_keys(self, prefix: str) -> Iterator[str]:
        base = self.local_path(prefix)
        if base.is_dir():
            for file in sorted(base.rglob("*")):
                if file.is_file() and not file.name.startswith(".tmp-"):
                    yield str(file.relative_to(self.root).as_posix())


def sha256_file(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        while block := handle.read(1 << 20):
            digest.update(block)
    return digest.hexdigest()


class _Verified:
    """Files whose sha256 was checked, by (path, size, mtime): an unchanged file is not hashed again."""

    MAX_ENTRIES = 4096

    def __init__(self) -> None:
        self._seen: dict[tuple[str, int, int], str] = {}
        self._lock = threading.Lock()

    def digest(self, path: Path) -> tuple[int, str]:
        stat = path.stat()
        key = (str(path), stat.st_size, stat.st_mtime_ns)
        with self._lock:
            known = self._seen.get(key)
        if known is None:
            known = sha256_file(path)
            with self._lock:
                if len(self._seen) >= self.MAX_ENTRIES:
                    self._seen.clear()
                self._seen[key] = known
        return stat.st_size, known


_VERIFIED = _Verified()


def intact_local_path(storage: Storage, key: str, sha256: str, size: int | None = None) -> Path:
    """The local file of ``key`` after checking it still holds the bytes recorded for it.

    Raises
    ------
    StorageError
        The file is missing, or its size or sha256 differs from the record (truncated, altered).
    """
    path = storage.local_path(key)
    if not path.is_file():
        raise StorageError(f"stored object {key!r} is missing")
    actual_size, actual = _VERIFIED.digest(path)
    if (size is not None and actual_size != size) or actual != sha256:
        raise StorageError(f"stored object {key!r} is damaged (its bytes no longer match their recorded sha256)")
    return path


def stored_copy_intact(storage: Storage, key: str, sha256: str, size: int | None = None) -> bool:
    try:
        intact_local_path(storage, key, sha256, size)
    except StorageError:
        return False
    return True
