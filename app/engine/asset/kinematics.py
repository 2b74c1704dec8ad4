"""Forward kinematics, vectorised over frames.

Conventions: a link pose maps link-frame points to the world frame (URDF root frame,
+Z up). ``child = parent @ joint.origin @ motion(q)``; the base pose (translation +
rotation of the whole object) is pre-multiplied onto every link.
"""

from __future__ import annotations

from collections.abc import Mapping
from weakref import WeakKeyDictionary

import numpy as np

from app.engine.asset.model import ArticulatedAsset, JointSpec
from app.engine.types import FloatArray, Transforms


def axis_angle_matrices(axis: FloatArray, angles: FloatArray) -> FloatArray:
    """(t, 3, 3) rotations by ``angles`` (t,) radians about the unit ``axis`` (3,) (Rodrigues)."""
    x, y, z = axis
    k = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    k2 = k @ k
    s = np.sin(angles)[:, None, None]
    c = np.cos(angles)[:, None, None]
    return np.eye(3)[None] + s * k[None] + (1.0 - c) * k2[None]


def joint_motion(joint: JointSpec, q: FloatArray) -> Transforms:
    """(t, 4, 4) motion of ``joint`` for values ``q`` (t,)."""
    count = q.shape[0]
    out = np.zeros((count, 4, 4))
    out[:, 3, 3] = 1.0
    if joint.type in ("revolute", "continuous"):
        out[:, :3, :3] = axis_angle_matrices(joint.axis, q)
    else:
        out[:, :3, :3] = np.eye(3)
        if joint.type == "prismatic":
            out[:, :3, 3] = q[:, None] * joint.axis[None, :]
    return out


def quaternion_matrices(xyzw: FloatArray) -> FloatArray:
    """(t, 3, 3) rotation matrices of unit quaternions (t, 4) given as x, y, z, w."""
    q = xyzw / np.linalg.norm(xyzw, axis=1, keepdims=True)
    x, y, z, w = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    return np.stack(
        [
            np.stack([1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)], axis=-1),
            np.stack([2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)], axis=-1),
            np.stack([2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)], axis=-1),
        ],
        axis=1,
    )


def base_transforms(translation: FloatArray, rotation_xyzw: FloatArray | None = None) -> Transforms:
    """(t, 4, 4) base poses from translations (t, 3) and optional quaternions (t, 4)."""
    count = translation.shape[0]
    out = np.zeros((count, 4, 4))
    out[:, 3, 3] = 1.0
    out[:, :3, :3] = np.eye(3) if rotation_xyzw is None else quaternion_matrices(rotation_xyzw)
    out[:, :3, 3] = translation
    return out


def link_poses(
    asset: ArticulatedAsset,
    joint_values: Mapping[str, FloatArray],
    base: Transforms | None = None,
    frames: int | None = None,
) -> dict[str, Transforms]:
    """World poses of every link.

    Parameters
    ----------
    joint_values
        {joint name: (t,) values}; joints not given sit at their rest value.
        Mimic joints are derived from their leader when absent.
    base
        (t, 4, 4) base poses; identity when ``None``.
    frames
        Number of frames t when it cannot be inferred from the inputs.

    Returns
    -------
    dict of link name -> (t, 4, 4) world transforms.
    """
    count = _frame_count(joint_values, base, frames)
    values = _driven_values(asset, joint_values, count)
    at_rest = _rest_locals(asset)
    root = np.broadcast_to(np.eye(4), (count, 4, 4)).copy() if base is None else np.asarray(base, dtype=np.float64)
    poses: dict[str, Transforms] = {asset.root_link: root}
    for name in asset.joint_order:
        joint = asset.joints[name]
        # a joint not driven (fixed, or at its rest value in every frame) has the same (1, 4, 4) local transform each frame
        local = joint.origin[None] @ joint_motion(joint, values[name]) if name in values else at_rest[name]
        poses[joint.child] = poses[joint.parent] @ local
    return poses


_REST_LOCALS: WeakKeyDictionary[ArticulatedAsset, dict[str, FloatArray]] = WeakKeyDictionary()
"""Per asset, as long as the asset lives (a collected asset's GPU buffers are freed: nothing here keeps it)."""


def _rest_locals(asset: ArticulatedAsset) -> dict[str, FloatArray]:
    """(1, 4, 4) joint frame motion of every joint at rest (fixed joints: their origin), per asset: the joints a
    call does not drive cost no motion of their own (one joint driven on a large asset was work in its size)."""
    known = _REST_LOCALS.get(asset)
    if known is None:
        rest = resolve_joint_values(asset, {}, 1)
        known = {name: (joint.origin[None] @ joint_motion(joint, rest[name]) if joint.movable else joint.origin[None])
                 for name, joint in asset.joints.items()}
        _REST_LOCALS[asset] = known
    return known


_LEADERS: WeakKeyDictionary[ArticulatedAsset, frozenset[str]] = WeakKeyDictionary()


