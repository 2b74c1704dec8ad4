"""Embed a link's meshes and materials into the USD stage of :mod:`app.engine.export.usd`.

Each :class:`MeshPart` becomes a ``Mesh`` prim under its link's Xform (``visual_<k>``;
points in the link frame, float32 metres; per-vertex normals; ``primvars:st`` with v up;
``subdivisionScheme`` none). Materials become ``UsdPreviewSurface`` shaders under
``/<asset>/materials`` (base colour, metallic, roughness, opacity; a texture becomes a PNG
file in ``usd_textures/`` read by a ``UsdUVTexture``); ``displayColor`` is set too for
viewers that ignore materials.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from app.engine.asset.model import ArticulatedAsset, Material, MeshPart
from app.engine.export.optional import require
from app.engine.files import atomic_write_bytes

TEXTURE_DIR = "usd_textures"
MATERIALS_SCOPE = "materials"


def add_geometry(stage: Any, asset: ArticulatedAsset, top: Any, paths: dict[str, Any], texture_dir: Path | None) -> list[str]:
    """Author every link's meshes; returns the texture files written (relative to ``texture_dir``)."""
    scope_name = MATERIALS_SCOPE
    while scope_name in {p.name for p in paths.values()}:
        scope_name = "_" + scope_name
    library = _Materials(stage, top.AppendChild(scope_name), texture_dir)
    for link in asset.link_order:
        taken = {paths[j.child].name for j in asset.child_joints(link)}
        for index, part in enumerate(asset.links[link].parts):
            name = f"visual_{index}"
            while name in taken:
                name = "_" + name
            _add_mesh(stage, paths[link].AppendChild(name), part, library.material(part.material))
    return library.files


class _Materials:
    """One USD material per distinct look (colour, metallic, roughness, sides, texture bytes), one PNG per distinct image."""

    def __init__(self, stage: Any, scope: Any, texture_dir: Path | None) -> None:
        self.stage, self.scope, self.texture_dir = stage, scope, texture_dir
        self.known: dict[tuple[object, ...], Any] = {}
        self.images: dict[bytes, str] = {}
        self.files: list[str] = []

    def material(self, material: Material) -> Any:
        key = (material.base_color, material.metallic, material.roughness, material.double_sided, material.image_png)
        found = self.known.get(key)
        if found is None:
            found = self._define(material, self.scope.AppendChild(f"material_{len(self.known)}"))
            self.known[key] = found
        return found

    def _image_file(self, image: bytes) -> str:
        """The texture's file relative to the stage (written once per distinct image)."""
        relative = self.images.get(image)
        if relative is None and self.texture_dir is not None:
            relative = f"{TEXTURE_DIR}/texture_{len(self.images)}.png"
            atomic_write_bytes(self.texture_dir / relative, image, sync=False)
            self.images[image] = relative
            self.files.append(relative)
        return relative or ""

    def _define(self, material: Material, path: Any) -> Any:
        usd_shade, sdf, gf = require("pxr.UsdShade"), require("pxr.Sdf"), require("pxr.Gf")
        result = usd_shade.Material.Define(self.stage, path)
        shader = usd_shade.Shader.Define(self.stage, path.AppendChild("surface"))
        shader.CreateIdAttr("UsdPreviewSurface")
        red, green, blue, alpha = material.base_color
        diffuse = shader.CreateInput("diffuseColor", sdf.ValueTypeNames.Color3f)
        diffuse.Set(gf.Vec3f(red, green, blue))
        shader.CreateInput("metallic", sdf.ValueTypeNames.Float).Set(float(material.metallic))
        shader.CreateInput("roughness", sdf.ValueTypeNames.Float).Set(float(material.roughness))
        shader.CreateInput("opacity", sdf.ValueTypeNames.Float).Set(float(alpha))
        if material.image_png is not None and self.texture_dir is not None:
            diffuse.ConnectToSource(self._texture(path, f"./{self._image_file(material.image_png)}").ConnectableAPI(), "rgb")
        result.CreateSurfaceOutput().ConnectToSource(shader.ConnectableAPI(), "surface")
        return result

    def _texture(self, path: Any, file: str) -> Any:
        usd_shade, sdf = require("pxr.UsdShade"), require("pxr.Sdf")
        reader = usd_shade.Shader.Define(self.stage, path.AppendChild("st_reader"))
        reader.CreateIdAttr("UsdPrimvarReader_float2")
        reader.CreateInput("varname", sdf.ValueTypeNames.Token).Set("st")
        texture = usd_shade.Shader.Define(self.stage, path.AppendChild("texture"))
        texture.CreateIdAttr("UsdUVTexture")
        texture.CreateInput("file", sdf.ValueTypeNames.Asset).Set(sdf.AssetPath(file))
        texture.CreateInput("st", sdf.ValueTypeNames.Float2).ConnectToSource(reader.ConnectableAPI(), "result")
        texture.CreateInput("wrapS", sdf.ValueTypeNames.Token).Set("repeat")
        texture.CreateInput("wrapT", sdf.ValueTypeNames.Token).Set("repeat")
        texture.CreateOutput("rgb", sdf.ValueTypeNames.Float3)
        return texture


def _add_mesh(stage: Any, path: Any, part: MeshPart, material: Any) -> None:
    usd_geom, usd_shade, vt, gf = require("pxr.UsdGeom"), require("pxr.UsdShade"), require("pxr.Vt"), require("pxr.Gf")
    sdf = require("pxr.Sdf")
    mesh = usd_geom.Mesh.Define(stage, path)
    points = np.ascontiguousarray(part.vertices, dtype=np.float32)
    mesh.CreatePointsAttr(vt.Vec3fArray.FromNumpy(points))
    mesh.CreateFaceVertexCountsAttr(vt.IntArray.FromNumpy(np.full(len(part.faces), 3, dtype=np.int32)))
    mesh.CreateFaceVertexIndicesAttr(vt.IntArray.FromNumpy(np.ascontiguousarray(part.faces, dtype=np.int32).ravel()))
    mesh.CreateSubdivisionSchemeAttr(usd_geom.Tokens.none)
    mesh.CreateDoubleSidedAttr(bool(part.material.double_sided))
    mesh.CreateExtentAttr(vt.Vec3fArray.FromNumpy(np.stack([points.min(axis=0), points.max(axis=0)])))
    if part.normals is not None:
        mesh.CreateNormalsAttr(vt.Vec3fArray.FromNumpy(np.ascontiguousarray(part.normals, dtype=np.float32)))
        mesh.SetNormalsInterpolation(usd_geom.Tokens.vertex)
    if part.uv is not None:
        st = np.column_stack([part.uv[:, 0], 1.0 - part.uv[:, 1]]).astype(np.float32)
        primvar = usd_geom.PrimvarsAPI(mesh).CreatePrimvar("st", sdf.ValueTypeNames.TexCoord2fArray, usd_geom.Tokens.vertex)
        primvar.Set(vt.Vec2fArray.FromNumpy(st))
    red, green, blue, alpha = part.material.base_color
    mesh.CreateDisplayColorPrimvar(usd_geom.Tokens.constant).Set(vt.Vec3fArray([gf.Vec3f(red, green, blue)]))
    if alpha < 1.0:
        mesh.CreateDisplayOpacityPrimvar(usd_geom.Tokens.constant).Set(vt.FloatArray([float(alpha)]))
    usd_shade.MaterialBindingAPI.Apply(mesh.GetPrim()).Bind(material)
