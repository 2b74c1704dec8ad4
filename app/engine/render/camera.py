"""Pinhole cameras: view/projection matrices, pixel projection and object-framing orbits.

Conventions
-----------
- World frame: the asset's root frame, +Z up (SPEC §1).
- Camera frame (OpenGL): +x right, +y up, the camera looks down -z.
- Pixels: origin at the top-left corner of the image, x to the right, y down; the
  centre of pixel column ``i`` is at ``x = i + 0.5``. This is exactly where the GL
  rasteriser puts a point once the read-back rows are flipped top-first.
- ``fov_deg`` is the **vertical** field of view; the horizontal one follows from the
  aspect ratio ``width / height``. The fov is used everywhere (matrices, framing,
  projection), unlike the authors' fixed 50 degrees.
- Orbits: azimuth is measured in the XY plane from +X toward +Y, elevation from the XY
  plane toward +Z; the eye sits at
  ``center + d * (cos el cos az, cos el sin az, sin el)`` looking at ``center``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from app.engine.asset.kinematics import rest_poses
from app.engine.asset.model import ArticulatedAsset
from app.engine.errors import RenderError
from app.engine.types import FloatArray, Points, Transform, Vector3

WORLD_UP = (0.0, 0.0, 1.0)
DEFAULT_FOV_DEG = 35.0
CANONICAL_AZIMUTHS_DEG = (0.0, 90.0, 180.0, 270.0)
CANONICAL_ELEVATION_DEG = 20.0
FRAME_MARGIN = 1.05
"""The bounding sphere is fitted with this much slack (5 %) so silhouettes never touch the border."""
MIN_RADIUS_M = 1e-3
"""Radius used for degenerate (point-like) bounds."""
CLIP_RADII = 3.0
"""Near/far planes sit this many bounding radii in front of / behind the target."""
MIN_NEAR_FRACTION = 0.01
"""The near plane is never closer than this fraction of the eye-target distance."""
PARALLEL_EPS = 1e-9


def _unit(vector: FloatArray, what: str) -> FloatArray:
    length = float(np.linalg.norm(vector))
    if not math.isfinite(length) or length < PARALLEL_EPS:
        raise RenderError(f"camera {what} is degenerate: {vector.tolist()}")
    return vector / length


@dataclass(frozen=True)
class ViewSpec:
    """An object-centred orbit view (the paper's camera-bank entry)."""

    azimuth_deg: float
    elevation_deg: float
    fov_deg: float = DEFAULT_FOV_DEG
    distance_scale: float = 1.0


def canonical_views() -> tuple[ViewSpec, ...]:
    """The four initial views: azimuth 0/90/180/270, elevation 20, fov 35, distance scale 1 (supp. §2.3)."""
    return tuple(ViewSpec(az, CANONICAL_ELEVATION_DEG, DEFAULT_FOV_DEG, 1.0) for az in CANONICAL_AZIMUTHS_DEG)


@dataclass(frozen=True, eq=False)
class Camera:
    """A perspective pinhole camera.

    Attributes
    ----------
    eye, target : (3,) float, metres, world frame
    up : (3,) float, world "up" hint (+Z by default); need not be orthogonal to the view
    fov_deg : float, vertical field of view in degrees, in (0, 180)
    width, height : int, image size in pixels
    near, far : float, metres, clip distances along the viewing direction
    """

    eye: Vector3
    target: Vector3
    up: Vector3 = field(default_factory=lambda: np.array(WORLD_UP))
    fov_deg: float = DEFAULT_FOV_DEG
    width: int = 800
    height: int = 600
    near: float = 0.01
    far: float = 100.0

    def __post_init__(self) -> None:
        for name in ("eye", "target", "up"):
            value = np.asarray(getattr(self, name), dtype=np.float64).reshape(3).copy()
            value.setflags(write=False)
            object.__setattr__(self, name, value)
        if not 0.0 < self.fov_deg < 180.0:
            raise RenderError(f"camera fov_deg must be in (0, 180), got {self.fov_deg}")
        if self.width <= 0 or self.height <= 0:
            raise RenderError(f"camera image size must be positive, got {self.width}x{self.height}")
        if not 0.0 < self.near < self.far:
            raise RenderError(f"camera needs 0 < near < far, got near={self.near}, far={self.far}")
        self.basis()  # validates eye != target and up not parallel to the view

    @property
    def aspect(self) -> float:
        return self.width / self.height

    @property
    def focal_px(self) -> float:
        """Focal length in pixels (the same for x and y: square pixels)."""
        return 0.5 * self.height / math.tan(math.radians(self.fov_deg) / 2.0)

    def basis(self) -> tuple[Vector3, Vector3, Vector3]:
        """(right, true_up, forward) unit vectors in world coordinates."""
        forward = _unit(self.target - self.eye, "viewing direction (eye == target)")
        right = np.cross(forward, self.up)
        right = _unit(right, "up vector (parallel to the viewing direction)")
        return right, np.cross(right, forward), forward

    def view_matrix(self) -> Transform:
        """(4, 4) world -> camera (OpenGL camera frame, looking down -z)."""
        right, true_up, forward = self.basis()
        rotation = np.stack([right, true_up, -forward])
        out = np.eye(4)
        out[:3, :3] = rotation
        out[:3, 3] = -rotation @ self.eye
        return out

    def projection_matrix(self) -> Transform:
        """(4, 4) camera -> clip space (OpenGL conventions, NDC z in [-1, 1])."""
        f = 1.0 / math.tan(math.radians(self.fov_deg) / 2.0)
        n, far = self.near, self.far
        out = np.zeros((4, 4))
        out[0, 0] = f / self.aspect
        out[1, 1] = f
        out[2, 2] = (far + n) / (n - far)
        out[2, 3] = 2.0 * far * n / (n - far)
        out[3, 2] = -1.0
        return out

    def view_projection(self) -> Transform:
        """(4, 4) world -> clip space."""
        return self.projection_matrix() @ self.view_matrix()

    def project(self, points: Points) -> tuple[FloatArray, FloatArray]:
        """Project world points to pixels.

        Parameters
        ----------
        points : (n, 3) float, metres, world frame

        Returns
        -------
        pixels : (n, 2) float, (x right, y down) from the image's top-left corner
        depth : (n,) float, metres along the viewing direction (> 0 in front of the
            camera; pixels of points with depth <= 0 are meaningless)
        """
        pts = np.asarray(points, dtype=np.float64).reshape(-1, 3)
        right, true_up, forward = self.basis()
        relative = pts - self.eye
        depth = relative @ forward
        safe = np.where(np.abs(depth) < PARALLEL_EPS, PARALLEL_EPS, depth)
        x = 0.5 * self.width + self.focal_px * (relative @ right) / safe
        y = 0.5 * self.height - self.focal_px * (relative @ true_up) / safe
        return np.stack([x, y], axis=1), depth

    def screen_direction(self, vector: Vector3) -> FloatArray:
        """(2,) components of a world direction on the screen (x right, y down), unnormalised.

        An orthographic approximation: the vector's components along the camera's
        right and up axes (the same projection the axis legend uses).
        """
        right, true_up, _ = self.basis()
        v = np.asarray(vector, dtype=np.float64).reshape(3)
        return np.array([v @ right, -(v @ true_up)])


def orbit_camera(
    bounds_center: Vector3,
    bounds_diag: float,
    azimuth_deg: float,
    elevation_deg: float,
    fov_deg: float = DEFAULT_FOV_DEG,
    distance_scale: float = 1.0,
    width: int = 800,
    height: int = 600,
) -> Camera:
    """A camera orbiting ``bounds_center`` that frames the object's bounding sphere.

    The distance is chosen from the fov so that the sphere of diameter ``bounds_diag``
    (plus :data:`FRAME_MARGIN`) fits inside the narrower of the vertical and horizontal
    fields of view, then multiplied by ``distance_scale`` (< 1 zooms in and may crop).

    Raises
    ------
    RenderError
        Non-positive ``distance_scale`` or an invalid fov/size.
    """
    if not distance_scale > 0.0:
        raise RenderError(f"distance_scale must be positive, got {distance_scale}")
    if not 0.0 < fov_deg < 180.0:
        raise RenderError(f"fov_deg must be in (0, 180), got {fov_deg}")
    center = np.asarray(bounds_center, dtype=np.float64).reshape(3)
    radius = max(0.5 * float(bounds_diag), MIN_RADIUS_M)
    half_v = math.radians(fov_deg) / 2.0
    half_h = math.atan(math.tan(half_v) * width / max(height, 1))
    distance = FRAME_MARGIN * radius / math.sin(min(half_v, half_h)) * distance_scale
    az, el = math.radians(azimuth_deg), math.radians(elevation_deg)
    direction = np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
    up = np.array(WORLD_UP)
    if abs(math.cos(el)) < 1e-6:  # straight above/below: +Z is the view axis; use the orbit's own up
        up = np.array([-math.sin(el) * math.cos(az), -math.sin(el) * math.sin(az), 0.0])
    near = max(distance - CLIP_RADII * radius, MIN_NEAR_FRACTION * distance)
    return Camera(
        eye=center + distance * direction,
        target=center,
        up=up,
        fov_deg=fov_deg,
        width=width,
        height=height,
        near=near,
        far=distance + CLIP_RADII * radius,
    )


def asset_bounds(asset: ArticulatedAsset, poses: Mapping[str, Transform] | None = None) -> tuple[Vector3, float]:
    """(center (3,), diagonal) of the world AABB of every visual link.

    ``poses`` holds one frame ``{link: (4, 4)}`` or several ``{link: (t, 4, 4)}`` (as
    returned by :func:`link_poses`); with several, the box is the union over all
    frames, so one camera can frame every state the same way. Rest pose when None.
    """
    if poses is None:
        poses = rest_poses(asset)
    low = np.full(3, np.inf)
    high = np.full(3, -np.inf)
    for name in asset.visual_links:
        if name not in poses:
            raise RenderError(f"no pose given for link '{name}'")
        stack = np.asarray(poses[name], dtype=np.float64).reshape(-1, 4, 4)
        vertices = asset.links[name].vertices()
        world = np.einsum("tij,nj->tni", stack[:, :3, :3], vertices) + stack[:, None, :3, 3]
        low = np.minimum(low, world.reshape(-1, 3).min(axis=0))
        high = np.maximum(high, world.reshape(-1, 3).max(axis=0))
    return 0.5 * (low + high), float(np.linalg.norm(high - low))


def view_camera(
    asset: ArticulatedAsset,
    view: ViewSpec,
    width: int = 800,
    height: int = 600,
    poses: Mapping[str, Transform] | None = None,
) -> Camera:
    """The orbit camera of ``view`` framing ``asset`` at ``poses`` (rest by default; several frames: their union)."""
    center, diag = asset_bounds(asset, poses)
    return orbit_camera(
        center, diag, view.azimuth_deg, view.elevation_deg, view.fov_deg, view.distance_scale, width, height
    )