def drives_mimics(asset: ArticulatedAsset, joint: str) -> bool:
    """Some mimic joint follows ``joint`` (the leaders are found once per asset: asking every joint is no walk over
    all joints; a follower's own followers follow it through that follower)."""
    known = _LEADERS.get(asset)
    if known is None:
        known = _LEADERS[asset] = frozenset(j.mimic.joint for j in asset.joints.values() if j.mimic is not None)
    return joint in known


def _driven_values(asset: ArticulatedAsset, joint_values: Mapping[str, FloatArray], count: int) -> dict[str, FloatArray]:
    """(t,) values of the movable joints given, and of the mimics following them (as :func:`resolve_joint_values`);
    every other joint sits at the value it has when nothing is given."""
    values: dict[str, FloatArray] = {}
    for name, value in joint_values.items():
        joint = asset.joints.get(name)
        if joint is not None and joint.movable:
            values[name] = np.asarray(value, dtype=np.float64).reshape(count)
    if not values:
        return values
    pending = [n for n in asset.movable_joints if n not in values and asset.joints[n].mimic is not None]
    progressed = True
    while pending and progressed:
        progressed = False
        for name in list(pending):
            mimic = asset.joints[name].mimic
            if mimic is not None and mimic.joint in values:
                values[name] = asset.joints[name].clamp_array(mimic.multiplier * values[mimic.joint] + mimic.offset)
                pending.remove(name)
                progressed = True
    return values


def resolve_joint_values(asset: ArticulatedAsset, joint_values: Mapping[str, FloatArray], count: int) -> dict[str, FloatArray]:
    """(t,) values for every movable joint: given, mimic-derived, or rest."""
    values: dict[str, FloatArray] = {}
    for name in asset.movable_joints:
        if name in joint_values:
            values[name] = np.asarray(joint_values[name], dtype=np.float64).reshape(count)
    pending = [n for n in asset.movable_joints if n not in values]
    while pending:
        progressed = False
        for name in list(pending):
            joint = asset.joints[name]
            if joint.mimic is None:
                values[name] = np.full(count, joint.rest)
            elif joint.mimic.joint in values:
                leader = values[joint.mimic.joint]
                values[name] = joint.clamp_array(joint.mimic.multiplier * leader + joint.mimic.offset)
            else:
                continue
            pending.remove(name)
            progressed = True
        if not progressed:  # leader of a mimic is fixed: treat as rest 0
            for name in pending:
                values[name] = np.full(count, asset.joints[name].rest)
            pending = []
    return values


def _frame_count(joint_values: Mapping[str, FloatArray], base: Transforms | None, frames: int | None) -> int:
    if frames is not None:
        return frames
    if base is not None:
        return int(np.asarray(base).shape[0])
    for value in joint_values.values():
        return int(np.asarray(value).reshape(-1).shape[0])
    return 1


def subtree_poses(asset: ArticulatedAsset, joint: str, values: FloatArray, rest: Mapping[str, Transforms]) -> dict[str, Transforms]:
    """(t, 4, 4) world poses of the links ``joint`` moves, for its values (t,), the rest of the asset at ``rest``
    (``link_poses(asset, {}, frames=1)``).

    The same arithmetic as :func:`link_poses` on the subtree only: work in the size of the subtree, not of the
    asset (a per-joint question asked of every joint was work in the square of the asset's size). When the
    joint drives mimic followers, their links may lie anywhere, so the whole asset is posed.
    """
    values = np.asarray(values, dtype=np.float64).reshape(-1)
    count = values.shape[0]
    if drives_mimics(asset, joint):
        poses = link_poses(asset, {joint: values}, frames=count)
        return {name: poses[name] for name in asset.moving_links(joint)}
    at_rest = _rest_locals(asset)
    out: dict[str, Transforms] = {}
    for link in asset.moving_links(joint):  # in link_order: a parent before its children
        spec = asset.parent_joint(link)
        assert spec is not None  # every moved link hangs from a joint
        local = spec.origin[None] @ joint_motion(spec, values) if spec.name == joint else at_rest[spec.name]
        parent = out.get(spec.parent)
        out[link] = (np.broadcast_to(rest[spec.parent], (count, 4, 4)) if parent is None else parent) @ local
    return out


def subtree_motion(asset: ArticulatedAsset, joint: str, values: FloatArray, rest: Mapping[str, Transforms]) -> Transforms | None:
    """(t, 4, 4) world motion that takes the links ``joint`` moves from their rest poses to its values (t,):
    one rigid transform for the whole subtree, so posing it is one product over its points. None when the
    joint drives mimic followers (their links move otherwise): use :func:`subtree_poses`."""
    values = np.asarray(values, dtype=np.float64).reshape(-1)
    if drives_mimics(asset, joint):
        return None
    spec = asset.joints[joint]
    return (rest[spec.parent][0] @ spec.origin)[None] @ joint_motion(spec, values) @ np.linalg.inv(rest[spec.child][0])[None]


def rest_poses(asset: ArticulatedAsset) -> dict[str, FloatArray]:
    """(4, 4) world pose of every link at the rest configuration."""
    return {name: pose[0] for name, pose in link_poses(asset, {}, frames=1).items()}
