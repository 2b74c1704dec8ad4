"""Uploaded file(s) -> one validated, deduplicated asset zip in storage + its ``Asset`` row.

One ``.zip`` is kept as sent; several files (URDF + meshes, names may hold sub-folders)
are packed into a deterministic zip (sorted names, fixed timestamps and permissions), so
the same files always give the same sha256, the dedupe key. A new asset is validated with
the engine's :func:`load_asset` in a worker thread: a bad asset is rejected (422) before
any job exists.
"""

from __future__ import annotations

import logging
import re
import zipfile
from functools import partial
from pathlib import Path, PurePosixPath

from fastapi.concurrency import run_in_threadpool
from sqlalchemy.orm import Session

from app.api.asset_summary import store_summary
from app.api.errors import NotFound, Unprocessable
from app.api.uploads import UploadedFile
from app.core.storage import Storage, sha256_file
from app.crud.assets import get_asset_for_client, get_or_create_asset
from app.db.models import ApiClient, Asset
from app.engine.asset.loader import load_asset
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import AssetError, EngineError

logger = logging.getLogger(__name__)

ZIP_EPOCH = (1980, 1, 1, 0, 0, 0)
ZIP_FILE_MODE = 0o644 << 16
ZIP_MAGIC = b"PK\x03\x04"
ZIP_EMPTY_MAGIC = b"PK\x05\x06"
PACKED_NAME = "asset.zip"
MAX_NAME_CHARS = 300
MAX_DISPLAY_CHARS = 100
_UNSAFE_CHARS = re.compile(r"[^A-Za-z0-9._-]+")


def _clean_name(filename: str) -> str:
    """A safe relative member name from a multipart file name.

    Raises
    ------
    Unprocessable
        Absolute names, ``..``, drive letters, control characters or empty names.
    """
    name = filename.replace("\\", "/")
    while name.startswith("./"):
        name = name[2:]
    path = PurePosixPath(name)
    bad = (
        not name or name.startswith("/") or (len(name) > 1 and name[1] == ":") or ".." in path.parts
        or any(ord(char) < 32 for char in name) or len(name) > MAX_NAME_CHARS or name.endswith("/")
    )
    if bad:
        raise Unprocessable(f"unsafe or empty file name {filename!r} in the upload", file=filename[:MAX_NAME_CHARS])
    return str(path)


def _is_zip(file: UploadedFile) -> bool:
    with open(file.path, "rb") as handle:
        head = handle.read(4)
    return head in (ZIP_MAGIC, ZIP_EMPTY_MAGIC) or file.filename.lower().endswith(".zip")


def _pack(files: list[UploadedFile], target: Path) -> str:
    """Write ``files`` into the deterministic zip ``target``; returns a display name for it."""
    members: dict[str, UploadedFile] = {}
    for file in files:
        name = _clean_name(file.filename)
        if name in members:
            raise Unprocessable(f"the upload holds {name!r} twice", file=name)
        members[name] = file
    with zipfile.ZipFile(target, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=6) as archive:
        for name in sorted(members):
            info = zipfile.ZipInfo(name, date_time=ZIP_EPOCH)
            info.external_attr = ZIP_FILE_MODE
            info.compress_type = zipfile.ZIP_DEFLATED
            with open(members[name].path, "rb") as source, archive.open(info, "w") as out:
                while block := source.read(1 << 20):
                    out.write(block)
    tops = {PurePosixPath(name).parts[0] for name in members}
    single_folder = len(tops) == 1 and all(len(PurePosixPath(n).parts) > 1 for n in members)
    return _display_zip_name(tops.pop()) if single_folder else PACKED_NAME


def _display_zip_name(filename: str) -> str:
    """A harmless ``<name>.zip`` from the client's file or folder name (shown in engine messages)."""
    name = PurePosixPath(filename.replace("\\", "/")).name
    name = name[:-4] if name.lower().endswith(".zip") else name
    name = _UNSAFE_CHARS.sub("_", name).strip("._ ")[:MAX_DISPLAY_CHARS]
    return f"{name or PACKED_NAME[:-4]}.zip"


def _validate(zip_path: Path) -> ArticulatedAsset:
    """Load the asset like a worker would; every problem becomes a 422 naming file/element."""
    try:
        return load_asset(zip_path)
    except EngineError:
        raise
    except Exception as exc:  # route boundary: an unexpected loader failure is still the asset's fault
        logger.exception("asset %s: unexpected error while validating", zip_path.name)
        raise AssetError(f"the asset could not be read ({type(exc).__name__}: {exc})", file=zip_path.name) from exc


async def store_upload(
    files: list[UploadedFile], *, work: Path, session: Session, storage: Storage, client: ApiClient
) -> tuple[Asset, bool]:
    """Turn uploaded file(s) into a stored asset granted to ``client``; ``True`` if new content.

    Blocking work (packing, hashing, validation, database) runs in the thread pool.

    Raises
    ------
    Unprocessable
        No file, unsafe names or duplicates.
    AssetError
        The asset does not load (zip slip, zip bomb, XML bomb, missing mesh, ...).
    """
    if not files:
        raise Unprocessable("no asset: send the 'asset' file(s) (one .zip, or a URDF and its meshes) or 'asset_ref'")
    if len(files) == 1 and _is_zip(files[0]):
        display = _display_zip_name(files[0].filename)
        source = files[0].path
    else:
        source = work / "packed.zip"
        display = await run_in_threadpool(_pack, files, source)
    named = work / "named" / display
    named.parent.mkdir(parents=True, exist_ok=True)
    source.replace(named)  # the engine names the zip in its messages: use the client's name
    digest = await run_in_threadpool(sha256_file, named)
    existing = await run_in_threadpool(partial(get_asset_for_client, session, client=client, ref=digest))
    if existing is not None:
        return existing, False
    key = f"assets/{digest}.zip"
    if not storage.exists(key):
        loaded = await run_in_threadpool(_validate, named)
        await run_in_threadpool(store_summary, storage, digest, loaded, PurePosixPath(display).stem)
        await run_in_threadpool(storage.put_file, key, named)
    return await run_in_threadpool(partial(
        get_or_create_asset, session, client=client, sha256=digest, filename=display,
        size_bytes=named.stat().st_size, storage_key=key,
    ))


def asset_by_ref(session: Session, *, client: ApiClient, ref: str) -> Asset:
    """The client's asset named by id or sha256.

    Raises
    ------
    NotFound
        Unknown, malformed, or another client's asset.
    """
    asset = get_asset_for_client(session, client=client, ref=ref)
    if asset is None:
        raise NotFound(f"no asset {ref[:100]!r} (upload it with POST /v1/assets first)")
    return asset
