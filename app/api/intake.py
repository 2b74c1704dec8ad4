"""Uploaded file(s) -> one validated, deduplicated asset zip in storage + the client's ``Asset`` record.

One ``.zip`` is kept as sent; several files (URDF + meshes, names may hold sub-folders)
are packed into a deterministic zip (sorted names, fixed timestamps and permissions), so
the same files always give the same sha256, the dedupe key of the stored content. New
content (or a URDF of it not used before) is validated with the engine's loader in a worker
thread: a bad asset is rejected (422) before any job exists; its summary is stored beside
it and the loaded asset is left in the workers' asset cache. Each client gets its own
record (id, name, time) over the shared content.
"""

from __future__ import annotations

import logging
import re
import zipfile
from functools import partial
from pathlib import Path, PurePosixPath

from fastapi.concurrency import run_in_threadpool
from sqlalchemy.orm import Session

from app.api.errors import Conflict, NotFound, Unprocessable
from app.api.uploads import UploadedFile
from app.core.asset_summary import has_summary, store_summary
from app.core.config import Settings
from app.core.storage import Storage, intact_local_path, sha256_file, stored_copy_intact
from app.crud.assets import find_assets_for_client, get_or_create_asset, get_or_create_content
from app.db.models import ApiClient, Asset
from app.engine.asset.cache import load_asset_cached
from app.engine.asset.model import ArticulatedAsset
from app.engine.asset.urdf_choice import urdf_in_zip
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


def _validate(zip_path: Path, display: str, urdf: str, cache_dir: Path | None, digest: str) -> ArticulatedAsset:
    """Load the asset like a worker would (and leave it in the workers' asset cache).

    Every problem becomes a 422 naming file/element; the zip is shown under the client's name.
    """
    try:
        return load_asset_cached(zip_path, cache_dir, name=PurePosixPath(display).stem, urdf=urdf, content_hash=digest)
    except EngineError:
        raise
    except Exception as exc:  # route boundary: an unexpected loader failure is still the asset's fault
        logger.exception("asset %s: unexpected error while validating", display)
        raise AssetError(f"the asset could not be read ({type(exc).__name__}: {exc})", file=display) from exc


def _chosen_urdf(source: Path, display: str, urdf: str | None) -> str:
    """The URDF the record will use (from the zip's member list; 422 when ambiguous or absent)."""
    try:
        return urdf_in_zip(source, urdf)
    except AssetError as exc:  # name the client's file, not the temporary one
        raise AssetError(exc.reason.replace(source.name, display), file=display, element=exc.element) from exc


def _store_content(storage: Storage, key: str, source: Path, digest: str, size: int) -> bool:
    """Store ``source`` under ``key`` unless an intact copy is there; ``True`` when it was (re)written.

    A stored copy that is missing, truncated or altered is replaced by the uploaded bytes.
    """
    if stored_copy_intact(storage, key, digest, size):
        return False
    if storage.exists(key):
        logger.warning("stored asset %s was damaged; restored from a new upload of the same bytes", key)
    storage.put_file(key, source)
    return True


async def store_upload(
    files: list[UploadedFile], *, work: Path, session: Session, storage: Storage, client: ApiClient, settings: Settings,
    urdf: str | None = None,
) -> tuple[Asset, bool]:
    """Turn uploaded file(s) into this client's asset record; ``True`` if the record is new.

    The content is stored (and validated) once per sha256 and URDF; every client gets its own
    record over it. Blocking work (packing, hashing, validation, database) runs in the thread pool.

    Raises
    ------
    Unprocessable
        No file, unsafe names or duplicates.
    AssetError
        The asset does not load (zip slip, zip bomb, XML bomb, missing mesh, several URDFs, ...).
    """
    if not files:
        raise Unprocessable("no asset: send the 'asset' file(s) (one .zip, or a URDF and its meshes) or 'asset_ref'")
    if len(files) == 1 and _is_zip(files[0]):
        display = _display_zip_name(files[0].filename)
        source = files[0].path
    else:
        source = work / "packed.zip"
        display = await run_in_threadpool(_pack, files, source)
    digest = await run_in_threadpool(sha256_file, source)
    size = source.stat().st_size
    chosen = await run_in_threadpool(_chosen_urdf, source, display, urdf)
    key = f"assets/{digest}.zip"
    if not await run_in_threadpool(has_summary, storage, digest, chosen):
        loaded = await run_in_threadpool(_validate, source, display, chosen, settings.engine_config().asset_cache_dir, digest)
        await run_in_threadpool(store_summary, storage, digest, chosen, loaded)
    await run_in_threadpool(_store_content, storage, key, source, digest, size)
    content = await run_in_threadpool(partial(get_or_create_content, session, sha256=digest, size_bytes=size, storage_key=key))
    return await run_in_threadpool(partial(get_or_create_asset, session, client=client, content=content, filename=display,
                                           urdf=chosen))


async def asset_with_urdf(asset: Asset, urdf: str, *, session: Session, storage: Storage, client: ApiClient,
                          settings: Settings) -> Asset:
    """The client's record of ``asset``'s content with another URDF of it (validated on first use)."""
    path = await run_in_threadpool(intact_local_path, storage, asset.storage_key, asset.sha256, asset.size_bytes)
    chosen = await run_in_threadpool(_chosen_urdf, path, asset.filename, urdf)
    if chosen == asset.urdf:
        return asset
    if not await run_in_threadpool(has_summary, storage, asset.sha256, chosen):
        loaded = await run_in_threadpool(_validate, path, asset.filename, chosen, settings.engine_config().asset_cache_dir,
                                         asset.sha256)
        await run_in_threadpool(store_summary, storage, asset.sha256, chosen, loaded)
    record, _ = await run_in_threadpool(partial(get_or_create_asset, session, client=client, content=asset.content,
                                                filename=asset.filename, urdf=chosen))
    return record


def asset_by_ref(session: Session, *, client: ApiClient, ref: str, any_urdf: bool = False) -> Asset:
    """The client's asset named by id or sha256 (``any_urdf``: the first of several records of that content).

    Raises
    ------
    NotFound
        Unknown, malformed, or another client's asset.
    Conflict
        A sha256 naming several of the client's records (one per chosen URDF): use the id.
    """
    found = find_assets_for_client(session, client=client, ref=ref)
    if not found:
        raise NotFound(f"no asset {ref[:100]!r} (upload it with POST /v1/assets first)")
    if len(found) > 1 and not any_urdf:
        choices = ", ".join(f"{a.id} ({a.urdf})" for a in found)
        raise Conflict(f"{ref[:100]!r} names {len(found)} of your assets, one per URDF: {choices}; refer to one by its id")
    return found[0]
