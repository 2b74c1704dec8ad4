"""``animation.usda``: the animation as a USD stage (read with ``pxr`` from ``usd-core``).

Layout: ``/<asset>`` (the default prim, an identity Xform) holds the root link's Xform,
and every link is an Xform **named as the link** (made a valid USD identifier when it is
not one; the URDF name is then kept as the prim's ``displayName``), nested as the
kinematic tree. Each link has one ``xformOp:transform``: its URDF local transform
(``joint.origin @ motion(q)``; the root link's is the base pose), time-sampled at every
frame for links that move (time code = frame index, ``timeCodesPerSecond`` = fps) and a
constant otherwise. Stage metadata as in the URDF: ``upAxis`` Z, ``metersPerUnit`` 1.
Meshes are embedded under each link (see :mod:`app.engine.export.usd_geometry`).
Opens in Blender (File > Import > USD), usdview, Omniverse / Isaac Sim.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from app.engine.export.optional import require
from app.engine.export.track import ExportTrack
from app.engine.files import atomic_write_text

USD_FILE = "animation.usda"
TRANSFORM_OP = "xformOp:transform"


def prim_names(names: list[str]) -> dict[str, str]:
    """{name: a valid, unique USD prim name} (``Tf.MakeValidIdentifier``, ``_N`` suffixes on clashes)."""
    tf = require("pxr.Tf")
    result: dict[str, str] = {}
    taken: set[str] = set()
    for name in names:
        candidate = base = tf.MakeValidIdentifier(name)
        suffix = 1
        while candidate in taken:
            candidate = f"{base}_{suffix}"
            suffix += 1
        taken.add(candidate)
        result[name] = candidate
    return result


def _matrices(stack: np.ndarray) -> list[Any]:
    """Gf.Matrix4d per (4, 4) transform; USD multiplies row vectors, so each is transposed."""
    gf = require("pxr.Gf")
    return [gf.Matrix4d(m) for m in np.transpose(stack, (0, 2, 1)).tolist()]


def usd_text(track: ExportTrack, *, geometry: bool = True, texture_dir: Path | None = None) -> str:
    """The ``animation.usda`` text (textures, if any, are written into ``texture_dir``).

    Raises
    ------
    ExportError
        ``usd-core`` is not installed (extra ``usd``).
    """
    usd = require("pxr.Usd")
    usd_geom = require("pxr.UsdGeom")
    sdf = require("pxr.Sdf")
    asset = track.asset
    stage = usd.Stage.CreateInMemory()
    usd_geom.SetStageUpAxis(stage, usd_geom.Tokens.z)
    usd_geom.SetStageMetersPerUnit(stage, 1.0)
    stage.SetTimeCodesPerSecond(track.fps)
    stage.SetFramesPerSecond(track.fps)
    stage.SetStartTimeCode(0)
    stage.SetEndTimeCode(max(track.frame_count - 1, 0))
    names = prim_names([asset.name, *asset.link_order])
    top = sdf.Path.absoluteRootPath.AppendChild(names[asset.name])
    stage.SetDefaultPrim(usd_geom.Xform.Define(stage, top).GetPrim())
    paths = {asset.root_link: top.AppendChild(names[asset.root_link])}
    for joint in (asset.joints[j] for j in asset.joint_order):
        paths[joint.child] = paths[joint.parent].AppendChild(names[joint.child])
    for link in asset.link_order:
        prim = usd_geom.Xform.Define(stage, paths[link])
        if names[link] != link:
            prim.GetPrim().SetDisplayName(link)
        op = prim.AddTransformOp()
        stack = track.local[link]
        if link in track.moving_links:
            for frame, matrix in enumerate(_matrices(stack)):
                op.Set(matrix, usd.TimeCode(frame))
        else:
            op.Set(_matrices(stack[:1])[0])
    if geometry:
        from app.engine.export.usd_geometry import add_geometry

        add_geometry(stage, asset, top, paths, texture_dir)
    text: str = stage.GetRootLayer().ExportToString()
    return text


def write_usd(track: ExportTrack, out_dir: Path, *, geometry: bool = True) -> str:
    """Write ``animation.usda`` (and ``usd_textures/*.png`` for textured meshes) into ``out_dir``."""
    atomic_write_text(out_dir / USD_FILE, usd_text(track, geometry=geometry, texture_dir=out_dir))
    return USD_FILE
