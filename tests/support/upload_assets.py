"""Tiny asset uploads for the service tests: good ones and one per kind of rejection.

Each builder returns ``(filename, bytes)`` ready for a multipart ``asset`` part; zips are
built in memory with fixed timestamps (same bytes every run).
"""

from __future__ import annotations

import io
import zipfile

from tests.support.primitive_assets import TRIANGLE_OBJ, box, cabinet_urdf, joint, link, mesh, robot

EPOCH = (1980, 1, 1, 0, 0, 0)

Upload = tuple[str, bytes]


def zip_bytes(members: dict[str, str | bytes], *, compression: int = zipfile.ZIP_DEFLATED) -> bytes:
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", compression=compression) as archive:
        for name in sorted(members):
            info = zipfile.ZipInfo(name, date_time=EPOCH)
            info.compress_type = compression
            data = members[name]
            archive.writestr(info, data.encode() if isinstance(data, str) else data)
    return buffer.getvalue()


def hinge_urdf(*, name: str = "box_hinge", mesh_file: str | None = None) -> str:
    """A base box and a lid on a revolute hinge (optionally the lid is a mesh file)."""
    lid = mesh(mesh_file) if mesh_file else box((1.0, 1.0, 0.1), xyz=(0.0, 0.5, 0.05))
    return robot(
        link("base", box((1.0, 1.0, 0.5), xyz=(0.0, 0.0, 0.25))),
        link("lid", lid),
        joint("lid_hinge", "revolute", "base", "lid", xyz=(0.0, -0.5, 0.5), axis=(1.0, 0.0, 0.0), limit=(0.0, 1.5)),
        name=name,
    )


def welded_urdf() -> str:
    """Two links joined by a fixed joint: a valid asset with nothing to animate."""
    return robot(link("base", box((1.0, 1.0, 0.5))), link("lid", box((1.0, 1.0, 0.1))),
                 joint("weld", "fixed", "base", "lid", axis=None), name="welded")


def cabinet_zip() -> Upload:
    return "cabinet.zip", zip_bytes({"cabinet/mobility.urdf": cabinet_urdf()})


def hinge_zip(variant: str = "") -> Upload:
    """A valid zip; ``variant`` changes the robot name, so the bytes (and sha256) differ."""
    return f"hinge{variant}.zip", zip_bytes({"hinge/mobility.urdf": hinge_urdf(name=f"hinge{variant}")})


def mesh_asset_files() -> list[Upload]:
    """A URDF and its OBJ as separate files (the multi-file upload form), with a sub-folder."""
    return [
        ("door/mobility.urdf", hinge_urdf(mesh_file="meshes/lid.obj").encode()),
        ("door/meshes/lid.obj", TRIANGLE_OBJ.encode()),
    ]


def zip_slip() -> Upload:
    return "slip.zip", zip_bytes({"mobility.urdf": hinge_urdf(), "../evil.txt": "x"})


def zip_bomb() -> Upload:
    """A member that inflates ~1000x (the engine's limit is 200x)."""
    return "bomb.zip", zip_bytes({"mobility.urdf": hinge_urdf(), "padding.bin": b"\0" * (4 * 1024 * 1024)})


def xml_bomb() -> Upload:
    urdf = (
        '<?xml version="1.0"?>\n<!DOCTYPE robot [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">]>\n'
        '<robot name="bomb"><link name="base"><visual><geometry><box size="1 1 1"/></geometry></visual></link>'
        "<!-- &b; --></robot>\n"
    )
    return "xmlbomb.zip", zip_bytes({"mobility.urdf": urdf})


def missing_mesh() -> Upload:
    return "nomesh.zip", zip_bytes({"mobility.urdf": hinge_urdf(mesh_file="meshes/missing.obj")})


def no_urdf() -> Upload:
    return "empty.zip", zip_bytes({"readme.txt": "no robot here"})


def not_a_zip() -> Upload:
    return "broken.zip", b"PK\x03\x04 this is not really a zip"
